// MooringLine's parameters (MooringLine.hpp): their checks (a section's
// and a joint's properties from tables of bounds), the sections, the saved
// state's layout, and the construction of the line.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>

#include "common/ConnectorError.hpp"
#include "mooringLine/LineStatics.hpp"
#include "mooringLine/MooringLine.hpp"

namespace connectors {

namespace {

const char* const lawName = "mooringLine";
constexpr double pi = 3.14159265358979323846;

//- A property's lower bound: > 0 (positive) or >= 0
template <class Properties> struct Bound {
    const char* name;
    double Properties::*value;
    const char* unit;
    bool positive;
};

//- ParameterError naming <prefix><name> for the first property of
//  table[first, last) out of its bound
template <class Properties, std::size_t n>
void requireBounds(const std::string& prefix, const Properties& properties,
                   const Bound<Properties> (&table)[n], std::size_t first = 0,
                   std::size_t last = n)
{
    for (std::size_t k = first; k < last; ++k) {
        const Bound<Properties>& b = table[k];
        const std::string name = prefix + b.name;
        if (b.positive) {
            requirePositive(lawName, name.c_str(), properties.*b.value, b.unit);
        } else {
            requireNonNegative(lawName, name.c_str(), properties.*b.value,
                               b.unit);
        }
    }
}

//- A section's properties: its line (length, stiffness, damping, mass,
//  diameter), then from morisonFirst its Morison coefficients
const Bound<LineSection> sectionBounds[] = {
    {"unstretchedLength", &LineSection::length, "m", true},
    {"EA", &LineSection::EA, "N", true},
    {"axialDamping", &LineSection::axialDamping, "N.s", false},
    {"massPerLength", &LineSection::massPerLength, "kg/m", true},
    {"diameter", &LineSection::diameter, "m", false},
    {"normalDrag", &LineSection::normalDrag, "1", false},
    {"tangentialDrag", &LineSection::tangentialDrag, "1", false},
    {"normalAddedMass", &LineSection::normalAddedMass, "1", false},
    {"tangentialAddedMass", &LineSection::tangentialAddedMass, "1", false},
};
constexpr std::size_t morisonFirst = 5;
//- The point at a joint
const Bound<LinePoint> jointBounds[] = {
    {"mass", &LinePoint::mass, "kg", false},
    {"volume", &LinePoint::volume, "m3", false},
    {"dragArea", &LinePoint::dragArea, "m2", false},
    {"addedMass", &LinePoint::addedMass, "1", false},
};

//- Sections 2, 3, ... and their joints' points (ParameterError naming the
//  FMU variable, section<k>.<name> or joint<k>.<name>)
void checkSections(const MooringLineParameters& p)
{
    int total = p.segments;
    for (std::size_t k = 0; k < p.sections.size(); ++k) {
        const LineSection& s = p.sections[k];
        const std::string section = "section" + std::to_string(k + 2) + ".";
        const auto name = [&](const char* n) { return section + n; };
        requireBounds(section, s, sectionBounds, 0, morisonFirst);
        if (p.seabedContact && !(s.diameter > 0.0)) {
            throw ParameterError(
                Refusal::inconsistent, lawName, name("diameter"), s.diameter,
                "m",
                "> 0 with seabedContact = 1: the seabed carries the line "
                "over its contact area, diameter times length");
        }
        requireBounds(section, s, sectionBounds, morisonFirst);
        total += s.segments;
        if (s.segments < 1 || total > 1000) {
            throw ParameterError(
                Refusal::outOfRange, name("segments"),
                "mooringLine: parameter " + name("segments") + " = "
                    + std::to_string(s.segments)
                    + " is out of range (allowed: an integer from 1 to "
                    + std::to_string(std::max(1000 - (total - s.segments), 0))
                    + ": the sections' segments add up to at most 1000)");
        }
        requireBounds("joint" + std::to_string(k + 1) + ".", s.joint,
                      jointBounds);
    }
}
} // namespace

double MooringLineParameters::weight() const
{
    return (massPerLength - waterDensity * 0.25 * pi * diameter * diameter)
        * gravity;
}

LineSection MooringLineParameters::section(std::size_t k) const
{
    if (k > 0) {
        return sections[k - 1];
    }
    LineSection s;
    s.length = length;
    s.EA = EA;
    s.axialDamping = axialDamping;
    s.massPerLength = massPerLength;
    s.diameter = diameter;
    s.normalDrag = normalDrag;
    s.tangentialDrag = tangentialDrag;
    s.normalAddedMass = normalAddedMass;
    s.tangentialAddedMass = tangentialAddedMass;
    s.segments = segments;
    return s;
}

int MooringLineParameters::totalSegments() const
{
    int N = segments;
    for (const LineSection& s : sections) {
        N += s.segments;
    }
    return N;
}

std::size_t MooringLineState::serializedSize(int segments)
{
    return 19 + 6 * std::size_t(segments - 1)
        + TrapezoidMatrix::savedSize(segments);
}

std::vector<double> MooringLineState::serialize() const
{
    std::vector<double> out;
    serialize(out);
    return out;
}

void MooringLineState::serialize(std::vector<double>& out) const
{
    const double ends[]
        = {time,  Q[0],  Q[1],  Q[2],  P[0],  P[1],  P[2],  vQ[0], vQ[1], vQ[2],
           vP[0], vP[1], vP[2], aQ[0], aQ[1], aQ[2], aP[0], aP[1], aP[2]};
    out.insert(out.end(), std::begin(ends), std::end(ends));
    out.insert(out.end(), nodes.begin(), nodes.end());
    TrapezoidMatrix::save(newton.get(), int(nodes.size() / 6) + 1, out);
}

MooringLineState MooringLineState::deserialize(const std::vector<double>& data,
                                               int segments)
{
    const std::size_t expected = serializedSize(segments);
    if (data.size() != expected) {
        throw std::invalid_argument(
            "mooringLine: a saved state of " + std::to_string(data.size())
            + " values does not fit a line of " + std::to_string(segments)
            + " segments (" + std::to_string(expected) + " values)");
    }
    MooringLineState s;
    s.time = data[0];
    s.Q = Vector3(data[1], data[2], data[3]);
    s.P = Vector3(data[4], data[5], data[6]);
    s.vQ = Vector3(data[7], data[8], data[9]);
    s.vP = Vector3(data[10], data[11], data[12]);
    s.aQ = Vector3(data[13], data[14], data[15]);
    s.aP = Vector3(data[16], data[17], data[18]);
    const std::size_t nodes = 19 + 6 * std::size_t(segments - 1);
    s.nodes.assign(data.begin() + 19, data.begin() + std::ptrdiff_t(nodes));
    s.newton = TrapezoidMatrix::load(data.data() + nodes, segments);
    return s;
}

MooringLine::MooringLine(const MooringLineParameters& p) : parameters_(p)
{
    requireFiniteAttachments(lawName, p.p_AoP_A, p.p_BoQ_B);
    const LineSection first = p.section(0);
    requireBounds("", first, sectionBounds, 0, morisonFirst);
    requireNonNegative(lawName, "waterDensity", p.waterDensity, "kg/m3");
    requireNonNegative(lawName, "gravity", p.gravity, "m/s2");
    requireBounds("", first, sectionBounds, morisonFirst);
    requireNonNegative(lawName, "seabedStiffness", p.seabedStiffness, "Pa/m");
    requireNonNegative(lawName, "seabedDamping", p.seabedDamping, "Pa.s/m");
    if (p.seabedContact) {
        // The seabed's penalty acts on the contact area (diameter times
        // length): without either the line would sink through the seabed
        if (!(p.diameter > 0.0)) {
            throw ParameterError(
                Refusal::inconsistent, lawName, "diameter", p.diameter, "m",
                "> 0 with seabedContact = 1: the seabed carries the line "
                "over its contact area, diameter times length");
        }
        if (!(p.seabedStiffness > 0.0)) {
            throw ParameterError(
                Refusal::inconsistent, lawName, "seabedStiffness",
                p.seabedStiffness, "Pa/m",
                "> 0 with seabedContact = 1: the seabed carries the line "
                "by its penalty stiffness");
        }
    }
    if (p.segments < 2 || p.segments > 1000) {
        throw ParameterError(
            Refusal::outOfRange, "segments",
            "mooringLine: parameter segments = " + std::to_string(p.segments)
                + " is out of range (allowed: an integer from 2 to 1000)");
    }
    requirePositive(lawName, "relativeTolerance", p.relativeTolerance, "1");
    requirePositive(lawName, "absoluteTolerance", p.absoluteTolerance, "1");
    requireNonNegative(lawName, "maxStep", p.maxStep, "s");
    if (!std::isfinite(p.waterLevel)) {
        throw ParameterError(Refusal::notFinite, lawName, "waterLevel",
                             p.waterLevel, "m", "finite");
    }
    requireFinite(lawName, "current.surface", p.currentSurface, "m/s");
    requireFinite(lawName, "current.seabed", p.currentSeabed, "m/s");
    requireNonNegative(lawName, "seabedFriction", p.seabedFriction, "1");
    requirePositive(lawName, "frictionVelocity", p.frictionVelocity, "m/s");
    requireNonNegative(lawName, "axialFrictionRatio", p.axialFrictionRatio,
                       "1");
    if (!(p.staticFrictionScale >= 1.0
          && std::isfinite(p.staticFrictionScale))) {
        throw ParameterError(Refusal::outOfRange, lawName,
                             "staticFrictionScale", p.staticFrictionScale, "1",
                             "finite and >= 1");
    }
    checkSections(p);
    weight_ = p.weight();
    layout_ = lineLayout(p, weight_);
    if (p.integrator == MooringLineParameters::Integrator::cvode) {
        CvodeBdf::Options options;
        options.relativeTolerance = p.relativeTolerance;
        options.absoluteTolerance = p.absoluteTolerance;
        options.halfBandwidth = 11; // a node's 6 states see its neighbours' 6
        integrator_ = std::make_unique<CvodeBdf>(
            6 * std::size_t(layout_.N - 1),
            [this](double t, const double* y, double* ydot) {
                return rhs(t, y, ydot);
            },
            options);
    }
}

MooringLine::~MooringLine() = default;

} // namespace connectors
