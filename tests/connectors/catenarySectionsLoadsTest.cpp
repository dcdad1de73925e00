// The loads and outputs of a catenary of sections (CatenaryLine::sections,
// the lines of CatenarySectionsLines.hpp): F = -grad(potentialEnergy), the
// joints' tensions and positions, and the refusals: two touchdown points,
// the sections' parameters by name.
#include <cmath>
#include <string>
#include <vector>

#include "CatenarySectionsLines.hpp"
#include "LawTestSupport.hpp"
#include "catenary/Catenary.hpp"
#include "common/ConnectorError.hpp"

namespace {

using namespace lawTest;
using namespace catenarySectionsTest;
using connectors::Catenary;
using connectors::CatenaryOutput;
using connectors::CatenaryRegime;
using connectors::CatenarySolution;
using connectors::solveCatenary;

TEST(CatenarySections, ForceIsMinusTheEnergyGradient)
{
    // Without friction the line is conservative: F = -grad E at both
    // ends. Central differences over 1e-4 m: truncation h^2 E''' and the
    // Gauss quadrature of the weight's potential (1e-10 relative) give
    // ~1e-6 of the tension; 1e-4 as in the uniform line's test
    const CatenaryLine lines[] = {chainRope(2e4, true), chainRope(2e4, false),
                                  chainRope(-3.5e4, true)};
    for (const CatenaryLine& line : lines) {
        const Catenary law(mooring(line));
        const BodyKinematics A
            = body(Vector3(95, 30, 43), rotation(0.2, Vector3(1, 1, 0)));
        const BodyKinematics B
            = body(Vector3(0, 0, line.seabedContact ? 0 : -10));
        const CatenaryOutput out = law.evaluate(A, B, nullptr, 0);
        // -dE/dr_i with the body `moved` (A: 0, B: 1) displaced along i
        const auto minusGradient = [&](int moved, int i) {
            BodyKinematics k[2][2] = {{A, B}, {A, B}};
            k[0][moved].p_WKo_W[i] += 1e-4;
            k[1][moved].p_WKo_W[i] -= 1e-4;
            return (law.evaluate(k[1][0], k[1][1]).potentialEnergy
                    - law.evaluate(k[0][0], k[0][1]).potentialEnergy)
                / 2e-4;
        };
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(minusGradient(0, i), out.loads.A.f_W[i],
                        1e-4 * out.fairleadTension)
                << regimeName(out.solution.regime) << " " << i;
            if (!(line.seabedContact && i == 2)) { // the seabed moves with B
                EXPECT_NEAR(minusGradient(1, i), out.loads.B.f_W[i],
                            1e-4 * out.fairleadTension)
                    << regimeName(out.solution.regime) << " " << i;
            }
        }
        // off the seabed the bodies carry the whole weight
        if (out.solution.groundedLength == 0.0) {
            const Vector3 sum = out.loads.A.f_W + out.loads.B.f_W;
            const double W
                = 700.0 * 60.0 + 50.0 * 60.0 + line.sections[0].jointWeight;
            expectVectorNear(sum, -W * Vector3::UnitZ(),
                             1e-9 * out.fairleadTension);
        }
        ASSERT_EQ(out.joints.size(), 1u);
        ASSERT_EQ(out.sectionUpperTension.size(), 2u);
        EXPECT_NEAR(out.sectionUpperTension[1], out.fairleadTension,
                    1e-9 * out.fairleadTension);
        EXPECT_NEAR(out.sectionLowerTension[0], out.anchorTension,
                    1e-9 * out.fairleadTension);
    }
}

