// mooringLineBench: the dynamic line coupled at CFD-like steps.
//
// Two reference lines (issue 15): the lab chain (1.2 m in 0.5 m of water,
// fairlead surging 0.01 m with a period of 1 s) and the OC4 line (835.5 m
// in 200 m, 1 m surge, 10 s). The surge is ramped in over the first period,
// x0 + A r(t) sin(2 pi t/T), r = (1 - cos(pi t/T))/2; positions and
// velocities are given at the end of every coupling step h, as the bridge
// gives them. Measured: the first-harmonic amplitude of the fairlead
// tension over the third period, its error against a converged reference
// (N = 80, trapezoidal rule at the fine step), the same N at the fine step,
// and the cost per simulated second (the start equilibrium not counted):
// wall time (steady_clock) and this thread's CPU time, which on a loaded
// machine leaves out the time other processes held the core.
//
// Rows: N, coupling step h, integrator (trapezoid: the implicit
// trapezoidal rule; CVODE with its tolerance, relative = absolute), the
// amplitude error [%], the same N by the trapezoidal rule at the fine step
// [%], their difference [percentage points], CPU and wall time per
// simulated second, force evaluations per coupling step (the loads are
// evaluated after every step, as the FMU reports them). The fine steps
// are 1e-5 s (lab) and 1e-4 s (OC4): the trapezoidal rule's error is
// second order in h (the harmonic at 1 ms differs from that at 1e-5 s by
// less than 2e-3 pp, lab chain, N = 20), and the cubic Hermite end path's
// own error, h^4/384 times the fourth derivative of the motion, is far
// below that.
//
// Usage: mooringLineBench [lab|oc4] (default both; a few minutes), or
//        mooringLineBench lab|oc4 N h [CVODE tolerance] (one run; the
//        trapezoidal rule without a tolerance), or
//        mooringLineBench friction N h mu [surge [period [vf [surge|sway
//        [r]]]]] (the lab chain with seabed friction; frictionRow)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "MooringLineReferences.hpp"
#include "mooringLine/MooringLine.hpp"

