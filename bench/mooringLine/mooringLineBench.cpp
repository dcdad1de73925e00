// mooringLineBench: the dynamic line coupled at CFD-like steps.
//
// Two reference lines (issue 15): the lab chain (1.2 m in 0.5 m of water,
// fairlead surging 0.01 m with a period of 1 s) and the OC4 line (835.5 m
// in 200 m, 1 m surge, 10 s). The surge is ramped in over the first period,
// x0 + A r(t) sin(2 pi t/T), r = (1 - cos(pi t/T))/2; positions and
// velocities are given at the end of every coupling step h, as the bridge
// gives them. Measured: the first-harmonic amplitude of the fairlead
// tension over the third period, its error against a converged reference
// (N = 80, CVODE tolerance 1e-9; 1 ms for the lab chain, 0.01 s for OC4),
// and the wall time per simulated second (one run, steady_clock).
//
// Rows: N, coupling step h, CVODE tolerance (relative = absolute), the
// amplitude error [%], the same N and tolerance at the fine step [%], their
// difference [percentage points], wall time per simulated second at h and
// at the fine step. The fine steps are 2e-4 s (lab) and 0.01 s (OC4): the
// cubic Hermite end path's own error there, h^4/384 times the fourth
// derivative of the motion, is 6e-17 m and 4e-12 m, so they stand for the
// resolved answer.
//
// Usage: mooringLineBench [lab|oc4] (default both; about a minute), or
//        mooringLineBench lab|oc4 N h [CVODE tolerance] (one run)
#include <chrono>
#include <cmath>
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
constexpr double pi = 3.14159265358979323846;

struct Case {
    references::ReferenceLine line;
    double amplitude, period, fineStep, referenceStep;
    std::vector<double> steps, tolerances;
};

Case lab()
{
    return {references::lab(20), 0.01, 1.0, 2e-4, 1e-3, {1e-3}, {1e-6, 1e-8}};
}

Case oc4()
{
    return {references::oc4(20), 1.0, 10.0, 1e-2, 1e-2, {0.1}, {1e-6}};
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
    A.p_WBo_W = c.line.fairlead
        + Vector3(c.amplitude * r * std::sin(w * t), 0.0, 0.0);
    A.v_WBo_W = Vector3(c.amplitude
                            * (dr * std::sin(w * t) + r * w * std::cos(w * t)),
                        0.0, 0.0);
    return A;
}

struct Result {
    double amplitude = 0.0, wallPerSecond = 0.0;
};

//- First harmonic of the fairlead tension over the third period
Result run(const Case& c, int N, double h, double tolerance = 1e-6)
{
    MooringLineParameters p = c.line.p;
    p.segments = N;
    p.relativeTolerance = p.absoluteTolerance = tolerance;
    MooringLine line(p);
    BodyKinematics B;
    B.p_WBo_W = c.line.anchor;
    const int perPeriod = int(std::lround(c.period / h));
    const auto start = Clock::now();
    MooringLineState s = line.initialState(fairleadAt(c, 0.0), B, 0.0);
    std::complex<double> a1 = 0.0;
    for (int k = 1; k <= 3 * perPeriod; ++k) {
        const double t = k * h;
        const BodyKinematics A = fairleadAt(c, t);
        line.advance(s, A, B, h);
        if (k
            > 2 * perPeriod) { // rectangle rule: exact for a periodic trigonometric sum
            const double T = line.evaluate(s, A, B, 0).fairleadTension;
            a1 += T
                * std::exp(std::complex<double>(0.0, -2.0 * pi * t / c.period));
        }
    }
    Result r;
    r.wallPerSecond
        = std::chrono::duration<double>(Clock::now() - start).count()
        / (3.0 * c.period);
    r.amplitude = 2.0 * std::abs(a1) / perPeriod;
    return r;
}

void bench(const Case& c)
{
    const double reference = run(c, 80, c.referenceStep, 1e-9).amplitude;
    std::printf(
        "%s: first-harmonic fairlead tension amplitude %.6g N (N = 80, h = %g s, "
        "tolerance 1e-9)\n",
        c.line.name, reference, c.referenceStep);
    std::printf("%4s %8s %9s %10s %10s %9s %12s %12s\n", "N", "h [s]",
                "tolerance", "error [%]", "fine [%]", "diff [pp]", "wall [s/s]",
                "fine [s/s]");
    for (const int N : {10, 20, 40}) {
        for (const double tolerance : c.tolerances) {
            const Result fine = run(c, N, c.fineStep, tolerance);
            const double fineError = 100.0 * (fine.amplitude / reference - 1.0);
            for (const double h : c.steps) {
                const Result r = run(c, N, h, tolerance);
                const double error = 100.0 * (r.amplitude / reference - 1.0);
                std::printf("%4d %8g %9g %10.3f %10.3f %9.3f %12.4g %12.4g\n",
                            N, h, tolerance, error, fineError,
                            error - fineError, r.wallPerSecond,
                            fine.wallPerSecond);
                std::fflush(stdout);
            }
        }
    }
}

} // namespace

int main(int argc, char** argv)
{
    if (argc == 4 || argc == 5) { // one run: lab|oc4 N h [tolerance]
        const Case c = std::strcmp(argv[1], "lab") == 0 ? lab() : oc4();
        const Result r = run(c, std::atoi(argv[2]), std::atof(argv[3]),
                             argc == 5 ? std::atof(argv[4]) : 1e-6);
        std::printf(
            "%s N = %s h = %s: amplitude %.9g N, wall %.4g s per simulated s\n",
            c.line.name, argv[2], argv[3], r.amplitude, r.wallPerSecond);
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