TEST(CatenarySections, OutputsGiveTheJointsTensionsAndPositions)
{
    // The law's outputs for a turned and moved fairlead body, suspended,
    // with touchdown and with a buoy lifting the joint (60 m of chain, 60 m
    // of rope): the tension at the sections' ends at the joint is the
    // closed form T = sqrt(H^2 + V^2), V the fairlead's less the rope's
    // weight (above the joint) and less the point's too (below it), and the
    // tension along the line there (catenaryTension, above the joint; 1 nm
    // below it); the joint in the global frame is the law's profile point
    // at its arc placed in the plane of P and Q, and the sixth of 11 shape
    // points (12 m of arc apart: 60 m from the anchor)
    struct Case {
        CatenaryLine line;
        double x, z; // spans from Q to P [m]
    };
    // the regimes of the tests against the reference above
    const Case cases[] = {{chainRope(2e4, false), 105.0, 30.0},
                          {chainRope(2e4, true), 108.0, 40.0},
                          {chainRope(-3.5e4, true), 100.0, 30.0}};
    for (const Case& c : cases) {
        const CatenaryLine& line = c.line;
        const Catenary law(mooring(line));
        const BodyKinematics B = body(Vector3(3, -2, -10));
        const Vector3 Q0 = B.p_WKo_W + Vector3(0.5, 0.2, 0.0);
        const Matrix3 R_A = rotation(0.2, Vector3(1, 1, 0));
        const Vector3 P0
            = Q0 + c.x * Vector3(0.6, 0.8, 0.0) + c.z * Vector3::UnitZ();
        const BodyKinematics A
            = body(Vector3(P0 - R_A * Vector3(2.0, -1.0, -3.0)), R_A);
        const CatenaryOutput out = law.evaluate(A, B, nullptr, 11);
        const CatenarySolution& s = out.solution;
        const double T = out.fairleadTension, J = line.sections[0].jointWeight;
        ASSERT_EQ(out.sectionLowerTension.size(), 2u);
        ASSERT_EQ(out.sectionUpperTension.size(), 2u);
        ASSERT_EQ(out.joints.size(), 1u);
        // the joint hangs (suspended pieces on both sides): round-off only
        const double above = s.V - 50.0 * 60.0, below = above - J;
        EXPECT_NEAR(out.sectionLowerTension[1], std::hypot(s.H, above),
                    1e-12 * T);
        EXPECT_NEAR(out.sectionUpperTension[0], std::hypot(s.H, below),
                    1e-12 * T);
        EXPECT_NEAR(out.sectionLowerTension[1],
                    connectors::catenaryTension(line, s, 60.0), 1e-12 * T);
        // 1e-9 m down the chain: its tension changes by w 1e-9 = 7e-7 N
        EXPECT_NEAR(out.sectionUpperTension[0],
                    connectors::catenaryTension(line, s, 60.0 - 1e-9),
                    1e-9 * T);
        // the profile plane: from Q, e_h horizontal towards P, z up
        const Vector3 P = A.p_WKo_W + A.R_WK * Vector3(2.0, -1.0, -3.0);
        const Vector3 Q = B.p_WKo_W + B.R_WK * Vector3(0.5, 0.2, 0.0);
        const Vector3 chord = P - Q;
        const double x = std::hypot(chord[0], chord[1]);
        const Vector3 eH(chord[0] / x, chord[1] / x, 0.0);
        const Eigen::Vector2d j
            = connectors::catenaryPoint(line, s, x, chord[2], 60.0);
        const Vector3 joint = Q + j[0] * eH + j[1] * Vector3::UnitZ();
        expectVectorNear(out.joints[0], joint, 1e-12 * 120.0);
        expectVectorNear(out.shape[5], out.joints[0], 1e-12 * 120.0);
        std::cout << regimeName(s.regime) << ": T at the joint "
                  << out.sectionUpperTension[0] << " N below, "
                  << out.sectionLowerTension[1] << " N above, joint at ("
                  << joint.transpose() << ") m\n";
    }
    // a uniform line is one section from the anchor to the fairlead
    const Catenary uniform(mooring(uniformLine(120.0, 5e8, 700.0, true, 0.0)));
    const CatenaryOutput u = uniform.evaluate(
        body(Vector3(95, 30, 43), rotation(0.2, Vector3(1, 1, 0))),
        body(Vector3::Zero()), nullptr, 0);
    EXPECT_EQ(u.sectionLowerTension, std::vector<double> {u.anchorTension});
    EXPECT_EQ(u.sectionUpperTension, std::vector<double> {u.fairleadTension});
    EXPECT_TRUE(u.joints.empty());
}

