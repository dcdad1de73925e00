// The energy account of the dynamic line (connectors/mooringLine/
// LineEnergy.hpp): over a slack-taut cycle the work done on the line (its
// ends, the water, the added mass) equals the change of its kinetic and
// potential energy plus the energy it dissipated, at the tutorials'
// coupling steps, with the trapezoidal rule and CVODE; the account against
// quantities computed without it (the kinetic energy's formula, the
// sampled power of the loads and the dissipated power); the water's work
// on a line held in a current against the Morison drag; sections against
// the uniform line.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "LawTestSupport.hpp"
#include "MooringLineReferences.hpp"
#include "mooringLine/MooringLine.hpp"

namespace {

using namespace lawTest;
using connectors::LineEnergy;
using connectors::LinePoint;
using connectors::MooringLine;
using connectors::MooringLineParameters;
using connectors::MooringLineState;
using connectors::references::lab;
using connectors::references::ReferenceLine;
using connectors::references::Snap;

//- What the account leaves unexplained over the energy through the
//  fairlead: its work less the change of kinetic + potential energy (the
//  outputs) less its dissipated energy
double closure(const Snap& r)
{
    return r.accountImbalance / r.throughput;
}

void print(const char* name, double h, const Snap& r)
{
    std::cout << name << " at " << h << " s: fairlead " << r.account.fairlead
              << " J, added mass " << r.account.addedMass << " J, water "
              << r.account.water << " J; change " << r.accountChange
              << " J; dissipated " << r.account.dissipated() << " J (drag "
              << r.account.dragTotal() << ", seabed " << r.account.seabedTotal()
              << ", axial " << r.account.axialTotal() << "); closure "
              << closure(r) << " of " << r.throughput
              << " J; loads' sampled work " << r.work
              << " J, sampled dissipation " << r.dissipated << " J; peak "
              << r.peak << " N\n";
}

//- The dynamic line of tutorials/mooredFloatingObjectDynamic (constant/
//  dynamicMeshDict: 1.1 m, EA 5000 N, 0.117 kg/m, 4.4 mm, on the floor,
//  10 segments; CVODE at 1e-9, 1e-11 there), its fairlead 0.9 m from the
//  anchor and 0.3 m above it: slack, part of it on the floor
ReferenceLine tutorialLine(bool cvode)
{
    MooringLineParameters p;
    p.length = 1.1;
    p.EA = 5000.0;
    p.axialDamping = 10.0;
    p.massPerLength = 0.117;
    p.diameter = 0.0044;
    p.waterDensity = 998.2;
    p.normalDrag = 1.2;
    p.tangentialDrag = 0.05;
    p.normalAddedMass = 1.0;
    p.seabedContact = true;
    p.segments = 10;
    if (cvode) {
        p.integrator = MooringLineParameters::Integrator::cvode;
        p.relativeTolerance = 1e-9;
        p.absoluteTolerance = 1e-11;
    }
    return {"tutorial line", p, Vector3(0.95, 0.95, 0.0),
            Vector3(0.95 - 0.9, 0.95, 0.3)};
}

TEST(MooringLineEnergy, SlackTautCycleClosesTheBalance)
{
    // The lab chain (N = 20) with its fairlead surging 0.112 m at 1 Hz,
    // ramped in over the first second, for 2 s: it lifts off the seabed
    // and snaps taut (9.4 N against 0.56 N at rest). Coupling steps: the
    // tutorials' largest, 0.01 s (maxDeltaT of the moored tutorials), their
    // first, 1 ms, and 0.1 ms.
    for (const double h : {1e-2, 1e-3, 1e-4}) {
        const Snap r
            = connectors::references::slackTaut(lab(20), 0.112, 1.0, h, 2.0);
        print("lab chain", h, r);
        ASSERT_TRUE(r.finite) << h;
        EXPECT_GT(r.peak, 10.0 * 0.56) << h; // slack, then taut
        // Measured -5.1e-6 (0.01 s), -5.5e-7 (1 ms), 1.2e-6 (0.1 ms): what
        // Newton's last correction leaves (each step's residual does work
        // below 1e-4 of the step's; LineEnergy.hpp, MooringLineTrapezoid.cpp)
        EXPECT_LT(std::abs(closure(r)), 1e-4) << h;
        // the anchor is held: it does no work, to the bit
        EXPECT_EQ(r.account.anchor, 0.0) << h;
        // the water is still: no work; the added mass does 6.5e-5 of the
        // throughput (its own balance term, not a loss)
        EXPECT_EQ(r.account.water, 0.0) << h;
        EXPECT_GT(r.account.addedMass, 0.0) << h;
        EXPECT_LT(r.account.addedMass, 1e-3 * r.throughput) << h;
        for (const double d : {r.account.dragTotal(), r.account.seabedTotal(),
                               r.account.axialTotal()}) {
            EXPECT_GT(d, 0.0) << h;
        }
        // the kinetic energy output against the harness's own formula
        // (v' M v / 2 from the parameters' masses and the nodes' tangents):
        // both changes share the potential energy, so round-off
        EXPECT_NEAR(r.accountChange, r.change, 1e-12 * r.throughput) << h;
        if (h == 1e-4) {
            // Quantities without the account converge to it: the loads'
            // power sampled at the coupling steps (measured -6.5e-5 of the
            // throughput) and the dissipated power's trapezoidal sum
            // (1.2e-5) at 0.1 ms
            EXPECT_NEAR(r.work, r.account.fairlead, 1e-4 * r.throughput);
            EXPECT_NEAR(r.dissipated, r.account.dissipated(),
                        1e-4 * r.throughput);
        }
    }
}

TEST(MooringLineEnergy, TheTutorialLineClosesItsBalance)
{
    // The moored tutorial's line surging 0.16 m at 1 Hz from 0.9 m off its
    // anchor: slack on the floor at 0.74 m, taut at 1.06 m (0.15 %
    // stretch, 7 N against 1 N of weight), at its time steps (0.01 and
    // 1 ms), with its integrator (CVODE at 1e-9, 1e-11) and the default
    // one. CVODE's account is the trapezoidal sum of the rates over its
    // internal steps.
    for (const bool cvode : {false, true}) {
        for (const double h : {1e-2, 1e-3}) {
            const ReferenceLine line = tutorialLine(cvode);
            const Snap r
                = connectors::references::slackTaut(line, 0.16, 1.0, h, 2.0);
            print(cvode ? "tutorial line, CVODE" : "tutorial line", h, r);
            ASSERT_TRUE(r.finite) << h;
            EXPECT_GT(r.peak, 3.0) << h; // taut (1.1 N at rest)
            // Measured: trapezoidal rule 2.0e-6 (0.01 s), 2.0e-6 (1 ms);
            // CVODE 3.6e-6, 1.6e-6
            EXPECT_LT(std::abs(closure(r)), 1e-4) << cvode << " " << h;
            EXPECT_GT(r.account.seabedTotal(), 0.0) << cvode << " " << h;
        }
    }
}

TEST(MooringLineEnergy, TheWaterDoesTheDragsWorkOnALineHeldInACurrent)
{
    // A weightless taut line (101 m between two bodies held still, 1 MN)
    // across a current of 1 m/s, settled (mooringLineWaterTest: at rest to
    // 1e-6 m/s after 40 s): for 10 s more the water does work at the rate
    // the drag dissipates it, the Morison drag of the line times U
    // (1/2 rho d Cdn U^2 times the chord: 3e-6 below the stretched,
    // deflected line's, mooringLineWaterTest), and the ends none
    MooringLineParameters p = lab(20).p;
    p.length = 100.0;
    p.EA = 1e8;
    p.diameter = 0.1;
    p.massPerLength = 80.0;
    p.seabedContact = false;
    p.gravity = 0.0;
    const double U = 1.0;
    p.currentSurface = p.currentSeabed = Vector3(0.0, U, 0.0);
    MooringLine law(p);
    const BodyKinematics A = body(Vector3(101.0, 0.0, -20.0));
    const BodyKinematics B = body(Vector3(0.0, 0.0, -20.0));
    MooringLineState s = law.initialState(A, B, 0.0);
    for (int k = 0; k < 400; ++k) {
        law.advance(s, A, B, 0.1);
    }
    LineEnergy e;
    const auto before = law.evaluate(s, A, B, 0);
    for (int k = 0; k < 100; ++k) {
        law.advance(s, A, B, 0.1);
        e += law.stepEnergy();
    }
    const auto after = law.evaluate(s, A, B, 0);
    const double morison
        = 0.5 * p.waterDensity * p.diameter * p.normalDrag * U * U * 101.0;
    const double change = after.kineticEnergy + after.loads.potentialEnergy
        - before.kineticEnergy - before.loads.potentialEnergy;
    std::cout << "line in a current, 10 s: water " << e.water << " J, drag "
              << e.dragTotal() << " J, Morison drag times U times 10 s "
              << morison * U * 10.0 << " J, unexplained "
              << (e.water - change - e.dissipated()) / e.water << "\n";
    EXPECT_EQ(e.fairlead, 0.0); // the bodies are held, to the bit
    EXPECT_EQ(e.anchor, 0.0);
    // the state hardly changes (node speeds below 1e-6 m/s): the water's
    // work is dissipated (measured: the balance to 2e-14 of it)
    EXPECT_NEAR(e.water - change, e.dissipated(), 1e-9 * e.water);
    EXPECT_NEAR(e.water, e.dragTotal(), 1e-9 * e.water);
    // the two effects of mooringLineWaterTest (measured 3e-6): 1e-5
    EXPECT_NEAR(e.water, morison * U * 10.0, 1e-5 * e.water);
}

//- The lab chain in two sections of 10 segments, with the point `joint`
//  at their joint
MooringLineParameters twoSections(const LinePoint& joint)
{
    MooringLineParameters p = lab(20).p;
    p.segments = 10;
    p.length = 0.6;
    p.sections = {connectors::references::sectionOf(
        connectors::references::labChain, 0.6, 10, joint)};
    return p;
}

TEST(MooringLineEnergy, SectionsAddUpToTheLine)
{
    // Two equal sections without a point are the uniform line (to 1e-11,
    // mooringLineSectionsTest): their accounts add up to the uniform
    // line's. The snaps carry round-off into Newton's choices (a second
    // correction or not): measured 1.3e-5 of the throughput apart
    ReferenceLine uniform = lab(20), split = lab(20);
    split.p = twoSections({});
    const Snap one
        = connectors::references::slackTaut(uniform, 0.112, 1.0, 1e-3, 2.0);
    const Snap two
        = connectors::references::slackTaut(split, 0.112, 1.0, 1e-3, 2.0);
    ASSERT_EQ(two.account.drag.size(), 2u);
    const double round = 1e-4 * one.throughput;
    EXPECT_NEAR(two.account.fairlead, one.account.fairlead, round);
    EXPECT_NEAR(two.account.dragTotal(), one.account.dragTotal(), round);
    EXPECT_NEAR(two.account.seabedTotal(), one.account.seabedTotal(), round);
    EXPECT_NEAR(two.account.axialTotal(), one.account.axialTotal(), round);
    EXPECT_NEAR(two.account.addedMass, one.account.addedMass, round);
    // the lower section lies on the seabed, the upper one lifts off it
    EXPECT_GT(two.account.seabed[0], two.account.seabed[1]);
    // With a clump weight at the joint, seabed friction and a current the
    // balance closes as well, the water doing work
    ReferenceLine clumped = lab(20);
    clumped.p = twoSections({0.02, 2e-6, 1e-4, 0.5});
    clumped.p.seabedFriction = 0.5;
    clumped.p.currentSurface = Vector3(0.05, 0.02, 0.0);
    const Snap c
        = connectors::references::slackTaut(clumped, 0.112, 1.0, 1e-3, 2.0);
    print("two sections, clump, friction, current", 1e-3, c);
    ASSERT_TRUE(c.finite);
    EXPECT_NE(c.account.water, 0.0);
    for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_GT(c.account.drag[k], 0.0) << k;
        EXPECT_GT(c.account.axial[k], 0.0) << k;
    }
    EXPECT_GT(c.account.seabed[0], 0.0);
    // Measured -3.6e-6
    EXPECT_LT(std::abs(closure(c)), 1e-4);
}

} // namespace
