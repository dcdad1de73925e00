// What the fmusim tests share besides running fmusim (fmusimHarness.hpp):
// looking for a text in its output and checking how a run failed.
#ifndef TESTS_FMUSIM_TEST_HPP
#define TESTS_FMUSIM_TEST_HPP

#include "fmusimHarness.hpp"

#include <gtest/gtest.h>

#include <string>

namespace harness {

inline bool contains(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

// fmusim `command` of the fixture `fmu` with `options`, its CSV written to
// a fresh scratch file: the result and the file
struct CsvRun {
    Result result;
    std::string csv;
};

inline CsvRun fmusimCsv(const std::string& command, const std::string& fmu,
                        const std::string& options, double limitSeconds = 600)
{
    const std::string out = scratch("out.csv");
    return {fmusim(command + " " + fixture(fmu) + " " + options
                       + " --output-file " + out,
                   limitSeconds),
            out};
}

// The run ended with exitCode and wrote message to standard error; else a
// failure showing what it wrote there.
inline ::testing::AssertionResult failed(const Result& r, int exitCode,
                                         const std::string& message)
{
    if (r.exitCode != exitCode)
        return ::testing::AssertionFailure()
            << "exit code " << r.exitCode << ", expected " << exitCode
            << "; standard error:\n"
            << r.err;
    if (!contains(r.err, message))
        return ::testing::AssertionFailure()
            << "standard error does not say '" << message << "':\n"
            << r.err;
    return ::testing::AssertionSuccess();
}

} // namespace harness

#endif
