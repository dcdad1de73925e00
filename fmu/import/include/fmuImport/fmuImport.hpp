// fmuImport: load an FMI 2.0 or FMI 3.0 co-simulation FMU and drive its
// instances.
//
// Public interface, C++11 (it is included by OpenFOAM code built with
// -std=c++11); the implementation is C++17. Every failure throws
// fmuImport::Error with a message naming the FMU file and the variable,
// function or archive entry involved.
#ifndef FMUIMPORT_FMUIMPORT_HPP
#define FMUIMPORT_FMUIMPORT_HPP

#include <cfenv>
#include <cstddef>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace fmuImport {

// Masks the caller's floating-point traps for its lifetime. OpenFOAM
// (FOAM_SIGFPE) enables the FE_DIVBYZERO, FE_INVALID and FE_OVERFLOW traps
// with feenableexcept. An FMU is written for the default IEEE environment:
// an overflow in its own arithmetic would then kill the host with SIGFPE
// instead of giving an infinity the FMU checks and reports as fmi2Error. So
// every call into FMU code runs inside one of these, and the caller's
// environment is restored afterwards. Switching traps costs a few hundred
// nanoseconds; a caller that makes several calls in a row (a connector's
// evaluation) masks once around them all, and the calls inside then find no
// trap to switch.
class MaskFpTraps {
public:
    // fegetexcept (glibc) only reads the control word, so a caller without
    // traps, the usual case, pays almost nothing.
    MaskFpTraps() : traps_(fegetexcept())
    {
        if (traps_ == 0)
            return;
        fegetexceptflag(&flags_, FE_ALL_EXCEPT);
        fedisableexcept(traps_);
    }

    // Restores the caller's status flags before its traps: the flags the
    // FMU raised are the FMU's business (it reports non-finite results
    // itself), and a flag left set under an enabled trap would fire at the
    // caller's next x87 instruction.
    ~MaskFpTraps()
    {
        if (traps_ == 0)
            return;
        fesetexceptflag(&flags_, FE_ALL_EXCEPT);
        feenableexcept(traps_);
    }

    MaskFpTraps(const MaskFpTraps&) = delete;
    MaskFpTraps& operator=(const MaskFpTraps&) = delete;

private:
    int traps_;
    fexcept_t flags_ {};
};

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

enum class Causality {
    parameter,
    calculatedParameter,
    input,
    output,
    local,
    independent,
    structuralParameter // FMI 3.0
};
enum class Variability { constant, fixed, tunable, discrete, continuous };
enum class Type { Real, Integer, Boolean, String, Enumeration };

// One <ScalarVariable> of an FMI 2.0 modelDescription.xml, or one element
// of a variable of an FMI 3.0 one.
//
// FMI 3.0 (fmiVersion "3.0"): a variable is typed by its element (Float64,
// Int32, ...) and may be an array (<Dimension>). The importer shows every
// element of an array as a Variable of its own, named as FMI 2.0 names
// scalars and FMI 3.0's structured naming names elements: "A.r[1]" for
// element 1 of the 3-vector A.r, "A.R[1,2]" for row 1, column 2 of the
// 3 x 3 matrix A.R (row-major, indices from 1); a scalar keeps its name.
// So an FMU of either version is used through the same names (the
// connector interface's "A.r[1]"), and getReal of elements gathers them
// from whole-array fmi3GetFloat64 calls. An element's value reference is
// the importer's: that of its array plus its position (the connector
// FMUs' 3.0 arrays take the value reference of their first 2.0 element,
// so their elements get the 2.0 value references), or, where that number
// is another variable's, one above every value reference of the FMU.
// Types: Float64 and Float32 are Real, the integer types Integer (an
// Int64 or UInt64 value outside int's range is an Error where it is read or
// set), Enumeration stays Enumeration, Binary is a String of hexadecimal
// digits ("666f6f"). Clocks are refused (the importer drives
// co-simulation without event mode).
struct Variable {
    std::string name;
    unsigned int valueReference = 0;
    Type type = Type::Real;
    Causality causality = Causality::local;
    Variability variability = Variability::continuous;
    std::string unit; // Real only; empty when not declared
    std::string description;
    bool hasStart = false;
    double start
        = 0; // numeric start (Real, Integer, Enumeration, Boolean as 0/1)
    std::string startString; // start exactly as written in the XML
    // FMI 3.0 only (empty or 0 for 2.0):
    std::string typeName; // the element type: "Float64", "Int8", "Binary", ...
    std::string arrayName; // an element's array, "A.r"; empty for a scalar
    std::vector<std::size_t> dimensions; // of that array: {3}, {3, 3}
    std::size_t element = 0; // position in the array, row-major from 0
    unsigned int arrayValueReference = 0; // the array's, as the FMU has it
};

