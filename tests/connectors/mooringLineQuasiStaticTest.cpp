// The dynamic line's start shape (the static equilibrium of its lumped
// masses) against the quasi-static catenary law for the same line of
// sections with a clump weight: the fairlead and anchor tensions converge
// to the catenary's as the segments shrink. The catenary takes the
// submerged weights the dynamic line computes: w = (mu - rho pi d^2/4) g
// per section, J = (m - rho V) g per point.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "LawTestSupport.hpp"
#include "catenary/Catenary.hpp"
#include "mooringLine/MooringLine.hpp"

namespace {

using namespace lawTest;
using connectors::Catenary;
using connectors::CatenaryParameters;
using connectors::CatenarySection;
using connectors::LineSection;
using connectors::MooringLine;
using connectors::MooringLineParameters;

//- A chain (from the anchor) of 45 m and a rope of 35 m, N/2 segments
//  each, a clump weight of 1500 kg and 0.2 m3 between them, under water
MooringLineParameters chainAndRope(int N, bool seabed)
{
    MooringLineParameters p;
    p.seabedContact = seabed;
    p.diameter = 0.1;
    p.massPerLength = 90.0;
    p.EA = 6e8;
    p.length = 45.0;
    p.segments = N / 2;
    LineSection rope = p.section(0);
    rope.length = 35.0;
    rope.massPerLength = 10.0;
    rope.EA = 5e7;
    rope.joint = {1500.0, 0.2};
    p.sections = {rope};
    p.waterLevel = 100.0; // the whole line under water
    return p;
}

CatenaryParameters quasiStatic(const MooringLineParameters& p)
{
    const auto weight = [&](const LineSection& s) {
        return (s.massPerLength
                - p.waterDensity * 0.25 * pi * s.diameter * s.diameter)
            * p.gravity;
    };
    CatenaryParameters c;
    const LineSection first = p.section(0);
    c.line.length = first.length;
    c.line.EA = first.EA;
    c.line.weight = weight(first);
    c.line.seabedContact = p.seabedContact;
    for (const LineSection& s : p.sections) {
        CatenarySection k;
        k.length = s.length;
        k.EA = s.EA;
        k.weight = weight(s);
        k.jointWeight
            = (s.joint.mass - p.waterDensity * s.joint.volume) * p.gravity;
        c.line.sections.push_back(k);
    }
    return c;
}

struct Errors {
    double fairlead, anchor;
};

Errors startAgainstCatenary(int N, bool seabed, const Vector3& fairlead)
{
    const MooringLineParameters p = chainAndRope(N, seabed);
    const BodyKinematics A = body(fairlead), B = body(Vector3::Zero());
    MooringLine dynamic(p);
    const auto d = dynamic.evaluate(dynamic.initialState(A, B, 0.0), A, B, 0);
    const auto c = Catenary(quasiStatic(p)).evaluate(A, B, nullptr, 0);
    std::cout << (seabed ? "seabed" : "no seabed") << ", N = " << N
              << ": fairlead tension " << d.fairleadTension << " N, catenary "
              << c.fairleadTension << " N; anchor " << d.anchorTension
              << " N, catenary " << c.anchorTension << " N ("
              << regimeName(c.solution.regime) << ", grounded "
              << c.solution.groundedLength << " m)\n";
    return {std::abs(d.fairleadTension / c.fairleadTension - 1.0),
            std::abs(d.anchorTension / c.anchorTension - 1.0)};
}

TEST(MooringLineQuasiStatic, StartTensionsConvergeToTheCatenaryOfSections)
{
    // Suspended (no seabed): the lumped masses' statics differ from the
    // continuous line by O(l^2). Measured at N = 20, 40, 80: fairlead
    // 5.7e-4, 1.4e-4, 3.7e-5 below the catenary's 38149.8 N, anchor 6.3e-4,
    // 1.6e-4, 4.0e-5 below its 27309.1 N: each halving divides the error
    // by 4, towards the catenary of sections
    Errors last {1.0, 1.0};
    for (const int N : {20, 40, 80}) {
        const Errors e = startAgainstCatenary(N, false, Vector3(60, 0, 30));
        EXPECT_LT(e.fairlead, 0.35 * last.fairlead) << N;
        EXPECT_LT(e.anchor, 0.35 * last.anchor) << N;
        last = e;
    }
    EXPECT_LT(last.fairlead, 6e-5);
    EXPECT_LT(last.anchor, 6e-5);
}

TEST(MooringLineQuasiStatic, StartTensionsWithTouchdownNearTheCatenary)
{
    // A third of the chain on the seabed, the clump lifted. The dynamic
    // line's seabed is a penalty spring (3e6 Pa/m): the grounded chain
    // sinks w/(kb d) = 2.7 mm into it, which the catenary's rigid seabed
    // does not. Measured, fairlead: 1.4e-4 and 2.3e-4 above the
    // catenary's 83233.9 N at N = 80 and 160 (anchor 1.4e-4, 2.4e-4): not
    // the discretisation's O(l^2) but the penalty's offset; 4e-4 allowed.
    // (The clump on the seabed: the tests below.)
    for (const int N : {80, 160}) {
        const Errors e = startAgainstCatenary(N, true, Vector3(76, 0, 20));
        EXPECT_LT(e.fairlead, 4e-4) << N;
        EXPECT_LT(e.anchor, 4e-4) << N;
    }
}

//- 60 m of chain (from the anchor, 80 kg/m, 0.1 m) and 60 m of rope
//  (14 kg/m, 0.08 m), `perSection` segments each, a clump weight of
//  2500 kg and 0.3 m3 (21.5 kN in water) at their joint, on a seabed of
//  stiffness kb [Pa/m]
MooringLineParameters chainRopeAndClump(int perSection, double kb)
{
    MooringLineParameters p = chainAndRope(2 * perSection, true);
    p.length = 60.0;
    p.massPerLength = 80.0;
    p.seabedStiffness = kb;
    LineSection& rope = p.sections[0];
    rope.length = 60.0;
    rope.massPerLength = 14.0;
    rope.diameter = 0.08;
    rope.segments = perSection;
    rope.joint = {2500.0, 0.3};
    return p;
}

//- The start shape of chainRopeAndClump with the fairlead 30 m up at
//  span x against the catenary: the clump's depth below the seabed and
//  its horizontal offset [m], the fairlead tension's relative error
struct ClumpErrors {
    double sink, x, fairlead;
};

ClumpErrors clumpAgainstCatenary(int perSection, double kb, double x)
{
    const MooringLineParameters p = chainRopeAndClump(perSection, kb);
    const BodyKinematics A = body(Vector3(x, 0, 30)), B = body(Vector3::Zero());
    MooringLine dynamic(p);
    const auto d = dynamic.evaluate(dynamic.initialState(A, B, 0.0), A, B, 0);
    const auto c = Catenary(quasiStatic(p)).evaluate(A, B, nullptr, 0);
    const ClumpErrors e {c.joints[0][2] - d.joints[0][2],
                         d.joints[0][0] - c.joints[0][0],
                         d.fairleadTension / c.fairleadTension - 1.0};
    std::cout << "span " << x << " m, kb " << kb << " Pa/m, N = " << perSection
              << " a section: the clump " << e.sink << " m deep, " << e.x
              << " m along; fairlead tension " << d.fairleadTension
              << " N, catenary " << c.fairleadTension << " N (" << e.fairlead
              << "); grounded " << d.groundedLength << " m, catenary "
              << c.solution.groundedLength << " m\n";
    return e;
}

//- Observed order of an error that falls from `coarse` at segment length
//  L to `fine` at L/ratio
double observedOrder(double coarse, double fine, double ratio = 2.0)
{
    return std::log(std::abs(coarse / fine)) / std::log(ratio);
}

TEST(MooringLineQuasiStatic, AClumpOnTheSeabedConvergesAtSecondOrder)
{
    // Span 110.5 m: the catenary's touchdown point is the joint, the chain
    // lies on the seabed and the rope holds part of the clump. A seabed of
    // 3e9 Pa/m: its penalty offset w/(kb d) = 2.4e-6 m moves the tension
    // by about 3e-7 (measured at 3e6 Pa/m: +3.3e-4), 2 % of the
    // discretisation's error at N = 160, so the error measured is the
    // discretisation's. Measured: fairlead -9.5e-4, -2.4e-4, -5.9e-5,
    // -1.45e-5 off the catenary's 7914.86 N, the clump 6.7e-7, 1.7e-7,
    // 4.1e-8, 1.0e-8 m along: orders 2.00, 2.01, 2.03 and 2.00, 2.01,
    // 2.02. Order above 1.9 required: a first-order term (a contact width
    // that moves with l, as before) shows as 1 at these N.
    ClumpErrors last {};
    for (const int N : {20, 40, 80, 160}) {
        const ClumpErrors e = clumpAgainstCatenary(N, 3e9, 110.5);
        // the clump rests as deep as the chain beside it, w/(kb d) =
        // 2.35e-6 m, less what the rope holds (2.2e-6 m measured)
        EXPECT_LT(e.sink, 2.4e-6) << N;
        EXPECT_GT(e.sink, 0.0) << N;
        if (N > 20) {
            const double tension = observedOrder(last.fairlead, e.fairlead);
            const double along = observedOrder(last.x, e.x);
            std::cout << "observed order at N = " << N << ": fairlead tension "
                      << tension << ", clump's place " << along << "\n";
            EXPECT_GT(tension, 1.9) << N;
            EXPECT_GT(along, 1.9) << N;
        }
        last = e;
    }
    EXPECT_LT(std::abs(last.fairlead), 2e-5);
}

TEST(MooringLineQuasiStatic, AClumpSinksAsFarWhateverTheSegments)
{
    // The default seabed (3e6 Pa/m): the clump rests where the chain
    // does, w/(kb d) = 2.35 mm, less what the rope holds, at any N.
    // Measured 2.197, 2.235, 2.255, 2.265 mm at N = 20, 40, 80, 160 a
    // section (before its own contact area, carried by the joint node's
    // l d alone: 2.7, 5.2, 10.0, 16.7 cm, the fairlead tension +0.31 %
    // to +2.7 %). 5 % of spread allowed (3 % measured, the rope's share
    // resolved better). The fairlead tension: the discretisation's error
    // (above) plus the penalty's offset, +3.3e-4: measured -6.2e-4,
    // +9.9e-5, +2.8e-4, +3.3e-4 (before: +3.1e-3 to +2.7e-2); 1e-3
    // allowed
    double first = 0.0;
    for (const int N : {20, 40, 80, 160}) {
        const ClumpErrors e = clumpAgainstCatenary(N, 3e6, 110.5);
        first = N == 20 ? e.sink : first;
        EXPECT_LT(e.sink, 2.35e-3) << N;
        EXPECT_NEAR(e.sink, first, 0.05 * first) << N;
        EXPECT_LT(std::abs(e.fairlead), 1e-3) << N;
    }
}

TEST(MooringLineQuasiStatic, LineNodesInContactConvergeAtSecondOrder)
{
    // Shorter spans: the clump and part of the rope on the seabed, the
    // touchdown point in the rope. Where it falls between two nodes
    // changes with N, so the error is not monotone (span 100 m: -3.3e-3,
    // -6.8e-4, -3.7e-5, +8.0e-5 at N = 20 to 160; span 104 m: -1.5e-3,
    // -1.1e-4, +1.7e-4, -2.8e-5) but its envelope falls at second order:
    // from N = 20 to 160 measured orders 1.79 and 1.92 (at N = 320 and
    // 480, span 100 m: -1.2e-5, +6.2e-6). Above 1.7 required over the
    // eightfold refinement; a first-order error would show about 1. Seabed
    // as in the test above (3e9 Pa/m)
    for (const double x : {100.0, 104.0}) {
        const ClumpErrors coarse = clumpAgainstCatenary(20, 3e9, x);
        for (const int N : {40, 80}) {
            clumpAgainstCatenary(N, 3e9, x);
        }
        const ClumpErrors fine = clumpAgainstCatenary(160, 3e9, x);
        const double order = observedOrder(coarse.fairlead, fine.fairlead, 8.0);
        std::cout << "span " << x << " m: observed order from N = 20 to 160 "
                  << order << "\n";
        EXPECT_GT(order, 1.7) << x;
        EXPECT_LT(std::abs(fine.fairlead), 1e-4) << x;
        EXPECT_LT(fine.sink, 2.4e-6) << x;
    }
}

} // namespace
