// fmuImport: what the importer throws: Error, and LostCall for a call
// into an FMU that did not come back.
// Part of the importer's public interface (fmuImport.hpp includes every
// part), C++11 like the rest of it.
#ifndef FMUIMPORT_ERROR_HPP
#define FMUIMPORT_ERROR_HPP

#include <stdexcept>
#include <string>

namespace fmuImport {

// Every failure of the importer; the message names the FMU file and the
// variable, function or archive entry involved.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A call into an FMU that did not come back: its process crashed or exited
// in it, it outlasted the time limit, or the FMU wrote to or closed the
// channel to its process. The message names the fmi2 function, the time,
// the FMU and the instance: "the FMU crashed (SIGSEGV, segmentation fault)
// in fmi2DoStep at t = 0.75 in FMU 'x.fmu', instance 'x'", "time-out: ...
// did not return within 1 s". The instance is gone: every later call
// throws the same.
class LostCall : public Error {
public:
    enum class Reason { crashed, exited, timedOut, brokeChannel };
    LostCall(Reason reason, const std::string& message)
        : Error(message), reason_(reason)
    {
    }
    Reason reason() const { return reason_; }

private:
    Reason reason_;
};

} // namespace fmuImport

#endif
