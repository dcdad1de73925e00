// The implicit trapezoidal rule of MooringLine (MooringLine.hpp): one step
// with one Newton solve on the block tridiagonal line, and the halving of a
// coupling interval whose predictor misses.
#include "mooringLine/MooringLine.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "mooringLine/LineForces.hpp"
#include "mooringLine/LineStatics.hpp"

namespace connectors {

namespace {

static_assert(sizeof(Vector3) == 3 * sizeof(double), "Vector3 is 3 doubles");
bool sameBits(const std::vector<Vector3>& a, const std::vector<Vector3>& b)
{
    return a.size() == b.size()
        && (a.empty()
            || std::memcmp(a.data(), b.data(), a.size() * sizeof(Vector3))
                == 0);
}

} // namespace

bool MooringLine::trapezoidStep(std::vector<double>& nodes, double s0,
                                double s1, double largestMiss)
{
    const double h = (s1 - s0) * ends_.h;
    const int N = layout_.N;
    const std::size_t n = std::size_t(N);
    Workspace& w = work_;
    w.r0.resize(n + 1);
    w.v0.resize(n + 1);
    w.b.resize(n - 1);
    unpack(nodes, N, w.r0, w.v0);
    endsAt(s0, w.r0[0], w.v0[0], w.r0[n], w.v0[n]);
    const double zb = w.r0[0][2];
    // The start's accelerations: those `evaluate` found at the same node
    // positions and velocities (the end of the previous step, as the FMU
    // reports its outputs), else a force evaluation; the same function of
    // the same numbers either way
    if (sameBits(lastEvaluated_.r, w.r0) && sameBits(lastEvaluated_.v, w.v0)
        && sameBits(lastEvaluated_.water.flow, water_.flow)) {
        w.a0 = lastEvaluated_.f.a;
    } else {
        nodeForces(parameters_, layout_, w.r0, w.v0, zb, w.f, &water_, false);
        ++trapezoidStatistics_.rhsEvaluations;
        w.a0 = w.f.a;
    }
    // Predictor: the start acceleration held over the step
    w.r.resize(n + 1);
    w.v.resize(n + 1);
    endsAt(s1, w.r[0], w.v[0], w.r[n], w.v[n]);
    for (std::size_t i = 1; i < n; ++i) {
        w.r[i] = w.r0[i] + h * w.v0[i] + 0.5 * h * h * w.a0[i];
        w.v[i] = w.v0[i] + h * w.a0[i];
    }
    // the shortest segment (the only one without sections)
    const double l = layout_.shortest;
    // Newton on the end positions x (v = 2 (x - x0)/h - v0) with the
    // matrix of the predictor; the residual (v - v0)/h - (a0 + a(x, v))/2
    // is scaled by M h^2/2. Each correction is about 1e-3 of the previous
    // one (the matrix omits only small terms): measured on the reference
    // lines, largest first corrections 1.8e-6 (lab chain, 1 ms) and 7.5e-6
    // (OC4, 0.1 s) of a segment, second ones 2e-9, third 2.5e-12. A
    // correction below 1e-5 of a segment ends the iteration: one solve per
    // step, and the tension harmonic equals that of Newton iterated to
    // 1e-10 of a segment within 5e-8 (lab) and 3e-6 (OC4) of itself. A
    // first correction above largestMiss segments rejects the step.
    const double inverseH = 1.0 / h;
    for (int iteration = 0; iteration < 10; ++iteration) {
        nodeForces(parameters_, layout_, w.r, w.v, zb, w.f, &water_, false);
        if (iteration == 0) {
            trapezoidMatrix(parameters_, layout_, w.r, w.f, zb, h, w.J);
            ++trapezoidStatistics_.jacobianEvaluations;
        }
        ++trapezoidStatistics_.rhsEvaluations;
        for (std::size_t i = 1; i < n; ++i) {
            const Vector3 residual
                = (w.v[i] - w.v0[i]) * inverseH - 0.5 * (w.a0[i] + w.f.a[i]);
            const Vector3& t = w.f.tangent[i];
            const double along = residual.dot(t);
            const double mn = w.f.normalMass[i], mt = w.f.tangentialMass[i];
            w.b[i - 1] = -0.5 * h * h * (mn * residual + (mt - mn) * along * t);
        }
        w.J.solve(w.b);
        double largest = 0.0;
        bool finite = true;
        for (std::size_t i = 1; i < n; ++i) {
            w.r[i] += w.b[i - 1];
            w.v[i] += (2.0 / h) * w.b[i - 1];
            largest = std::max(largest, w.b[i - 1].lpNorm<Eigen::Infinity>());
            finite = finite && w.b[i - 1].allFinite();
        }
        if (!finite) {
            break;
        }
        if (iteration == 0 && largest > largestMiss * l) {
            ++trapezoidStatistics_.errorTestFailures;
            return false;
        }
        if (largest <= 1e-5 * l) {
            for (std::size_t i = 1; i < n; ++i) {
                double* y = nodes.data() + 6 * (i - 1);
                for (int k = 0; k < 3; ++k) {
                    y[k] = w.r[i][k];
                    y[3 + k] = w.v[i][k];
                }
            }
            ++trapezoidStatistics_.steps;
            return true;
        }
    }
    ++trapezoidStatistics_.convergenceFailures;
    return false;
}

void MooringLine::trapezoidInterval(std::vector<double>& nodes, double s0,
                                    double s1, int depth)
{
    // The predictor's miss (Newton's first correction) is about three
    // times the step's local error, h^3/12 times the third derivative of
    // the positions. Above 1e-5 of a segment the interval is halved, so
    // that every step takes one Newton solve (that correction ends
    // trapezoidStep's iteration). The reference lines miss by at most
    // 1.8e-6 (lab chain, 1 ms) and 7.5e-6 (OC4, N = 20, 0.1 s): one step
    // per coupling step. A snap (the lab chain pulled to 0.9997 of its
    // length) is resolved in shorter steps: its energy balance closes to
    // 1e-4 of the work done (at 1e-4 of a segment: 0.27, no better than
    // 0.1 ms steps throughout; bench/mooringLine). At the tenth halving
    // Newton iterates to 1e-5 of a segment, whatever the first correction.
    constexpr int deepest = 10;
    if (trapezoidStep(
            nodes, s0, s1,
            depth < deepest ? 1e-5 : std::numeric_limits<double>::infinity())) {
        return;
    }
    if (depth == deepest) {
        throw std::runtime_error(
            "Newton did not converge in the trapezoidal step, not even at "
            "1/1024 of the coupling step");
    }
    const double middle = 0.5 * (s0 + s1);
    trapezoidInterval(nodes, s0, middle, depth + 1);
    trapezoidInterval(nodes, middle, s1, depth + 1);
}

} // namespace connectors