struct ModelDescription {
    // guid: FMI 3.0's instantiationToken
    std::string fmiVersion, modelName, guid, modelIdentifier, description,
        generationTool;
    int fmiMajorVersion = 2; // 2 or 3
    bool hasEventMode = false; // FMI 3.0; instances never use it
    bool canHandleVariableCommunicationStepSize = false;
    bool canGetAndSetFMUstate = false;
    bool canSerializeFMUstate = false;
    bool providesDirectionalDerivative = false;
    bool canBeInstantiatedOnlyOncePerProcess
        = false; // then Instance refuses a second live instance
    bool hasDefaultExperiment = false;
    double startTime = 0, stopTime = 0,
           stepSize = 0; // <DefaultExperiment>, 0 when not given
    std::vector<Variable> variables; // in the order of the XML
};

// Receives the FMU's log messages, formatted; status is an fmi2Status value
// (0 OK, 1 Warning, 2 Discard, 3 Error, 4 Fatal, 5 Pending).
using Logger = std::function<void(const std::string& instanceName, int status,
                                  const std::string& category,
                                  const std::string& message)>;

// Where the code of an FMU's instances runs.
enum class Isolation {
    // In this process, the fastest. An FMU that crashes, aborts or calls
    // exit() in a call ends this process, after a report on standard error
    // naming the call (the FMU, the instance, the fmi2 function and the
    // time): the importer's handlers for SIGSEGV, SIGBUS, SIGFPE, SIGILL
    // and SIGABRT write it and then hand the signal to the handler that was
    // there before (the host's: OpenFOAM's stack trace); an exit hook makes
    // the status of an exit(0) non-zero (Reports). A call that outlasts the
    // time limit ends the process too (a watchdog thread).
    none,
    // Each instance in a child process of its own, the helper program
    // fmuImportWorker (started with posix_spawn; found through the
    // environment variable FMUIMPORT_WORKER, beside the running program,
    // in ../bin of the library that holds the importer, in the build tree,
    // or on PATH), driven through a page of shared memory. The FMU's
    // binary is not loaded in this process. A crash, abort() or exit() of
    // the FMU, a call that outlasts the time limit (the child is killed),
    // or an FMU that writes to or closes the channel throws LostCall from
    // the call; this process goes on. A call costs microseconds: calls that
    // return nothing (fmi2Set*, fmi2GetFMUstate, fmi2SetFMUstate,
    // fmi2FreeFMUstate) after initialization go with the next call that
    // returns something, whose Error reports their failure. Not a sandbox:
    // the child runs with this process's rights.
    process
};

