#include "fmusimHarness.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>

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
    for (const char c : line)
    {
        if (c == '"')
            quoted = !quoted;
        else if (c == ',' && !quoted)
        {
            out.push_back(field);
            field.clear();
        }
        else
            field += c;
    }
    out.push_back(field);
    return out;
}

}  // namespace

std::string scratch(const std::string& name)
{
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "fmusimTests" /
                                      (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

Result fmusim(const std::string& arguments)
{
    const std::string out = scratch("stdout.txt"), err = scratch("stderr.txt");
    const std::string command = std::string(FMUSIM) + " " + arguments + " > " + out + " 2> " + err;
    const int status = std::system(command.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
}

std::string fixture(const std::string& name) { return std::string(FIXTURE_FMU_DIR) + "/" + name + ".fmu"; }

void writeFile(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

std::size_t Table::column(const std::string& name) const
{
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return i;
    throw std::runtime_error("no column " + name);
}

std::vector<double> Table::values(const std::string& name) const
{
    const std::size_t c = column(name);
    std::vector<double> v;
    for (const std::vector<double>& row : rows) v.push_back(row.at(c));
    return v;
}

Table parseTable(const std::string& text)
{
    Table t;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line))
    {
        if (line.empty()) continue;
        if (t.names.empty())
        {
            t.names = fields(line);
            continue;
        }
        std::vector<double> row;
        for (const std::string& f : fields(line))
        {
            char* end = nullptr;
            const double value = std::strtod(f.c_str(), &end);
            row.push_back(end != f.c_str() && *end == '\0' ? value : std::numeric_limits<double>::quiet_NaN());
        }
        t.rows.push_back(row);
    }
    return t;
}

Table readTable(const std::string& path) { return parseTable(slurp(path)); }

}  // namespace harness
