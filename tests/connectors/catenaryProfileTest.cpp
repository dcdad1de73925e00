// The elastic catenary profile against Irvine's closed-form relations
// (evaluated here in their textbook form), in every regime.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "catenary/CatenaryProfile.hpp"
#include "common/ConnectorError.hpp"

namespace {

using connectors::CatenaryGuess;
using connectors::CatenaryLine;
using connectors::CatenaryRegime;
using connectors::CatenarySolution;
using connectors::solveCatenary;

//- Spans of a fully suspended line, textbook form (Irvine eq. 2.25)
void suspendedSpans(const CatenaryLine& l, double H, double V, double& x,
                    double& z)
{
    const double w = l.weight, L = l.length, EA = l.EA;
    x = H / w * (std::asinh(V / H) - std::asinh((V - w * L) / H)) + H * L / EA;
    z = H / w
            * (std::sqrt(1 + V * V / (H * H))
               - std::sqrt(1 + (V - w * L) * (V - w * L) / (H * H)))
        + (V * L - w * L * L / 2) / EA;
}

//- Spans of an anchored line with a grounded part (MoorDyn's Catenary)
void touchdownSpans(const CatenaryLine& l, double H, double V, double& x,
                    double& z)
{
    const double w = l.weight, L = l.length, EA = l.EA, CB = l.seabedFriction;
    const double Lb = L - V / w;
    x = Lb + H / w * std::asinh(V / H) + H * L / EA;
    if (CB > 0) {
        const double u = Lb - H / (CB * w);
        x += 0.5 * CB * w / EA * (-Lb * Lb + u * std::max(u, 0.0));
    }
    z = H / w * (std::sqrt(1 + V * V / (H * H)) - 1) + V * V / (2 * EA * w);
}

CatenaryLine chain(bool seabed, double friction = 0.0)
{
    CatenaryLine l;
    l.length = 100.0;
    l.EA = 5e7; // N, a studless chain of ~ 60 mm
    l.weight = 700; // N/m submerged
    l.seabedFriction = friction;
    l.seabedContact = seabed;
    return l;
}

// Newton stops at a residual of 1e-10 L = 1e-8 m; with dx/dH ~ L/H... the
// recovered tensions agree to ~1e-7 relative; 1e-6 leaves a margin.
constexpr double relTol = 1e-6;

TEST(CatenaryProfile, SuspendedMatchesClosedForm)
{
    for (const bool seabed : {false, true}) {
        const CatenaryLine l = chain(seabed);
        for (const auto& [H, V] :
             {std::pair {2e4, 9e4}, {1e5, 7.5e4}, {3e3, 7.01e4}, {5e5, -1e5}}) {
            if (seabed && V < l.weight * l.length) {
                continue; // would touch down
            }
            double x, z;
            suspendedSpans(l, H, V, x, z);
            const CatenarySolution s = solveCatenary(l, x, z);
            EXPECT_EQ(s.regime, CatenaryRegime::suspended) << H << " " << V;
            EXPECT_NEAR(s.H, H, relTol * std::hypot(H, V));
            EXPECT_NEAR(s.V, V, relTol * std::hypot(H, V));
            // tension balance: fairlead = anchor + weight, vectorially
            EXPECT_NEAR(s.HA, s.H, 1e-9 * s.H);
            EXPECT_NEAR(s.V - s.VA, l.weight * l.length, 1e-9 * std::abs(s.V));
        }
    }
}

TEST(CatenaryProfile, TouchdownMatchesClosedForm)
{
    for (const double friction : {0.0, 0.5, 1.0}) {
        const CatenaryLine l = chain(true, friction);
        for (const auto& [H, V] :
             {std::pair {2e4, 3e4}, {500.0, 1.4e4}, {8e4, 6.9e4}}) {
            double x, z;
            touchdownSpans(l, H, V, x, z);
            const CatenarySolution s = solveCatenary(l, x, z);
            EXPECT_EQ(s.regime, CatenaryRegime::touchdown);
            EXPECT_NEAR(s.H, H, relTol * std::hypot(H, V)) << friction;
            EXPECT_NEAR(s.V, V, relTol * std::hypot(H, V)) << friction;
            EXPECT_NEAR(s.groundedLength, l.length - V / l.weight, 1e-6);
            // the seabed carries the grounded weight: V = w (L - Lb); the
            // anchor keeps H minus the friction on the grounded part
            EXPECT_NEAR(s.V, l.weight * (l.length - s.groundedLength),
                        1e-9 * V);
            EXPECT_NEAR(
                s.HA, std::max(H - friction * l.weight * s.groundedLength, 0.0),
                relTol * H);
            EXPECT_EQ(s.VA, 0.0);
        }
    }
}

TEST(CatenaryProfile, InextensibleLimit)
{
    // EA -> infinity: the inextensible catenary x = (H/w)(asinh a - asinh b),
    // z = (H/w)(sqrt(1+a^2) - sqrt(1+b^2)). The elastic terms (~ H L/EA)
    // shift H by O(1/EA): the error falls 100-fold per 100-fold EA until
    // Newton's tolerance (1e-8 m, ~1e-4 N here) is reached.
    CatenaryLine l = chain(false);
    const double H = 4e4, V = 9e4, w = l.weight, L = l.length;
    const double a = V / H, b = (V - w * L) / H;
    const double x = H / w * (std::asinh(a) - std::asinh(b));
    const double z = H / w * (std::sqrt(1 + a * a) - std::sqrt(1 + b * b));
    double error[3];
    int k = 0;
    for (const double EA : {1e9, 1e11, 1e13}) {
        l.EA = EA;
        const CatenarySolution s = solveCatenary(l, x, z);
        error[k++] = std::hypot(s.H - H, s.V - V);
        EXPECT_LE(s.iterations, 10) << EA;
    }
    EXPECT_NEAR(error[0] / error[1], 100.0, 5.0);
    EXPECT_NEAR(error[1] / error[2], 100.0, 5.0);
    EXPECT_LT(error[2], 1e-6 * H);
}

TEST(CatenaryProfile, TautStraightLine)
{
    // Weightless: exactly straight, T = EA (chord/L - 1)
    CatenaryLine l = chain(false);
    l.weight = 0.0;
    const double x = 80.0, z = 60.5; // chord 100.2 m, 0.2 % stretch
    const CatenarySolution s = solveCatenary(l, x, z);
    const double T = l.EA * (std::hypot(x, z) / l.length - 1.0);
    EXPECT_NEAR(std::hypot(s.H, s.V), T, 1e-7 * T);
    EXPECT_NEAR(s.V / s.H, z / x, 1e-9);
    // With weight, fully taut (2 % stretch): sag ~ w L^2/(8 T) ~ 0.9 m adds
    // ~ 8 sag^2/(3 L) ~ 0.02 m of arc to the 2 m stretch, so the tension is
    // within ~ 1 % of the weightless one (3 % asserted); along the line
    // dT = w dz/(1 + T/EA), so T_fairlead - T_anchor = w z to T/EA ~ 2 %.
    const double xt = 80.0, zt = std::sqrt(102.0 * 102.0 - xt * xt);
    const double Tt = l.EA * 0.02;
    l.weight = 700.0;
    const CatenarySolution t = solveCatenary(l, xt, zt);
    EXPECT_EQ(t.regime, CatenaryRegime::suspended);
    const double Tf = std::hypot(t.H, t.V), Ta = std::hypot(t.HA, t.VA);
    EXPECT_NEAR(Tf, Tt, 0.03 * Tt);
    EXPECT_NEAR(Tf - Ta, l.weight * zt, 0.03 * l.weight * zt);
}

TEST(CatenaryProfile, SlackWeightlessLineCarriesNothing)
{
    CatenaryLine l = chain(false);
    l.weight = 0.0;
    const CatenarySolution s = solveCatenary(l, 50.0, 20.0);
    EXPECT_EQ(s.regime, CatenaryRegime::slackWeightless);
    EXPECT_EQ(s.H, 0.0);
    EXPECT_EQ(s.V, 0.0);
}

TEST(CatenaryProfile, BuoyantLineMirrorsAHangingOne)
{
    // w -> -w with z -> -z and V -> -V leaves the equations unchanged
    CatenaryLine heavy = chain(false), buoyant = chain(false);
    buoyant.weight = -heavy.weight;
    const CatenarySolution h = solveCatenary(heavy, 70.0, 30.0);
    const CatenarySolution b = solveCatenary(buoyant, 70.0, -30.0);
    EXPECT_NEAR(b.H, h.H, 1e-6 * h.H);
    EXPECT_NEAR(b.V, -h.V, 1e-6 * h.H);
    // and a buoyant line anchored on the seabed floats: nothing grounded
    buoyant.seabedContact = true;
    const CatenarySolution f = solveCatenary(buoyant, 70.0, 30.0);
    EXPECT_EQ(f.regime, CatenaryRegime::suspended);
    EXPECT_EQ(f.groundedLength, 0.0);
    EXPECT_LT(f.V, 0.0); // the line pulls the fairlead up
}

TEST(CatenaryProfile, SlackOnTheSeabedAndAnchorBelowTheFairlead)
{
    const CatenaryLine l = chain(true, 0.3);
    const double z = 20.0;
    // hanging length Ls: z = Ls + w Ls^2/(2 EA)
    const double Ls
        = (std::sqrt(1 + 2 * l.weight * z / l.EA) - 1) * l.EA / l.weight;
    for (const double x : {0.0, 30.0, l.length - Ls - 1e-9}) {
        const CatenarySolution s = solveCatenary(l, x, z);
        EXPECT_EQ(s.regime, CatenaryRegime::slackOnSeabed) << x;
        EXPECT_EQ(s.H, 0.0);
        EXPECT_NEAR(s.V, l.weight * Ls, 1e-9 * l.weight * Ls);
        EXPECT_NEAR(s.groundedLength, l.length - Ls, 1e-9);
    }
    // just beyond: touchdown with a small H, continuous with H = 0
    const CatenarySolution t = solveCatenary(l, l.length - Ls + 1e-3, z);
    EXPECT_EQ(t.regime, CatenaryRegime::touchdown);
    EXPECT_GT(t.H, 0.0);
    EXPECT_LT(t.H, 1e-2 * l.weight * Ls);
    // taut vertical line: z = L + (V L - w L^2/2)/EA
    const double zTaut = l.length + 0.2; // above L + w L^2/(2 EA) = L + 0.07
    const CatenarySolution v = solveCatenary(l, 0.0, zTaut);
    EXPECT_EQ(v.regime, CatenaryRegime::vertical);
    EXPECT_NEAR(
        v.V, (zTaut - l.length) * l.EA / l.length + 0.5 * l.weight * l.length,
        1e-6);
}

TEST(CatenaryProfile, LiftOffIsContinuous)
{
    // At lift-off V = wL: the touchdown and suspended relations coincide
    const CatenaryLine l = chain(true);
    const double H = 3e4, V = l.weight * l.length;
    double x0, z0;
    suspendedSpans(l, H, V, x0, z0);
    const CatenarySolution below = solveCatenary(l, x0 - 1e-4, z0);
    const CatenarySolution above = solveCatenary(l, x0 + 1e-4, z0);
    EXPECT_EQ(below.regime, CatenaryRegime::touchdown);
    EXPECT_EQ(above.regime, CatenaryRegime::suspended);
    // dH/dx ~ 1e5 N/m here: 2e-4 m moves H by ~ 20 N
    EXPECT_NEAR(below.H, H, 50.0);
    EXPECT_NEAR(above.H, H, 50.0);
    EXPECT_LT(below.groundedLength, 1e-3);
}

TEST(CatenaryProfile, SweepFromSlackToTautIsMonotoneAndFinite)
{
    // Every regime along the way, cold and warm; H never decreases with x
    for (const bool seabed : {true, false}) {
        const CatenaryLine l = chain(seabed, 0.5);
        double previous = 0.0;
        CatenaryGuess warm {};
        for (double x = 0.0; x <= 102.0; x += 0.5) {
            const double z = 40.0;
            const CatenarySolution cold = solveCatenary(l, x, z);
            const CatenarySolution hot
                = solveCatenary(l, x, z, warm.H > 0 ? &warm : nullptr);
            ASSERT_TRUE(std::isfinite(cold.H) && std::isfinite(cold.V)) << x;
            EXPECT_NEAR(hot.H, cold.H, 1e-6 * std::hypot(cold.H, cold.V)) << x;
            EXPECT_GE(cold.H, previous * (1 - 1e-9)) << x;
            previous = cold.H;
            warm = {hot.H, hot.V};
        }
    }
}

TEST(CatenaryProfile, WarmStartTakesFewerIterations)
{
    // A fairlead moving 0.02 m per call (a CFD time step), from a slack
    // line mostly on the seabed through lift-off to a taut one
    const CatenaryLine l = chain(true, 0.5);
    CatenaryGuess guess {};
    int cold = 0, warm = 0, worstWarm = 0;
    for (double x = 62.0; x < 92.0; x += 0.02) {
        const double z = 40.0 + 5.0 * std::sin(x);
        const CatenarySolution c = solveCatenary(l, x, z);
        const CatenarySolution h
            = solveCatenary(l, x, z, guess.H > 0 ? &guess : nullptr);
        cold += c.iterations;
        warm += h.iterations;
        worstWarm = std::max(worstWarm, h.iterations);
        guess = {h.H, h.V};
    }
    EXPECT_LT(warm, cold) << "warm " << warm << ", cold " << cold;
    // entering the touchdown regime from the slack one (no previous H) or
    // crossing lift-off (a kink in the Jacobian) takes a few more
    EXPECT_LE(worstWarm, 8);
    std::cout << "Newton iterations over the path: cold " << cold << ", warm "
              << warm << '\n';
}

TEST(CatenaryProfile, FailuresNameTheRegimeAndResidual)
{
    const CatenaryLine l = chain(true);
    try {
        solveCatenary(l, 10.0, -5.0);
        ADD_FAILURE() << "no exception";
    } catch (const connectors::UndefinedStateError& e) {
        EXPECT_EQ(
            std::string(e.what()),
            "catenary: the fairlead is 5 m below the seabed (the anchor's height): "
            "horizontal span 10 m, vertical span -5 m, H = 0 N, V = 0 N");
    }
    connectors::CatenaryOptions one;
    one.maxIterations = 1;
    try {
        solveCatenary(l, 90.0, 40.0, nullptr, one);
        ADD_FAILURE() << "no exception";
    } catch (const connectors::UndefinedStateError& e) {
        const std::string m = e.what();
        EXPECT_EQ(
            m.rfind(
                "catenary: Newton did not converge in 1 iterations (regime ",
                0),
            0u)
            << m;
        EXPECT_NE(m.find(", residual "), std::string::npos) << m;
    }
}

TEST(CatenaryProfile, SlackLineOnOneVerticalFolds)
{
    // Two bodies one above the other, slack line: a strand hangs from each
    // end to a fold without tension (H = 0); the strands' stretched lengths
    // differ by z: 2V - wL = z/(1/w + L/(2EA)). The limit of the suspended
    // solution as the horizontal span vanishes.
    for (const double w : {700.0, -300.0}) {
        CatenaryLine l = chain(false);
        l.weight = w;
        const double z = 30.0;
        const CatenarySolution f = solveCatenary(l, 0.0, z);
        EXPECT_EQ(f.regime, CatenaryRegime::folded);
        const double V = 0.5
            * (w * l.length + z / (1 / std::abs(w) + l.length / (2 * l.EA)));
        EXPECT_NEAR(f.V, V, 1e-9 * std::abs(V));
        EXPECT_LE(f.V * f.VA, 0.0); // one strand up, one down
        const CatenarySolution near = solveCatenary(l, 1e-6, z);
        EXPECT_NEAR(near.V, f.V, 1e-6 * std::abs(V));
        EXPECT_LT(near.H, 1e-3);
        // the shape reaches the fairlead and the fold is the lowest (or,
        // buoyant, highest) point
        const Eigen::Vector2d end
            = connectors::catenaryPoint(l, f, 0.0, z, l.length);
        EXPECT_NEAR(end[1], z, 1e-9);
        const Eigen::Vector2d fold
            = connectors::catenaryPoint(l, f, 0.0, z, -f.VA / w);
        EXPECT_NEAR(fold[1], w > 0 ? -(l.length - z) / 2 : (l.length + z) / 2,
                    2e-3 * l.length); // plus the strands' elastic stretch
    }
}

} // namespace

