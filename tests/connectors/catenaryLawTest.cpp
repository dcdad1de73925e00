// The catenary connector law in 3D: loads on both bodies, balance with the
// line's weight, energy consistency, shape, parameters.
#include <cmath>

#include "LawTestSupport.hpp"
#include "catenary/Catenary.hpp"
#include "common/ConnectorError.hpp"

namespace {

using namespace lawTest;
using connectors::Catenary;
using connectors::CatenaryOutput;
using connectors::CatenaryParameters;

CatenaryParameters mooring(bool seabed, double weight = 700.0)
{
    CatenaryParameters p;
    p.p_AoP_A = Vector3(2.0, -1.0, -3.0);
    p.p_BoQ_B = Vector3(0.5, 0.2, 0.0);
    p.line.length = 100.0;
    p.line.EA = 5e7;
    p.line.weight = weight;
    p.line.seabedContact = seabed;
    return p;
}

const Vector3 zHat = Vector3::UnitZ();

TEST(CatenaryLaw, AnchoredLineLoadsAndBalance)
{
    const Catenary law(mooring(true));
    const BodyKinematics A
        = body(Vector3(60, 45, 43), rotation(0.3, Vector3(0.2, 1, 3)));
    const BodyKinematics world;
    const CatenaryOutput out = law.evaluate(A, world, nullptr, 11);
    const auto& s = out.solution;
    EXPECT_EQ(s.regime, connectors::CatenaryRegime::touchdown);
    // Seabed carries the grounded weight and no friction here: horizontal
    // loads equal and opposite, vertical: the bodies carry w (L - Lb)
    const Vector3 sum = out.loads.A.f_W + out.loads.B.f_W;
    const double wSuspended = 700.0 * (100.0 - s.groundedLength);
    expectVectorNear(sum, -wSuspended * zHat, 1e-9 * out.fairleadTension);
    // The fairlead force points from P towards the anchor, horizontally
    const Vector3 P = A.p_WKo_W + A.R_WK * Vector3(2, -1, -3);
    const Vector3 Q(0.5, 0.2, 0.0);
    Vector3 toAnchor = Q - P;
    toAnchor[2] = 0;
    EXPECT_NEAR(out.loads.A.f_W.head<2>().normalized().dot(
                    toAnchor.head<2>().normalized()),
                1.0, 1e-12);
    expectVectorNear(out.loads.A.m_Ko_W,
                     (A.R_WK * Vector3(2, -1, -3)).cross(out.loads.A.f_W),
                     1e-9 * out.fairleadTension);
    EXPECT_NEAR(out.fairleadTension, std::hypot(s.H, s.V),
                1e-9 * out.fairleadTension);
    EXPECT_EQ(out.loads.tension, out.fairleadTension);
    // Shape: from P to Q, grounded points on the seabed (z = 0)
    ASSERT_EQ(out.shape.size(), 11u);
    // ends to Newton's tolerance 1e-10 L plus elastic round-off
    expectVectorNear(out.shape.front(), P, 1e-7);
    expectVectorNear(out.shape.back(), Q, 1e-12);
    int onSeabed = 0;
    for (const Vector3& x : out.shape) {
        EXPECT_GE(x[2], -1e-12);
        onSeabed += x[2] == 0.0;
    }
    EXPECT_EQ(onSeabed, 1 + int(s.groundedLength / 10.0)); // points every 10 m
}

TEST(CatenaryLaw, LineBetweenTwoBodies)
{
    // Weightless taut line: loads exactly equal, opposite and collinear
    const Catenary straight(mooring(false, 0.0));
    const BodyKinematics A
        = body(Vector3(1, 2, 3), rotation(0.7, Vector3(1, 0, 1)));
    const BodyKinematics B
        = body(Vector3(70, 60, -20), rotation(-0.4, Vector3(0, 1, 1)));
    const CatenaryOutput s = straight.evaluate(A, B, nullptr, 0);
    expectVectorNear(s.loads.A.f_W + s.loads.B.f_W, Vector3::Zero(),
                     1e-9 * s.fairleadTension);
    expectVectorNear(totalMomentAboutOrigin(s.loads, A, B), Vector3::Zero(),
                     1e-9 * s.fairleadTension * 100);
    // Heavy line: horizontal parts equal and opposite, the bodies share
    // the weight w L
    const Catenary heavy(mooring(false));
    const CatenaryOutput h = heavy.evaluate(A, B, nullptr, 0);
    expectVectorNear(h.loads.A.f_W + h.loads.B.f_W, -700.0 * 100.0 * zHat,
                     1e-9 * h.fairleadTension);
    EXPECT_LT(h.loads.A.f_W[2], 0.0);
    EXPECT_LT(h.loads.B.f_W[2], 0.0);
}

TEST(CatenaryLaw, ForceIsMinusTheEnergyGradient)
{
    // Without friction the line is conservative: F_A = -dE/dr_P and
    // F_B = -dE/dr_Q. Central differences with a 1e-4 m step: truncation
    // ~ E''' h^2 and Newton noise 1e-8 m * T / h; 1e-4 relative is ample.
    for (const bool seabed : {true, false}) {
        const Catenary law(mooring(seabed));
        const BodyKinematics A
            = body(Vector3(70, 50, 8), rotation(0.2, Vector3(1, 1, 0)));
        const BodyKinematics B = body(Vector3(0, 0, seabed ? 0 : -30));
        const CatenaryOutput out = law.evaluate(A, B, nullptr, 0);
        for (int i = 0; i < 3; ++i) {
            const double h = 1e-4;
            BodyKinematics plus = A, minus = A;
            plus.p_WKo_W[i] += h;
            minus.p_WKo_W[i] -= h;
            const double dE = (law.evaluate(plus, B).potentialEnergy
                               - law.evaluate(minus, B).potentialEnergy)
                / (2 * h);
            EXPECT_NEAR(-dE, out.loads.A.f_W[i], 1e-4 * out.fairleadTension)
                << (seabed ? "seabed " : "free ") << i;
            BodyKinematics bp = B, bm = B;
            bp.p_WKo_W[i] += h;
            bm.p_WKo_W[i] -= h;
            if (seabed && i == 2) {
                continue; // the seabed moves with the anchor
            }
            const double dEB = (law.evaluate(A, bp).potentialEnergy
                                - law.evaluate(A, bm).potentialEnergy)
                / (2 * h);
            EXPECT_NEAR(-dEB, out.loads.B.f_W[i], 1e-4 * out.fairleadTension)
                << i;
        }
        EXPECT_EQ(out.loads.dissipatedPower, 0.0);
    }
}

TEST(CatenaryLaw, FairleadAboveTheWaterLineAndTranslation)
{
    // Nothing depends on the absolute height but the weight's potential
    const Catenary law(mooring(true));
    const BodyKinematics A = body(Vector3(80, 0, 45)); // fairlead z = 42 > 0
    const BodyKinematics B = body(Vector3(0, 0, -50));
    const BodyKinematics A2 = body(Vector3(80, 0, 95));
    const BodyKinematics B2 = body(Vector3(0, 0, 0));
    const ConnectorResult r = law.evaluate(A, B), r2 = law.evaluate(A2, B2);
    expectVectorNear(r.A.f_W, r2.A.f_W, 1e-9 * r.tension);
    EXPECT_NEAR(r2.potentialEnergy - r.potentialEnergy, 700.0 * 100.0 * 50.0,
                1e-9 * 700.0 * 100.0 * 50.0);
    expectAllFinite(r);
}

TEST(CatenaryLaw, ParametersAreChecked)
{
    CatenaryParameters p = mooring(true);
    p.line.EA = 0.0;
    expectThrowWithMessage<connectors::ParameterError>(
        [&] { Catenary law(p); },
        "catenary: parameter EA = 0 N is out of range (allowed: finite and > 0)");
    p = mooring(true);
    p.line.length = -1;
    expectThrowWithMessage<connectors::ParameterError>(
        [&] { Catenary law(p); },
        "catenary: parameter unstretchedLength = -1 m is out of range (allowed: finite and > 0)");
    p = mooring(true);
    p.line.seabedFriction = -0.1;
    EXPECT_THROW(Catenary {p}, connectors::ParameterError);
    const Catenary law(mooring(true));
    BodyKinematics A = body(Vector3(80, 0, 45));
    A.v_WKo_W[1] = std::nan("");
    expectThrowWithMessage<connectors::InputError>(
        [&] { law.evaluate(A, BodyKinematics()); },
        "catenary: input A.v[2] = nan is not finite");
}

} // namespace
