// Running the fmusim program from tests and reading its CSV output.
#ifndef TESTS_FMUSIM_HARNESS_HPP
#define TESTS_FMUSIM_HARNESS_HPP

#include <cstddef>
#include <string>
#include <vector>

namespace harness {

struct Result {
    int exitCode; // -1 when fmusim did not exit but was killed by a signal
    std::string out, err;
    int signal = 0; // the signal that killed fmusim, else 0
    double seconds = 0; // wall-clock time of the run
};

// Runs `fmusim <arguments>` through the shell (quote arguments yourself),
// without core dumps; killed (SIGKILL) after limitSeconds.
Result fmusim(const std::string& arguments, double limitSeconds = 600);

// <build>/tests/fixture-fmus/<name>.fmu
std::string fixture(const std::string& name);

// A fresh scratch file path for this test.
std::string scratch(const std::string& name);

void writeFile(const std::string& path, const std::string& text);

// A CSV table as fmusim writes it; non-numeric fields read as NaN.
struct Table {
    std::vector<std::string> names;
    std::vector<std::vector<double>> rows;

    std::size_t column(const std::string& name) const; // throws if absent
    std::vector<double> values(const std::string& name) const;
};

Table readTable(const std::string& path);
Table parseTable(const std::string& text);

} // namespace harness

#endif
