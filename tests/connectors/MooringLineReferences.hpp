// The lines of the dynamic line's tests, its FMU's and the benches: line
// types as rows of a line-type table; the 100 m chain; the two reference
// lines of bench/mooringLine, a lab chain (1.2 m in 0.5 m of water) and
// the OC4 semi-submersible's line (835.5 m in 200 m), with the fairlead
// and anchor positions [m] of the measurements; and a snap (a line pulled
// to 0.9997 of its length) with its energy balance.
#ifndef TESTS_CONNECTORS_MOORINGLINEREFERENCES_HPP
#define TESTS_CONNECTORS_MOORINGLINEREFERENCES_HPP

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <vector>

#include "mooringLine/LineForces.hpp"
#include "mooringLine/MooringLine.hpp"

namespace connectors {
namespace references {

//- The columns of a line type, a row of MoorDyn's line-type table:
//  diameter d [m], mass per length w [kg/m], axial stiffness EA [N], axial
//  damping [N.s], normal and tangential drag Cn, Ct and added mass Can,
//  Cat [-]
inline constexpr double MooringLineParameters::*lineTypeColumns[]
    = {&MooringLineParameters::diameter,
       &MooringLineParameters::massPerLength,
       &MooringLineParameters::EA,
       &MooringLineParameters::axialDamping,
       &MooringLineParameters::normalDrag,
       &MooringLineParameters::tangentialDrag,
       &MooringLineParameters::normalAddedMass,
       &MooringLineParameters::tangentialAddedMass};
using LineType = std::array<double, std::size(lineTypeColumns)>;

//- Lab chain (1.2 m in 0.5 m of water)
inline constexpr LineType labChain {3.6e-3, 0.0796, 3.416e5, 2.473,
                                    1.33,   0.2,    1.0,     0.5};
//- OC4 semi-submersible's line
inline constexpr LineType oc4Chain {0.0766, 113.35, 7.536e8, 3.052e6,
                                    2.0,    0.4,    0.8,     0.25};
//- A chain of 80 kg/m with Morison drag; its axial damping is about
//  critical for the axial mode of a 2.5 m segment
inline constexpr LineType chain80 {0.1, 80.0, 5e7, 2e5, 1.2, 0.05, 1.0, 0.0};

//- A line of `type` and `length` [m] in `segments` segments, with or
//  without seabed contact
inline MooringLineParameters lineOf(const LineType& type, double length,
                                    bool seabedContact, int segments)
{
    MooringLineParameters p;
    for (std::size_t i = 0; i < type.size(); ++i) {
        p.*lineTypeColumns[i] = type[i];
    }
    p.length = length;
    p.seabedContact = seabedContact;
    p.segments = segments;
    return p;
}

//- A section after the first, of `type` and `length` [m] in `segments`
//  segments, with the point `joint` at its joint with the section before
inline LineSection sectionOf(const LineType& type, double length, int segments,
                             const LinePoint& joint)
{
    LineSection s = lineOf(type, length, false, segments).section(0);
    s.joint = joint;
    return s;
}

//- `p` with the seabed's penalty stiffness [Pa/m] and damping [Pa.s/m]
inline MooringLineParameters onSeabed(MooringLineParameters p, double stiffness,
                                      double damping)
{
    p.seabedStiffness = stiffness;
    p.seabedDamping = damping;
    return p;
}

//- `p` with the integrator's relative and absolute tolerances
inline MooringLineParameters withTolerance(MooringLineParameters p,
                                           double tolerance)
{
    p.relativeTolerance = tolerance;
    p.absoluteTolerance = tolerance;
    return p;
}

//- The 100 m chain of chain80 on the seabed, moored 80 m from its anchor
//  in 40 m of water in the dynamic line's tests, the FMU's and the bench
inline MooringLineParameters chain100(int segments)
{
    return lineOf(chain80, 100.0, true, segments);
}

struct ReferenceLine {
    const char* name;
    MooringLineParameters p;
    Vector3 anchor, fairlead;
};

//- Lab chain: 1.2 m in 0.5 m of water
inline ReferenceLine lab(int segments)
{
    return {"lab chain",
            onSeabed(lineOf(labChain, 1.2, true, segments), 3e5, 3e3),
            Vector3(-1.0, 0.0, -0.5), Vector3(0.0, 0.0, -0.05)};
}

//- OC4 semi-submersible line: 835.5 m in 200 m of water
inline ReferenceLine oc4(int segments)
{
    return {"OC4 line",
            onSeabed(lineOf(oc4Chain, 835.5, true, segments), 3e6, 3e5),
            Vector3(-837.6, 0.0, -200.0), Vector3(-40.868, 0.0, -14.0)};
}

//- Energy balance and tension of `line` with its fairlead moving as
//  `fairlead(t)` (position and velocity) for `duration` s at coupling step
//  h, the anchor held: peak fairlead tension and its time, tension at the
//  end, the work done on the line by the fairlead against the change of
//  its potential and kinetic energy (v' M v / 2, added mass about the
//  node's tangent, the masses of a uniform line) plus the dissipated
//  energy, power integrals by the trapezoidal rule; the law's energy
//  account (any line); and the first harmonic of the fairlead tension at
//  `frequency` [Hz] over the whole periods after the first (0: none).
struct Snap {
    double peak = 0.0, peakTime = 0.0, final = 0.0;
    //- work - energy change - dissipated energy; the energy that flowed
    //  through the fairlead (integral of |power|) [J]
    double imbalance = 0.0, throughput = 0.0;
    //- work done on the line, its energy change, the dissipated energy [J]
    double work = 0.0, change = 0.0, dissipated = 0.0;
    //- The work of the ends in the trapezoidal rule's own terms
    //  (MooringLine::stepWork), and the imbalance with it, work - energy
    //  change - dissipated energy [J]
    double stepWork = 0.0, stepImbalance = 0.0;
    //- The law's energy account summed over the run (MooringLine::
    //  stepEnergy), the change of kinetic + potential energy from its
    //  outputs, and what the account leaves unexplained: its work less
    //  that change less its dissipated energy [J]
    LineEnergy account;
    double accountChange = 0.0, accountImbalance = 0.0;
    //- first-harmonic amplitude of the fairlead tension [N]
    double harmonic = 0.0;
    bool finite = true;
};

template <class Fairlead>
Snap energyBalance(const ReferenceLine& line, Fairlead fairlead, double h,
                   double duration, double frequency = 0.0)
{
    constexpr double pi = 3.14159265358979323846;
    const MooringLineParameters& p = line.p;
    const int N = p.totalSegments();
    MooringLine law(p);
    BodyKinematics B;
    B.p_WKo_W = line.anchor;
    const double l = p.length / N;
    const double area = 0.25 * pi * p.diameter * p.diameter;
    const double mn
        = (p.massPerLength + p.normalAddedMass * p.waterDensity * area) * l;
    const double mt
        = (p.massPerLength + p.tangentialAddedMass * p.waterDensity * area) * l;
    const auto energy = [&](const MooringLineState& s,
                            const MooringLineOutput& out) {
        std::vector<Vector3> r(std::size_t(N + 1)), v(std::size_t(N + 1));
        unpack(s.nodes, N, r, v);
        r[0] = s.Q;
        r[std::size_t(N)] = s.P;
        double kinetic = 0.0;
        for (int i = 1; i < N; ++i) {
            const Vector3 t
                = (r[std::size_t(i + 1)] - r[std::size_t(i - 1)]).normalized();
            const Vector3& vi = v[std::size_t(i)];
            const double along = vi.dot(t);
            kinetic += 0.5
                * (mn * (vi.squaredNorm() - along * along)
                   + mt * along * along);
        }
        return out.loads.potentialEnergy + kinetic;
    };
    MooringLineState s = law.initialState(fairlead(0.0), B, 0.0);
    MooringLineOutput out = law.evaluate(s, fairlead(0.0), B, 0);
    const double energy0 = energy(s, out);
    const double outputEnergy0 = out.kineticEnergy + out.loads.potentialEnergy;
    Snap result;
    result.account.clear(p.sections.size() + 1);
    double power = 0.0, dissipation = out.loads.dissipatedPower;
    const int steps = int(std::lround(duration / h));
    const int perPeriod
        = frequency > 0.0 ? int(std::lround(1.0 / (frequency * h))) : 0;
    const int periods = perPeriod > 0 ? steps / perPeriod : 0;
    double re = 0.0, im = 0.0;
    for (int k = 1; k <= steps; ++k) {
        const BodyKinematics A = fairlead(k * h);
        law.advance(s, A, B, h);
        out = law.evaluate(s, A, B, 0);
        const double newPower = -out.loads.A.f_W.dot(A.v_WKo_W);
        result.work += 0.5 * h * (power + newPower);
        result.stepWork += law.stepWork();
        result.account += law.stepEnergy();
        result.throughput += 0.5 * h * (std::abs(power) + std::abs(newPower));
        result.dissipated
            += 0.5 * h * (dissipation + out.loads.dissipatedPower);
        power = newPower;
        dissipation = out.loads.dissipatedPower;
        result.finite = result.finite && std::isfinite(out.fairleadTension);
        if (out.fairleadTension > result.peak) {
            result.peak = out.fairleadTension;
            result.peakTime = k * h;
        }
        if (perPeriod > 0 && k > perPeriod && k <= periods * perPeriod) {
            const double phase = 2.0 * pi * frequency * k * h;
            re += out.fairleadTension * std::cos(phase);
            im -= out.fairleadTension * std::sin(phase);
        }
    }
    result.final = out.fairleadTension;
    result.change = energy(s, out) - energy0;
    result.imbalance = result.work - result.change - result.dissipated;
    result.stepImbalance = result.stepWork - result.change - result.dissipated;
    result.accountChange
        = out.kineticEnergy + out.loads.potentialEnergy - outputEnergy0;
    result.accountImbalance = result.account.work() - result.accountChange
        - result.account.dissipated();
    if (periods > 1) {
        result.harmonic
            = 2.0 * std::hypot(re, im) / ((periods - 1) * perPeriod);
    }
    return result;
}

//- Snap: the fairlead of `line` pulled in surge over 0.5 s (smooth start
//  and stop) to 0.9997 of the line's length from the anchor, then held,
//  for `duration` s at coupling step h (energyBalance)
inline Snap pullTaut(const ReferenceLine& line, double h, double duration)
{
    constexpr double pi = 3.14159265358979323846;
    const MooringLineParameters& p = line.p;
    const Vector3 span = line.fairlead - line.anchor;
    // surge a such that |span + a x^| = 0.9997 L
    const double reach = 0.9997 * p.length;
    const double a
        = std::sqrt(reach * reach - span[1] * span[1] - span[2] * span[2])
        - span[0];
    const double pull = 0.5;
    const auto fairlead = [&](double t) {
        const double u = std::min(t / pull, 1.0);
        BodyKinematics A;
        A.p_WKo_W = line.fairlead
            + Vector3(a * (u - std::sin(2.0 * pi * u) / (2.0 * pi)), 0.0, 0.0);
        A.v_WKo_W = Vector3(t < pull ? a / pull * (1.0 - std::cos(2.0 * pi * u))
                                     : 0.0,
                            0.0, 0.0);
        return A;
    };
    return energyBalance(line, fairlead, h, duration);
}

//- Slack-taut: the fairlead of `line` surging with the amplitude `a` [m]
//  at `frequency` [Hz] about its rest position, ramped in over the first
//  period, x0 + a r(t) sin(2 pi f t), r = (1 - cos(pi f t))/2, for
//  `duration` s at coupling step h (energyBalance, the harmonic at f)
inline Snap slackTaut(const ReferenceLine& line, double a, double frequency,
                      double h, double duration)
{
    constexpr double pi = 3.14159265358979323846;
    const double w = 2.0 * pi * frequency, T = 1.0 / frequency;
    const auto fairlead = [&](double t) {
        const double ramp = t < T ? 0.5 * (1.0 - std::cos(pi * t / T)) : 1.0;
        const double rate = t < T ? 0.5 * pi / T * std::sin(pi * t / T) : 0.0;
        BodyKinematics A;
        A.p_WKo_W
            = line.fairlead + Vector3(a * ramp * std::sin(w * t), 0.0, 0.0);
        A.v_WKo_W
            = Vector3(a * (rate * std::sin(w * t) + ramp * w * std::cos(w * t)),
                      0.0, 0.0);
        return A;
    };
    return energyBalance(line, fairlead, h, duration, frequency);
}

} // namespace references
} // namespace connectors

#endif
