// The implicit trapezoidal rule of MooringLine (MooringLine.hpp): one step
// with one Newton solve on the block tridiagonal line, the elastic tension
// over the step as the discrete gradient of the strain energy
// (AxialGradient.hpp), and the halving of a coupling interval whose
// predictor misses.
#include "mooringLine/MooringLine.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "mooringLine/AxialGradient.hpp"
#include "mooringLine/LineForces.hpp"
#include "mooringLine/LineLayout.hpp"
#include "mooringLine/LineStatics.hpp"

namespace connectors {

void startSegments(const LineLayout& layout, const std::vector<Vector3>& r0,
                   const NodeForces& f0, std::vector<StartSegment>& segments)
{
    segments.resize(std::size_t(layout.N));
    // through raw pointers (as nodeForces)
    StartSegment* const S = segments.data();
    const Vector3* const R = r0.data();
    const Vector3* const q = f0.q.data();
    const double* const stretched = f0.stretched.data();
    for (const LineLayout::Section& c : layout.sections) {
        for (int j = c.firstSegment; j < c.firstSegment + c.segments; ++j) {
            const std::size_t k = std::size_t(j);
            StartSegment& s = S[k];
            s.dr = R[k + 1] - R[k];
            s.length = stretched[k];
            s.strain = s.length * c.inverseL - 1.0;
            s.pull = s.strain > 0.0 ? Vector3(c.EA * s.strain * q[k])
                                    : Vector3::Zero();
        }
    }
}

namespace {

//- Segment j's discrete gradient pull on node j towards j + 1 less its
//  elastic pull at the step's start (into d0[j]) and at its end (into
//  d1[j]), the ends at r (f: its forces), the start in `start` [N]; node
//  j + 1 feels the opposite. True when a segment is slack at one end of
//  the step and taut at the other
bool axialCorrections(const LineLayout& layout,
                      const std::vector<StartSegment>& start,
                      const std::vector<Vector3>& r, const NodeForces& f,
                      std::vector<Vector3>& d0, std::vector<Vector3>& d1)
{
    const int N = layout.N;
    d0.resize(std::size_t(N));
    d1.resize(std::size_t(N));
    // through raw pointers (as nodeForces)
    Vector3* const D0 = d0.data();
    Vector3* const D1 = d1.data();
    const Vector3* const R = r.data();
    const StartSegment* const S = start.data();
    const double* const stretched = f.stretched.data();
    bool kink = false;
    for (const LineLayout::Section& c : layout.sections) {
        for (int j = c.firstSegment; j < c.firstSegment + c.segments; ++j) {
            const std::size_t k = std::size_t(j);
            const StartSegment& s = S[k];
            const Vector3 dr = R[k + 1] - R[k];
            const double length = stretched[k];
            const double strain = length * c.inverseL - 1.0;
            const double L = s.length + length;
            if (!(L > 0.0) || (s.strain <= 0.0 && strain <= 0.0)) {
                // slack throughout: no elastic tension at all
                D0[k].setZero();
                D1[k].setZero();
                continue;
            }
            kink = kink || s.strain <= 0.0 || strain <= 0.0;
            const Vector3 gradient
                = axialGradient(c.EA, s.strain, strain).tension / L
                * (s.dr + dr);
            const Vector3 end = strain > 0.0
                ? Vector3(c.EA * strain / length * dr)
                : Vector3::Zero();
            D0[k] = gradient - s.pull;
            D1[k] = gradient - end;
        }
    }
    return kink;
}

//- Whether a kept Newton matrix J serves a step of h [s] whose forces at
//  the predictor r are f: formed for the same h, no segment going taut
//  or slack within the step (kink), no node in the free surface's ramp or
//  held by seabed friction, and the terms that change with the positions
//  within maxChange of a node's mass: each segment's alpha q q' (its
//  unit vector turned by dq changes it by about alpha |dq|) and each
//  node's seabed terms. The kept matrix's correction then differs from
//  the step's own by about maxChange of it (the mass carries the
//  transverse directions; along a taut segment alpha is far larger)
bool serves(const TrapezoidMatrix& J, double h, bool kink,
            const MooringLineParameters& p, const LineLayout& layout,
            const std::vector<Vector3>& r, const NodeForces& f, double zb)
{
    constexpr double maxChange = 1e-2;
    if (J.h != h || kink) {
        return false;
    }
    const std::size_t N = std::size_t(layout.N);
    for (std::size_t i = 1; i < N; ++i) {
        if (f.friction[i] != 0.0
            || (f.submerged[i] > 0.0 && f.submerged[i] < 1.0)) {
            return false;
        }
        const double seabed = p.seabedContact && r[i][2] <= zb
            ? seabedTerms(p, layout.nodes[i], r[i][2], zb, h)
            : 0.0;
        if (std::abs(seabed - J.seabed[i - 1]) > maxChange * J.mass[i - 1]) {
            return false;
        }
    }
    // segment j between nodes j and j + 1: against the lighter free one
    for (std::size_t j = 0; j < N; ++j) {
        const double mass = j == 0 ? J.mass[0]
            : j + 1 == N           ? J.mass[j - 1]
                                   : std::min(J.mass[j - 1], J.mass[j]);
        if (J.alpha[j] * (f.q[j] - J.segmentQ[j]).lpNorm<Eigen::Infinity>()
            > maxChange * mass) {
            return false;
        }
    }
    return true;
}

//- A matrix of `matrices` no one else holds (its storage reused), else a
//  new one (kept in `matrices` while they are few)
std::shared_ptr<TrapezoidMatrix>
spareMatrix(std::vector<std::shared_ptr<TrapezoidMatrix>>& matrices)
{
    for (const std::shared_ptr<TrapezoidMatrix>& m : matrices) {
        if (m.use_count() == 1) {
            return m;
        }
    }
    auto m = std::make_shared<TrapezoidMatrix>();
    if (matrices.size() < 4) {
        matrices.push_back(m);
    }
    return m;
}

} // namespace

bool MooringLine::trapezoidStep(std::vector<double>& nodes, double s0,
                                double s1, double largestMiss,
                                std::shared_ptr<const TrapezoidMatrix>& newton)
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
    // The start's forces: those of the previous step's end or of
    // `evaluate` at the same node positions and velocities, else a force
    // evaluation; the same function of the same numbers either way
    const NodeForces* f0 = &lastEvaluated_.f;
    if (!(sameBits(lastEvaluated_.r, w.r0) && sameBits(lastEvaluated_.v, w.v0)
          && lastEvaluated_.zb == zb
          && sameBits(lastEvaluated_.water.flow, water_.flow))) {
        nodeForces(parameters_, layout_, w.r0, w.v0, zb, w.f0, &water_);
        ++trapezoidStatistics_.rhsEvaluations;
        f0 = &w.f0;
    }
    const std::vector<Vector3>& a0 = f0->a;
    startSegments(layout_, w.r0, *f0, w.start);
    // Predictor: the start acceleration held over the step
    w.r.resize(n + 1);
    w.v.resize(n + 1);
    endsAt(s1, w.r[0], w.v[0], w.r[n], w.v[n]);
    // the loops through raw pointers (as nodeForces)
    Vector3* const r = w.r.data();
    Vector3* const v = w.v.data();
    const Vector3* const r0 = w.r0.data();
    const Vector3* const v0 = w.v0.data();
    for (std::size_t i = 1; i < n; ++i) {
        r[i] = r0[i] + h * v0[i] + 0.5 * h * h * a0[i];
        v[i] = v0[i] + h * a0[i];
    }
    // the shortest segment (the only one without sections)
    const double l = layout_.shortest;
    // Newton on the end positions x (v = 2 (x - x0)/h - v0) with the
    // matrix of the predictor; the residual (v - v0)/h - (a0 + a(x, v))/2,
    // the elastic tensions in a0 and a replaced by the discrete gradient,
    // is scaled by M h^2/2. Each correction is about 1e-3 of the previous
    // one (the matrix omits only small terms): measured on the reference
    // lines, largest first corrections 1.8e-6 (lab chain, 1 ms) and 7.5e-6
    // (OC4, 0.1 s) of a segment, second ones 2e-9, third 2.5e-12. A first
    // correction above largestMiss segments rejects the step.
    //
    // The iteration ends at the iterate after a correction below
    // smallCorrection of a segment, or after one below 1e-5 of a segment
    // where the residual's work over the step (dx . M times the residual,
    // summed over the nodes: the energy the step makes or loses) is below
    // energyTolerance of the work the mean forces do on the nodes (the sum
    // of |dx . M dv/h|). The forces at that iterate are the step's end's:
    // the energy account, the next step's start and the loads' `evaluate`
    // take them, so that a step costs two force evaluations, as before.
    // Where a segment goes taut or slack within the step the predictor's
    // matrix may not converge at all (the corrections cycle about 3e-7 of
    // a segment, the segment taut at one iterate and slack at the next):
    // after maxEnergyCorrections more corrections the step is halved
    // (the deepest halving takes the first iterate after a correction
    // below 1e-5 of a segment). On the lab chain's slack-taut forcing
    // (2 s) the first iterate after a correction below 1e-5 of a segment
    // (the rule before) left 4e-4 and 2e-3 of the energy through the
    // fairlead unexplained at 1 ms and 0.1 ms (Newton converged to
    // round-off: 1e-10); with these rules -5.5e-7 and 1.2e-6
    // (mooringLineEnergyTest), at 2.01 force evaluations a step where
    // nothing snaps (one step in a hundred takes a second correction; OC4
    // at 0.01 and 0.1 s, N = 10 to 40: none). Over its 10 s the snapping
    // lab chain at 1 ms takes 36 force evaluations and 16 matrices a
    // coupling step (9.2 steps), against 39 and 21 (11 steps) before.
    constexpr double smallCorrection = 1e-7, energyTolerance = 1e-4;
    constexpr int maxEnergyCorrections = 2;
    const bool lastResort = !(largestMiss < 1e300); // the deepest halving
    int energyCorrections = 0;
    //
    // A matrix kept from the steps before (chord Newton) replaces the
    // step's own where it serves (`serves`) and its first correction is
    // below chordMiss segments: the correction's error, the kept matrix's
    // difference from the step's own times the correction, is then below
    // the 1e-3 of a correction the step's own matrix leaves. Else the
    // step forms its own at the predictor, and keeps it for the steps
    // after it.
    constexpr double chordMiss = 1e-6;
    const double inverseH = 1.0 / h;
    const TrapezoidMatrix* J = nullptr;
    std::shared_ptr<TrapezoidMatrix> formed;
    double previous = 0.0; // the last correction [m]
    // Converged at w.r, w.v: the forces there (w.f) are the step's end's;
    // with those at its start they give the step's energy account (the
    // mean forces times the nodes' displacements, LineEnergy.hpp), then
    // the next step's start and the loads' `evaluate` (lastEvaluated_)
    const auto accept = [&]() {
        if (parameters_.energyAccount) {
            addTrapezoidStep(layout_, {w.r0, w.v0, *f0}, {w.r, w.v, w.f},
                             w.start, h, &water_, stepEnergy_);
        }
        for (std::size_t i = 1; i < n; ++i) {
            double* y = nodes.data() + 6 * (i - 1);
            for (int k = 0; k < 3; ++k) {
                y[k] = w.r[i][k];
                y[3 + k] = w.v[i][k];
            }
        }
        lastEvaluated_.f.swap(w.f);
        lastEvaluated_.r.swap(w.r);
        lastEvaluated_.v.swap(w.v);
        lastEvaluated_.zb = zb;
        lastEvaluated_.water = water_;
        ++trapezoidStatistics_.steps;
        if (formed) {
            newton = std::move(formed);
        }
        return true;
    };
    for (int iteration = 0; iteration < 10; ++iteration) {
        nodeForces(parameters_, layout_, w.r, w.v, zb, w.f, &water_,
                   iteration > 0);
        ++trapezoidStatistics_.rhsEvaluations;
        if (iteration > 0 && previous <= smallCorrection * l) {
            return accept();
        }
        const bool kink
            = axialCorrections(layout_, w.start, w.r, w.f, w.d0, w.d1);
        const Vector3* const a1 = w.f.a.data();
        const Vector3* const t0 = f0->tangent.data();
        const Vector3* const t1 = w.f.tangent.data();
        const double* const mn0 = f0->normalMass.data();
        const double* const mt0 = f0->tangentialMass.data();
        const double* const mn1 = w.f.normalMass.data();
        const double* const mt1 = w.f.tangentialMass.data();
        const Vector3* const d0 = w.d0.data();
        const Vector3* const d1 = w.d1.data();
        Vector3* const b = w.b.data(); // (swapped with w.chord below)
        // (mn (I - t t') + mt t t')^-1 F of a node's masses mn, mt and tangent
        // t (a lambda: inlined, where a function was not)
        const auto inverseTimes = [](double mn, double mt, const Vector3& t,
                                     const Vector3& F) {
            return Vector3(F / mn + ((1.0 / mt - 1.0 / mn) * F.dot(t)) * t);
        };
        const bool check = iteration > 0; // the residual's work
        double residualWork = 0.0, work = 0.0;
        for (std::size_t i = 1; i < n; ++i) {
            // the elastic tensions at the step's start and end replaced by
            // the discrete gradient, through the masses at the start and
            // the end (node i: segment i's pull less segment i - 1's)
            const Vector3& t = t1[i];
            const double mn = mn1[i], mt = mt1[i];
            const Vector3 dv = (v[i] - v0[i]) * inverseH;
            const Vector3 residual = dv
                - 0.5
                    * (a0[i] + a1[i]
                       + inverseTimes(mn0[i], mt0[i], t0[i], d0[i] - d0[i - 1])
                       + inverseTimes(mn, mt, t, d1[i] - d1[i - 1]));
            const double along = residual.dot(t);
            b[i - 1] = -0.5 * h * h * (mn * residual + (mt - mn) * along * t);
            if (check) {
                const Vector3 dx = r[i] - r0[i];
                residualWork += dx.dot(b[i - 1]);
                work += std::abs(mn * dx.dot(dv)
                                 + (mt - mn) * dx.dot(t) * dv.dot(t));
            }
        }
        if (iteration > 0 && previous <= 1e-5 * l) {
            if (std::abs(residualWork) <= 0.5 * h * h * energyTolerance * work
                || lastResort) {
                return accept();
            }
            if (++energyCorrections > maxEnergyCorrections) {
                break; // not converging: halved
            }
        }
        if (iteration == 0 && newton
            && serves(*newton, h, kink, parameters_, layout_, w.r, w.f, zb)) {
            w.chord = w.b;
            newton->solve(w.chord);
            bool small = true;
            for (const Vector3& c : w.chord) {
                small = small && c.lpNorm<Eigen::Infinity>() <= chordMiss * l;
            }
            if (small) { // (false for a NaN)
                w.b.swap(w.chord);
                J = newton.get();
            }
        }
        if (!J) {
            formed = spareMatrix(w.matrices);
            trapezoidMatrix(parameters_, layout_, w.r, w.f, zb, h, *formed,
                            w.start);
            ++trapezoidStatistics_.jacobianEvaluations;
            J = formed.get();
            J->solve(w.b);
        } else if (iteration > 0) {
            J->solve(w.b);
        }
        double largest = 0.0;
        bool finite = true;
        const Vector3* const correction = w.b.data();
        for (std::size_t i = 1; i < n; ++i) {
            r[i] += correction[i - 1];
            v[i] += (2.0 / h) * correction[i - 1];
            largest = std::max(largest,
                               correction[i - 1].lpNorm<Eigen::Infinity>());
            finite = finite && correction[i - 1].allFinite();
        }
        if (!finite) {
            break;
        }
        // a segment going taut or slack within the step (a snap) is
        // resolved in shorter steps: their first correction must stay
        // below 0.3 of largestMiss (on the lab chain's slack-taut forcing
        // at 1 ms, 1.0 left the axial modes ringing after the snaps, and
        // the dissipated power sampled at the steps' ends overstated the
        // dissipation by 0.5 % of the work done; 0.3 and 0.2: 0.03 %)
        if (iteration == 0 && largest > (kink ? 0.3 : 1.0) * largestMiss * l) {
            ++trapezoidStatistics_.errorTestFailures;
            return false;
        }
        previous = largest;
    }
    ++trapezoidStatistics_.convergenceFailures;
    return false;
}

void MooringLine::trapezoidInterval(
    std::vector<double>& nodes, double s0, double s1, int depth,
    std::shared_ptr<const TrapezoidMatrix>& newton)
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
    if (trapezoidStep(nodes, s0, s1,
                      depth < deepest ? 1e-5
                                      : std::numeric_limits<double>::infinity(),
                      newton)) {
        return;
    }
    if (depth == deepest) {
        throw std::runtime_error(
            "Newton did not converge in the trapezoidal step, not even at "
            "1/1024 of the coupling step");
    }
    const double middle = 0.5 * (s0 + s1);
    trapezoidInterval(nodes, s0, middle, depth + 1, newton);
    trapezoidInterval(nodes, middle, s1, depth + 1, newton);
}

} // namespace connectors
