#include "common/ConnectorError.hpp"

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <string>
#include <utility>

namespace connectors {

std::string formatValue(double value)
{
    char buffer[32];
    for (int precision = 6; precision <= 17; ++precision) {
        std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
        if (std::isnan(value) || std::strtod(buffer, nullptr) == value) {
            break;
        }
    }
    return buffer;
}

std::string formatVector(const Vector3& value)
{
    return "(" + formatValue(value[0]) + ", " + formatValue(value[1]) + ", "
        + formatValue(value[2]) + ")";
}

const char* refusalName(Refusal code)
{
    static const char* const names[]
        = {"notFinite",  "negative",    "notPositive",
           "outOfRange", "noDirection", "inconsistent"};
    const auto i = static_cast<std::size_t>(code);
    return i < std::size(names) ? names[i] : "outOfRange";
}

ParameterError::ParameterError(Refusal code, const std::string& law,
                               const std::string& name, double value,
                               const std::string& unit,
                               const std::string& allowed)
    : ParameterError(code, name,
                     law + ": parameter " + name + " = " + formatValue(value)
                         + (unit.empty() || unit == "1" ? "" : " " + unit)
                         + " is out of range (allowed: " + allowed + ")")
{
}

ParameterError::ParameterError(Refusal code, std::string name,
                               const std::string& message)
    : ConnectorError(message), code_(code), parameter_(std::move(name))
{
}

InputError::InputError(const std::string& law, const std::string& name,
                       double value)
    : ConnectorError(law + ": input " + name + " = " + formatValue(value)
                     + " is not finite")
{
}

void requireNonNegative(const char* law, const char* name, double value,
                        const char* unit)
{
    if (!(std::isfinite(value) && value >= 0.0)) {
        throw ParameterError(std::isfinite(value) ? Refusal::negative
                                                  : Refusal::notFinite,
                             law, name, value, unit, "finite and >= 0");
    }
}

void requirePositive(const char* law, const char* name, double value,
                     const char* unit)
{
    if (!(std::isfinite(value) && value > 0.0)) {
        throw ParameterError(std::isfinite(value) ? Refusal::notPositive
                                                  : Refusal::notFinite,
                             law, name, value, unit, "finite and > 0");
    }
}

void requireFinite(const char* law, const char* name, const Vector3& value,
                   const char* unit)
{
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(value[i])) {
            throw ParameterError(Refusal::notFinite, law,
                                 std::string(name) + "[" + std::to_string(i + 1)
                                     + "]",
                                 value[i], unit, "finite");
        }
    }
}

namespace {

void checkVector(const char* law, const char* body, const char* name,
                 const Vector3& value)
{
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(value[i])) {
            throw InputError(law,
                             std::string(body) + "." + name + "["
                                 + std::to_string(i + 1) + "]",
                             value[i]);
        }
    }
}

//- Whether every input of the body is finite: one pass without a branch
//  per value, the search for the one to name left to the failure
bool finiteInputs(const BodyKinematics& kinematics)
{
    bool finite = true;
    for (int i = 0; i < 3; ++i) {
        finite &= std::isfinite(kinematics.p_WKo_W[i])
            & std::isfinite(kinematics.v_WKo_W[i])
            & std::isfinite(kinematics.w_WK_W[i]);
        for (int j = 0; j < 3; ++j) {
            finite &= std::isfinite(kinematics.R_WK(i, j));
        }
    }
    return finite;
}

} // namespace

void requireFiniteInputs(const char* law, const char* body,
                         const BodyKinematics& kinematics)
{
    if (finiteInputs(kinematics)) {
        return;
    }
    checkVector(law, body, "r", kinematics.p_WKo_W);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            if (!std::isfinite(kinematics.R_WK(i, j))) {
                throw InputError(law,
                                 std::string(body) + ".R["
                                     + std::to_string(i + 1) + ","
                                     + std::to_string(j + 1) + "]",
                                 kinematics.R_WK(i, j));
            }
        }
    }
    checkVector(law, body, "v", kinematics.v_WKo_W);
    checkVector(law, body, "omega", kinematics.w_WK_W);
}

void requireFiniteAttachments(const char* law, const Vector3& p_AoP_A,
                              const Vector3& p_BoQ_B)
{
    requireFinite(law, "A.p", p_AoP_A, "m");
    requireFinite(law, "B.p", p_BoQ_B, "m");
}

void requireFiniteInputs(const char* law, const BodyKinematics& A,
                         const BodyKinematics& B)
{
    requireFiniteInputs(law, "A", A);
    requireFiniteInputs(law, "B", B);
}

} // namespace connectors