namespace {

using namespace connectors;
using Clock = std::chrono::steady_clock;

//- CPU time of this thread [s]: on a loaded machine the wall time also
//  counts the time other processes held the core
double cpuSeconds()
{
    timespec t {};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}
constexpr double pi = 3.14159265358979323846;

struct Case {
    references::ReferenceLine line;
    double amplitude, period, fineStep;
    //- Coupling steps of the table; CVODE's tolerance for the comparison
    std::vector<double> steps;
    double cvodeTolerance;
    //- The fairlead's direction of motion: surge (x) or sway (y)
    Vector3 direction = Vector3::UnitX();
};

Case lab()
{
    return {references::lab(20), 0.01, 1.0, 1e-5, {1e-3}, 1e-8};
}

Case oc4()
{
    return {references::oc4(20), 1.0, 10.0, 1e-4, {0.1, 0.01}, 1e-6};
}

BodyKinematics fairleadAt(const Case& c, double t)
{
    const double w = 2.0 * pi / c.period;
    const double r
        = t < c.period ? 0.5 * (1.0 - std::cos(pi * t / c.period)) : 1.0;
    const double dr = t < c.period
        ? 0.5 * pi / c.period * std::sin(pi * t / c.period)
        : 0.0;
    BodyKinematics A;
    A.p_WKo_W
        = c.line.fairlead + c.direction * c.amplitude * r * std::sin(w * t);
    A.v_WKo_W = c.direction * c.amplitude
        * (dr * std::sin(w * t) + r * w * std::cos(w * t));
    return A;
}

struct Result {
    double amplitude = 0.0, wallPerSecond = 0.0, cpuPerSecond = 0.0;
    //- Force evaluations (the integrator's and the loads') and
    //  integrator steps per coupling step
    double forcesPerStep = 0.0, stepsPerStep = 0.0;
    //- Newton matrices formed per coupling step (trapezoidal rule; a step
    //  reuses the one before while it serves)
    double matricesPerStep = 0.0;
};

//- First harmonic of the fairlead tension over the third period
//  (CVODE at `tolerance`, or the trapezoidal rule where tolerance is 0)
Result run(const Case& c, int N, double h, double tolerance = 0.0)
{
    MooringLineParameters p = c.line.p;
    p.segments = N;
    if (tolerance > 0.0) {
        p.integrator = MooringLineParameters::Integrator::cvode;
        p.relativeTolerance = p.absoluteTolerance = tolerance;
    }
    MooringLine line(p);
    BodyKinematics B;
    B.p_WKo_W = c.line.anchor;
    const int perPeriod = int(std::lround(c.period / h));
    MooringLineState s = line.initialState(fairleadAt(c, 0.0), B, 0.0);
    const auto start = Clock::now();
    const double cpuStart = cpuSeconds();
    std::complex<double> a1 = 0.0;
    for (int k = 1; k <= 3 * perPeriod; ++k) {
        const double t = k * h;
        const BodyKinematics A = fairleadAt(c, t);
        line.advance(s, A, B, h);
        // the loads after every step, as the FMU reports them
        const double T = line.evaluate(s, A, B, 0).fairleadTension;
        if (k > 2 * perPeriod) { // rectangle rule: exact for a periodic
            // trigonometric sum
            a1 += T
                * std::exp(std::complex<double>(0.0, -2.0 * pi * t / c.period));
        }
    }
    Result r;
    r.wallPerSecond
        = std::chrono::duration<double>(Clock::now() - start).count()
        / (3.0 * c.period);
    r.cpuPerSecond = (cpuSeconds() - cpuStart) / (3.0 * c.period);
    r.amplitude = 2.0 * std::abs(a1) / perPeriod;
    const CvodeBdf::Statistics st = line.statistics();
    // + the loads' evaluation after each step (the trapezoidal rule's
    // takes the forces its step's end found)
    r.forcesPerStep = double(st.rhsEvaluations) / (3 * perPeriod)
        + (tolerance > 0.0 ? 1.0 : 0.0);
    r.stepsPerStep = double(st.steps) / (3 * perPeriod);
    r.matricesPerStep = double(st.jacobianEvaluations) / (3 * perPeriod);
    return r;
}

void bench(const Case& c)
{
    const double reference = run(c, 80, c.fineStep).amplitude;
    std::printf("%s: first-harmonic fairlead tension amplitude %.6g N (N = 80, "
                "trapezoidal rule, h = %g s)\n",
                c.line.name, reference, c.fineStep);
    std::printf("%4s %7s %15s %10s %9s %10s %11s %11s %9s\n", "N", "h [s]",
                "integrator", "error [%]", "fine [%]", "diff [pp]", "CPU [s/s]",
                "wall [s/s]", "forces");
    for (const int N : {10, 20, 40}) {
        const double fine
            = 100.0 * (run(c, N, c.fineStep).amplitude / reference - 1.0);
        for (const double h : c.steps) {
            for (const double tolerance : {0.0, c.cvodeTolerance}) {
                const Result r = run(c, N, h, tolerance);
                const double error = 100.0 * (r.amplitude / reference - 1.0);
                char integrator[32];
                std::snprintf(integrator, sizeof integrator,
                              tolerance > 0.0 ? "CVODE %g" : "trapezoid",
                              tolerance);
                std::printf(
                    "%4d %7g %15s %10.3f %9.3f %10.3f %11.3g %11.3g %9.3g\n", N,
                    h, integrator, error, fine, error - fine, r.cpuPerSecond,
                    r.wallPerSecond, r.forcesPerStep);
                std::fflush(stdout);
            }
        }
    }
}

//- Work-precision: error against the same N at the fine step and against
//  N = 80, and CPU time, over N, coupling step and CVODE's tolerance
void workPrecision(const Case& c, const std::vector<double>& steps,
                   double cvodeStep)
{
    const double reference = run(c, 80, c.fineStep).amplitude;
    std::printf("%s: work-precision (tension harmonic; time error against the "
                "same N at %g s, total against N = 80)\n",
                c.line.name, c.fineStep);
    std::printf("%4s %7s %15s %14s %15s %11s\n", "N", "h [s]", "integrator",
                "time err [pp]", "total err [%]", "CPU [s/s]");
    for (const int N : {10, 20, 40}) {
        const double fine = run(c, N, c.fineStep).amplitude;
        const auto row = [&](double h, double tolerance) {
            const Result r = run(c, N, h, tolerance);
            char integrator[32];
            std::snprintf(integrator, sizeof integrator,
                          tolerance > 0.0 ? "CVODE %g" : "trapezoid",
                          tolerance);
            std::printf("%4d %7g %15s %14.4f %15.3f %11.3g\n", N, h, integrator,
                        100.0 * (r.amplitude - fine) / reference,
                        100.0 * (r.amplitude / reference - 1.0),
                        r.cpuPerSecond);
            std::fflush(stdout);
        };
        for (const double h : steps) {
            row(h, 0.0);
        }
        for (const double tolerance : {1e-6, 1e-8, 1e-10}) {
            row(cvodeStep, tolerance);
        }
    }
}

//- The snap (references::pullTaut) of the lab chain at N, h, with or
//  without added mass, by the trapezoidal rule or CVODE at `tolerance`;
//  cpu: CPU time of the run [s]
references::Snap snap(int N, double h, bool addedMass, double tolerance,
                      double& cpu)
{
    references::ReferenceLine line = references::lab(N);
    MooringLineParameters& p = line.p;
    if (!addedMass) {
        p.normalAddedMass = p.tangentialAddedMass = 0.0;
    }
    if (tolerance > 0.0) {
        p.integrator = MooringLineParameters::Integrator::cvode;
        p.relativeTolerance = p.absoluteTolerance = tolerance;
    }
    const double start = cpuSeconds();
    const references::Snap result = references::pullTaut(line, h, 2.0);
    cpu = cpuSeconds() - start;
    return result;
}

void snapTable()
{
    std::printf("lab chain snap: fairlead pulled to 0.9997 L in 0.5 s, held "
                "to 2 s\n");
    std::printf("%4s %7s %15s %11s %9s %11s %15s %10s %9s\n", "N", "h [s]",
                "integrator", "added mass", "peak [N]", "at [s]",
                "imbalance [J]", "of [J]", "CPU [s]");
    const auto row = [](int N, double h, bool addedMass, double tolerance) {
        double cpu = 0.0;
        const references::Snap r = snap(N, h, addedMass, tolerance, cpu);
        char integrator[32];
        std::snprintf(integrator, sizeof integrator,
                      tolerance > 0.0 ? "CVODE %g" : "trapezoid", tolerance);
        std::printf("%4d %7g %15s %11s %9.4g %11.4f %15.3g %10.3g %9.3g%s\n", N,
                    h, integrator, addedMass ? "yes" : "no", r.peak, r.peakTime,
                    r.imbalance, r.throughput, cpu,
                    r.finite ? "" : " (not finite)");
        std::fflush(stdout);
    };
    for (const int N : {10, 20, 40, 80}) {
        row(N, 1e-3, true, 0.0);
        row(N, 1e-4, true, 0.0);
        row(N, 1e-3, false, 0.0);
    }
    row(20, 1e-3, true, 1e-8);
    row(20, 1e-3, false, 1e-8);
}

//- Seabed friction against MoorDyn's (moordyn/moordynDriver.cpp with
//  mu=): the lab chain at N, h with seabedFriction mu and frictionVelocity
//  vf (and axialFrictionRatio r: 1, isotropic, as MoorDyn's), its
//  fairlead surging (or swaying) `surge` m with period T (as
//  `run`); over the third period the fairlead tension's mean, first and
//  second harmonics (a sway's tension has twice its frequency), and how
//  the grounded free nodes (below the seabed, z < Q's z) move: their mean
//  number, their largest horizontal speed, the share of their node-steps
//  faster than vf (friction saturated at mu Fn), and their push on the
//  seabed Fn (the law's: kb (zb - z) d l - cb s vz d l, s the damping's
//  ramp) over their submerged weight w l, weighted by |v_h|^2 (as the
//  friction's power below vf: mu Fn |v_h|^2/vf, MoorDyn's mu C |v_h|^2)
void frictionRow(int N, double h, double mu, double surge, double period,
                 double vf, bool sway, double r)
{
    Case c = lab();
    c.amplitude = surge;
    c.period = period;
    c.direction = sway ? Vector3::UnitY() : Vector3::UnitX();
    MooringLineParameters p = c.line.p;
    p.segments = N;
    p.seabedFriction = mu;
    p.frictionVelocity = vf;
    p.axialFrictionRatio = r;
    MooringLine line(p);
    BodyKinematics B;
    B.p_WKo_W = c.line.anchor;
    const int perPeriod = int(std::lround(period / h));
    MooringLineState s = line.initialState(fairleadAt(c, 0.0), B, 0.0);
    const double cpuStart = cpuSeconds();
    std::complex<double> a1 = 0.0, a2 = 0.0;
    double mean = 0.0, grounded = 0.0, fastest = 0.0, sliding = 0.0;
    double pushed = 0.0, squares = 0.0;
    const double l = p.length / N, d = p.diameter;
    const double wl
        = (p.massPerLength - p.waterDensity * pi / 4.0 * d * d) * p.gravity * l;
    const double restDepth = wl / (p.seabedStiffness * d * l);
    for (int k = 1; k <= 3 * perPeriod; ++k) {
        const double t = k * h;
        const BodyKinematics A = fairleadAt(c, t);
        line.advance(s, A, B, h);
        const double T = line.evaluate(s, A, B, 0).fairleadTension;
        if (k <= 2 * perPeriod) {
            continue;
        }
        mean += T;
        a1 += T * std::exp(std::complex<double>(0.0, -2.0 * pi * t / period));
        a2 += T * std::exp(std::complex<double>(0.0, -4.0 * pi * t / period));
        for (std::size_t i = 0; i + 5 < s.nodes.size(); i += 6) {
            const double depth = B.p_WKo_W.z() - s.nodes[i + 2];
            if (depth > 0.0) {
                const double v = std::hypot(s.nodes[i + 3], s.nodes[i + 4]);
                const double push = d * l
                    * (p.seabedStiffness * depth
                       - p.seabedDamping * std::min(depth / restDepth, 1.0)
                           * s.nodes[i + 5]);
                pushed += std::max(push, 0.0) / wl * v * v;
                squares += v * v;
                grounded += 1.0;
                fastest = std::max(fastest, v);
                sliding += v > vf ? 1.0 : 0.0;
            }
        }
    }
    std::printf(
        "friction N = %d h = %g mu = %g vf = %g r = %g %s %g m period %g "
        "s: mean %.9g N, amplitude %.9g N, second %.9g N; grounded "
        "nodes %.3g, fastest %.3g m/s, faster than vf %.3g of "
        "node-steps, push %.3g w l; CPU %.3g s per simulated s\n",
        N, h, mu, vf, r, sway ? "sway" : "surge", surge, period,
        mean / perPeriod, 2.0 * std::abs(a1) / perPeriod,
        2.0 * std::abs(a2) / perPeriod, grounded / perPeriod, fastest,
        grounded > 0.0 ? sliding / grounded : 0.0,
        squares > 0.0 ? pushed / squares : 0.0,
        (cpuSeconds() - cpuStart) / (3.0 * period));
}

} // namespace

