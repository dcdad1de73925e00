// MooringLine (MooringLine.hpp): the start state, the ends' path over a
// step, CVODE's right-hand side and the step itself; the trapezoidal rule
// in MooringLineTrapezoid.cpp, the loads and diagnostics in
// MooringLineEvaluate.cpp, the parameters in MooringLineParameters.cpp.
#include "mooringLine/MooringLine.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "catenary/Catenary.hpp"
#include "common/ConnectorError.hpp"
#include "mooringLine/LineForces.hpp"
#include "mooringLine/LineStatics.hpp"

namespace connectors {

namespace {
const char* const lawName = "mooringLine";
} // namespace

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
    requireFiniteInputs(lawName, A, B);
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

void MooringLine::energyRatesAt(double t, const double* y, LineEnergy& rates)
{
    const int N = layout_.N;
    std::vector<Vector3>& r = work_.r;
    std::vector<Vector3>& v = work_.v;
    r.resize(std::size_t(N + 1));
    v.resize(std::size_t(N + 1));
    endsAt(std::clamp((t - ends_.t0) / ends_.h, 0.0, 1.0), r[0], v[0], r[N],
           v[N]);
    for (int i = 1; i < N; ++i) {
        const double* yi = y + 6 * (i - 1);
        r[std::size_t(i)] = Vector3(yi[0], yi[1], yi[2]);
        v[std::size_t(i)] = Vector3(yi[3], yi[4], yi[5]);
    }
    nodeForces(parameters_, layout_, r, v, r[0][2], work_.f, &water_);
    ++energyEvaluations_;
    energyRates(parameters_, layout_, r, v, work_.f, r[0][2], &water_, rates);
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

void MooringLine::advance(MooringLineState& state, const BodyKinematics& A,
                          const BodyKinematics& B, double h,
                          const std::vector<Vector3>& flow,
                          const std::vector<Vector3>& flowAcceleration)
{
    requireFiniteInputs(lawName, A, B);
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
    stepEnergy_.clear(layout_.sections.size());
    try {
        if (integrator_) {
            // the account: the rates' trapezoidal integral over CVODE's
            // internal steps (one force evaluation each)
            integrator_->restart(state.time, state.nodes.data());
            const bool account = parameters_.energyAccount;
            if (account) {
                energyRatesAt(state.time, state.nodes.data(), work_.rates0);
            }
            double t0 = state.time;
            integrator_->advance(state.time + h, y.data(),
                                 [&](double t, const double* yt) {
                                     if (!account) {
                                         return;
                                     }
                                     energyRatesAt(t, yt, work_.rates1);
                                     stepEnergy_.addTrapezoid(
                                         work_.rates0, work_.rates1, t - t0);
                                     std::swap(work_.rates0, work_.rates1);
                                     t0 = t;
                                 });
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

} // namespace connectors
