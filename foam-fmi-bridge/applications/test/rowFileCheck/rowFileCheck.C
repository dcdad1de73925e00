// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
/*---------------------------------------------------------------------------*\
Application
    rowFileCheck

Description
    Check of the numbers the project's tables are written with
    (rowFile::appendNumber, the connectors' rows): every double reads back
    as the same double, in the shortest form that does.

    The doubles: the special ones (+-0, the smallest subnormal, the largest
    and smallest normal, 0.1, 1/3, 2^53 + 2, powers of ten from 1e-300 to
    1e300) and n (default 100000) of random bit patterns (every finite one
    equally likely: every exponent, subnormals included) and of random
    numbers of the size of a connector's outputs (uniform in -1e4..1e4).
    For each, in this program:
     - std::strtod and std::from_chars read the written form back to the
       same bits (the round trip);
     - it is no longer than the shortest scientific form with the fewest
       digits that reads back ("%.*e"; std::to_chars takes the fixed form
       where that has fewer characters): the shortest.
    They are also written as rows of 10 through rowFile to
    <dir>/numbers.dat, and their bits to <dir>/numbers.bin (native order),
    so that the readers of the tables (Python's float, numpy) are checked
    on the same file (tests/bridge/test_row_numbers.py).

    Prints one line per check and "<passed> passed, <failed> failed"; exits
    1 on a failure.

Usage
    rowFileCheck <dir> [n]
\*---------------------------------------------------------------------------*/

#include "rowFile.H"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

std::uint64_t bits(const double x)
{
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof(b));
    return b;
}


//- The shortest scientific form that reads back as x ("%.*e": the
//  fewest digits that do; a round trip with p digits after the point holds
//  with more too, so the fewest are found by bisection)
std::string shortestScientific(const double x)
{
    auto form = [x](const int p)
    {
        char s[64];
        std::snprintf(s, sizeof(s), "%.*e", p, x);
        return std::string(s);
    };
    int low = 0, high = 16;  // 17 significant digits always read back
    while (low < high)
    {
        const int mid = (low + high)/2;
        if (bits(std::strtod(form(mid).c_str(), nullptr)) == bits(x))
        {
            high = mid;
        }
        else
        {
            low = mid + 1;
        }
    }
    return form(low);
}


//- The doubles checked (see Description)
std::vector<double> numbers(const size_t n)
{
    std::vector<double> x
    {
        0.0, -0.0, std::numeric_limits<double>::denorm_min(),
        -std::numeric_limits<double>::denorm_min(),
        std::numeric_limits<double>::min(), std::numeric_limits<double>::max(),
        -std::numeric_limits<double>::max(), 0.1, 1.0/3.0, 9007199254740994.0,
        0.30000000000000004, 1e23, 5e-324, 2.2250738585072009e-308
    };
    for (int e = -300; e <= 300; ++e)
    {
        x.push_back(std::pow(10.0, e));
    }

    std::mt19937_64 random(20261206);
    while (x.size() < n + 615)
    {
        const std::uint64_t b = random();
        double y;
        std::memcpy(&y, &b, sizeof(y));
        if (std::isfinite(y))
        {
            x.push_back(y);
        }
    }
    std::uniform_real_distribution<double> outputs(-1e4, 1e4);
    for (size_t i = 0; i < n; ++i)
    {
        x.push_back(outputs(random));
    }
    return x;
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    if (argc < 2)
    {
        std::cerr << "Usage: rowFileCheck <dir> [n]" << std::endl;
        return 2;
    }
    const std::string dir(argv[1]);
    const size_t n = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 100000;
    const std::vector<double> x(numbers(n));

    size_t badStrtod = 0, badFromChars = 0, notShortest = 0;
    std::string example;
    std::string rows;
    rowFile table(fileName(dir + "/numbers.dat"));
    table.append("# numbers of rowFileCheck, 10 a row\n", "the header");

    for (size_t i = 0; i < x.size(); ++i)
    {
        std::string s;
        rowFile::appendNumber(s, x[i]);

        // Read back: strtod (C, as Python's float and numpy read), and
        // from_chars
        if (bits(std::strtod(s.c_str(), nullptr)) != bits(x[i]))
        {
            if (!badStrtod++) example = s;
        }
        double y = 0;
        std::from_chars(s.data(), s.data() + s.size(), y);
        if (bits(y) != bits(x[i]))
        {
            if (!badFromChars++) example = s;
        }

        // The shortest: no longer than the shortest scientific form that
        // reads back (to_chars takes the fixed form where that has fewer
        // characters: 1e+20 is "100000000000000000000" no longer)
        const std::string shortest(shortestScientific(x[i]));
        if (s.size() > shortest.size())
        {
            if (!notShortest++) example = s + " (" + shortest + ")";
        }

        rows += s;
        rows += (i % 10 == 9 || i + 1 == x.size()) ? '\n' : ' ';
    }
    table.append(rows, "the numbers");

    std::ofstream bin(dir + "/numbers.bin", std::ios::binary);
    bin.write(reinterpret_cast<const char*>(x.data()), x.size()*sizeof(double));
    bin.close();

    const size_t failures = (badStrtod > 0) + (badFromChars > 0) + (notShortest > 0);
    auto line = [&](const bool ok, const std::string& what, const size_t bad)
    {
        std::cout
            << (ok ? "PASS " : "FAIL ") << what << ": " << bad << " of "
            << x.size() << " differ" << (ok ? "" : ", first " + example)
            << std::endl;
    };
    line(!badStrtod, "strtod reads the written form back to the same bits", badStrtod);
    line(!badFromChars, "from_chars reads it back to the same bits", badFromChars);
    line(!notShortest, "no shorter form reads back to the same bits", notShortest);
    std::cout
        << (bin ? "PASS" : "FAIL") << " numbers.bin written" << std::endl
        << 4 - failures - !bin << " passed, " << failures + !bin << " failed"
        << std::endl;

    return failures || !bin ? 1 : 0;
}


// ************************************************************************* //