// How an Fmu's instances run and how reports name them.
struct FmuOptions {
    Isolation isolation = Isolation::none;
    // The longest one fmi2 call of an instance may take [s]; 0: no limit.
    // Isolation::none: the process ends with a report (Reports); process:
    // the child is killed and the call throws LostCall. Loading the binary
    // (dlopen) is not limited.
    double timeout = 0;
    // How reports of a lost call name the instance's owner, "restraint
    // spring": "... in FMU 'x.fmu' of restraint spring"; empty: "... in
    // FMU 'x.fmu', instance '<name>'".
    std::string owner;
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

// The words and exit statuses of the reports that this process writes when
// an FMU running in it (Isolation::none) crashes, hangs or exits in a call:
// "<prefix>the FMU crashed (SIGSEGV, segmentation fault) in fmi2DoStep at t
// = 0.75 in FMU 'x.fmu', instance 'x'", "<prefix>time-out: ... did not
// return within 1 s<timeoutSource>", "<prefix>the FMU exited (status 0) in
// ...". Process-wide; set it before the first FMU is loaded.
struct Reports {
    std::string prefix; // "fmusim: "; at most 255 characters, as the next
    std::string timeoutSource; // what set the limit: " (--timeout)"
    int timeoutStatus = 1; // exit status after a time-out
    int exitStatus = 1; // exit status in place of an FMU's exit(0)
};
void setReports(const Reports& reports);

// A function of the host's that the importer calls when the process ends
// without running its exit handlers: from its handlers of fatal signals
// (those named at Fmu: the faults, and SIGINT, SIGTERM, ... when they end
// the process) and before a time-out ends it (Reports). It runs in a signal
// handler or in the watchdog thread while the process may be stopped
// anywhere: it must be async-signal-safe and return soon (the OpenFOAM
// bridge waits there, at most a second, for its writer thread to put the
// rows it holds on disk). One per process: the latest set; nullptr for none.
void setEndingHook(void (*hook)());

// An unpacked and loaded .fmu. Reads and checks modelDescription.xml from
// the archive (fmiVersion 2.0 or 3.0, <CoSimulation>: an FMI 3.0 FMU for
// model exchange or scheduled execution only, or with clocks, is refused
// with an Error that says so), then unpacks it, the binary
// (binaries/linux64/<modelIdentifier>.so for 2.0,
// binaries/x86_64-linux/<modelIdentifier>.so for 3.0) and everything under
// resources/ (nothing else) into a private temporary directory,
// $TMPDIR/fmuImport-<pid>-XXXXXX, loads the binary and resolves the common
// and co-simulation fmi2 (or fmi3) functions (a co-simulation-only FMU need
// not export the model-exchange ones).
//
// Limits: an entry may unpack to at most 256 MiB, all of them together to
// at most 1 GiB, or to the number of bytes in the environment variable
// FMUIMPORT_MAX_UNPACK_BYTES (which also caps an entry). They are checked
// on the sizes the zip directory declares, before anything is written, and
// again on the bytes written.
//
// Fmu objects of one file (the same canonical path, size and modification
// time) made while an earlier one or its instances are alive share one
// unpack directory and one loaded binary.
//
// The directory is removed on failure and when the last Fmu and Instance of
// it are gone (instances keep the binary loaded), and also when the process
// ends by exit() or by SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGSEGV,
// SIGFPE, SIGABRT, SIGBUS or SIGILL (handlers installed at the first load;
// they chain to the handlers installed before or after them). SIGKILL
// leaves it behind: the first load of a process into a temporary folder
// removes there every fmuImport-<pid>-XXXXXX directory of its user whose
// process no longer exists (no /proc/<pid>). Host floating-point traps are masked
// during every call into the FMU. A moved-from Fmu or Instance may only be
// destroyed or assigned to.
class Fmu {
public:
    // With Isolation::process the binary is not loaded here: a missing
    // fmi2 function is reported when the first instance is made.
    explicit Fmu(const std::string& fmuPath,
                 const FmuOptions& options = FmuOptions());
    ~Fmu();
    Fmu(Fmu&&) noexcept;
    Fmu& operator=(Fmu&&) noexcept;
    Fmu(const Fmu&) = delete;
    Fmu& operator=(const Fmu&) = delete;

    const std::string& path() const; // as given to the constructor
    const FmuOptions& options() const;
    const ModelDescription& modelDescription() const;
    bool hasVariable(const std::string& name) const;
    const Variable& variable(const std::string& name) const;
    std::string
    resourceLocation() const; // file:// URI of the unpacked resources folder
    std::string
    unpackDirectory() const; // the temporary directory the FMU is unpacked in

