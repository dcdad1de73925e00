// The flow's inertia on the dynamic line (Froude-Krylov and added mass of
// an accelerating flow, MoorDyn's Ap and Aq), against analytic answers: on
// a line held still in a uniformly accelerating flow each node feels
// rho A lambda ((1 + Can) a_n + (1 + Cat) a_t) and the line rho V (1 + Can) a
// across it; a joint's point adds rho V (1 + Ca) a; the bodies' loads take
// the end nodes' half segments; a neutrally buoyant line whose ends move
// with the water moves with it; no acceleration changes nothing.
#include <gtest/gtest.h>

#include <cmath>

#include "LawTestSupport.hpp"
#include "MooringLineReferences.hpp"
#include "common/ConnectorError.hpp"
#include "mooringLine/LineForces.hpp"
#include "mooringLine/LineLayout.hpp"
#include "mooringLine/MooringLine.hpp"

namespace {

using namespace lawTest;
using connectors::MooringLine;
using connectors::MooringLineParameters;
using connectors::MooringLineState;
using connectors::NodeForces;
using connectors::WaterMotion;

//- A 100 m line of 10 segments, d = 0.1 m, straight along x under a
//  pretension (weightless: gravity 0), no drag
MooringLineParameters straightLine()
{
    // d, w, EA, axial damping, Cn, Ct, Can, Cat
    MooringLineParameters p = connectors::references::lineOf(
        {0.1, 50.0, 1e8, 1e6, 0.0, 0.0, 1.0, 0.5}, 100.0, false, 10);
    p.gravity = 0.0;
    return p;
}

//- straightLine() under gravity (9.81 m/s2)
MooringLineParameters hangingLine()
{
    MooringLineParameters p = straightLine();
    p.gravity = 9.81;
    return p;
}

//- The line's ends [m]: A 60 m along x and 80.5 m above B at the origin,
//  100.4 m apart (the 100 m line stretched)
const BodyKinematics endA = body(Vector3(60.0, 0.0, 80.5));
const BodyKinematics endB = body(Vector3::Zero());

//- Nodes 0..N on the straight line from the origin to (x, 0, 0), at rest
void straightNodes(int N, double x, std::vector<Vector3>& r,
                   std::vector<Vector3>& v)
{
    r.resize(std::size_t(N + 1));
    v.assign(std::size_t(N + 1), Vector3::Zero());
    for (int i = 0; i <= N; ++i) {
        r[std::size_t(i)] = Vector3(x * i / N, 0.0, 0.0);
    }
}

TEST(MooringLineFlowInertia, LineHeldStillInAnAcceleratingFlow)
{
    // A straight line along x at rest: the flow accelerating at a adds to
    // node i rho A lambda_i ((1 + Can) a_n + (1 + Cat) a_t), lambda the
    // node's unstretched length (l, l/2 at the ends): in all
    // rho A L ((1 + Can) a_n + (1 + Cat) a_t)
    const MooringLineParameters p = straightLine();
    const int N = p.segments;
    std::vector<Vector3> r, v;
    straightNodes(N, 100.5, r, v);
    const Vector3 a(0.3, -0.4, 0.7);
    WaterMotion still, accelerating;
    accelerating.flowAcceleration.assign(std::size_t(N + 1), a);
    const NodeForces f0
        = connectors::nodeForces(p, p.weight(), r, v, 0.0, &still);
    const NodeForces f1
        = connectors::nodeForces(p, p.weight(), r, v, 0.0, &accelerating);
    const double rho = p.waterDensity;
    const double A = 0.25 * pi * p.diameter * p.diameter;
    const double l = p.length / N;
    const Vector3 aT(a[0], 0.0, 0.0), aN(0.0, a[1], a[2]);
    Vector3 total = Vector3::Zero();
    for (int i = 0; i <= N; ++i) {
        const double lambda = (i == 0 || i == N) ? 0.5 * l : l;
        const Vector3 want = rho * A * lambda
            * ((1.0 + p.normalAddedMass) * aN
               + (1.0 + p.tangentialAddedMass) * aT);
        const Vector3 got
            = f1.external[std::size_t(i)] - f0.external[std::size_t(i)];
        // the same products in another order: round-off of the forces
        // (about 1 N), 1e-13 of them
        EXPECT_LT((got - want).norm(), 1e-13 * want.norm()) << i;
        total += got;
        if (i > 0 && i < N) {
            EXPECT_LT(
                (f1.F[std::size_t(i)] - f0.F[std::size_t(i)] - want).norm(),
                1e-12 * want.norm())
                << i;
        }
    }
    const double V = A * p.length;
    const Vector3 want = rho * V
        * ((1.0 + p.normalAddedMass) * aN + (1.0 + p.tangentialAddedMass) * aT);
    // rho V (1 + Can) |a_n| = 10.3 N; round-off of 11 sums
    EXPECT_LT((total - want).norm(), 1e-13 * want.norm());
    // the normal part alone is rho V (1 + Ca) a
    EXPECT_NEAR(total[1], rho * V * 2.0 * a[1], 1e-13 * want.norm());
    EXPECT_NEAR(total[2], rho * V * 2.0 * a[2], 1e-13 * want.norm());
}

TEST(MooringLineFlowInertia, ScaledBySubmergedFractionAndAddsThePoint)
{
    // Two sections with a buoy at the joint, the free surface at the
    // joint's height: every node's force is phi times its pieces' and its
    // point's rho V (1 + Ca) a
    MooringLineParameters p = straightLine();
    p.segments = 4;
    p.length = 40.0;
    // d, w, EA, axial damping, Cn, Ct, Can, Cat; the buoy's m, V, CdA, Ca
    p.sections = {connectors::references::sectionOf(
        {0.2, 20.0, 1e8, 0.0, 0.0, 0.0, 0.8, 0.1}, 60.0, 6,
        {100.0, 0.5, 0.0, 0.6})};
    p.freeSurface = true;
    p.waterLevel = 0.0;
    const connectors::LineLayout L = connectors::lineLayout(p, p.weight());
    const int N = L.N;
    std::vector<Vector3> r, v;
    straightNodes(N, 100.5, r, v);
    // a vertical flow acceleration: normal to the line along x
    const Vector3 a(0.0, 0.0, 1.3);
    WaterMotion still, accelerating;
    accelerating.flowAcceleration.assign(std::size_t(N + 1), a);
    connectors::NodeForces f0, f1;
    connectors::nodeForces(p, L, r, v, -10.0, f0, &still);
    connectors::nodeForces(p, L, r, v, -10.0, f1, &accelerating);
    const double rho = p.waterDensity;
    const double A1 = 0.25 * pi * 0.1 * 0.1, A2 = 0.25 * pi * 0.2 * 0.2;
    for (int i = 0; i <= N; ++i) {
        // node's pieces: section 1 below the joint (node 4), section 2 above
        double inertia = 0.0;
        const double l1 = 10.0, l2 = 10.0;
        if (i < 4) {
            inertia = rho * A1 * 2.0 * (i == 0 ? 0.5 * l1 : l1);
        } else if (i > 4) {
            inertia = rho * A2 * 1.8 * (i == N ? 0.5 * l2 : l2);
        } else {
            inertia = rho * A1 * 2.0 * 0.5 * l1 + rho * A2 * 1.8 * 0.5 * l2
                + rho * 0.5 * 1.6;
        }
        // on z = 0 (the water level): phi = 1/2
        const Vector3 want = 0.5 * inertia * a;
        const Vector3 got
            = f1.external[std::size_t(i)] - f0.external[std::size_t(i)];
        EXPECT_LT((got - want).norm(), 1e-13 * want.norm()) << i;
    }
}

TEST(MooringLineFlowInertia, BodiesTakeTheEndsHalfSegments)
{
    // The same state evaluated with and without the flow's acceleration
    // (given at two points: uniform): the loads on A and B change by the
    // end nodes' half segments' rho A l/2 ((1 + Can) a_n + (1 + Cat) a_t)
    // about their end segments, and nothing else
    const MooringLineParameters p = hangingLine();
    MooringLine law(p);
    const BodyKinematics A = endA, B = endB;
    const MooringLineState s = law.initialState(A, B, 0.0);
    const Vector3 a(0.5, 0.2, -0.3);
    const std::vector<Vector3> flow
        = {Vector3(0.1, 0.0, 0.0), Vector3(0.1, 0.0, 0.0)};
    const connectors::MooringLineOutput o0 = law.evaluate(s, A, B, 0, flow);
    const connectors::MooringLineOutput o1
        = law.evaluate(s, A, B, 0, flow, {a, a});
    const double rho = p.waterDensity;
    const double A0 = 0.25 * pi * p.diameter * p.diameter;
    const double halfL = 0.5 * p.length / p.segments;
    const auto half = [&](const Vector3& t) {
        const Vector3 aT = a.dot(t) * t;
        return Vector3(rho * A0 * halfL
                       * ((1.0 + p.normalAddedMass) * (a - aT)
                          + (1.0 + p.tangentialAddedMass) * aT));
    };
    const std::size_t top = 6 * std::size_t(p.segments - 2);
    const Vector3 belowP(s.nodes[top], s.nodes[top + 1], s.nodes[top + 2]);
    const Vector3 aboveQ(s.nodes[0], s.nodes[1], s.nodes[2]);
    const Vector3 tP = (A.p_WKo_W - belowP).normalized();
    const Vector3 tQ = aboveQ.normalized();
    const Vector3 dA = o1.loads.A.f_W - o0.loads.A.f_W;
    const Vector3 dB = o1.loads.B.f_W - o0.loads.B.f_W;
    // differences of loads of about 1e5 N (the pretension): their
    // round-off, 1e-10 N, against a change of 0.4 N
    EXPECT_LT((dA - half(tP)).norm(), 1e-9);
    EXPECT_LT((dB - half(tQ)).norm(), 1e-9);
    EXPECT_GT(half(tP).norm(), 0.3);
}

TEST(MooringLineFlowInertia, NeutrallyBuoyantLineMovesWithTheWater)
{
    // mu = rho A: a node's mass and added mass, rho V (1 + Ca), equal the
    // flow's inertia on it, so in a flow U = a t whose ends move with the
    // water the line translates with it, x(t) = x(0) + a t^2/2, its
    // tensions unchanged; the trapezoidal rule is exact for a uniform
    // acceleration, so the nodes follow to Newton's tolerance (1e-5 of a
    // segment) at most
    MooringLineParameters p = straightLine();
    p.massPerLength = p.waterDensity * 0.25 * pi * p.diameter * p.diameter;
    p.normalDrag = 1.2;
    p.tangentialDrag = 0.05;
    MooringLine law(p);
    const Vector3 a(0.2, 0.5, -0.4);
    const Vector3 P0(60.0, 0.0, 80.5);
    const auto moving = [&](const Vector3& start, double t) {
        BodyKinematics k = body(start + 0.5 * a * t * t);
        k.v_WKo_W = a * t;
        return k;
    };
    MooringLineState s
        = law.initialState(moving(P0, 0.0), moving(Vector3::Zero(), 0.0), 0.0);
    const MooringLineState start = s;
    const double T0
        = law.evaluate(s, moving(P0, 0.0), moving(Vector3::Zero(), 0.0), 0)
              .sectionUpperTension[0];
    const double h = 0.01;
    for (int k = 0; k < 200; ++k) {
        const double t = k * h;
        const std::vector<Vector3> flow(11, a * t);
        law.advance(s, moving(P0, t + h), moving(Vector3::Zero(), t + h), h,
                    flow, std::vector<Vector3>(11, a));
    }
    const double t = 200 * h;
    double largest = 0.0;
    for (std::size_t i = 0; i < s.nodes.size(); i += 6) {
        for (int c = 0; c < 3; ++c) {
            largest = std::max(largest,
                               std::abs(s.nodes[i + std::size_t(c)]
                                        - start.nodes[i + std::size_t(c)]
                                        - 0.5 * a[c] * t * t));
            largest = std::max(
                largest, std::abs(s.nodes[i + 3 + std::size_t(c)] - a[c] * t));
        }
    }
    EXPECT_LT(largest, 1e-5 * p.length / p.segments);
    const connectors::MooringLineOutput o = law.evaluate(
        s, moving(P0, t), moving(Vector3::Zero(), t), 0,
        std::vector<Vector3>(11, a * t), std::vector<Vector3>(11, a));
    // the segments' tensions (the loads carry the end halves' inertia):
    // strain of a displacement of at most 1e-4 m on 10 m segments of
    // EA = 1e8 N
    EXPECT_NEAR(o.sectionUpperTension[0], T0, 1e3) << T0;
    // without the flow's inertia the line lags the water and is dragged
    MooringLineState lagging = start;
    for (int k = 0; k < 200; ++k) {
        law.advance(lagging, moving(P0, (k + 1) * h),
                    moving(Vector3::Zero(), (k + 1) * h), h,
                    std::vector<Vector3>(11, a * (k * h)));
    }
    EXPECT_GT(std::abs(lagging.nodes[6 * 4 + 1] - start.nodes[6 * 4 + 1]
                       - 0.5 * a[1] * t * t),
              1e3 * largest);
}

TEST(MooringLineFlowInertia, NoAccelerationChangesNothing)
{
    // an empty and a zero acceleration: the run of no acceleration, bit
    // for bit (the force adds exact zeros)
    MooringLine law(hangingLine());
    const BodyKinematics A = endA, B = endB;
    MooringLineState s0 = law.initialState(A, B, 0.0), s1 = s0;
    const std::vector<Vector3> flow(11, Vector3(0.3, 0.1, 0.0));
    for (int k = 0; k < 20; ++k) {
        law.advance(s0, A, B, 0.05, flow);
        law.advance(s1, A, B, 0.05, flow,
                    std::vector<Vector3>(11, Vector3::Zero()));
    }
    EXPECT_EQ(s0.nodes, s1.nodes);
}

TEST(MooringLineFlowInertia, AccelerationPointsAreChecked)
{
    MooringLine law(straightLine());
    const BodyKinematics A = endA, B = endB;
    MooringLineState s = law.initialState(A, B, 0.0);
    const std::vector<Vector3> flow(11, Vector3::Zero());
    EXPECT_THROW(law.advance(s, A, B, 0.1, flow,
                             std::vector<Vector3>(5, Vector3::Zero())),
                 std::invalid_argument);
    std::vector<Vector3> bad(11, Vector3::Zero());
    bad[3][1] = NAN;
    try {
        law.advance(s, A, B, 0.1, flow, bad);
        FAIL() << "a NaN acceleration was taken";
    } catch (const connectors::UndefinedStateError& e) {
        EXPECT_STREQ(e.what(),
                     "mooringLine: the flow acceleration at shape "
                     "point 4 is not finite");
    }
}

} // namespace
