// fmuImport: an FMU's modelDescription.xml as the importer reads it (FMI 2.0
// and 3.0): its variables and capabilities.
// Part of the importer's public interface (fmuImport.hpp includes every
// part), C++11 like the rest of it.
#ifndef FMUIMPORT_MODEL_DESCRIPTION_HPP
#define FMUIMPORT_MODEL_DESCRIPTION_HPP

#include <cstddef>
#include <string>
#include <vector>

namespace fmuImport {

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

} // namespace fmuImport

#endif
