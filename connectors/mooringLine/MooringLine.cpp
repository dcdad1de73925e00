#include "mooringLine/MooringLine.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
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

void requirePositive(const char* name, double value, const char* unit)
{
    if (!(std::isfinite(value) && value > 0.0)) {
        throw ParameterError(lawName, name, value, unit, "finite and > 0");
    }
}

//- Whether a and b hold the same doubles to the bit (-0 differs from 0)
static_assert(sizeof(Vector3) == 3 * sizeof(double), "Vector3 is 3 doubles");
bool sameBits(const std::vector<Vector3>& a, const std::vector<Vector3>& b)
{
    return a.size() == b.size()
        && (a.empty()
            || std::memcmp(a.data(), b.data(), a.size() * sizeof(Vector3))
                == 0);
}

} // namespace

double MooringLineParameters::weight() const
{
    return (massPerLength - waterDensity * 0.25 * pi * diameter * diameter)
        * gravity;
}

std::vector<double> MooringLineState::serialize() const
{
    std::vector<double> out
        = {time,  Q[0],  Q[1],  Q[2],  P[0],  P[1],  P[2],  vQ[0], vQ[1], vQ[2],
           vP[0], vP[1], vP[2], aQ[0], aQ[1], aQ[2], aP[0], aP[1], aP[2]};
    out.insert(out.end(), nodes.begin(), nodes.end());
    return out;
}

MooringLineState MooringLineState::deserialize(const std::vector<double>& data,
                                               int segments)
{
    const std::size_t expected = 19 + 6 * std::size_t(segments - 1);
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
    s.nodes.assign(data.begin() + 19, data.end());
    return s;
}

