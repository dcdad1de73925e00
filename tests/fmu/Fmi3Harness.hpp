// Test harness for the FMI 3.0 connector FMUs through their C entry points:
// <FOAMFMI_FMU_DIR>/fmi3/<name>.fmu unpacked, its modelDescription.xml read
// and its binary loaded by the importer (fmuImport: Fmu::Impl, Library),
// as FmuHarness.hpp does for FMI 2.0; terminalsAndIcons.xml read from the
// archive with the importer's FmuArchive.
#ifndef TESTS_FMU_FMI3HARNESS_HPP
#define TESTS_FMU_FMI3HARNESS_HPP

#include <pugixml.hpp>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "UnpackedFmu.hpp"
#include "fmi3FunctionTypes.h"

namespace fmuTest {

// The fmi3 functions the tests call that fmuImport::Fmi3Api (co-simulation
// without events) does not have, without the fmi3 prefix
// clang-format off
#define FMU_TEST_FMI3_OTHER_FUNCTIONS(X) \
    X(InstantiateModelExchange) \
    X(EnterEventMode) \
    X(GetDirectionalDerivative)
// clang-format on

struct Fmi3Api : fmuImport::Fmi3Api {
#define FMU_TEST_DECLARE(name) fmi3##name##TYPE* name = nullptr;
    FMU_TEST_FMI3_OTHER_FUNCTIONS(FMU_TEST_DECLARE)
#undef FMU_TEST_DECLARE
};

//- Path of <FOAMFMI_FMU_DIR>/fmi3/<name>.fmu
std::string fmu3Path(const std::string& name);

//- A variable of an FMI 3.0 modelDescription.xml: the importer's
//  elements of one array (or its one scalar) together
struct Variable3 {
    std::string name;
    fmi3ValueReference valueReference = 0;
    std::string type; // Float64 or Boolean
    fmuImport::Causality causality = fmuImport::Causality::local;
    std::vector<std::size_t> dimensions;
    //- Number of elements: the product of the dimensions
    std::size_t size = 1;
    //- Start values (empty for a calculated one)
    std::vector<double> start;
};

//- <FOAMFMI_FMU_DIR>/fmi3/<name>.fmu unpacked (UnpackedFmu) and its binary
//  loaded; `missing`: the functions of FMU_TEST_FMI3_OTHER_FUNCTIONS it does
//  not export
class LoadedFmu3 : public UnpackedFmu {
public:
    explicit LoadedFmu3(const std::string& name);

    Fmi3Api api;
    std::string token;
    //- terminalsAndIcons.xml as written in the FMU
    pugi::xml_document terminals;
    //- In the order of modelDescription.xml
    std::vector<Variable3> variables;

    const Variable3& variable(const std::string& name) const;
};

struct LogRecord3 {
    fmi3Status status;
    std::string category;
    std::string message;
};

//- An instance with its own log; freed on destruction
class Instance3 {
public:
    explicit Instance3(const LoadedFmu3& fmu, const char* token = nullptr);
    ~Instance3();
    Instance3(const Instance3&) = delete;
    Instance3& operator=(const Instance3&) = delete;

    fmi3Instance c = nullptr;
    std::vector<LogRecord3> log;

    //- Instantiated -> step mode, with parameters set in between
    fmi3Status
    initialize(const std::map<std::string, std::vector<double>>& parameters);
    fmi3Status set(const std::map<std::string, std::vector<double>>& values);
    //- The elements of an array variable, row-major
    std::vector<double> get(const std::string& name);
    fmi3Status doStep(double t, double h);
    std::string lastMessage() const;

private:
    const LoadedFmu3& fmu_;
};

//- The FMI 2.0 scalar names of the elements of an FMI 3.0 variable, in
//  its (row-major) order, by the mapping of docs/connector-fmu-interface.md:
//  X -> X; X of n -> X[1..n]; X of r x c -> X[i,j]
std::vector<std::string> fmi2ElementNames(const Variable3& v);

//- FMI 2.0 scalar values (name -> value) as FMI 3.0 array values: every
//  3.0 variable with an element in `scalars`, the other elements at their
//  start values
std::map<std::string, std::vector<double>>
arrayValues(const std::map<std::string, double>& scalars,
            const LoadedFmu3& fmu3);

} // namespace fmuTest

#endif
