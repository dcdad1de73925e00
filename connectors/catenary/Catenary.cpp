#include "catenary/Catenary.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>
#include <string>

#include "common/AxialGeometry.hpp"
#include "common/ConnectorError.hpp"

namespace connectors {

namespace {

const char* const lawName = "catenary";

} // namespace

Catenary::Catenary(const CatenaryParameters& parameters)
    : parameters_(parameters)
{
    requireFinite(lawName, "A.p", parameters.p_AoP_A, "m");
    requireFinite(lawName, "B.p", parameters.p_BoQ_B, "m");
    requirePositive(lawName, "unstretchedLength", parameters.line.length, "m");
    requirePositive(lawName, "EA", parameters.line.EA, "N");
    if (!std::isfinite(parameters.line.weight)) {
        throw ParameterError(Refusal::notFinite, lawName, "weight",
                             parameters.line.weight, "N/m", "finite");
    }
    requireNonNegative(lawName, "seabedFriction",
                       parameters.line.seabedFriction, "1");
    // sections 2, 3, ... and the joints below them, named as the FMU's
    // parameters
    for (std::size_t k = 0; k < parameters.line.sections.size(); ++k) {
        const CatenarySection& s = parameters.line.sections[k];
        const std::string section = "section" + std::to_string(k + 2) + ".";
        requirePositive(lawName, (section + "unstretchedLength").c_str(),
                        s.length, "m");
        requirePositive(lawName, (section + "EA").c_str(), s.EA, "N");
        if (!std::isfinite(s.weight)) {
            throw ParameterError(Refusal::notFinite, lawName,
                                 section + "weight", s.weight, "N/m", "finite");
        }
        if (!std::isfinite(s.jointWeight)) {
            throw ParameterError(Refusal::notFinite, lawName,
                                 "joint" + std::to_string(k + 1) + ".weight",
                                 s.jointWeight, "N", "finite");
        }
    }
}

ConnectorResult Catenary::evaluate(const BodyKinematics& A,
                                   const BodyKinematics& B) const
{
    return evaluate(A, B, nullptr, 0).loads;
}

CatenaryOutput Catenary::evaluate(const BodyKinematics& A,
                                  const BodyKinematics& B,
                                  const CatenaryGuess* guess, int shapePoints,
                                  const CatenaryOptions& options) const
{
    requireFiniteInputs(lawName, "A", A);
    requireFiniteInputs(lawName, "B", B);
    const CatenaryLine& line = parameters_.line;
    const AxialGeometry g
        = axialGeometry(A, B, parameters_.p_AoP_A, parameters_.p_BoQ_B);

    // Profile plane: origin Q, e_h horizontal towards P, z up
    const Vector3 p_QP_W = -g.p_PQ_W;
    const Vector3 p_WQ_W = B.p_WKo_W + g.p_BoQ_W;
    const Vector3 zHat = Vector3::UnitZ();
    const Vector3 horizontal(p_QP_W[0], p_QP_W[1], 0.0);
    const double x = horizontal.norm();
    const double z = p_QP_W[2];
    const Vector3 eH
        = x > 1e-12 * line.length ? Vector3(horizontal / x) : Vector3::UnitX();

    CatenaryOutput out;
    out.solution = solveCatenary(line, x, z, guess, options);
    const CatenarySolution& s = out.solution;
    ConnectorResult& r = out.loads;
    r.A.f_W = -s.H * eH - s.V * zHat;
    r.B.f_W = s.HA * eH + s.VA * zHat;
    r.A.m_Ko_W = g.p_AoP_W.cross(r.A.f_W);
    r.B.m_Ko_W = g.p_BoQ_W.cross(r.B.f_W);
    r.length = g.length;
    r.lengthRate = g.lengthRate;
    out.fairleadTension = std::hypot(s.H, s.V);
    out.anchorTension = std::hypot(s.HA, s.VA);
    r.tension = out.fairleadTension;
    r.potentialEnergy
        = catenaryEnergy(line, s, x, z) + totalWeight(line) * p_WQ_W[2];
    r.dissipatedPower = 0.0;

    if (shapePoints == 1 || shapePoints < 0) {
        throw std::invalid_argument("catenary: shapePoints must be 0 or >= 2");
    }
    out.shape.resize(std::size_t(shapePoints));
    out.shapeTension.resize(std::size_t(shapePoints));
    const double L = totalLength(line);
    for (int i = 0; i < shapePoints; ++i) {
        const double sArc = L * (1.0 - double(i) / (shapePoints - 1));
        const Eigen::Vector2d p = catenaryPoint(line, s, x, z, sArc);
        out.shape[std::size_t(i)] = p_WQ_W + p[0] * eH + p[1] * zHat;
        out.shapeTension[std::size_t(i)] = catenaryTension(line, s, sArc);
    }
    if (line.sections.empty()) {
        out.sectionLowerTension = {out.anchorTension};
        out.sectionUpperTension = {out.fairleadTension};
    } else {
        const CatenarySectionTensions t = catenarySectionTensions(line, s, x);
        out.sectionLowerTension = t.lower;
        out.sectionUpperTension = t.upper;
        double arc = 0.0;
        for (std::size_t k = 0; k < line.sections.size(); ++k) {
            arc += k == 0 ? line.length : line.sections[k - 1].length;
            const Eigen::Vector2d p = catenaryPoint(line, s, x, z, arc);
            out.joints.push_back(p_WQ_W + p[0] * eH + p[1] * zHat);
        }
    }
    return out;
}

} // namespace connectors