MooringLine::MooringLine(const MooringLineParameters& p) : parameters_(p)
{
    requireFinite(lawName, "A.p", p.p_AoP_A, "m");
    requireFinite(lawName, "B.p", p.p_BoQ_B, "m");
    requirePositive("unstretchedLength", p.length, "m");
    requirePositive("EA", p.EA, "N");
    requireNonNegative(lawName, "axialDamping", p.axialDamping, "N.s");
    requirePositive("massPerLength", p.massPerLength, "kg/m");
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
    if (p.segments < 2 || p.segments > 1000) {
        throw ConnectorError(
            "mooringLine: parameter segments = " + std::to_string(p.segments)
            + " is out of range (allowed: an integer from 2 to 1000)");
    }
    requirePositive("relativeTolerance", p.relativeTolerance, "1");
    requirePositive("absoluteTolerance", p.absoluteTolerance, "1");
    if (!(std::isfinite(p.maxStep) && p.maxStep >= 0.0)) {
        throw ParameterError(lawName, "maxStep", p.maxStep, "s",
                             "finite and >= 0");
    }
    if (!std::isfinite(p.waterLevel)) {
        throw ParameterError(lawName, "waterLevel", p.waterLevel, "m",
                             "finite");
    }
    requireFinite(lawName, "current.surface", p.currentSurface, "m/s");
    requireFinite(lawName, "current.seabed", p.currentSeabed, "m/s");
    requireNonNegative(lawName, "seabedFriction", p.seabedFriction, "1");
    requirePositive("frictionVelocity", p.frictionVelocity, "m/s");
    weight_ = p.weight();
    if (p.integrator == MooringLineParameters::Integrator::cvode) {
        CvodeBdf::Options options;
        options.relativeTolerance = p.relativeTolerance;
        options.absoluteTolerance = p.absoluteTolerance;
        options.halfBandwidth = 11; // a node's 6 states see its neighbours' 6
        integrator_ = std::make_unique<CvodeBdf>(
            6 * std::size_t(p.segments - 1),
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
    CatenaryParameters c;
    c.p_AoP_A = p.p_AoP_A;
    c.p_BoQ_B = p.p_BoQ_B;
    c.line.length = p.length;
    c.line.EA = p.EA;
    c.line.weight = weight_;
    c.line.seabedContact = p.seabedContact;
    CatenaryOutput shape;
    try {
        shape = Catenary(c).evaluate(A, B, nullptr, p.segments + 1);
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
    const int N = p.segments;
    // shape runs from P (index 0) to Q (index N); node i is shape[N - i]
    std::vector<Vector3> r(std::size_t(N + 1));
    for (int i = 0; i <= N; ++i) {
        r[std::size_t(i)] = shape.shape[std::size_t(N - i)];
    }
    r[0] = s.Q;
    r[std::size_t(N)] = s.P;
    // The discrete line's own equilibrium (straight segments, seabed
    // penalty), so that a line held still stays still; the catenary shape
    // is kept where Newton cannot reach one (a slack weightless line, a
    // line folded on the seabed, whose grounded nodes have no unique place)
    std::vector<Vector3> equilibrium(r);
    if (solveStatics(p, weight_, equilibrium, s.Q[2])) {
        r.swap(equilibrium);
    }
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
    const int N = parameters_.segments;
    std::vector<Vector3> r(std::size_t(N + 1)), v(std::size_t(N + 1));
    endsAt(std::clamp((t - ends_.t0) / ends_.h, 0.0, 1.0), r[0], v[0], r[N],
           v[N]);
    for (int i = 1; i < N; ++i) {
        const double* yi = y + 6 * (i - 1);
        r[i] = Vector3(yi[0], yi[1], yi[2]);
        v[i] = Vector3(yi[3], yi[4], yi[5]);
    }
    const NodeForces forces
        = nodeForces(parameters_, weight_, r, v, r[0][2], &water_);
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

bool MooringLine::trapezoidStep(std::vector<double>& nodes, double s0,
                                double s1, double largestMiss)
{
    const double h = (s1 - s0) * ends_.h;
    const int N = parameters_.segments;
    const std::size_t n = std::size_t(N);
    Workspace& w = work_;
    w.r0.resize(n + 1);
    w.v0.resize(n + 1);
    w.b.resize(n - 1);
    unpack(nodes, N, w.r0, w.v0);
    endsAt(s0, w.r0[0], w.v0[0], w.r0[n], w.v0[n]);
    const double zb = w.r0[0][2];
    // The start's accelerations: those `evaluate` found at the same node
    // positions and velocities (the end of the previous step, as the FMU
    // reports its outputs), else a force evaluation; the same function of
    // the same numbers either way
    if (sameBits(lastEvaluated_.r, w.r0) && sameBits(lastEvaluated_.v, w.v0)
        && sameBits(lastEvaluated_.water.flow, water_.flow)) {
        w.a0 = lastEvaluated_.f.a;
    } else {
        nodeForces(parameters_, weight_, w.r0, w.v0, zb, w.f, &water_);
        ++trapezoidStatistics_.rhsEvaluations;
        w.a0 = w.f.a;
    }
    // Predictor: the start acceleration held over the step
    w.r = w.r0;
    w.v = w.v0;
    endsAt(s1, w.r[0], w.v[0], w.r[n], w.v[n]);
    for (std::size_t i = 1; i < n; ++i) {
        w.r[i] = w.r0[i] + h * w.v0[i] + 0.5 * h * h * w.a0[i];
        w.v[i] = w.v0[i] + h * w.a0[i];
    }
    const double l = parameters_.length / N;
    // Newton on the end positions x (v = 2 (x - x0)/h - v0) with the
    // matrix of the predictor; the residual (v - v0)/h - (a0 + a(x, v))/2
    // is scaled by M h^2/2. Each correction is about 1e-3 of the previous
    // one (the matrix omits only small terms): measured on the reference
    // lines, largest first corrections 1.8e-6 (lab chain, 1 ms) and 7.5e-6
    // (OC4, 0.1 s) of a segment, second ones 2e-9, third 2.5e-12. A
    // correction below 1e-5 of a segment ends the iteration: one solve per
    // step, and the tension harmonic equals that of Newton iterated to
    // 1e-10 of a segment within 5e-8 (lab) and 3e-6 (OC4) of itself. A
    // first correction above largestMiss segments rejects the step.
    for (int iteration = 0; iteration < 10; ++iteration) {
        nodeForces(parameters_, weight_, w.r, w.v, zb, w.f, &water_);
        if (iteration == 0) {
            trapezoidMatrix(parameters_, weight_, w.r, w.f, zb, h, w.J);
            w.J.factorize();
            ++trapezoidStatistics_.jacobianEvaluations;
        }
        ++trapezoidStatistics_.rhsEvaluations;
        for (std::size_t i = 1; i < n; ++i) {
            const Vector3 residual
                = (w.v[i] - w.v0[i]) / h - 0.5 * (w.a0[i] + w.f.a[i]);
            const Vector3& t = w.f.tangent[i];
            const double along = residual.dot(t);
            const double mn = w.f.normalMass[i], mt = w.f.tangentialMass[i];
            w.b[i - 1] = -0.5 * h * h * (mn * residual + (mt - mn) * along * t);
        }
        w.J.solveFactored(w.b);
        double largest = 0.0;
        bool finite = true;
        for (std::size_t i = 1; i < n; ++i) {
            w.r[i] += w.b[i - 1];
            w.v[i] += (2.0 / h) * w.b[i - 1];
            largest = std::max(largest, w.b[i - 1].lpNorm<Eigen::Infinity>());
            finite = finite && w.b[i - 1].allFinite();
        }
        if (!finite) {
            break;
        }
        if (iteration == 0 && largest > largestMiss * l) {
            ++trapezoidStatistics_.errorTestFailures;
            return false;
        }
        if (largest <= 1e-5 * l) {
            for (std::size_t i = 1; i < n; ++i) {
                double* y = nodes.data() + 6 * (i - 1);
                for (int k = 0; k < 3; ++k) {
                    y[k] = w.r[i][k];
                    y[3 + k] = w.v[i][k];
                }
            }
            ++trapezoidStatistics_.steps;
            return true;
        }
    }
    ++trapezoidStatistics_.convergenceFailures;
    return false;
}

void MooringLine::trapezoidInterval(std::vector<double>& nodes, double s0,
                                    double s1, int depth)
{
    // The predictor's miss (Newton's first correction) is about three
    // times the step's local error, h^3/12 times the third derivative of
    // the positions. Above 1e-5 of a segment the interval is halved, so
    // that every step takes one Newton solve (that correction ends
    // trapezoidStep's iteration). The reference lines miss by at most
    // 1.8e-6 (lab chain, 1 ms) and 7.5e-6 (OC4, N = 20, 0.1 s): one step
    // per coupling step. A snap (the lab chain pulled to 0.9997 of its
    // length) is resolved in shorter steps: its energy balance closes to
    // 1e-4 of the work done (at 1e-4 of a segment: 0.27, no better than
    // 0.1 ms steps throughout; bench/mooringLine). At the tenth halving
    // Newton iterates to 1e-5 of a segment, whatever the first correction.
    constexpr int deepest = 10;
    if (trapezoidStep(
            nodes, s0, s1,
            depth < deepest ? 1e-5 : std::numeric_limits<double>::infinity())) {
        return;
    }
    if (depth == deepest) {
        throw std::runtime_error(
            "Newton did not converge in the trapezoidal step, not even at "
            "1/1024 of the coupling step");
    }
    const double middle = 0.5 * (s0 + s1);
    trapezoidInterval(nodes, s0, middle, depth + 1);
    trapezoidInterval(nodes, middle, s1, depth + 1);
}

void MooringLine::waterMotion(const std::vector<Vector3>& flow,
                              WaterMotion& water) const
{
    const MooringLineParameters& p = parameters_;
    water.current
        = !p.currentSurface.isZero(0.0) || !p.currentSeabed.isZero(0.0);
    if (flow.empty()) {
        water.flow.clear();
        return;
    }
    if (flow.size() < 2) {
        throw std::invalid_argument(
            "mooringLine: the flow needs 0 or at least 2 points");
    }
    for (std::size_t k = 0; k < flow.size(); ++k) {
        if (!flow[k].allFinite()) {
            throw UndefinedStateError(
                "mooringLine: the flow velocity at shape point "
                + std::to_string(k + 1) + " is not finite");
        }
    }
    // node i is (N - i)/N of the line from P: between points k and k + 1
    const int N = p.segments;
    const int last = int(flow.size()) - 1;
    water.flow.resize(std::size_t(N + 1));
    for (int i = 0; i <= N; ++i) {
        const double u = double(N - i) * last / N;
        const int k = std::min(int(u), last - 1);
        const double f01 = u - k;
        water.flow[std::size_t(i)] = (1.0 - f01) * flow[std::size_t(k)]
            + f01 * flow[std::size_t(k + 1)];
    }
}

void MooringLine::advance(MooringLineState& state, const BodyKinematics& A,
                          const BodyKinematics& B, double h,
                          const std::vector<Vector3>& flow)
{
    requireFiniteInputs(lawName, "A", A);
    requireFiniteInputs(lawName, "B", B);
    if (!(std::isfinite(h) && h > 0.0)) {
        throw UndefinedStateError("mooringLine: step size " + formatValue(h)
                                  + " s must be finite and > 0");
    }
    const std::size_t size = 6 * std::size_t(parameters_.segments - 1);
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
    waterMotion(flow, water_);
    std::vector<double> y(state.nodes);
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
                                  double(k + 1) / substeps, 0);
            }
        }
    } catch (const std::runtime_error& e) {
        throw UndefinedStateError(std::string("mooringLine: step from t = ")
                                  + formatValue(state.time) + " s by "
                                  + formatValue(h) + " s failed: " + e.what());
    }
    state.nodes = std::move(y);
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

MooringLineOutput MooringLine::evaluate(const MooringLineState& state,
                                        const BodyKinematics& A,
                                        const BodyKinematics& B,
                                        int shapePoints,
                                        const std::vector<Vector3>& flow) const
{
    requireFiniteInputs(lawName, "A", A);
    requireFiniteInputs(lawName, "B", B);
    const MooringLineParameters& p = parameters_;
    const int N = p.segments;
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
    waterMotion(flow, water);
    NodeForces& f = lastEvaluated_.f;
    nodeForces(p, weight_, r, v, r[0][2], f, &water);
    const double l = p.length / N;

    MooringLineOutput out;
    ConnectorResult& res = out.loads;
    // The end nodes' own forces (their half segments' weight, buoyancy,
    // drag, seabed) act on the bodies
    res.A.f_W = -f.T[N - 1] * f.q[N - 1] + f.external[N];
    res.B.f_W = f.T[0] * f.q[0] + f.external[0];
    if (p.endInertia) {
        // and their inertia: half a segment's mass and added mass moving
        // with the attachment point
        const double area = 0.25 * pi * p.diameter * p.diameter;
        const auto inertia = [&](int i, const Vector3& a) {
            const double added
                = 0.5 * l * p.waterDensity * area * f.submerged[std::size_t(i)];
            const Vector3& t = f.tangent[std::size_t(i)];
            const double along = a.dot(t);
            return Vector3(0.5 * l * p.massPerLength * a
                           + added * p.normalAddedMass * (a - along * t)
                           + added * p.tangentialAddedMass * along * t);
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
    out.groundedLength = l * f.groundedSegments;
    out.H = std::hypot(res.A.f_W[0], res.A.f_W[1]);
    out.V = -res.A.f_W[2];
    if (shapePoints == 1 || shapePoints < 0) {
        throw std::invalid_argument(
            "mooringLine: shapePoints must be 0 or >= 2");
    }
    for (int k = 0; k < shapePoints; ++k) {
        const double u = N * (1.0 - double(k) / (shapePoints - 1));
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
    return out;
}

CvodeBdf::Statistics MooringLine::statistics() const
{
    return integrator_ ? integrator_->statistics() : trapezoidStatistics_;
}

} // namespace connectors