namespace {

TEST(CatenaryProfile, TensionAlongTheLineMatchesItsStretchAndSlope)
{
    // The tension along the profile against the profile's own geometry:
    // an elastic line stretches by 1 + T/EA, and the horizontal part of T
    // is H wherever the line hangs (the seabed carries no horizontal
    // load, only the friction). Central differences over 1 mm of arc:
    // truncation (1 mm)^2/6 times the squared curvature (H/w ~ 30 m) is
    // 1e-9 of the stretch, 0.05 N in EA; round-off of the 100 m
    // coordinates over 2 mm, 1e-13 x EA = 5e-6 N
    for (const double friction : {0.0, 0.5}) {
        for (const bool seabed : {false, true}) {
            const CatenaryLine l = chain(seabed, friction);
            const double x = 85.0, z = 40.0;
            const CatenarySolution s = solveCatenary(l, x, z);
            // with the seabed a part lies on it (checked there too)
            EXPECT_EQ(s.groundedLength > 5.0, seabed) << s.groundedLength;
            const double ds = 1e-3;
            for (const double arc : {3.0, 20.0, 51.0, 77.0, 99.0}) {
                if (std::abs(arc - s.groundedLength) < 1.0) {
                    continue; // the touchdown point's kink
                }
                const Eigen::Vector2d slope
                    = (connectors::catenaryPoint(l, s, x, z, arc + ds)
                       - connectors::catenaryPoint(l, s, x, z, arc - ds))
                    / (2.0 * ds);
                const double T = connectors::catenaryTension(l, s, arc);
                EXPECT_NEAR(T, l.EA * (slope.norm() - 1.0), 0.1)
                    << friction << " " << seabed << " " << arc;
                if (arc > s.groundedLength) {
                    // (with H ~ 2e4 N: round-off of the division)
                    EXPECT_NEAR(T * slope[0] / slope.norm(), s.H, 1e-6 * T)
                        << friction << " " << seabed << " " << arc;
                }
            }
            // the ends: the end tensions of the solution
            EXPECT_NEAR(connectors::catenaryTension(l, s, l.length),
                        std::hypot(s.H, s.V), 1e-9 * std::hypot(s.H, s.V));
            EXPECT_NEAR(connectors::catenaryTension(l, s, 0.0),
                        std::hypot(s.HA, s.VA), 1e-9 * std::hypot(s.H, s.V));
        }
    }
}

} // namespace