    struct Impl;

private:
    friend class Instance;
    Fmu(std::shared_ptr<Impl> impl, const std::string& path);
    std::shared_ptr<Impl> impl_;
    std::string path_;
    FmuOptions options_;
};

// One co-simulation fmi2Component (FMI 2.0) or fmi3Instance (FMI 3.0,
// instantiated with eventModeUsed and earlyReturnAllowed false: the FMU
// handles its events inside fmi3DoStep), in this process or in a child
// process (the Fmu's FmuOptions). The functions below are named after FMI
// 2.0's; for an FMI 3.0 FMU setupExperiment keeps the times for
// fmi3EnterInitializationMode, getReal and setReal call fmi3GetFloat64 and
// fmi3SetFloat64 (and Float32) on whole arrays, getInteger and setInteger
// the fmi3 integer functions, and a step that asks for event handling or
// returns early throws Error naming it. Every call is checked: fmi2Error,
// fmi2Fatal, fmi2Discard or fmi2Pending (fmi3Error, ...) throw Error naming the FMU, the
// instance and the function, with the last error the FMU logged appended;
// fmi2Warning is reported to the logger and the call goes on. A call that
// does not come back throws LostCall (Isolation::process) or ends the
// process (Isolation::none). Calls come from one thread at a time.
class Instance {
public:
    // The FMU's log messages go to logger, or to stderr when it is empty.
    // Throws Error if the FMU declares canBeInstantiatedOnlyOncePerProcess
    // and another instance of its binary is alive.
    Instance(const Fmu& fmu, const std::string& instanceName,
             Logger logger = Logger(), bool loggingOn = false);
    ~Instance();
    Instance(Instance&&) noexcept;
    Instance& operator=(Instance&&) noexcept;
    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;

    const std::string& name() const;
    const std::string& fmuPath() const; // as the Fmu names it

    void setupExperiment(double startTime, bool stopTimeDefined = false,
                         double stopTime = 0);
    void enterInitializationMode();
    void exitInitializationMode();
    void terminate();
    void reset();

    void setReal(const std::vector<unsigned int>& vrs,
                 const std::vector<double>& values);
    std::vector<double> getReal(const std::vector<unsigned int>& vrs);
    void setInteger(const std::vector<unsigned int>& vrs,
                    const std::vector<int>& values);
    std::vector<int> getInteger(const std::vector<unsigned int>& vrs);
    void setBoolean(const std::vector<unsigned int>& vrs,
                    const std::vector<bool>& values);
    std::vector<bool> getBoolean(const std::vector<unsigned int>& vrs);
    void setString(const std::vector<unsigned int>& vrs,
                   const std::vector<std::string>& values);
    std::vector<std::string> getString(const std::vector<unsigned int>& vrs);

    // Advances from currentTime to currentTime + stepSize; fmi2Discard throws.
    void doStep(double currentTime, double stepSize,
                bool noSetFMUStatePriorToCurrentPoint = false);

    // What a step that the FMU may refuse came to (FMI 2.0, 4.2.3):
    // completed; discarded, the FMU computed only part of the step
    // (lastSuccessfulTime() says how far); or terminated, the FMU asks to
    // end the simulation (fmi2Discard with fmi2Terminated true: its outputs
    // are those of lastSuccessfulTime()).
    enum class StepResult { completed, discarded, terminated };

    // doStep that returns fmi2Discard as discarded or terminated instead of
    // throwing; fmi2Error, fmi2Fatal and fmi2Pending throw. time() stays at
    // currentTime after a discarded or terminated step.
    StepResult tryDoStep(double currentTime, double stepSize,
                         bool noSetFMUStatePriorToCurrentPoint = false);

    // fmi2GetRealStatus(fmi2LastSuccessfulTime): after a discarded step, the
    // time up to which the FMU computed (FMI 3.0: fmi3DoStep's
    // lastSuccessfulTime; a step whose terminateSimulation is true with
    // fmi3OK is terminated too)
    double lastSuccessfulTime();

    // The FMU's last log message at fmi2Warning or above during the latest
    // call (a discarded step's reason), empty if none
    std::string lastMessage() const;

    struct Impl;

