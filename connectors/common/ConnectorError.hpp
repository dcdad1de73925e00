// Typed exceptions thrown by connector laws. Every message names the
// variable (with the FMU variable name, e.g. "A.p[2]" or "stiffness"), its
// value and, for parameters, the allowed range.
#ifndef CONNECTORS_COMMON_CONNECTORERROR_HPP
#define CONNECTORS_COMMON_CONNECTORERROR_HPP

#include <stdexcept>
#include <string>

#include "common/Kinematics.hpp"

namespace connectors {

//- Base of every error raised by a connector law
class ConnectorError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

//- A parameter outside its allowed range
class ParameterError : public ConnectorError {
public:
    ParameterError(const std::string& law, const std::string& name,
                   double value, const std::string& unit,
                   const std::string& allowed);
    //- A message of another form; it names the parameter as
    //  "parameter <name>" all the same (the bridge finds the entry by it)
    using ConnectorError::ConnectorError;
};

//- A non-finite input
class InputError : public ConnectorError {
public:
    InputError(const std::string& law, const std::string& name, double value);
};

//- Inputs for which the law is undefined (e.g. a spring of zero length)
class UndefinedStateError : public ConnectorError {
public:
    using ConnectorError::ConnectorError;
};

//- Shortest printable form of a double that reads back exactly ("-1", "0.5")
std::string formatValue(double value);

//- A vector as "(x, y, z)", each component as formatValue
std::string formatVector(const Vector3& value);

// The checks below build no string unless they throw: they run on every
// evaluation.

//- Throws ParameterError unless value is finite and >= 0
void requireNonNegative(const char* law, const char* name, double value,
                        const char* unit);

//- Throws ParameterError unless value is finite and > 0
void requirePositive(const char* law, const char* name, double value,
                     const char* unit);

//- Throws ParameterError naming "<name>[i]" unless every component is finite
void requireFinite(const char* law, const char* name, const Vector3& value,
                   const char* unit);

//- Throws InputError naming e.g. "A.R[2,3]" for the first non-finite input
//  of body `body` ("A" or "B")
void requireFiniteInputs(const char* law, const char* body,
                         const BodyKinematics& kinematics);

} // namespace connectors

#endif
