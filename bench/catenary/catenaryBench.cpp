// catenaryBench: cost of the mooring line laws.
//
// 1. Quasi-static catenary (100 m chain, 40 m of water, seabed friction
//    0.5): a fairlead drifting 0.02 m per call from a slack line mostly on
//    the seabed to a nearly taut one, solved cold (no previous solution)
//    and warm (from the previous H, V); time per profile solve, Newton
//    iterations, and time per full law evaluation (3D loads, energy, 11
//    shape points).
// 2. Dynamic lumped-mass line, same chain without friction, fairlead
//    surging 3 m and heaving 1 m (motion ramped in over 5 s, velocities
//    given consistently: the axial damping of the end segment uses them)
//    for 15 s in steps of 0.05 s: cpu time per simulated second against the
//    RMS error of the fairlead tension, for several N and CVODE
//    tolerances. Reference: N = 80, tolerances 1e-8.
// Each timing is the best of 2 runs (steady_clock); the reference runs once.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "catenary/Catenary.hpp"
#include "mooringLine/MooringLine.hpp"
#include "MooringLineReferences.hpp"

namespace {

using namespace connectors;
using Clock = std::chrono::steady_clock;

template <class Body> double bestSeconds(Body&& body, int runs = 2)
{
    double best = 1e300;
    for (int run = 0; run < runs; ++run) {
        const auto start = Clock::now();
        body();
        best = std::min(
            best, std::chrono::duration<double>(Clock::now() - start).count());
    }
    return best;
}

void quasiStatic()
{
    // length [m], EA [N], weight [N/m], seabed friction, seabed contact
    const CatenaryLine line {100.0, 5e7, 700.0, 0.5, true, {}};
    std::vector<std::pair<double, double>> path;
    for (double x = 62.0; x < 92.0; x += 0.02) {
        path.emplace_back(x, 40.0 + 5.0 * std::sin(x));
    }
    long coldIterations = 0, warmIterations = 0;
    double sink = 0.0;
    const double cold = bestSeconds([&] {
        coldIterations = 0;
        for (const auto& [x, z] : path) {
            const CatenarySolution s = solveCatenary(line, x, z);
            coldIterations += s.iterations;
            sink += s.H;
        }
    });
    const double warm = bestSeconds([&] {
        warmIterations = 0;
        CatenaryGuess guess {};
        for (const auto& [x, z] : path) {
            const CatenarySolution s
                = solveCatenary(line, x, z, guess.H > 0.0 ? &guess : nullptr);
            warmIterations += s.iterations;
            guess = {s.H, s.V};
            sink += s.H;
        }
    });
    CatenaryParameters p;
    p.line = line;
    const Catenary law(p);
    const double full = bestSeconds([&] {
        CatenaryGuess guess {};
        for (const auto& [x, z] : path) {
            BodyKinematics A;
            A.p_WKo_W = Vector3(x, 0.0, z);
            const CatenaryOutput o = law.evaluate(
                A, BodyKinematics(), guess.H > 0.0 ? &guess : nullptr, 11);
            guess = {o.solution.H, o.solution.V};
            sink += o.loads.A.f_W[0];
        }
    });
    const double n = double(path.size());
    std::printf("## Quasi-static catenary (%zu solves along the path)\n\n",
                path.size());
    std::printf("| solve | time per solve | Newton iterations per solve |\n");
    std::printf("| --- | --- | --- |\n");
    std::printf("| cold | %.2f us | %.2f |\n", 1e6 * cold / n,
                coldIterations / n);
    std::printf("| warm | %.2f us | %.2f |\n", 1e6 * warm / n,
                warmIterations / n);
    std::printf(
        "| warm, full law (loads, energy, 11 shape points) | %.2f us | |\n\n",
        1e6 * full / n);
    if (sink == 42.0) {
        std::printf("\n"); // keeps the loops from being optimised away
    }
}

BodyKinematics fairlead(double t)
{
    constexpr double pi = 3.14159265358979323846, ramp = 5.0;
    const double r = t < ramp ? 0.5 * (1.0 - std::cos(pi * t / ramp)) : 1.0;
    const double dr
        = t < ramp ? 0.5 * pi / ramp * std::sin(pi * t / ramp) : 0.0;
    const double sx = 3.0 * std::sin(0.4 * t), sz = std::sin(0.8 * t);
    BodyKinematics A;
    A.p_WKo_W = Vector3(80.0 + r * sx, 0.0, 40.0 + r * sz);
    A.v_WKo_W = Vector3(dr * sx + r * 1.2 * std::cos(0.4 * t), 0.0,
                        dr * sz + r * 0.8 * std::cos(0.8 * t));
    return A;
}

MooringLineParameters chain(int N, double tolerance)
{
    return references::withTolerance(references::chain100(N), tolerance);
}

constexpr double duration = 15.0, step = 0.05;

std::vector<double> tensionHistory(int N, double tolerance, double& seconds,
                                   long& steps, int runs = 2)
{
    std::vector<double> history;
    seconds = bestSeconds(
        [&] {
            history.clear();
            MooringLine line(chain(N, tolerance));
            MooringLineState s
                = line.initialState(fairlead(0.0), BodyKinematics(), 0.0);
            for (int k = 1; k * step <= duration + 1e-9; ++k) {
                line.advance(s, fairlead(k * step), BodyKinematics(), step);
                history.push_back(
                    line.evaluate(s, fairlead(k * step), BodyKinematics(), 0)
                        .fairleadTension);
            }
            steps = line.statistics().steps;
        },
        runs);
    return history;
}

void dynamic()
{
    double referenceSeconds = 0.0;
    long referenceSteps = 0;
    const std::vector<double> reference
        = tensionHistory(80, 1e-8, referenceSeconds, referenceSteps, 1);
    double rms = 0.0;
    for (const double T : reference) {
        rms += T * T;
    }
    rms = std::sqrt(rms / double(reference.size()));
    std::printf(
        "## Dynamic line (%.0f s of fairlead motion, steps of %.2f s)\n\n",
        duration, step);
    std::printf(
        "Reference N = 80, tolerances 1e-8: %.3f s cpu per simulated second, "
        "RMS fairlead tension %.0f N.\n\n",
        referenceSeconds / duration, rms);
    std::printf(
        "| N | tolerance | cpu s per simulated s | CVODE steps per step | RMS tension "
        "error |\n");
    std::printf("| --- | --- | --- | --- | --- |\n");
    for (const int N : {5, 10, 20, 40}) {
        for (const double tolerance : {1e-4, 1e-6, 1e-8}) {
            double seconds = 0.0;
            long steps = 0;
            const std::vector<double> T
                = tensionHistory(N, tolerance, seconds, steps);
            double error = 0.0;
            for (std::size_t i = 0; i < T.size(); ++i) {
                error += (T[i] - reference[i]) * (T[i] - reference[i]);
            }
            error = std::sqrt(error / double(T.size())) / rms;
            std::printf("| %d | %.0e | %.4f | %.1f | %.2e |\n", N, tolerance,
                        seconds / duration, double(steps) / double(T.size()),
                        error);
        }
    }
    std::printf("\n");
}

} // namespace

int main()
{
    quasiStatic();
    dynamic();
    return 0;
}
