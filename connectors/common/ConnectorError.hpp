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

//- Why a parameter is refused: the code a ParameterError carries beside its
//  message (the FMUs report it in their log category refusedParameter,
//  docs/connector-fmu-interface.md)
enum class Refusal {
    //- Not a finite number (NaN or infinite)
    notFinite,
    //- Below 0 where >= 0 is required
    negative,
    //- 0 or below where > 0 is required
    notPositive,
    //- Outside a range or set of values (0 or 1, an integer from 2 to 1000)
    outOfRange,
    //- A vector too short to give a direction
    noDirection,
    //- Allowed alone, refused with the value of another parameter
    inconsistent
};

//- The code's name as the FMUs report it: "notFinite", "negative", ...
const char* refusalName(Refusal code);

//- A parameter outside its allowed range: its code and name as data, the
//  message for the user
class ParameterError : public ConnectorError {
public:
    //- "<law>: parameter <name> = <value> <unit> is out of range (allowed:
    //  <allowed>)"
    ParameterError(Refusal code, const std::string& law,
                   const std::string& name, double value,
                   const std::string& unit, const std::string& allowed);
    //- A message of another form; it names the parameter as
    //  "parameter <name>" all the same
    ParameterError(Refusal code, std::string name, const std::string& message);

    Refusal code() const noexcept { return code_; }

    //- The FMU variable refused ("stiffness", "A.p[2]"), or the name of a
    //  vector refused as a whole ("A.axis", whose variables are A.axis[i])
    const std::string& parameter() const noexcept { return parameter_; }

private:
    Refusal code_;
    std::string parameter_;
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

//- Throws ParameterError (notFinite or negative) unless value is finite and
//  >= 0
void requireNonNegative(const char* law, const char* name, double value,
                        const char* unit);

//- Throws ParameterError (notFinite or notPositive) unless value is finite
//  and > 0
void requirePositive(const char* law, const char* name, double value,
                     const char* unit);

//- Throws ParameterError (notFinite) naming "<name>[i]" unless every
//  component is finite
void requireFinite(const char* law, const char* name, const Vector3& value,
                   const char* unit);

//- Throws InputError naming e.g. "A.R[2,3]" for the first non-finite input
//  of body `body` ("A" or "B")
void requireFiniteInputs(const char* law, const char* body,
                         const BodyKinematics& kinematics);

//- requireFinite of the attachment points A.p (P on A, A's frame) and B.p
//  (Q on B, B's frame) [m], A.p first
void requireFiniteAttachments(const char* law, const Vector3& p_AoP_A,
                              const Vector3& p_BoQ_B);

//- requireFiniteInputs of both bodies, A first
void requireFiniteInputs(const char* law, const BodyKinematics& A,
                         const BodyKinematics& B);

} // namespace connectors

#endif