//- The call throws UndefinedStateError with each of `parts` in its message
template <class Call>
void expectRefusal(Call&& call, const std::vector<std::string>& parts)
{
    try {
        call();
        ADD_FAILURE() << "no exception";
    } catch (const connectors::UndefinedStateError& e) {
        for (const std::string& part : parts) {
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
                << e.what();
        }
    }
}

TEST(CatenarySections, TwoTouchdownsAreRefused)
{
    // a buoy on the grounded chain would lift it off the seabed between
    // two touchdown points
    CatenaryLine l = chainRope(0.0, true);
    CatenarySection chain;
    chain.length = 60.0;
    chain.EA = 5e8;
    chain.weight = 700.0;
    chain.jointWeight = -500.0;
    l.sections.insert(l.sections.begin(), chain); // chain, chain, rope
    l.sections[1].jointWeight = 0.0;
    expectRefusal([&] { solveCatenary(l, 120.0, 20.0); },
                  {"the buoy at joint 1 (between sections 1 and 2) (net "
                   "weight -500 N, allowed >= 0 on the seabed) lies on the "
                   "seabed below the touchdown point",
                   "touch the seabed twice"});
    // a buoyant first section would rise from the seabed as well
    CatenaryLine buoyant = chainRope(0.0, true);
    buoyant.weight = -10.0;
    buoyant.sections[0].jointWeight = 4e4; // pins the joint to the seabed
    expectRefusal([&] { solveCatenary(buoyant, 110.0, 20.0); },
                  {"section 1 (weight -10 N/m, allowed > 0 on the seabed)"});
    // a buoy holding up a long heavy rope whose sag would go through the
    // seabed between the buoy and the fairlead
    CatenaryLine sag = chainRope(-2e4, true);
    sag.length = 30.0;
    sag.sections[0].length = 90.0;
    sag.sections[0].weight = 200.0;
    expectRefusal([&] { solveCatenary(sag, 110.0, 20.0); },
                  {"catenary: the line would reach 1.4393",
                   "m below the seabed at 65.119",
                   "m from the anchor (section 2), held up on both sides: "
                   "it would touch the seabed twice"});
    EXPECT_EQ(solveCatenary(sag, 116.0, 20.0).regime,
              CatenaryRegime::touchdown); // taut enough to clear it
    // a slack line of sections folded on one vertical
    expectThrowWithMessage<connectors::UndefinedStateError>(
        [&] { solveCatenary(chainRope(2e4, false), 0.0, 10.0); },
        "catenary: the fairlead is straight above or below the anchor "
        "(horizontal span 0 m, vertical span 10 m) and the line of sections "
        "is slack there: a folded line of sections is not solved by the "
        "quasi-static catenary");
}

TEST(CatenarySections, ParametersAreCheckedByName)
{
    CatenaryParameters p = mooring(chainRope(2e4, true));
    p.line.sections[0].length = -1.0;
    expectThrowWithMessage<connectors::ParameterError>(
        [&] { Catenary law(p); },
        "catenary: parameter section2.unstretchedLength = -1 m is out of "
        "range (allowed: finite and > 0)");
    p = mooring(chainRope(2e4, true));
    p.line.sections[0].EA = 0.0;
    expectThrowWithMessage<connectors::ParameterError>(
        [&] { Catenary law(p); },
        "catenary: parameter section2.EA = 0 N is out of range (allowed: "
        "finite and > 0)");
    p = mooring(chainRope(std::nan(""), true));
    expectThrowWithMessage<connectors::ParameterError>(
        [&] { Catenary law(p); },
        "catenary: parameter joint1.weight = nan N is out of range (allowed: "
        "finite)");
}

} // namespace
