// The dynamic line in moving water and at its boundaries, each against an
// analytic answer: the end nodes' drag, inertia and seabed force on the
// bodies; drag on the stretched length; a taut line in a uniform current
// (total drag = the bodies' horizontal loads = the Morison formula); a
// line through the free surface (dry weight above it) held still from the
// start; the current profile; flow velocities at the shape points against
// the same current; the tension along the shape.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "LawTestSupport.hpp"
#include "MooringLineReferences.hpp"
#include "common/ConnectorError.hpp"
#include "mooringLine/LineForces.hpp"
#include "mooringLine/MooringLine.hpp"

namespace {

using namespace lawTest;
using connectors::MooringLine;
using connectors::MooringLineParameters;
using connectors::MooringLineState;

//- A 100 m line of 50 kg/m, d = 0.1 m, between two bodies (no seabed)
MooringLineParameters line(int segments)
{
    namespace references = connectors::references;
    // d [m], w [kg/m], EA [N], axial damping [N.s], Cn, Ct, Can, Cat
    constexpr references::LineType rope {0.1, 50.0, 1e8, 1e6,
                                         1.2, 0.05, 1.0, 0.5};
    return references::lineOf(rope, 100.0, false, segments);
}

double largestSpeed(const MooringLineState& s)
{
    double speed = 0.0;
    for (std::size_t i = 0; i + 5 < s.nodes.size(); i += 6) {
        speed = std::max(
            speed, std::hypot(s.nodes[i + 3], s.nodes[i + 4], s.nodes[i + 5]));
    }
    return speed;
}

TEST(MooringLineWater, FairleadDragActsOnTheBody)
{
    // The same line state evaluated with the fairlead at rest and moving:
    // the load on A changes by the drag of the fairlead node's half segment
    // (stretched length s/2) in still water, 1/2 rho d Cdn s/2 |un| un +
    // 1/2 rho pi d Cdt s/2 |ut| ut with u = -v, and nothing else (no axial
    // damping; the ends' inertia comes from the state's accelerations,
    // zero at the start)
    MooringLineParameters p = line(10);
    p.axialDamping = 0.0;
    p.gravity = 0.0;
    MooringLine law(p);
    const BodyKinematics B = body(Vector3::Zero());
    const BodyKinematics still = body(Vector3(60.0, 0.0, 80.5));
    const MooringLineState s = law.initialState(still, B, 0.0);
    BodyKinematics moving = still;
    moving.v_WKo_W = Vector3(1.5, -0.5, 0.8);
    const Vector3 F0 = law.evaluate(s, still, B, 0).loads.A.f_W;
    const Vector3 F1 = law.evaluate(s, moving, B, 0).loads.A.f_W;
    // top segment: from node N-1 to P
    const std::size_t top = 6 * std::size_t(p.segments - 2);
    const Vector3 below(s.nodes[top], s.nodes[top + 1], s.nodes[top + 2]);
    const Vector3 dr = still.p_WKo_W - below;
    const Vector3 t = dr.normalized();
    const double half = 0.5 * dr.norm(), rho = p.waterDensity, d = p.diameter;
    const Vector3 u = -moving.v_WKo_W;
    const Vector3 ut = u.dot(t) * t, un = u - ut;
    const Vector3 drag = 0.5 * rho * d * p.normalDrag * half * un.norm() * un
        + 0.5 * rho * pi * d * p.tangentialDrag * half * ut.norm() * ut;
    std::cout << "fairlead drag " << (F1 - F0).transpose() << " N, formula "
              << drag.transpose() << " N\n";
    // the same formula evaluated in another order: round-off of the ~1 kN
    // drag and of the ~1 MN tension it is added to (1e-16 x 1e6)
    expectVectorNear(F1 - F0, drag, 1e-8 * F0.norm());
    EXPECT_GT(drag.norm(), 100.0); // the drag is there
}

TEST(MooringLineWater, FairleadInertiaActsOnTheBody)
{
    // The fairlead accelerated uniformly (a quadratic path, which the
    // step's Hermite path reproduces exactly) for one step from rest: the
    // load on A differs from that without endInertia by minus the half
    // segment's mass and added mass times the acceleration, split along
    // the top segment: -(mu l/2 a + Can rho A l/2 an + Cat rho A l/2 at)
    MooringLineParameters p = line(10);
    p.gravity = 0.0;
    p.endInertia = true;
    MooringLineParameters off = p;
    off.endInertia = false;
    MooringLine law(p), without(off);
    const BodyKinematics B = body(Vector3::Zero());
    const BodyKinematics A0 = body(Vector3(60.0, 0.0, 80.5));
    const Vector3 a(0.4, 0.3, -0.2);
    const double h = 0.1;
    const BodyKinematics A1
        = body(A0.p_WKo_W + 0.5 * a * h * h, Matrix3::Identity(), a * h);
    MooringLineState s = law.initialState(A0, B, 0.0);
    law.advance(s, A1, B, h);
    // the acceleration kept in the state: exact for a quadratic path up to
    // the round-off of 6 (r0 - r1)/h^2 (1e-14 m / 1e-2 s^2)
    expectVectorNear(s.aP, a, 1e-10);
    const auto withInertia = law.evaluate(s, A1, B, 0);
    const auto withoutInertia = without.evaluate(s, A1, B, 0);
    const double l = p.length / p.segments;
    const double added = 0.25 * pi * p.diameter * p.diameter * p.waterDensity;
    const std::size_t top = 6 * std::size_t(p.segments - 2);
    const Vector3 t
        = (A1.p_WKo_W
           - Vector3(s.nodes[top], s.nodes[top + 1], s.nodes[top + 2]))
              .normalized();
    const Vector3 at = a.dot(t) * t, an = a - at;
    const Vector3 inertia = 0.5 * l
        * (p.massPerLength * a + added * p.normalAddedMass * an
           + added * p.tangentialAddedMass * at);
    // round-off of the ~1 MN tension in both loads
    expectVectorNear(withInertia.loads.A.f_W - withoutInertia.loads.A.f_W,
                     -inertia, 1e-8 * withInertia.fairleadTension);
}

TEST(MooringLineWater, EndNodeOnTheSeabedCarriesItsPenalty)
{
    // nodeForces: the fairlead node (half a segment) sunk by delta into the
    // seabed feels kb delta d l/2 up besides its submerged weight w l/2
    MooringLineParameters p = line(4);
    p.seabedContact = true;
    const int N = p.segments;
    const double l = p.length / N, delta = 0.01;
    std::vector<Vector3> r(std::size_t(N + 1)), v(std::size_t(N + 1));
    for (int i = 0; i <= N; ++i) {
        r[std::size_t(i)] = Vector3(i * l, 0.0, 0.0);
        v[std::size_t(i)].setZero();
    }
    r[std::size_t(N)][2] = -delta;
    const connectors::NodeForces f
        = connectors::nodeForces(p, p.weight(), r, v, 0.0);
    const double expected = -p.weight() * 0.5 * l
        + p.seabedStiffness * delta * p.diameter * 0.5 * l;
    // one product of exact inputs: round-off of the 1.2e3 N penalty
    EXPECT_NEAR(f.external[std::size_t(N)][2], expected, 1e-9);
    // and a node above the seabed none
    r[std::size_t(N)][2] = delta;
    EXPECT_DOUBLE_EQ(connectors::nodeForces(p, p.weight(), r, v, 0.0)
                         .external[std::size_t(N)][2],
                     -p.weight() * 0.5 * l);
}

TEST(MooringLineWater, DragActsOnTheStretchedLength)
{
    // A straight line stretched 2 % across a uniform current U (normal to
    // it), at rest: each free node's drag is 1/2 rho d Cdn s U^2 with s the
    // stretched segment length, 1.02 l (MoorDyn), not l
    MooringLineParameters p = line(5);
    const double U = 0.8;
    p.currentSurface = p.currentSeabed = Vector3(0.0, U, 0.0);
    const int N = p.segments;
    const double s = 1.02 * p.length / N;
    std::vector<Vector3> r(std::size_t(N + 1)), v(std::size_t(N + 1));
    for (int i = 0; i <= N; ++i) {
        r[std::size_t(i)] = Vector3(i * s, 0.0, -50.0);
        v[std::size_t(i)].setZero();
    }
    connectors::WaterMotion water;
    water.current = true;
    const connectors::NodeForces f
        = connectors::nodeForces(p, p.weight(), r, v, -100.0, &water);
    const double drag
        = 0.5 * p.waterDensity * p.diameter * p.normalDrag * s * U * U;
    for (int i = 1; i < N; ++i) {
        // products of exact inputs: round-off of the ~200 N drag
        EXPECT_NEAR(f.external[std::size_t(i)][1], drag, 1e-10 * drag) << i;
    }
    // the ends' half segments: half of it
    EXPECT_NEAR(f.external[0][1], 0.5 * drag, 1e-10 * drag);
    EXPECT_NEAR(f.external[std::size_t(N)][1], 0.5 * drag, 1e-10 * drag);
}

TEST(MooringLineWater, CurrentProfileIsLinearBetweenSeabedAndSurface)
{
    MooringLineParameters p = line(5);
    p.waterLevel = 10.0;
    p.currentSurface = Vector3(1.0, 0.5, 0.0);
    p.currentSeabed = Vector3(0.2, -0.5, 0.1);
    const double zb = -30.0; // seabed: 40 m below the surface
    // exact: the profile's own definition at a quarter of the depth, and
    // constant beyond its ends
    expectVectorNear(connectors::currentAt(p, -20.0, zb),
                     Vector3(0.4, -0.25, 0.075), 1e-15);
    expectVectorNear(connectors::currentAt(p, 12.0, zb), p.currentSurface, 0.0);
    expectVectorNear(connectors::currentAt(p, -31.0, zb), p.currentSeabed, 0.0);
}

//- Two bodies 99.5 m apart on a horizontal line held still in a uniform
//  current along y for `duration` s (steps of 0.1 s), weightless
connectors::MooringLineOutput heldInCurrent(const MooringLineParameters& p,
                                            const std::vector<Vector3>& flow,
                                            MooringLineState& s)
{
    MooringLine law(p);
    const BodyKinematics A = body(Vector3(101.0, 0.0, -20.0));
    const BodyKinematics B = body(Vector3(0.0, 0.0, -20.0));
    s = law.initialState(A, B, 0.0);
    for (int k = 0; k < 400; ++k) {
        law.advance(s, A, B, 0.1, flow);
    }
    return law.evaluate(s, A, B, 11, flow);
}

TEST(MooringLineWater, TautLineInUniformCurrent)
{
    // Weightless taut line (1 % stretch, 1 MN) across a current of 1 m/s:
    // it settles (40 s; the drag damps the transverse modes in ~1 s) on the
    // drag-deflected shape. Momentum balance: the bodies' loads along the
    // current add up to the total drag, 1/2 rho d Cdn U^2 times the
    // stretched length; the line sags by w_d L^2/(8 T) = 0.077 m, so its
    // segments turn by up to 4 sag/L = 3e-3 rad: the normal part of the
    // current drops by 1 - cos = 5e-6 at most, and the stretched length
    // exceeds the chord by 8/3 (sag/L)^2 = 2e-6
    MooringLineParameters p = line(20);
    p.gravity = 0.0;
    const double U = 1.0;
    p.currentSurface = p.currentSeabed = Vector3(0.0, U, 0.0);
    MooringLineState s;
    const auto out = heldInCurrent(p, {}, s);
    const double loadAlong = out.loads.A.f_W[1] + out.loads.B.f_W[1];
    double stretched = 0.0;
    for (std::size_t k = 0; k + 1 < out.shape.size(); ++k) {
        stretched += (out.shape[k + 1] - out.shape[k]).norm();
    }
    const double morison
        = 0.5 * p.waterDensity * p.diameter * p.normalDrag * U * U * 101.0;
    std::cout << "taut line in current: loads along it " << loadAlong
              << " N, Morison on the chord " << morison
              << " N, largest node speed " << largestSpeed(s) << " m/s\n";
    // at rest (the drag's damping leaves round-off)
    EXPECT_LT(largestSpeed(s), 1e-6);
    // those two effects (measured 3e-6): 1e-5
    EXPECT_NEAR(loadAlong, morison, 1e-5 * morison);
    // the line is pushed along the current, by the sag above at its middle
    EXPECT_NEAR(out.shape[5][1], 0.077, 0.002);
}

TEST(MooringLineWater, FlowAtTheShapePointsEqualsTheSameCurrent)
{
    // flow velocities at the 11 shape points equal to a uniform current:
    // the same run as the current parameter, to round-off (the flow is
    // interpolated between the points: (1 - f) U + f U)
    MooringLineParameters withCurrent = line(20);
    withCurrent.gravity = 0.0;
    withCurrent.currentSurface = withCurrent.currentSeabed
        = Vector3(0.3, 1.0, -0.2);
    MooringLineParameters still = withCurrent;
    still.currentSurface = still.currentSeabed = Vector3::Zero();
    MooringLineState a, b;
    const auto byCurrent = heldInCurrent(withCurrent, {}, a);
    const auto byFlow = heldInCurrent(
        still, std::vector<Vector3>(11, withCurrent.currentSurface), b);
    // states: round-off of 100 m coordinates amplified by 400 steps
    for (std::size_t i = 0; i < a.nodes.size(); ++i) {
        EXPECT_NEAR(a.nodes[i], b.nodes[i], 1e-9) << i;
    }
    // loads: round-off of the 1 MN tension
    expectVectorNear(byFlow.loads.A.f_W, byCurrent.loads.A.f_W, 1e-6);
}

TEST(MooringLineWater, FlowVaryingAlongTheLineEqualsTheCurrentProfile)
{
    // A taut vertical line from the seabed to the surface in a sheared
    // current, against the same line in still water fed with the profile
    // sampled, every step, at the shape points the previous step reported
    // (the flow inputs' contract): the flow, interpolated linearly along
    // the line, equals the profile, linear in z, where the nodes' heights
    // are linear in arc length
    MooringLineParameters profile = line(10);
    profile.EA = 1e9; // 0.1 % stretch, uniform within 1e-5
    profile.seabedContact = true;
    profile.waterLevel = 0.0;
    profile.currentSurface = Vector3(1.0, 0.0, 0.0);
    profile.currentSeabed = Vector3(0.2, 0.3, 0.0);
    MooringLineParameters still = profile;
    still.currentSurface = still.currentSeabed = Vector3::Zero();
    const BodyKinematics A = body(Vector3(0.0, 0.0, 0.1));
    const BodyKinematics B = body(Vector3(0.0, 0.0, -100.0));
    MooringLine byProfile(profile), byFlow(still);
    MooringLineState a = byProfile.initialState(A, B, 0.0);
    MooringLineState b = byFlow.initialState(A, B, 0.0);
    std::vector<Vector3> flow;
    for (int k = 0; k < 50; ++k) {
        flow.clear();
        for (const Vector3& point : byFlow.evaluate(b, A, B, 11).shape) {
            flow.push_back(connectors::currentAt(profile, point[2], -100.0));
        }
        byProfile.advance(a, A, B, 0.1);
        byFlow.advance(b, A, B, 0.1, flow);
    }
    double largest = 0.0, moved = 0.0;
    for (std::size_t i = 0; i < a.nodes.size(); i += 6) {
        for (std::size_t j = i; j < i + 3; ++j) {
            largest = std::max(largest, std::abs(a.nodes[j] - b.nodes[j]));
        }
        moved = std::max(moved, std::hypot(a.nodes[i], a.nodes[i + 1]));
    }
    std::cout << "sheared current: profile against flow inputs, largest "
                 "position difference "
              << largest << " m, the current moved the nodes by " << moved
              << " m\n";
    // The flow lags the line by a step (the nodes move sideways, their
    // heights hardly change) and its interpolation misses the nodes'
    // heights by the stretch's nonuniformity (1e-5 of 100 m, 1e-7 m/s of
    // the current): measured 5e-9 of the motion, 1e-6 asserted
    EXPECT_LT(largest, 1e-6 * moved);
    EXPECT_GT(moved, 1e-3); // the current moved the line
}

TEST(MooringLineWater, LineThroughTheFreeSurface)
{
    // A vertical line (stiff: its nodes at their unstretched heights) from
    // z = -60 m to a fairlead 40 m above the water, the surface half way
    // between two nodes so that the nodes' submerged fractions (a ramp of
    // one segment around each node) add up to the exact wet length. At
    // rest the loads on both ends carry the dry weight above the surface
    // and the submerged weight below it, mu g L - rho g A L_wet, and the
    // start (the statics with that buoyancy) holds still
    MooringLineParameters p = line(20);
    p.EA = 1e12; // stretched by 1e-6: taut (the bottom end pulled up)
    p.freeSurface = true;
    p.waterLevel = -2.5; // node 12 at 0 m (l = 5 m), node 11 at -5 m
    const BodyKinematics A = body(Vector3(0.0, 0.0, 40.0001));
    const BodyKinematics B = body(Vector3(0.0, 0.0, -60.0));
    MooringLine law(p);
    MooringLineState s = law.initialState(A, B, 0.0);
    const auto start = law.evaluate(s, A, B, 11);
    const double wet = 57.5, area = 0.25 * pi * p.diameter * p.diameter;
    const double weight = p.massPerLength * p.gravity * p.length
        - p.waterDensity * p.gravity * area * wet;
    const double carried = -(start.loads.A.f_W[2] + start.loads.B.f_W[2]);
    std::cout << "through the surface: the ends carry " << carried
              << " N, dry above and wet below " << weight << " N\n";
    // the ramp integrates exactly at the unstretched heights; the stretch
    // moves the nodes at the surface by 6e-5 m and their buoyancy by
    // rho g A times that, 5e-3 N
    EXPECT_NEAR(carried, weight, 0.05);
    // all submerged (freeSurface off) the ends carry w L
    MooringLineParameters under = p;
    under.freeSurface = false;
    MooringLine submerged(under);
    const auto wetAll
        = submerged.evaluate(submerged.initialState(A, B, 0.0), A, B, 0);
    // round-off of the 1e6 N tension in both loads
    EXPECT_NEAR(-(wetAll.loads.A.f_W[2] + wetAll.loads.B.f_W[2]),
                p.weight() * p.length, 1e-3);
    // held still: the start is the statics with the free surface
    double change = 0.0;
    for (int k = 0; k < 100; ++k) {
        law.advance(s, A, B, 0.1);
        change = std::max(change,
                          std::abs(law.evaluate(s, A, B, 0).fairleadTension
                                   - start.fairleadTension));
    }
    // Newton's round-off at rest (as the reference lines' start)
    EXPECT_LT(change, 1e-6 * start.fairleadTension);
    // the tension along a hanging line rises with height by the local
    // weight per length: at the shape points (every 10 m, on nodes)
    // against the bottom end's (anchorTension, F_B pulls B up) plus the
    // weight below each point; the shape's tensions interpolate segment
    // tensions, exact for a tension linear along the line and at nodes
    // (the surface lies half way between two)
    const double Tbottom = start.anchorTension;
    for (int k = 0; k < 11; ++k) {
        const double z = 40.0 - 10.0 * k;
        const double below = z + 60.0;
        const double wetBelow = std::min(below, wet);
        const double T = Tbottom + p.massPerLength * p.gravity * below
            - p.waterDensity * p.gravity * area * wetBelow;
        // round-off of EA times a strain, 1e12 x 4e-15 (and the surface's
        // 5e-3 N above)
        EXPECT_NEAR(start.shapeTension[std::size_t(k)], T, 0.05) << k;
    }
    EXPECT_EQ(start.shapeTension.front(), start.fairleadTension);
    EXPECT_EQ(start.shapeTension.back(), start.anchorTension);
}

TEST(MooringLineWater, NewParametersAreChecked)
{
    MooringLineParameters p = line(5);
    p.seabedFriction = -0.1;
    expectThrowWithMessage<connectors::ParameterError>(
        [&] { MooringLine law(p); },
        "mooringLine: parameter seabedFriction = -0.1 is out of range "
        "(allowed: finite and >= 0)");
    p = line(5);
    p.frictionVelocity = 0.0;
    expectThrowWithMessage<connectors::ParameterError>(
        [&] { MooringLine law(p); },
        "mooringLine: parameter frictionVelocity = 0 m/s is out of range "
        "(allowed: finite and > 0)");
    p = line(5);
    p.currentSeabed[1] = std::nan("");
    expectThrowWithMessage<connectors::ParameterError>(
        [&] { MooringLine law(p); },
        "mooringLine: parameter current.seabed[2] = nan m/s is out of range "
        "(allowed: finite)");
}

} // namespace
