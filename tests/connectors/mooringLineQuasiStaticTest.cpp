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
    // (With the clump on the seabed the penalty spring carries its weight
    // on one node of l d: the clump sinks deeper as l shrinks, centimetres
    // at N = 80, and the start shape leaves the catenary's as N grows, so
    // that case is no measure of the law.)
    for (const int N : {80, 160}) {
        const Errors e = startAgainstCatenary(N, true, Vector3(76, 0, 20));
        EXPECT_LT(e.fairlead, 4e-4) << N;
        EXPECT_LT(e.anchor, 4e-4) << N;
    }
}

} // namespace