//- Slack-taut forcing (references::slackTaut): the lab chain's fairlead
//  surging 0.112 m at 1 Hz for 10 s at N, h, by the trapezoidal rule or
//  CVODE at `tolerance`
void slackTautRow(int N, double h, double tolerance)
{
    references::ReferenceLine line = references::lab(N);
    if (tolerance > 0.0) {
        line.p.integrator = MooringLineParameters::Integrator::cvode;
        line.p.relativeTolerance = line.p.absoluteTolerance = tolerance;
    }
    const double start = cpuSeconds();
    const references::Snap r = references::slackTaut(line, 0.112, 1.0, h, 10.0);
    std::printf(
        "slack-taut N = %d h = %g tolerance %g: work %.6g J, energy "
        "change %.6g J, dissipated %.6g J, unreported %.4g J (%.3g of "
        "%.6g J through the fairlead); the scheme's work %.6g J, "
        "unreported %.3g of the throughput; the energy account "
        "(stepEnergy: added mass %.3g J, dissipated %.6g J) unexplained "
        "%.3g of it; harmonic %.8g N, peak %.5g N, CPU %.3g s\n",
        N, h, tolerance, r.work, r.change, r.dissipated, r.imbalance,
        r.imbalance / r.throughput, r.throughput, r.stepWork,
        r.stepImbalance / r.throughput, r.account.addedMass,
        r.account.dissipated(), r.accountImbalance / r.throughput, r.harmonic,
        r.peak, cpuSeconds() - start);
    std::fflush(stdout);
}