    // A saved FMU state, freed with fmi2FreeFMUstate when destroyed; it keeps
    // its instance's fmi2Component alive.
    class State {
    public:
        State();
        ~State();
        State(State&&) noexcept;
        State& operator=(State&&) noexcept;
        State(const State&) = delete;
        State& operator=(const State&) = delete;
        bool valid() const;

    private:
        friend class Instance;
        std::shared_ptr<Impl> owner_;
        void* state_;
        double
            time_; // communication point when saved; NaN after deserializeState
    };

    State getState();
    void setState(
        const State& state); // restores time() too, when the state carries it
    std::vector<char> serializeState(const State& state);
    State deserializeState(const std::vector<char>& bytes);

    // Current communication point: the start time, then currentTime +
    // stepSize of the last successful doStep.
    double time() const;

private:
    std::shared_ptr<Impl> impl_;
};

// The SHA-256 of the file at path, 64 lowercase hexadecimal digits (as
// sha256sum prints it); Error naming the file when it cannot be read. A
// case that names the hash of the .fmu it was set up with is sure to run
// that file: an FMU is native code, run with the rights of its host.
std::string fileSha256(const std::string& path);

// The connector FMU interface (docs/connector-fmu-interface.md) as every
// importer of connectors sees it: the vocabulary of interface variables with
// their rules, and a connector FMU's variables resolved against it. fmusim
// check reports what departs from it; the OpenFOAM bridge refuses such an
// FMU; both from the same list.
namespace connector {

enum class Shape { scalar, vector, matrix };
enum class Requirement { always, twoBody, optional };

// One name of the interface: base "A.r" with shape vector stands for
// A.r[1], A.r[2], A.r[3].
struct Term {
    std::string base;
    Shape shape;
    Causality causality;
    Variability variability;
    std::vector<std::string>
        units; // accepted units; the first is the documented one
    Requirement requirement;
};

// Every term of the interface: A's, B's, then the diagnostics.
const std::vector<Term>& vocabulary();

// The scalar names of a term: "A.r[1]".."A.r[3]", "A.R[1,1]".."A.R[3,3]".
std::vector<std::string> componentNames(const std::string& base, Shape shape);

// "input", "fixed", ...: the names modelDescription.xml uses.
const char* causalityName(Causality c);
const char* variabilityName(Variability v);

// One way in which a connector FMU departs from the vocabulary.
struct Problem {
    enum class Kind {
        missing, // a component of a required term, or of an optional term
        // of which other components are declared
        type, // not Real (FMI 3.0: not Float64)
        causality,
        variability,
        unit,
        // FMI 3.0: the term's variable has other dimensions than its
        // shape's ("A.r is an array of dimensions [4], expected an array
        // of dimensions [3]"); variable is the term's base, and its other
        // problems are not looked for
        dimensions
    };
    Kind kind;
    bool required; // a problem of a term the FMU must declare
    const Term* term; // into vocabulary()
    std::string variable; // the component: "A.r[2]"
    std::string text; // "missing A.r[2]", "A.F[1] has unit 'kN', expected 'N'"
};

// A connector FMU's interface variables. It is a two-body connector when it
// declares an input of B; a term counts as declared when all its components
// are declared Real variables. It follows the interface when problems() is
// empty.
class Variables {
public:
    explicit Variables(const Fmu& fmu);

    bool twoBody() const { return twoBody_; }
    bool required(const Term& term) const;

    // Value references of a term's components, in componentNames() order,
    // when it is declared; empty otherwise (also for a name that is not a
    // term).
    const std::vector<unsigned int>& refs(const std::string& base) const;
    bool declared(const std::string& base) const { return !refs(base).empty(); }

    // The required terms not declared ("A.F", ...): empty for a usable
    // connector.
    std::vector<std::string> missingRequired() const;

    // In vocabulary order, each term's components in order.
    const std::vector<Problem>& problems() const { return problems_; }

private:
    bool twoBody_;
    std::vector<std::vector<unsigned int>> refs_; // by vocabulary() index
    std::vector<Problem> problems_;
};

} // namespace connector

} // namespace fmuImport

#endif
