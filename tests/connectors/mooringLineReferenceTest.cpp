// The dynamic line on the two reference lines of issue 15 (a lab chain and
// the OC4 line): it starts in the static equilibrium of its own discrete
// equations, so that held still its fairlead tension stays constant from
// t = 0, for any N; parameters and start positions it cannot use are
// refused by name; coupled at CFD-like steps (ends moving along the cubic
// Hermite path through positions and velocities), the tension harmonic at
// a coarse step equals that at a fine one, with one Newton solve per step;
// pulled taut (a snap), it stays finite with its energy balance.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <iostream>

#include "LawTestSupport.hpp"
#include "common/ConnectorError.hpp"
#include "mooringLine/MooringLine.hpp"
#include "MooringLineReferences.hpp"

namespace {

using namespace lawTest;
using connectors::MooringLine;
using connectors::MooringLineParameters;
using connectors::MooringLineState;

using connectors::references::lab;
using connectors::references::oc4;
using connectors::references::ReferenceLine;

//- Largest relative change of the fairlead tension and largest node speed
//  over `steps` coupling steps of h with both ends held still
void holdStill(const ReferenceLine& r, double h, int steps, double& change,
               double& speed, double& T0)
{
    MooringLine line(r.p);
    const BodyKinematics A = body(r.fairlead), B = body(r.anchor);
    MooringLineState s = line.initialState(A, B, 0.0);
    T0 = line.evaluate(s, A, B, 0).fairleadTension;
    change = 0.0;
    speed = 0.0;
    for (int k = 0; k < steps; ++k) {
        line.advance(s, A, B, h);
        change = std::max(
            change,
            std::abs(line.evaluate(s, A, B, 0).fairleadTension - T0) / T0);
        for (std::size_t i = 0; i + 5 < s.nodes.size(); i += 6) {
            speed = std::max(
                speed,
                std::hypot(s.nodes[i + 3], s.nodes[i + 4], s.nodes[i + 5]));
        }
    }
    ASSERT_EQ(s.P, r.fairlead); // the fairlead is held where it was put
}

TEST(MooringLineStart, HeldStillTheTensionIsConstantFromTheStart)
{
    // Lab chain for 0.3 s (the catenary start snapped from 0.02 N to
    // 2.84 N within 13 ms), OC4 for 20 s (the catenary start rang 3.1 % low
    // for minutes), at 1 ms and 0.1 s coupling steps. The start was the
    // continuous catenary's shape before: this test then measured relative
    // changes of 38, 111 and 244 (lab, N = 5, 20, 80).
    // tolerance 0: the trapezoidal rule; else CVODE at that tolerance
    for (const double tolerance : {0.0, 1e-10}) {
        for (const int N : {5, 20, 80}) {
            for (auto [r, h, steps] :
                 {std::tuple<ReferenceLine, double, int> {lab(N), 1e-3, 300},
                  {oc4(N), 0.1, 200}}) {
                if (tolerance > 0.0) {
                    r.p.integrator = MooringLineParameters::Integrator::cvode;
                    r.p.relativeTolerance = r.p.absoluteTolerance = tolerance;
                }
                double change = 0.0, speed = 0.0, T0 = 0.0;
                holdStill(r, h, steps, change, speed, T0);
                std::cout << r.name << ", N = " << N << ", "
                          << (tolerance > 0.0 ? "CVODE tolerance "
                                              : "trapezoid ")
                          << tolerance << ": fairlead tension " << T0
                          << " N, largest relative change " << change
                          << ", largest node speed " << speed << " m/s\n";
                // Newton leaves node forces at round-off (16 eps EA |r| / l
                // at most), so what moves the tension is the integrator's
                // error at rest: a velocity error dv of the top node
                // changes the tension by BA/l dv (the lab chain: 10 to
                // 165 N.s/m for N = 5 to 80 against 0.56 N; OC4: 1.8e4 to
                // 2.9e5 N.s/m against 1.1e6 N). The trapezoidal rule's
                // predictor is the start itself (forces at round-off), so
                // its change is round-off too (measured 2e-9 lab, 2e-12
                // OC4); CVODE's is bounded by its tolerance (measured at
                // 1e-10: 2e-7 lab, 3e-9 OC4; at the default 1e-6 the lab
                // chain reached 1.6e-6). The goal, 1e-6, holds.
                EXPECT_LT(change, 1e-6) << r.name << ", N = " << N;
            }
        }
    }
}

TEST(MooringLineStart, NodesRestOnTheSeabedPenalty)
{
    // At rest, and below the seabed only by the penalty's sink w / (kb d)
    // (0.63 mm for the lab chain), never more
    const ReferenceLine r = lab(20);
    MooringLine line(r.p);
    const MooringLineState s
        = line.initialState(body(r.fairlead), body(r.anchor), 0.0);
    const double sink = r.p.weight() / (r.p.seabedStiffness * r.p.diameter);
    int grounded = 0;
    for (std::size_t i = 0; i + 5 < s.nodes.size(); i += 6) {
        EXPECT_GE(s.nodes[i + 2], r.anchor[2] - (1.0 + 1e-6) * sink)
            << i / 6 + 1;
        grounded += s.nodes[i + 2] < r.anchor[2];
        EXPECT_EQ(s.nodes[i + 3], 0.0);
    }
    EXPECT_GT(grounded, 0);
}

TEST(MooringLineStart, UnusableParametersAreNamed)
{
    const ReferenceLine r = lab(20);
    MooringLineParameters p = r.p;
    p.length = -1.2;
    expectThrowWithMessage<connectors::ParameterError>(
        [&] { MooringLine line(p); },
        "mooringLine: parameter unstretchedLength = -1.2 m is out of range (allowed: "
        "finite and > 0)");
    p = r.p;
    p.maxStep = -1e-3;
    expectThrowWithMessage<connectors::ParameterError>(
        [&] { MooringLine line(p); },
        "mooringLine: parameter maxStep = -0.001 s is out of range (allowed: "
        "finite and >= 0)");
    p = r.p;
    p.segments = 0;
    expectThrowWithMessage<connectors::ConnectorError>(
        [&] { MooringLine line(p); },
        "mooringLine: parameter segments = 0 is out of range (allowed: an integer from "
        "2 to 1000)");
    MooringLine line(r.p);
    expectThrowWithMessage<connectors::UndefinedStateError>(
        [&] {
            line.initialState(body(Vector3(0.0, 0.0, -0.6)), body(r.anchor),
                              0.0);
        },
        "mooringLine: the fairlead (A.p on body A) at z = -0.6 m is below the seabed "
        "(z = -0.5 m, the height of the anchor B.p); with seabedContact = 1 it must not "
        "be");
}

//- Fairlead surging x0 + a r(t) sin(2 pi t/T), r = (1 - cos(pi t/T))/2
//  over the first period, with its velocity
BodyKinematics surging(const ReferenceLine& r, double a, double T, double t)
{
    const double w = 2.0 * pi / T;
    const double ramp = t < T ? 0.5 * (1.0 - std::cos(pi * t / T)) : 1.0;
    const double rampRate = t < T ? 0.5 * pi / T * std::sin(pi * t / T) : 0.0;
    return body(
        r.fairlead + Vector3(a * ramp * std::sin(w * t), 0.0, 0.0),
        Matrix3::Identity(),
        Vector3(a * (rampRate * std::sin(w * t) + ramp * w * std::cos(w * t)),
                0.0, 0.0));
}

//- First-harmonic amplitude of the fairlead tension over the last of
//  `periods` periods at coupling step h; forcesPerStep: the line's force
//  evaluations per coupling step; keepMatrix false: every step forms its
//  own Newton matrix (the state's kept one dropped), matricesPerStep: the
//  Newton matrices formed per coupling step
double tensionHarmonic(const ReferenceLine& r, double a, double T, int periods,
                       double h, double* forcesPerStep = nullptr,
                       bool keepMatrix = true,
                       double* matricesPerStep = nullptr)
{
    MooringLine line(r.p);
    const BodyKinematics B = body(r.anchor);
    MooringLineState s = line.initialState(surging(r, a, T, 0.0), B, 0.0);
    const int perPeriod = int(std::lround(T / h));
    std::complex<double> sum = 0.0;
    for (int k = 1; k <= periods * perPeriod; ++k) {
        const BodyKinematics A = surging(r, a, T, k * h);
        if (!keepMatrix) {
            s.newton.reset();
        }
        line.advance(s, A, B, h);
        if (k > (periods - 1) * perPeriod) {
            sum += line.evaluate(s, A, B, 0).fairleadTension
                * std::exp(std::complex<double>(0.0, -2.0 * pi * k * h / T));
        }
    }
    if (forcesPerStep != nullptr) {
        *forcesPerStep
            = double(line.statistics().rhsEvaluations) / (periods * perPeriod);
    }
    if (matricesPerStep != nullptr) {
        *matricesPerStep = double(line.statistics().jacobianEvaluations)
            / (periods * perPeriod);
    }
    return 2.0 * std::abs(sum) / perPeriod;
}

TEST(MooringLineCoupling, CoarseStepsGiveTheResolvedTensionHarmonic)
{
    // The goal: at a 1 ms step the lab chain's tension harmonic is
    // within 1 percentage point of the same N at a 1e-5 s step, for N = 10,
    // 20, 40; the OC4 line likewise at 0.1 s (against 1e-3 s here). The
    // trapezoidal rule's error is second order in the step and the cubic
    // Hermite end path's h^4/384 times the fourth derivative of the motion
    // (4e-17 m, 4e-8 m at the coarse steps): measured within 0.002 pp
    // (lab) and 0.08 pp (OC4) of the fine step. CVODE at tolerance 1e-8
    // was 0.15 to 0.8 pp off at 1 ms (bench/mooringLine). One Newton
    // solve per step: two force evaluations (the predictor's residual and
    // the step's end, whose forces are the next step's start and the
    // loads'; measured 2.0005, 2.01, 2.0033 on the lab chain: a step in a
    // hundred takes a second correction to close its energy balance), one
    // step per coupling step, except OC4 at N = 40, whose predictor misses
    // by more than 1e-5 of a segment on some steps, which are halved
    // (measured 1.7 steps, 4.7 evaluations per coupling step; its
    // difference then 0.025 %).
    struct Coupled {
        ReferenceLine (*line)(int);
        double amplitude, period;
        int periods;
        double coarse, fine, difference; // steps [s], largest difference [%]
    };
    for (const Coupled c : {Coupled {lab, 0.01, 1.0, 2, 1e-3, 1e-5, 0.1},
                            Coupled {oc4, 1.0, 10.0, 3, 0.1, 1e-3, 0.2}}) {
        for (const int N : {10, 20, 40}) {
            const ReferenceLine r = c.line(N);
            double forces = 0.0;
            const double coarse = tensionHarmonic(r, c.amplitude, c.period,
                                                  c.periods, c.coarse, &forces);
            const double fine
                = tensionHarmonic(r, c.amplitude, c.period, c.periods, c.fine);
            const double difference = 100.0 * (coarse / fine - 1.0);
            std::cout << r.name << " N = " << N << ": harmonic " << coarse
                      << " N at " << c.coarse << " s (" << forces
                      << " force evaluations per step), " << fine << " N at "
                      << c.fine << " s (" << difference << " %)\n";
            EXPECT_LT(std::abs(difference), c.difference) << N; // goal: 1
            EXPECT_LE(forces, N < 40 ? 2.02 : 6.0) << N;
        }
    }

    // CVODE (tolerance 1e-10, error control on its own internal steps)
    // agrees with the trapezoidal rule at 1e-5 s: an independent check of
    // the fine answer (lab chain, N = 10)
    ReferenceLine r = lab(10);
    const double trapezoid = tensionHarmonic(r, 0.01, 1.0, 2, 1e-5);
    r.p.integrator = MooringLineParameters::Integrator::cvode;
    r.p.relativeTolerance = r.p.absoluteTolerance = 1e-10;
    const double cvode = tensionHarmonic(r, 0.01, 1.0, 2, 1e-3);
    std::cout << "lab chain N = 10: CVODE (1e-10) at 1 ms " << cvode
              << " N, trapezoidal rule at 1e-5 s " << trapezoid << " N\n";
    EXPECT_NEAR(cvode / trapezoid, 1.0, 1e-3);

    // hermiteEnds = false moves the ends on straight lines inside a step
    // (a fallback for cases where the given velocities do not fit the
    // positions). CVODE, which follows the path inside the step, is then
    // well off at 1 ms (measured +137 %; at least 50 % asserted): the
    // kinks of the path at every step shake the stiff axial modes. The
    // trapezoidal rule sees the ends only at the step's ends, with the
    // step's mean velocity instead of the given ones: -0.0013 % at N = 10
    // (1 ms) and -0.0008 % at N = 20 (0.5 ms), where no step is halved;
    // at N = 20 and 1 ms it goes wrong from t = 0.297 s (its predictor
    // misses, the steps are halved over and over, the tension swings
    // between 0.04 and 1 N). That swinging is chaotic: its harmonic moves
    // with the round-off of the Newton matrix (+110 % with general 3 x 3
    // block inverses, +30 % with the symmetric blocks' cofactors); at
    // least 20 % asserted (connectors/mooringLine/README.md; the README
    // once claimed -0.002 % for that case)
    r.p.relativeTolerance = r.p.absoluteTolerance = 1e-9;
    r.p.hermiteEnds = false;
    const double straightCvode = tensionHarmonic(r, 0.01, 1.0, 2, 1e-3);
    EXPECT_GT(100.0 * (straightCvode / trapezoid - 1.0), 50.0) << straightCvode;
    r = lab(10);
    r.p.hermiteEnds = false;
    const double straight = tensionHarmonic(r, 0.01, 1.0, 2, 1e-3);
    EXPECT_NEAR(straight / trapezoid, 1.0, 1e-3);
    r = lab(20);
    const double hermite20 = tensionHarmonic(r, 0.01, 1.0, 2, 5e-4);
    r.p.hermiteEnds = false;
    EXPECT_NEAR(tensionHarmonic(r, 0.01, 1.0, 2, 5e-4) / hermite20, 1.0, 1e-4);
    const double straight20 = tensionHarmonic(r, 0.01, 1.0, 2, 1e-3);
    EXPECT_GT(100.0 * (straight20 / hermite20 - 1.0), 20.0) << straight20;
}

TEST(MooringLineCoupling, AKeptNewtonMatrixKeepsTheHarmonic)
{
    // A step reuses the Newton matrix of the steps before while it serves
    // and its correction is small (MooringLineTrapezoid.cpp): the harmonic
    // must equal that of a matrix formed at every step to far below the
    // time error the bench reports (1e-5 relative, 0.001 pp, at OC4
    // 0.01 s). Measured 2.3e-7 (OC4, 0.01 s, one matrix in ten steps over
    // the ramp and the period after it), 1.5e-9 (OC4, 0.1 s) and 2.8e-10
    // (lab chain, 1 ms), where nearly every step forms its own (its first
    // correction above 1e-6 of a segment, or the segments turned too far);
    // 1e-6 asserted, and at most 0.2 matrices a step at OC4 0.01 s (a
    // matrix every step would fail it), never more than one a step
    struct Coupled {
        ReferenceLine (*line)(int);
        double amplitude, period, h, difference, matrices;
    };
    for (const Coupled c : {Coupled {oc4, 1.0, 10.0, 0.01, 1e-6, 0.2},
                            Coupled {oc4, 1.0, 10.0, 0.1, 1e-6, 1.0},
                            Coupled {lab, 0.01, 1.0, 1e-3, 1e-6, 1.0}}) {
        const ReferenceLine r = c.line(20);
        double kept = 0.0, formed = 0.0;
        const double chord = tensionHarmonic(r, c.amplitude, c.period, 2, c.h,
                                             nullptr, true, &kept);
        const double newton = tensionHarmonic(r, c.amplitude, c.period, 2, c.h,
                                              nullptr, false, &formed);
        std::cout << r.name << " N = 20, h = " << c.h << " s: harmonic "
                  << chord << " N with the kept matrix (" << kept
                  << " matrices per step), " << newton
                  << " N with one per step (" << formed
                  << "), relative difference " << chord / newton - 1.0 << "\n";
        EXPECT_NEAR(chord / newton, 1.0, c.difference) << c.h;
        EXPECT_EQ(formed, 1.0) << c.h;
        EXPECT_LE(kept, c.matrices) << c.h;
    }
}

TEST(MooringLineSnap, PulledTautItStaysFiniteAndBalancesEnergy)
{
    // The lab chain's fairlead pulled in 0.5 s to 0.9997 of the line's
    // length from the anchor (11.2 cm of surge), then held: the line
    // lifts off the seabed and snaps taut as the fairlead stops (peak
    // 23 N against 0.56 N at rest, at 0.554 s), goes slack and snaps
    // again. The trapezoidal rule at 1 ms halves the steps whose predictor
    // misses (bench/mooringLine snap).
    double previousPeak = 0.0, previousChange = 0.0;
    for (const int N : {10, 20, 40}) {
        const connectors::references::Snap snap
            = connectors::references::pullTaut(lab(N), 1e-3, 1.0);
        std::cout << "lab chain N = " << N << ": snap peak " << snap.peak
                  << " N at " << snap.peakTime << " s, energy imbalance "
                  << snap.imbalance << " J of " << snap.throughput << " J\n";
        ASSERT_TRUE(snap.finite) << N;
        EXPECT_GT(snap.peak, 20.0 * 0.56) << N;
        EXPECT_NEAR(snap.peakTime, 0.554, 0.005) << N;
        // Power integrals by the trapezoidal rule over 1 ms, the added
        // mass's configuration dependent matrix (not energy consistent):
        // measured 5e-4, 3e-4, 2e-4 (N = 10, 20, 40) of the energy through
        // the fairlead; with one step per coupling step N = 40 was 7e-2
        // off and N = 80 0.43 (the slack line's second snap unresolved)
        EXPECT_LT(std::abs(snap.imbalance), 2e-3 * snap.throughput) << N;
        // The peak converges in N, at second order (measured 21.9, 23.0,
        // 23.2 N: changes 1.1 and 0.27 N)
        if (N > 10) {
            const double change = snap.peak - previousPeak;
            EXPECT_GT(change, 0.0) << N;
            if (N > 20) {
                EXPECT_LT(change, 0.4 * previousChange) << N;
            }
            previousChange = change;
        }
        previousPeak = snap.peak;
    }
}

TEST(MooringLineSnap, SlackTautForcingKeepsTheEnergyBalance)
{
    // The lab chain's fairlead surging 0.112 m at 1 Hz (ramped in over the
    // first second) for 10 s: the line lifts off the seabed and snaps taut
    // every cycle (peak 9.4 N against 0.56 N at rest). At the CFD step of
    // 1 ms the trapezoidal rule averaged the elastic tension at the step's
    // ends, whose work is not the strain energy's change where a segment
    // goes taut inside the step: it lost 1.2 % of the energy through the
    // fairlead, and its tension harmonic was 3.3 % below that at 1e-5 s.
    // The discrete gradient of the strain energy (AxialGradient.hpp)
    // conserves it; the seabed's dissipated power now counts the energy of
    // a node leaving the seabed faster than its penalty relaxes (0.5 % of
    // the throughput before, at any step).
    const connectors::references::ReferenceLine line = lab(20);
    const connectors::references::Snap coarse
        = connectors::references::slackTaut(line, 0.112, 1.0, 1e-3, 10.0);
    const connectors::references::Snap fine
        = connectors::references::slackTaut(line, 0.112, 1.0, 1e-5, 10.0);
    for (const auto& [name, r] :
         {std::pair<const char*, connectors::references::Snap> {"1 ms", coarse},
          {"1e-5 s", fine}}) {
        std::cout << "slack-taut at " << name << ": work " << r.stepWork
                  << " J (from the loads at the steps' ends " << r.work
                  << " J), energy change " << r.change << " J, dissipated "
                  << r.dissipated << " J, unreported " << r.stepImbalance
                  << " J of " << r.throughput << " J (by the account "
                  << r.accountImbalance << " J); harmonic " << r.harmonic
                  << " N, peak " << r.peak << " N\n";
    }
    ASSERT_TRUE(coarse.finite);
    EXPECT_GT(coarse.peak, 10.0 * 0.56); // it snaps
    // Unreported: the work of the fairlead in the scheme's own terms
    // (MooringLine::stepWork) less the change of kinetic and potential
    // energy and the dissipated power's trapezoidal sum. Left: the added
    // mass's work (MooringLine::stepEnergy, -1e-4 at 1e-5 s; 3e-8 without
    // added mass) and the dissipated power sampled at 1 ms; measured
    // -1.9e-4 (-5.9e-4 while Newton stopped at the first correction below
    // 1e-5 of a segment); 1e-3 asserted (the old average of the tensions
    // lost 1.2e-2). The account itself, which has both, closes to 1e-4
    // (mooringLineEnergyTest). The loads' sampled power misses the snaps
    // between the steps' ends (a 0.6 ms axial wave along the line): its
    // work differs from the scheme's by -0.31 % (+0.4 % with the 1 ms
    // steps resolved by substeps of 1e-5 s), the coupling's quadrature,
    // which resolves at 1e-5 s (both 1e-4 off the balance).
    EXPECT_LT(std::abs(coarse.stepImbalance), 1e-3 * coarse.throughput);
    EXPECT_LT(std::abs(fine.stepImbalance), 3e-4 * fine.throughput);
    EXPECT_LT(std::abs(fine.work - fine.stepWork), 1e-4 * fine.throughput);
    EXPECT_LT(std::abs(coarse.accountImbalance), 1e-4 * coarse.throughput);
    EXPECT_LT(std::abs(fine.accountImbalance), 1e-4 * fine.throughput);
    // The tension's first harmonic over seconds 1 to 10 at 1 ms against
    // 1e-5 s: measured -0.14 % (1.4937 against 1.4957 N; -3.3 % before);
    // the 1 percentage point asserted at 0.3 %
    EXPECT_NEAR(coarse.harmonic / fine.harmonic, 1.0, 3e-3);
}

} // namespace
