#include "io/Csv.hpp"

#include "io/Args.hpp"
#include "Errors.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace fmusim {

std::optional<std::vector<std::string>> splitCsvLine(const std::string& line)
{
    std::vector<std::string> fields;
    std::string field;
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                field += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                field += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            fields.push_back(trim(field));
            field.clear();
        } else {
            field += c;
        }
    }
    if (quoted)
        return std::nullopt;
    fields.push_back(trim(field));
    return fields;
}

std::string csvField(const std::string& s)
{
    const bool needsQuotes = s.find_first_of(",\"") != std::string::npos
        || (!s.empty() && (s.front() == ' ' || s.back() == ' '));
    if (!needsQuotes)
        return s;
    std::string quoted = "\"";
    for (const char c : s) {
        if (c == '"')
            quoted += '"';
        quoted += c;
    }
    return quoted + "\"";
}

std::string formatNumber(double value)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    return buffer;
}

InputTable::InputTable(const std::string& path) : path_(path)
{
    std::ifstream in(path);
    if (!in)
        throw FileError(path + ": cannot be read");
    std::string line;
    int lineNumber = 0;
    while (std::getline(in, line)) {
        ++lineNumber;
        const std::string content = trim(line);
        if (content.empty() || content.front() == '#')
            continue;
        const std::optional<std::vector<std::string>> fields
            = splitCsvLine(content);
        const std::string where
            = path + ":" + std::to_string(lineNumber) + ": ";
        if (!fields)
            throw FileError(where + "unterminated quote");
        if (headerLine_ == 0) {
            if (fields->size() < 2)
                throw FileError(
                    where
                    + "the header needs a time column and at least one variable");
            headerLine_ = lineNumber;
            names_.assign(fields->begin() + 1, fields->end());
            continue;
        }
        if (fields->size() != names_.size() + 1)
            throw FileError(
                where + "expected " + std::to_string(names_.size() + 1)
                + " values, found " + std::to_string(fields->size()));
        std::vector<double> row;
        for (std::size_t i = 0; i < fields->size(); ++i) {
            const std::optional<double> value = toNumber((*fields)[i]);
            if (!value)
                throw FileError(where + "'" + (*fields)[i] + "' in column "
                                + std::to_string(i + 1)
                                + " is not a finite number");
            row.push_back(*value);
        }
        if (!times_.empty() && row[0] < times_.back())
            throw FileError(where + "time " + (*fields)[0]
                            + " is before the time of the previous row");
        times_.push_back(row[0]);
        values_.emplace_back(row.begin() + 1, row.end());
    }
    if (headerLine_ == 0)
        throw FileError(path + ": no header row");
    if (times_.empty())
        throw FileError(path + ": no data rows after the header");
}

std::size_t InputTable::rowAtOrBefore(double t) const
{
    const auto after = std::upper_bound(times_.begin(), times_.end(), t);
    return after == times_.begin()
        ? 0
        : static_cast<std::size_t>(after - times_.begin()) - 1;
}

double InputTable::interpolate(std::size_t column, double t) const
{
    if (t < times_.front())
        return values_.front()[column];
    const std::size_t i = rowAtOrBefore(t);
    if (i + 1 >= times_.size())
        return values_.back()[column];
    const double w = (t - times_[i]) / (times_[i + 1] - times_[i]);
    return (1 - w) * values_[i][column] + w * values_[i + 1][column];
}

double InputTable::previous(std::size_t column, double t) const
{
    return values_[rowAtOrBefore(t)][column];
}

CsvWriter::CsvWriter(const std::string& path) : path_(path), out_(&std::cout)
{
    if (path.empty())
        return;
    file_.open(path);
    if (!file_)
        throw FileError(path + ": cannot be written");
    out_ = &file_;
}

void CsvWriter::row(const std::vector<std::string>& fields)
{
    for (std::size_t i = 0; i < fields.size(); ++i) {
        if (i)
            *out_ << ',';
        *out_ << fields[i];
    }
    *out_ << '\n';
    // Written through, not left in the stream's buffer: when the FMU
    // crashes or hangs in its next call (a SIGSEGV, the --timeout's _exit,
    // a kill), every row so far is on disk. A signal handler flushing the
    // buffer instead could not be trusted: flushing a std::ostream is not
    // async-signal-safe, the crash may have corrupted the heap, and SIGKILL
    // runs no handler. The price, one write(2) per row, is lost in the
    // formatting of the numbers: twobody writing 10 000 rows of 44 columns
    // takes 0.16 s with or without it.
    out_->flush();
}

void CsvWriter::finish()
{
    out_->flush();
    if (!*out_)
        throw FileError((path_.empty() ? std::string("standard output") : path_)
                        + ": write failed");
}

} // namespace fmusim
