// CSV input tables (time in the first column, one column per variable) and
// CSV output.
#ifndef FMUSIM_IO_CSV_HPP
#define FMUSIM_IO_CSV_HPP

#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace fmusim {

// The fields of one CSV line; a field may be quoted ("A.R[1,1]", with ""
// for a quote inside). Empty optional for an unterminated quote.
std::optional<std::vector<std::string>> splitCsvLine(const std::string& line);

// s quoted when it holds a comma, a quote or a blank at either end.
std::string csvField(const std::string& s);

// A number with enough digits to read it back exactly.
std::string formatNumber(double value);

// An input table: a header row of names (the first is the time column,
// any name), then rows of numbers with non-decreasing times. Blank lines
// and lines starting with '#' are skipped. Errors are FileError with
// "file:line: problem".
class InputTable {
public:
    explicit InputTable(const std::string& path);

    const std::string& path() const { return path_; }
    const std::vector<std::string>& names() const
    {
        return names_;
    } // the columns after time
    int headerLine() const { return headerLine_; }

    // Linear interpolation in time; the first and last rows hold outside
    // the table; at a repeated time the later row counts.
    double interpolate(std::size_t column, double t) const;
    // The value of the last row at or before t (the first row before it).
    double previous(std::size_t column, double t) const;

private:
    std::size_t rowAtOrBefore(double t) const;

    std::string path_;
    int headerLine_ = 0;
    std::vector<std::string> names_;
    std::vector<double> times_;
    std::vector<std::vector<double>> values_; // [row][column]
};

// Writes rows to a file, or to standard output when the path is empty;
// each row is flushed as it is written.
class CsvWriter {
public:
    explicit CsvWriter(
        const std::string& path); // FileError if it cannot be created
    void row(const std::vector<std::string>& fields);
    void finish(); // FileError if writing failed

private:
    std::string path_;
    std::ofstream file_;
    std::ostream* out_;
};

} // namespace fmusim

#endif
