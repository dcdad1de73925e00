#include "fmusimHarness.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace harness {

namespace {

std::string slurp(const std::string& path)
{
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::vector<std::string> fields(const std::string& line)
{
    std::vector<std::string> out;
    std::string field;
    bool quoted = false;
    for (const char c : line) {
        if (c == '"')
            quoted = !quoted;
        else if (c == ',' && !quoted) {
            out.push_back(field);
            field.clear();
        } else
            field += c;
    }
    out.push_back(field);
    return out;
}

} // namespace

std::string scratch(const std::string& name)
{
    const ::testing::TestInfo* info
        = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::filesystem::path dir = std::filesystem::temp_directory_path()
        / "fmusimTests"
        / (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

Result fmusim(const std::string& arguments, double limitSeconds)
{
    const std::string out = scratch("stdout.txt"), err = scratch("stderr.txt");
    // exec: fmusim replaces the shell, so its exit status is the shell's.
    const std::string command = "ulimit -c 0; exec timeout -s KILL "
        + std::to_string(limitSeconds) + " " + std::string(FMUSIM) + " "
        + arguments + " > " + out + " 2> " + err;
    const auto start = std::chrono::steady_clock::now();
    const int status = std::system(command.c_str());
    Result r {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out),
              slurp(err)};
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now()
                                              - start)
                    .count();
    // timeout(1) reports a child killed by signal N as killed by N itself,
    // and a shell as exit status 128 + N.
    if (WIFSIGNALED(status))
        r.signal = WTERMSIG(status);
    else if (r.exitCode > 128)
        r.signal = r.exitCode - 128;
    return r;
}

std::string fixture(const std::string& name)
{
    return std::string(FIXTURE_FMU_DIR) + "/" + name + ".fmu";
}

void writeFile(const std::string& path, const std::string& text)
{
    std::ofstream(path) << text;
}

std::size_t Table::column(const std::string& name) const
{
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name)
            return i;
    throw std::runtime_error("no column " + name);
}

std::vector<double> Table::values(const std::string& name) const
{
    const std::size_t c = column(name);
    std::vector<double> v;
    for (const std::vector<double>& row : rows)
        v.push_back(row.at(c));
    return v;
}

Table parseTable(const std::string& text)
{
    Table t;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty())
            continue;
        if (t.names.empty()) {
            t.names = fields(line);
            continue;
        }
        std::vector<double> row;
        for (const std::string& f : fields(line)) {
            char* end = nullptr;
            const double value = std::strtod(f.c_str(), &end);
            row.push_back(end != f.c_str() && *end == '\0'
                              ? value
                              : std::numeric_limits<double>::quiet_NaN());
        }
        t.rows.push_back(row);
    }
    return t;
}

Table readTable(const std::string& path)
{
    return parseTable(slurp(path));
}

} // namespace harness
