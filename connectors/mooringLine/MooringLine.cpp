#include "mooringLine/MooringLine.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "catenary/Catenary.hpp"
#include "common/AxialGeometry.hpp"
#include "common/ConnectorError.hpp"
#include "mooringLine/LineForces.hpp"
#include "mooringLine/LineStatics.hpp"

namespace connectors {

namespace {

const char* const lawName = "mooringLine";
constexpr double pi = 3.14159265358979323846;

//- Sections 2, 3, ... and their joints' points (ParameterError naming the
//  FMU variable, section<k>.<name> or joint<k>.<name>)
void checkSections(const MooringLineParameters& p)
{
    int total = p.segments;
    for (std::size_t k = 0; k < p.sections.size(); ++k) {
        const LineSection& s = p.sections[k];
        const std::string section = "section" + std::to_string(k + 2) + ".";
        const auto name = [&](const char* n) { return section + n; };
        requirePositive(lawName, name("unstretchedLength").c_str(), s.length,
                        "m");
        requirePositive(lawName, name("EA").c_str(), s.EA, "N");
        requireNonNegative(lawName, name("axialDamping").c_str(),
                           s.axialDamping, "N.s");
        requirePositive(lawName, name("massPerLength").c_str(), s.massPerLength,
                        "kg/m");
        requireNonNegative(lawName, name("diameter").c_str(), s.diameter, "m");
        if (p.seabedContact && !(s.diameter > 0.0)) {
            throw ParameterError(
                Refusal::inconsistent, lawName, name("diameter"), s.diameter,
                "m",
                "> 0 with seabedContact = 1: the seabed carries the line "
                "over its contact area, diameter times length");
        }
        requireNonNegative(lawName, name("normalDrag").c_str(), s.normalDrag,
                           "1");
        requireNonNegative(lawName, name("tangentialDrag").c_str(),
                           s.tangentialDrag, "1");
        requireNonNegative(lawName, name("normalAddedMass").c_str(),
                           s.normalAddedMass, "1");
        requireNonNegative(lawName, name("tangentialAddedMass").c_str(),
                           s.tangentialAddedMass, "1");
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
        const std::string joint = "joint" + std::to_string(k + 1) + ".";
        requireNonNegative(lawName, (joint + "mass").c_str(), s.joint.mass,
                           "kg");
        requireNonNegative(lawName, (joint + "volume").c_str(), s.joint.volume,
                           "m3");
        requireNonNegative(lawName, (joint + "dragArea").c_str(),
                           s.joint.dragArea, "m2");
        requireNonNegative(lawName, (joint + "addedMass").c_str(),
                           s.joint.addedMass, "1");
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
    std::vector<double> out
        = {time,  Q[0],  Q[1],  Q[2],  P[0],  P[1],  P[2],  vQ[0], vQ[1], vQ[2],
           vP[0], vP[1], vP[2], aQ[0], aQ[1], aQ[2], aP[0], aP[1], aP[2]};
    out.insert(out.end(), nodes.begin(), nodes.end());
    TrapezoidMatrix::save(newton.get(), int(nodes.size() / 6) + 1, out);
    return out;
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
    requireFinite(lawName, "A.p", p.p_AoP_A, "m");
    requireFinite(lawName, "B.p", p.p_BoQ_B, "m");
    requirePositive(lawName, "unstretchedLength", p.length, "m");
    requirePositive(lawName, "EA", p.EA, "N");
    requireNonNegative(lawName, "axialDamping", p.axialDamping, "N.s");
    requirePositive(lawName, "massPerLength", p.massPerLength, "kg/m");
    requireNonNegative(lawName, "diameter", p.diameter, "m");
    requireNonNegative(lawName, "waterDensity", p.waterDensity, "kg/m3");
    requireNonNegative(lawName, "gravity", p.gravity, "m/s2");
    requireNonNegative(lawName, "normalDrag", p.normalDrag, "1");
    requireNonNegative(lawName, "tangentialDrag", p.tangentialDrag, "1");
    requireNonNegative(lawName, "normalAddedMass", p.normalAddedMass, "1");
    requireNonNegative(lawName, "tangentialAddedMass", p.tangentialAddedMass,
                       "1");
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

Vector3 MooringLine::attachment(const BodyKinematics& body,
                                const Vector3& p) const
{
    return body.p_WKo_W + body.R_WK * p;
}

Vector3 MooringLine::attachmentVelocity(const BodyKinematics& body,
                                        const Vector3& p) const
{
    return body.v_WKo_W + body.w_WK_W.cross(body.R_WK * p);
}

MooringLineState MooringLine::initialState(const BodyKinematics& A,
                                           const BodyKinematics& B,
                                           double time) const
{
    requireFiniteInputs(lawName, "A", A);
    requireFiniteInputs(lawName, "B", B);
    const MooringLineParameters& p = parameters_;
    const Vector3 P = attachment(A, p.p_AoP_A), Q = attachment(B, p.p_BoQ_B);
    if (p.seabedContact && P[2] < Q[2]) {
        throw UndefinedStateError(
            "mooringLine: the fairlead (A.p on body A) at z = "
            + formatValue(P[2])
            + " m is below the seabed (z = " + formatValue(Q[2])
            + " m, the height of the anchor B.p); with "
              "seabedContact = 1 it must not be");
    }
    // A line far shorter than the distance between its ends would start
    // stretched beyond what any mooring material bears, its elastic law
    // far out of its range. Not named as "parameter ...": it depends on
    // the inputs (docs/connector-fmu-interface.md)
    const double chord = (P - Q).norm();
    if (chord > (1.0 + maxStartStrain) * layout_.length) {
        throw UndefinedStateError(
            std::string("mooringLine: ")
            + (p.sections.empty() ? "unstretchedLength"
                                  : "the sum of the sections' "
                                    "unstretchedLength")
            + " = " + formatValue(layout_.length)
            + " m is out of range for the ends at the start (allowed: at least "
            + formatValue(chord / (1.0 + maxStartStrain))
            + " m, the distance from the fairlead A.p to B.p, "
            + formatValue(chord) + " m, over 1 + " + formatValue(maxStartStrain)
            + ": a start strain of at most "
            + formatValue(100.0 * maxStartStrain) + " %)");
    }
    // The quasi-static catenary through the ends: of the line itself, or
    // for sections one of the whole line's length, the mean of their
    // weights (points included) and compliances, its shape taken at the
    // nodes' unstretched arcs
    const LineLayout& L = layout_;
    const int N = L.N;
    const bool uniform = L.sections.size() == 1;
    CatenaryParameters c;
    c.p_AoP_A = p.p_AoP_A;
    c.p_BoQ_B = p.p_BoQ_B;
    c.line.length = L.length;
    c.line.EA = p.EA;
    c.line.weight = weight_;
    c.line.seabedContact = p.seabedContact;
    if (!uniform) {
        double weight = 0.0, compliance = 0.0;
        for (const LineLayout::Section& k : L.sections) {
            weight += k.w * k.l * k.segments;
            compliance += k.l * k.segments / k.EA;
        }
        for (const LineSection& k : p.sections) {
            weight
                += (k.joint.mass - p.waterDensity * k.joint.volume) * p.gravity;
        }
        c.line.weight = weight / L.length;
        c.line.EA = L.length / compliance;
    }
    const int points = uniform ? N + 1 : 8 * N + 1;
    CatenaryOutput shape;
    try {
        shape = Catenary(c).evaluate(A, B, nullptr, points);
    } catch (const UndefinedStateError& e) {
        throw UndefinedStateError(
            std::string("mooringLine: no quasi-static start "
                        "shape: ")
            + e.what());
    }
    MooringLineState s;
    s.time = time;
    s.P = attachment(A, p.p_AoP_A);
    s.Q = attachment(B, p.p_BoQ_B);
    s.vP = attachmentVelocity(A, p.p_AoP_A);
    s.vQ = attachmentVelocity(B, p.p_BoQ_B);
    // shape runs from P (index 0) to Q (index points - 1)
    std::vector<Vector3> r(std::size_t(N + 1));
    for (int i = 0; i <= N; ++i) {
        if (uniform) {
            r[std::size_t(i)] = shape.shape[std::size_t(N - i)];
            continue;
        }
        const double u
            = (points - 1) * (1.0 - L.arc[std::size_t(i)] / L.length);
        const int k = std::min(int(u), points - 2);
        r[std::size_t(i)] = shape.shape[std::size_t(k)]
            + (u - k)
                * (shape.shape[std::size_t(k + 1)]
                   - shape.shape[std::size_t(k)]);
    }
    r[0] = s.Q;
    r[std::size_t(N)] = s.P;
    // The discrete line's own equilibrium (straight segments, seabed
    // penalty), so that a line held still stays still; the catenary shape
    // is kept where Newton cannot reach one (a slack weightless line, a
    // line folded on the seabed, whose grounded nodes have no unique place)
    std::vector<Vector3> equilibrium(r);
    if (solveStatics(p, layout_, equilibrium, s.Q[2])) {
        r.swap(equilibrium);
    }
    checkJointsSubmerged(r);
    s.nodes.assign(6 * std::size_t(N - 1), 0.0);
    for (int i = 1; i < N; ++i) {
        for (int k = 0; k < 3; ++k) {
            s.nodes[6 * std::size_t(i - 1) + std::size_t(k)]
                = r[std::size_t(i)][k];
        }
    }
    return s;
}

void MooringLine::endsAt(double s, Vector3& rQ, Vector3& vQ, Vector3& rP,
                         Vector3& vP) const
{
    // cubic Hermite basis at s in [0, 1] and its derivative by t
    const double h = ends_.h;
    if (!parameters_.hermiteEnds) {
        rQ = ends_.Q0 + s * (ends_.Q1 - ends_.Q0);
        rP = ends_.P0 + s * (ends_.P1 - ends_.P0);
        vQ = (ends_.Q1 - ends_.Q0) / h;
        vP = (ends_.P1 - ends_.P0) / h;
        return;
    }
    const double s2 = s * s, s3 = s2 * s;
    const double h00 = 2.0 * s3 - 3.0 * s2 + 1.0, h10 = s3 - 2.0 * s2 + s;
    const double h01 = 3.0 * s2 - 2.0 * s3, h11 = s3 - s2;
    const double d00 = 6.0 * (s2 - s) / h, d10 = 3.0 * s2 - 4.0 * s + 1.0;
    const double d11 = 3.0 * s2 - 2.0 * s; // d01 = -d00
    rQ = h00 * ends_.Q0 + h10 * h * ends_.vQ0 + h01 * ends_.Q1
        + h11 * h * ends_.vQ1;
    rP = h00 * ends_.P0 + h10 * h * ends_.vP0 + h01 * ends_.P1
        + h11 * h * ends_.vP1;
    vQ = d00 * (ends_.Q0 - ends_.Q1) + d10 * ends_.vQ0 + d11 * ends_.vQ1;
    vP = d00 * (ends_.P0 - ends_.P1) + d10 * ends_.vP0 + d11 * ends_.vP1;
    if (s == 1.0) { // exactly the given end velocities (as evaluate sees them)
        vQ = ends_.vQ1;
        vP = ends_.vP1;
    }
}

int MooringLine::rhs(double t, const double* y, double* ydot) const
{
    const int N = layout_.N;
    std::vector<Vector3> r(std::size_t(N + 1)), v(std::size_t(N + 1));
    endsAt(std::clamp((t - ends_.t0) / ends_.h, 0.0, 1.0), r[0], v[0], r[N],
           v[N]);
    for (int i = 1; i < N; ++i) {
        const double* yi = y + 6 * (i - 1);
        r[i] = Vector3(yi[0], yi[1], yi[2]);
        v[i] = Vector3(yi[3], yi[4], yi[5]);
    }
    NodeForces forces;
    nodeForces(parameters_, layout_, r, v, r[0][2], forces, &water_);
    for (int i = 1; i < N; ++i) {
        double* d = ydot + 6 * (i - 1);
        for (int k = 0; k < 3; ++k) {
            d[k] = v[i][k];
            d[3 + k] = forces.a[i][k];
        }
        if (!forces.a[i].allFinite()) {
            return 1; // recoverable: CVODE retries with a smaller step
        }
    }
    return 0;
}

void MooringLine::checkJointsSubmerged(const std::vector<Vector3>& r) const
{
    // With freeSurface = 0 a buoy keeps its buoyancy above the water: a
    // joint it holds up there is a line floating in the air
    const MooringLineParameters& p = parameters_;
    if (p.freeSurface) {
        return;
    }
    const std::vector<int> joints = layout_.jointNodes();
    for (std::size_t k = 0; k < joints.size(); ++k) {
        const LinePoint& point = p.sections[k].joint;
        const double lift
            = (p.waterDensity * point.volume - point.mass) * p.gravity;
        const double z = r[std::size_t(joints[k])][2];
        if (lift > 0.0 && z > p.waterLevel) {
            const std::string joint = "joint" + std::to_string(k + 1);
            throw UndefinedStateError(
                "mooringLine: the buoy at " + joint + " (" + joint
                + ".volume = " + formatValue(point.volume) + " m3, " + joint
                + ".mass = " + formatValue(point.mass) + " kg: a net lift of "
                + formatValue(lift)
                + " N) holds the line above the water "
                  "surface in the start equilibrium, the joint at z = "
                + formatValue(z)
                + " m above waterLevel = " + formatValue(p.waterLevel)
                + " m (allowed: a joint at or below waterLevel; with "
                  "freeSurface = 0 a buoy keeps its buoyancy in the air: "
                  "lower "
                + joint + ".volume or raise " + joint
                + ".mass, or set freeSurface = 1 for a buoy floating at the "
                  "surface)");
        }
    }
}

void MooringLine::alongLine(const std::vector<Vector3>& points,
                            std::vector<Vector3>& atNodes) const
{
    // node i is (N - i)/N of the line from P (its unstretched arc from P
    // over L with sections): between points k and k + 1
    const LineLayout& L = layout_;
    const int N = L.N;
    const int last = int(points.size()) - 1;
    atNodes.resize(std::size_t(N + 1));
    for (int i = 0; i <= N; ++i) {
        const double u = L.sections.size() == 1
            ? double(N - i) * last / N
            : (L.length - L.arc[std::size_t(i)]) / L.length * last;
        const int k = std::min(int(u), last - 1);
        const double f01 = u - k;
        atNodes[std::size_t(i)] = (1.0 - f01) * points[std::size_t(k)]
            + f01 * points[std::size_t(k + 1)];
    }
}

void MooringLine::waterMotion(const std::vector<Vector3>& flow,
                              const std::vector<Vector3>& flowAcceleration,
                              WaterMotion& water) const
{
    const MooringLineParameters& p = parameters_;
    water.current
        = !p.currentSurface.isZero(0.0) || !p.currentSeabed.isZero(0.0);
    const auto check = [](const std::vector<Vector3>& points,
                          const char* what) {
        if (points.size() == 1) {
            throw std::invalid_argument(std::string("mooringLine: the ") + what
                                        + " needs 0 or at least 2 points");
        }
        for (std::size_t k = 0; k < points.size(); ++k) {
            if (!points[k].allFinite()) {
                throw UndefinedStateError(
                    std::string("mooringLine: the ") + what + " at shape point "
                    + std::to_string(k + 1) + " is not finite");
            }
        }
    };
    check(flow, "flow velocity");
    check(flowAcceleration, "flow acceleration");
    if (!flow.empty() && !flowAcceleration.empty()
        && flow.size() != flowAcceleration.size()) {
        throw std::invalid_argument(
            "mooringLine: the flow's velocity and acceleration need the same "
            "points");
    }
    if (flow.empty()) {
        water.flow.clear();
    } else {
        alongLine(flow, water.flow);
    }
    if (flowAcceleration.empty()) {
        water.flowAcceleration.clear();
    } else {
        alongLine(flowAcceleration, water.flowAcceleration);
    }
}

void MooringLine::advance(MooringLineState& state, const BodyKinematics& A,
                          const BodyKinematics& B, double h,
                          const std::vector<Vector3>& flow,
                          const std::vector<Vector3>& flowAcceleration)
{
    requireFiniteInputs(lawName, "A", A);
    requireFiniteInputs(lawName, "B", B);
    if (!(std::isfinite(h) && h > 0.0)) {
        throw UndefinedStateError("mooringLine: step size " + formatValue(h)
                                  + " s must be finite and > 0");
    }
    const std::size_t size = 6 * std::size_t(layout_.N - 1);
    if (state.nodes.size() != size) {
        throw std::invalid_argument(
            "mooringLine: state of " + std::to_string(state.nodes.size())
            + " node values, expected " + std::to_string(size));
    }
    ends_.Q0 = state.Q;
    ends_.P0 = state.P;
    ends_.Q1 = attachment(B, parameters_.p_BoQ_B);
    ends_.P1 = attachment(A, parameters_.p_AoP_A);
    ends_.vQ0 = state.vQ;
    ends_.vP0 = state.vP;
    ends_.vQ1 = attachmentVelocity(B, parameters_.p_BoQ_B);
    ends_.vP1 = attachmentVelocity(A, parameters_.p_AoP_A);
    ends_.t0 = state.time;
    ends_.h = h;
    waterMotion(flow, flowAcceleration, water_);
    if (lastEvaluated_.water.flowAcceleration != water_.flowAcceleration) {
        // the last evaluation's accelerations are not this water's
        lastEvaluated_.r.clear();
    }
    std::vector<double>& y = work_.nodes; // its storage kept
    y = state.nodes;
    std::shared_ptr<const TrapezoidMatrix> newton = state.newton;
    stepWork_ = 0.0;
    try {
        if (integrator_) {
            integrator_->restart(state.time, state.nodes.data());
            integrator_->advance(state.time + h, y.data());
        } else {
            // Equal substeps no longer than maxStep, each halved where it
            // fails (trapezoidInterval)
            const int substeps = parameters_.maxStep > 0.0
                ? int(std::min(std::ceil(h / parameters_.maxStep - 1e-9), 1e6))
                : 1;
            for (int k = 0; k < substeps; ++k) {
                trapezoidInterval(y, double(k) / substeps,
                                  double(k + 1) / substeps, 0, newton);
            }
        }
    } catch (const std::runtime_error& e) {
        throw UndefinedStateError(std::string("mooringLine: step from t = ")
                                  + formatValue(state.time) + " s by "
                                  + formatValue(h) + " s failed: " + e.what());
    }
    state.nodes.swap(y);
    state.newton = std::move(newton);
    state.time += h;
    state.Q = ends_.Q1;
    state.P = ends_.P1;
    state.vQ = ends_.vQ1;
    state.vP = ends_.vP1;
    // The ends' acceleration at the step's end: the Hermite path's
    // (6 (r0 - r1)/h^2 + (2 v0 + 4 v1)/h), which is (v1 - v0)/h for
    // positions and velocities of the trapezoidal rule (implicit Newmark);
    // the straight path's mean, (v1 - v0)/h
    const auto acceleration = [this](const Vector3& r0, const Vector3& r1,
                                     const Vector3& v0, const Vector3& v1) {
        const double h = ends_.h;
        return parameters_.hermiteEnds
            ? Vector3(6.0 * (r0 - r1) / (h * h) + (2.0 * v0 + 4.0 * v1) / h)
            : Vector3((v1 - v0) / h);
    };
    state.aQ = acceleration(ends_.Q0, ends_.Q1, ends_.vQ0, ends_.vQ1);
    state.aP = acceleration(ends_.P0, ends_.P1, ends_.vP0, ends_.vP1);
}

MooringLineOutput
MooringLine::evaluate(const MooringLineState& state, const BodyKinematics& A,
                      const BodyKinematics& B, int shapePoints,
                      const std::vector<Vector3>& flow,
                      const std::vector<Vector3>& flowAcceleration) const
{
    requireFiniteInputs(lawName, "A", A);
    requireFiniteInputs(lawName, "B", B);
    const MooringLineParameters& p = parameters_;
    const LineLayout& L = layout_;
    const int N = L.N;
    if (state.nodes.size() != 6 * std::size_t(N - 1)) {
        throw std::invalid_argument("mooringLine: state does not fit the line");
    }
    const AxialGeometry g = axialGeometry(A, B, p.p_AoP_A, p.p_BoQ_B);
    // into lastEvaluated_ (storage kept from call to call)
    std::vector<Vector3>& r = lastEvaluated_.r;
    std::vector<Vector3>& v = lastEvaluated_.v;
    r.resize(std::size_t(N + 1));
    v.resize(std::size_t(N + 1));
    unpack(state.nodes, N, r, v);
    r[0] = attachment(B, p.p_BoQ_B);
    r[N] = attachment(A, p.p_AoP_A);
    v[0] = attachmentVelocity(B, p.p_BoQ_B);
    v[N] = attachmentVelocity(A, p.p_AoP_A);
    WaterMotion& water = lastEvaluated_.water;
    waterMotion(flow, flowAcceleration, water);
    NodeForces& f = lastEvaluated_.f;
    nodeForces(p, L, r, v, r[0][2], f, &water);

    MooringLineOutput out;
    ConnectorResult& res = out.loads;
    // The end nodes' own forces (their half segments' weight, buoyancy,
    // drag, seabed) act on the bodies
    res.A.f_W = -f.T[N - 1] * f.q[N - 1] + f.external[N];
    res.B.f_W = f.T[0] * f.q[0] + f.external[0];
    if (p.endInertia) {
        // and their inertia: half a segment's mass and added mass moving
        // with the attachment point
        const auto inertia = [&](int i, const Vector3& a) {
            const LineSection s = p.section(i == 0 ? 0 : L.sections.size() - 1);
            const double l = s.length / s.segments;
            const double area = 0.25 * pi * s.diameter * s.diameter;
            const double added
                = 0.5 * l * p.waterDensity * area * f.submerged[std::size_t(i)];
            const Vector3& t = f.tangent[std::size_t(i)];
            const double along = a.dot(t);
            return Vector3(0.5 * l * s.massPerLength * a
                           + added * s.normalAddedMass * (a - along * t)
                           + added * s.tangentialAddedMass * along * t);
        };
        res.A.f_W -= inertia(N, state.aP);
        res.B.f_W -= inertia(0, state.aQ);
    }
    res.A.m_Ko_W = g.p_AoP_W.cross(res.A.f_W);
    res.B.m_Ko_W = g.p_BoQ_W.cross(res.B.f_W);
    res.length = g.length;
    res.lengthRate = g.lengthRate;
    out.fairleadTension = res.A.f_W.norm();
    out.anchorTension = res.B.f_W.norm();
    res.tension = out.fairleadTension;
    res.potentialEnergy = f.strainEnergy + f.seabedEnergy + f.gravityEnergy;
    res.dissipatedPower = std::max(f.dissipatedPower, 0.0);
    // l times the grounded segments (both nodes on the seabed), section
    // by section
    const auto grounded
        = [&](int i) { return i == 0 || i == N || r[i][2] <= r[0][2]; };
    for (const LineLayout::Section& c : L.sections) {
        int count = 0;
        for (int j = c.firstSegment;
             p.seabedContact && j < c.firstSegment + c.segments; ++j) {
            count += grounded(j) && grounded(j + 1);
        }
        out.groundedLength += c.l * count;
    }
    out.H = std::hypot(res.A.f_W[0], res.A.f_W[1]);
    out.V = -res.A.f_W[2];
    if (shapePoints == 1 || shapePoints < 0) {
        throw std::invalid_argument(
            "mooringLine: shapePoints must be 0 or >= 2");
    }
    for (int k = 0; k < shapePoints; ++k) {
        const double u = L.nodeCoordinate(1.0 - double(k) / (shapePoints - 1));
        const int i = std::min(int(u), N - 1);
        const double f01 = u - i;
        out.shape.push_back((1.0 - f01) * r[i] + f01 * r[i + 1]);
        // tension: anchorTension at node 0, T_j at u = j + 1/2,
        // fairleadTension at node N, linear between
        double T = 0.0;
        if (u <= 0.5) {
            T = out.anchorTension + 2.0 * u * (f.T[0] - out.anchorTension);
        } else if (u >= N - 0.5) {
            T = f.T[N - 1]
                + 2.0 * (u - (N - 0.5)) * (out.fairleadTension - f.T[N - 1]);
        } else {
            const int j = std::min(int(u - 0.5), N - 2);
            const double g = u - 0.5 - j;
            T = (1.0 - g) * f.T[j] + g * f.T[j + 1];
        }
        out.shapeTension.push_back(T);
    }
    out.sectionLowerTension = L.sectionEnds(f.T, false);
    out.sectionUpperTension = L.sectionEnds(f.T, true);
    for (const int i : L.jointNodes()) {
        out.joints.push_back(r[std::size_t(i)]);
    }
    return out;
}

CvodeBdf::Statistics MooringLine::statistics() const
{
    return integrator_ ? integrator_->statistics() : trapezoidStatistics_;
}

} // namespace connectors
