// The dynamic lumped-mass line: static limit against the quasi-static
// catenary, transverse natural frequency of a taut line (and the
// trapezoidal rule's known period error), exact repetition of a step from
// a saved state with either integrator, energy balance, state
// serialization.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "LawTestSupport.hpp"
#include "MooringLineReferences.hpp"
#include "catenary/Catenary.hpp"
#include "mooringLine/MooringLine.hpp"

namespace {

using namespace lawTest;
using namespace connectors;

//- A chain of 100 m in 40 m of water with Morison drag and axial damping
MooringLineParameters chain(int segments)
{
    return references::withTolerance(references::chain100(segments), 1e-7);
}

const BodyKinematics fairlead = body(Vector3(80.0, 0.0, 40.0));
const BodyKinematics anchor = body(Vector3::Zero());

TEST(MooringLine, HeldStillSettlesOnTheQuasiStaticCatenary)
{
    connectors::CatenaryParameters c;
    c.line.length = 100.0;
    c.line.EA = 5e7;
    c.line.weight = chain(10).weight();
    c.line.seabedContact = true;
    const double Tqs = connectors::Catenary(c)
                           .evaluate(fairlead, anchor, nullptr, 0)
                           .fairleadTension;
    double previous = 1.0;
    for (const int N : {5, 10, 20}) {
        MooringLine line(chain(N));
        MooringLineState s = line.initialState(fairlead, anchor, 0.0);
        // 40 s in steps of 0.2 s; the tension averaged over the last 10 s
        double sum = 0.0;
        int samples = 0;
        for (int step = 1; step <= 200; ++step) {
            line.advance(s, fairlead, anchor, 0.2);
            if (step > 150) {
                sum += line.evaluate(s, fairlead, anchor, 0).fairleadTension;
                ++samples;
            }
        }
        double speed = 0.0;
        for (int i = 0; i + 5 < int(s.nodes.size()); i += 6) {
            speed = std::max(
                speed,
                std::hypot(s.nodes[i + 3], s.nodes[i + 4], s.nodes[i + 5]));
        }
        const double T = sum / samples;
        const double difference = std::abs(T - Tqs) / Tqs;
        std::cout << "N = " << N << ": mean fairlead tension " << T
                  << " N, quasi-static " << Tqs << " N, relative difference "
                  << difference << ", largest node speed " << speed
                  << " m/s at 40 s\n";
        // Nearly at rest: quadratic drag removes small motions slowly
        // (amplitude ~ 1/t); residual vibration of a few cm/s moves the
        // tension by ~0.1 %
        EXPECT_LT(speed, 0.1);
        // Straight segments between lumped masses: the static chain differs
        // from the continuous catenary by O(1/N^2) (plus the seabed penalty,
        // a ~2 mm sink); it must shrink with N and stay below 5 % at N = 5.
        EXPECT_LT(difference, 0.05);
        EXPECT_LT(difference, previous);
        previous = difference;
    }
}

//- Transverse frequency of a taut weightless line between fixed ends,
//  coupled at 0.05 s, by CVODE (tolerance 1e-9) or the trapezoidal rule
//  with substeps of at most maxStep (0: none)
double measuredFrequency(int N, bool cvode, double maxStep,
                         double& expectedDiscrete, double& string)
{
    MooringLineParameters p;
    p.length = 100.0;
    p.EA = 1e7;
    p.massPerLength = 50.0;
    p.gravity = 0.0;
    p.segments = N;
    if (cvode) {
        p.integrator = MooringLineParameters::Integrator::cvode;
    }
    p.maxStep = maxStep;
    p.relativeTolerance = 1e-9;
    p.absoluteTolerance = 1e-9;
    MooringLine line(p);
    const BodyKinematics A = body(Vector3(101.0, 0, 0)); // 1 % stretch
    const BodyKinematics B = body(Vector3::Zero());
    MooringLineState s = line.initialState(A, B, 0.0);
    for (int i = 1; i < N; ++i) {
        s.nodes[6 * std::size_t(i - 1) + 1] = 0.1 * std::sin(pi * i / N); // y
    }
    const double stretched = 101.0, T = p.EA * 0.01;
    const double muStretched = p.massPerLength * p.length / stretched;
    string = 0.5 / stretched * std::sqrt(T / muStretched);
    // chain of N equal masses: omega = 2 sqrt(T/(m l)) sin(pi/(2N))
    expectedDiscrete = N / (pi * stretched) * std::sqrt(T / muStretched)
        * std::sin(pi / (2.0 * N));
    const std::size_t mid = 6 * std::size_t(N / 2 - 1) + 1;
    const double h = 0.05;
    double previous = s.nodes[mid], t = 0.0;
    std::vector<double> crossings;
    while (crossings.size() < 5) {
        line.advance(s, A, B, h);
        t += h;
        const double y = s.nodes[mid];
        if ((previous > 0.0) != (y > 0.0)) {
            crossings.push_back(t - h * y / (y - previous));
        }
        previous = y;
    }
    return 2.0 / (crossings.back() - crossings.front()); // 4 half periods
}

TEST(MooringLine, TautLineTransverseFrequency)
{
    double previousError = 1.0;
    for (const int N : {4, 8, 16}) {
        double discrete = 0.0, string = 0.0;
        const double f = measuredFrequency(N, true, 0.0, discrete, string);
        const double error = std::abs(f - string) / string;
        std::cout << "N = " << N << ": f1 = " << f << " Hz, string " << string
                  << " Hz (error " << error << "), chain of N masses "
                  << discrete << " Hz\n";
        // The integrator reproduces the discrete chain's frequency (tolerance
        // 1e-9, crossings interpolated over 0.05 s of a 4.5 s period: 1e-4)
        EXPECT_NEAR(f, discrete, 1e-4 * string);
        // and the discretisation error, ~ pi^2/(24 N^2), shrinks with N
        EXPECT_LT(error, previousError / 3.0);
        EXPECT_LT(error, 0.6 / (N * N));
        previousError = error;
    }
}

TEST(MooringLine, TrapezoidalRulePeriodError)
{
    // The trapezoidal rule turns a linear oscillation of omega into one of
    // (2/h) atan(omega h/2): at h = 0.05 s a taut line's 0.22 Hz is 4e-4
    // slow (N = 8), at substeps of maxStep = 0.005 s 4e-6, within the 1e-4
    // of the frequency that CVODE holds above. The shift between the two
    // is the formula's (measured within 1e-6 Hz of it; the measurement's
    // own bias, 2e-5 Hz in CVODE's frequency above, cancels).
    const int N = 8;
    double discrete = 0.0, string = 0.0;
    const double coupled = measuredFrequency(N, false, 0.0, discrete, string);
    const double substepped
        = measuredFrequency(N, false, 0.005, discrete, string);
    const auto trapezoid = [&](double h) {
        return std::atan(pi * discrete * h) / (pi * h); // (2/h) atan(omega h/2)
    };
    std::cout << "N = " << N << ": chain of N masses " << discrete
              << " Hz; trapezoidal rule at 0.05 s " << coupled
              << " Hz (formula " << trapezoid(0.05) << " Hz), at 0.005 s "
              << substepped << " Hz (formula " << trapezoid(0.005) << " Hz)\n";
    EXPECT_NEAR(substepped - coupled, trapezoid(0.005) - trapezoid(0.05),
                1e-5 * string);
    EXPECT_GT(substepped - coupled, 3e-4 * discrete); // the error is there
    EXPECT_NEAR(substepped, discrete, 1e-4 * string);
}

TEST(MooringLine, RepeatedStepFromASavedStateIsIdentical)
{
    for (const bool cvode : {false, true}) {
        MooringLineParameters p = chain(10);
        if (cvode) {
            p.integrator = MooringLineParameters::Integrator::cvode;
        }
        MooringLine line(p);
        MooringLineState s = line.initialState(fairlead, anchor, 0.0);
        BodyKinematics moving = fairlead;
        for (int step = 0; step < 5; ++step) {
            moving.p_WKo_W[0] += 0.05;
            line.advance(s, moving, anchor, 0.1);
        }
        // uninterrupted: two more steps
        MooringLineState straight = s;
        const MooringLineState saved = s;
        BodyKinematics next = moving;
        next.p_WKo_W[2] += 0.1;
        line.advance(straight, next, anchor, 0.1);
        const std::vector<double> afterOne = straight.serialize();
        next.p_WKo_W[2] += 0.1;
        line.advance(straight, next, anchor, 0.1);
        // restored: an unrelated step in between, then the same two steps
        MooringLineState other = saved;
        line.advance(other, fairlead, anchor, 0.3);
        MooringLineState restored = MooringLineState::deserialize(
            saved.serialize(), line.parameters().segments);
        next = moving;
        next.p_WKo_W[2] += 0.1;
        line.advance(restored, next, anchor, 0.1);
        EXPECT_EQ(restored.serialize(), afterOne) << cvode; // bit for bit
        next.p_WKo_W[2] += 0.1;
        line.advance(restored, next, anchor, 0.1);
        EXPECT_EQ(restored.serialize(), straight.serialize()) << cvode;
        const auto a = line.evaluate(restored, next, anchor, 11);
        const auto b = line.evaluate(straight, next, anchor, 11);
        EXPECT_EQ(a.loads.A.f_W, b.loads.A.f_W);
        EXPECT_EQ(a.shape, b.shape);
        // a fresh line (no integrator history at all) gives the same bits
        MooringLine fresh(p);
        MooringLineState again = MooringLineState::deserialize(
            saved.serialize(), line.parameters().segments);
        next = moving;
        next.p_WKo_W[2] += 0.1;
        fresh.advance(again, next, anchor, 0.1);
        EXPECT_EQ(again.serialize(), afterOne) << cvode;
    }
}

TEST(MooringLine, LoadsBetweenStepsDoNotChangeTheSteps)
{
    // The trapezoidal rule takes the start's forces from the last step's
    // end or the last `evaluate` when the nodes are exactly where they
    // were found (the FMU reports its loads after every step; `evaluate`
    // takes the step's end's likewise): the steps must be the same to the
    // bit as without those calls, and a rollback in between (other inputs
    // evaluated, then the saved state) must not reuse stale ones
    MooringLine quiet(chain(10)), reporting(chain(10));
    MooringLineState a = quiet.initialState(fairlead, anchor, 0.0);
    MooringLineState b = a;
    for (int step = 1; step <= 20; ++step) {
        const BodyKinematics A = body(
            fairlead.p_WKo_W
            + Vector3(0.3 * std::sin(0.5 * step), 0.0, 0.1 * std::cos(step)));
        quiet.advance(a, A, anchor, 0.1);
        reporting.advance(b, A, anchor, 0.1);
        reporting.evaluate(b, A, anchor, 0);
        if (step % 5 == 0) { // a trial step that is rolled back
            MooringLineState trial = b;
            reporting.advance(trial, fairlead, anchor, 0.1);
            reporting.evaluate(trial, fairlead, anchor, 0);
        }
        ASSERT_EQ(a.serialize(), b.serialize()) << step;
    }
    // and the force evaluation is saved: a step held still takes three
    // (start, predictor, end), two after a step, the loads' `evaluate`
    // none (the step's end's serve it)
    MooringLine still(chain(10));
    MooringLineState s = still.initialState(fairlead, anchor, 0.0);
    const long n0 = still.statistics().rhsEvaluations;
    still.advance(s, fairlead, anchor, 0.1);
    const long n1 = still.statistics().rhsEvaluations;
    still.evaluate(s, fairlead, anchor, 0);
    still.advance(s, fairlead, anchor, 0.1);
    EXPECT_EQ(n1 - n0, 3);
    EXPECT_EQ(still.statistics().rhsEvaluations - n1, 2);
}

TEST(MooringLine, EnergyBalance)
{
    // Work done by the bodies on the line = change of its potential and
    // kinetic energy + dissipated energy. No added mass (its configuration
    // dependent mass matrix is not energy consistent) and no seabed.
    for (const bool cvode : {false, true}) {
        MooringLineParameters p = chain(10);
        p.normalAddedMass = 0.0;
        p.seabedContact = false;
        // the ends' half segments' inertia on the bodies: their kinetic
        // energy is the line's
        p.endInertia = true;
        if (cvode) {
            p.integrator = MooringLineParameters::Integrator::cvode;
        }
        p.relativeTolerance = 1e-9;
        p.absoluteTolerance = 1e-9;
        MooringLine line(p);
        const auto fairleadAt = [](double t) {
            const double r
                = t < 5.0 ? 0.5 * (1.0 - std::cos(pi * t / 5.0)) : 1.0;
            const double dr
                = t < 5.0 ? 0.5 * pi / 5.0 * std::sin(pi * t / 5.0) : 0.0;
            return body(Vector3(70.0 + 2.0 * r * std::sin(0.5 * t), 0.0, 10.0),
                        Matrix3::Identity(),
                        Vector3(2.0
                                    * (dr * std::sin(0.5 * t)
                                       + 0.5 * r * std::cos(0.5 * t)),
                                0.0, 0.0));
        };
        const BodyKinematics B = body(Vector3::Zero());
        const double l = p.length / p.segments;
        // the free nodes' and the ends' half segments (endInertia: the
        // bodies feel the ends' inertia, so their energy is the line's)
        const auto kinetic = [&](const MooringLineState& s) {
            double e = 0.25 * p.massPerLength * l
                * (s.vP.squaredNorm() + s.vQ.squaredNorm());
            for (std::size_t i = 0; i + 5 < s.nodes.size(); i += 6) {
                e += 0.5 * p.massPerLength * l
                    * (s.nodes[i + 3] * s.nodes[i + 3]
                       + s.nodes[i + 4] * s.nodes[i + 4]
                       + s.nodes[i + 5] * s.nodes[i + 5]);
            }
            return e;
        };
        MooringLineState s = line.initialState(fairleadAt(0.0), B, 0.0);
        auto out = line.evaluate(s, fairleadAt(0.0), B, 0);
        const double energy0 = out.loads.potentialEnergy + kinetic(s);
        double power = -out.loads.A.f_W.dot(fairleadAt(0.0).v_WKo_W);
        double dissipation = out.loads.dissipatedPower;
        double work = 0.0, dissipated = 0.0, throughput = 0.0;
        const double h = 0.01;
        for (int k = 1; k <= 1000; ++k) {
            const BodyKinematics A = fairleadAt(k * h);
            line.advance(s, A, B, h);
            out = line.evaluate(s, A, B, 0);
            const double newPower = -out.loads.A.f_W.dot(A.v_WKo_W);
            work += 0.5 * h * (power + newPower); // trapezoid
            throughput += 0.5 * h * (std::abs(power) + std::abs(newPower));
            dissipated += 0.5 * h * (dissipation + out.loads.dissipatedPower);
            power = newPower;
            dissipation = out.loads.dissipatedPower;
            EXPECT_GE(out.loads.dissipatedPower, 0.0);
        }
        const double change = out.loads.potentialEnergy + kinetic(s) - energy0;
        std::cout << "work in " << work << " J, energy change " << change
                  << " J, dissipated " << dissipated << " J, imbalance "
                  << work - change - dissipated << " J of " << throughput
                  << " J through the fairlead\n";
        // Trapezoidal power integrals over 0.01 s steps of a 0.5 rad/s
        // motion: errors of order (omega h)^2/12 = 2e-6 of the energy that
        // flows through the fairlead; measured 4e-7 (trapezoidal rule) and
        // 9e-7 (CVODE, tolerance 1e-9) without the ends' inertia, 5.0e-6
        // and 5.4e-6 with it (the end acceleration from the step's Hermite
        // path, second order in h); 1e-5 asserted.
        EXPECT_NEAR(work, change + dissipated, 1e-5 * throughput) << cvode;
        EXPECT_GT(dissipated, 0.01 * throughput); // drag and damping did work
    }
}

TEST(MooringLine, StateSerialization)
{
    MooringLine line(chain(6));
    const MooringLineState s = line.initialState(fairlead, anchor, 2.5);
    const std::vector<double> data = s.serialize();
    // time, 6 end vectors, 5 free nodes, the Newton matrix: its step, 20
    // values per free node and 4 per segment
    ASSERT_EQ(data.size(), 19u + 6u * 5u + 1u + 20u * 5u + 4u * 6u);
    const MooringLineState back = MooringLineState::deserialize(data, 6);
    EXPECT_EQ(back.time, 2.5);
    EXPECT_EQ(back.P, s.P);
    EXPECT_EQ(back.Q, s.Q);
    EXPECT_EQ(back.vP, s.vP);
    EXPECT_EQ(back.vQ, s.vQ);
    EXPECT_EQ(back.nodes, s.nodes);
    expectThrowWithMessage<std::invalid_argument>(
        [&] { MooringLineState::deserialize(data, 7); },
        "mooringLine: a saved state of 174 values does not fit a line of 7 "
        "segments (204 values)");
}

TEST(MooringLine, LoadsAndShapeAtTheStart)
{
    // At the start the line is the quasi-static catenary: shape ends on
    // P and Q, the anchor pulled horizontally only (seabed contact)
    MooringLine line(chain(10));
    const MooringLineState s = line.initialState(fairlead, anchor, 0.0);
    const auto out = line.evaluate(s, fairlead, anchor, 11);
    expectVectorNear(out.shape.front(), fairlead.p_WKo_W, 0.0);
    expectVectorNear(out.shape.back(), Vector3::Zero(), 0.0);
    EXPECT_GT(out.groundedLength, 0.0);
    EXPECT_LT(out.loads.A.f_W[0], 0.0); // pulled towards the anchor
    EXPECT_GT(out.V, 0.0); // and down
    EXPECT_GE(out.loads.dissipatedPower, 0.0);
    expectAllFinite(out.loads);
}

} // namespace