int main(int argc, char** argv)
{
    if ((argc == 4 || argc == 5) && std::strcmp(argv[1], "slacktaut") == 0) {
        slackTautRow(std::atoi(argv[2]), std::atof(argv[3]),
                     argc == 5 ? std::atof(argv[4]) : 0.0);
        return 0;
    }
    if (argc >= 5 && argc <= 10 && std::strcmp(argv[1], "friction") == 0) {
        // friction N h mu [surge [period [vf [surge|sway [r]]]]]
        frictionRow(std::atoi(argv[2]), std::atof(argv[3]), std::atof(argv[4]),
                    argc > 5 ? std::atof(argv[5]) : 0.01,
                    argc > 6 ? std::atof(argv[6]) : 1.0,
                    argc > 7 ? std::atof(argv[7]) : 0.01,
                    argc > 8 && std::strcmp(argv[8], "sway") == 0,
                    argc > 9 ? std::atof(argv[9]) : 1.0);
        return 0;
    }
    if (argc == 5 && std::strcmp(argv[1], "snap") == 0) { // snap N h tol
        double cpu = 0.0;
        const references::Snap r = snap(std::atoi(argv[2]), std::atof(argv[3]),
                                        true, std::atof(argv[4]), cpu);
        std::printf("snap N = %s h = %s tolerance %s: peak %.6g N at %.5g s, "
                    "imbalance %.3g J of %.3g J, CPU %.3g s, final %.6g N\n",
                    argv[2], argv[3], argv[4], r.peak, r.peakTime, r.imbalance,
                    r.throughput, cpu, r.final);
        return 0;
    }
    if (argc == 4 || argc == 5) { // one run: lab|oc4 N h [tolerance]
        const Case c = std::strcmp(argv[1], "lab") == 0 ? lab() : oc4();
        const Result r = run(c, std::atoi(argv[2]), std::atof(argv[3]),
                             argc == 5 ? std::atof(argv[4]) : 0.0);
        std::printf(
            "%s N = %s h = %s: amplitude %.9g N, wall %.4g s (CPU %.4g s) "
            "per simulated s, per coupling step %.3g steps, %.3g force "
            "evaluations, %.3g Newton matrices\n",
            c.line.name, argv[2], argv[3], r.amplitude, r.wallPerSecond,
            r.cpuPerSecond, r.stepsPerStep, r.forcesPerStep, r.matricesPerStep);
        return 0;
    }
    if (argc == 2 && std::strcmp(argv[1], "precision") == 0) {
        workPrecision(lab(), {4e-3, 2e-3, 1e-3, 5e-4}, 1e-3);
        workPrecision(oc4(), {0.4, 0.2, 0.1, 0.01}, 0.1);
        return 0;
    }
    if (argc == 2 && std::strcmp(argv[1], "snap") == 0) {
        snapTable();
        return 0;
    }
    const bool all = argc < 2;
    if (all || std::strcmp(argv[1], "lab") == 0) {
        bench(lab());
    }
    if (all || std::strcmp(argv[1], "oc4") == 0) {
        bench(oc4());
    }
    return 0;
}
