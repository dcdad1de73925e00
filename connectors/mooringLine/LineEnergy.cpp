#include "mooringLine/LineEnergy.hpp"

#include <stdexcept>
#include <string>

#include "mooringLine/AxialGradient.hpp"
#include "mooringLine/LineForces.hpp"
#include "mooringLine/LineLayout.hpp"
#include "mooringLine/LineStatics.hpp"
#include "mooringLine/MooringLine.hpp"

namespace connectors {

void LineEnergy::clear(std::size_t sections)
{
    fairlead = anchor = water = addedMass = 0.0;
    drag.assign(sections, 0.0);
    seabed.assign(sections, 0.0);
    axial.assign(sections, 0.0);
}

LineEnergy& LineEnergy::operator+=(const LineEnergy& e)
{
    fairlead += e.fairlead;
    anchor += e.anchor;
    water += e.water;
    addedMass += e.addedMass;
    for (std::size_t k = 0; k < drag.size() && k < e.drag.size(); ++k) {
        drag[k] += e.drag[k];
        seabed[k] += e.seabed[k];
        axial[k] += e.axial[k];
    }
    return *this;
}

void LineEnergy::addTrapezoid(const LineEnergy& a, const LineEnergy& b,
                              double dt)
{
    const double w = 0.5 * dt;
    fairlead += w * (a.fairlead + b.fairlead);
    anchor += w * (a.anchor + b.anchor);
    water += w * (a.water + b.water);
    addedMass += w * (a.addedMass + b.addedMass);
    for (std::size_t k = 0; k < drag.size(); ++k) {
        drag[k] += w * (a.drag[k] + b.drag[k]);
        seabed[k] += w * (a.seabed[k] + b.seabed[k]);
        axial[k] += w * (a.axial[k] + b.axial[k]);
    }
}

double LineEnergy::sum(const std::vector<double>& x)
{
    double s = 0.0;
    for (const double e : x) {
        s += e;
    }
    return s;
}

std::vector<double> LineEnergy::values() const
{
    std::vector<double> out;
    appendValues(out);
    return out;
}

void LineEnergy::appendValues(std::vector<double>& out) const
{
    out.insert(out.end(), {fairlead, anchor, water, addedMass});
    for (std::size_t k = 0; k < drag.size(); ++k) {
        out.insert(out.end(), {drag[k], seabed[k], axial[k]});
    }
}

LineEnergy LineEnergy::fromValues(const double* values, std::size_t count,
                                  std::size_t sections)
{
    if (count != 4 + 3 * sections) {
        throw std::invalid_argument(
            "mooringLine: an energy account of " + std::to_string(count)
            + " values, expected " + std::to_string(4 + 3 * sections));
    }
    LineEnergy e(sections);
    e.fairlead = values[0];
    e.anchor = values[1];
    e.water = values[2];
    e.addedMass = values[3];
    for (std::size_t k = 0; k < sections; ++k) {
        e.drag[k] = values[4 + 3 * k];
        e.seabed[k] = values[5 + 3 * k];
        e.axial[k] = values[6 + 3 * k];
    }
    return e;
}

namespace {

//- (v0' dM v0 + v1' dM v1)/4 for a free node whose masses mn, mt about
//  its unit tangent t go from (mn0, mt0, t0) to (mn1, mt1, t1)
double massChange(double mn0, double mt0, const Vector3& t0, double mn1,
                  double mt1, const Vector3& t1, const Vector3& v0,
                  const Vector3& v1)
{
    const auto change = [&](const Vector3& v) {
        const double along0 = v.dot(t0), along1 = v.dot(t1);
        return (mn1 - mn0) * v.squaredNorm() - (mn1 - mt1) * along1 * along1
            + (mn0 - mt0) * along0 * along0;
    };
    return 0.25 * (change(v0) + change(v1));
}

//- The nodes' terms of addTrapezoidStep (drag, seabed, the water's work,
//  the added mass's) into e, and the axial dissipation `axial` of a line
//  of one section; general false: a line of one section in still water,
//  whose terms for sections and water are left out at compile time
template <bool general>
void nodeTerms(const LineLayout& layout, const LineSnapshot& start,
               const LineSnapshot& end, double h, const WaterMotion* water,
               LineEnergy& e, double axial)
{
    const std::size_t n = std::size_t(layout.N);
    const NodeForces& f0 = start.f;
    const NodeForces& f1 = end.f;
    const bool uniform = !general || layout.sections.size() == 1;
    const bool moving = general && water
        && (water->current || !water->flow.empty()
            || !water->flowAcceleration.empty());
    const bool inertia
        = general && !f0.flowInertia.empty() && !f1.flowInertia.empty();
    // through raw pointers (as nodeForces)
    const Vector3* const r0 = start.r.data();
    const Vector3* const r1 = end.r.data();
    const Vector3* const v0 = start.v.data();
    const Vector3* const v1 = end.v.data();
    const Vector3* const drag0 = f0.drag.data();
    const Vector3* const drag1 = f1.drag.data();
    const Vector3* const seabed0 = f0.seabed.data();
    const Vector3* const seabed1 = f1.seabed.data();
    const Vector3* const t0 = f0.tangent.data();
    const Vector3* const t1 = f1.tangent.data();
    const double* const mn0 = f0.normalMass.data();
    const double* const mt0 = f0.tangentialMass.data();
    const double* const mn1 = f1.normalMass.data();
    const double* const mt1 = f1.tangentialMass.data();
    double drag = 0.0, seabed = 0.0, fromWater = 0.0, added = 0.0;
    for (std::size_t i = 0; i <= n; ++i) {
        const Vector3 d = r1[i] - r0[i];
        double dragLoss = -0.5 * (drag0[i] + drag1[i]).dot(d);
        if (moving) {
            // the water's velocity U = u + v
            const double share = 0.5 * h
                * (drag0[i].dot(f0.relative[i] + v0[i])
                   + drag1[i].dot(f1.relative[i] + v1[i]));
            dragLoss += share;
            fromWater += share;
            if (inertia) {
                fromWater
                    += 0.5 * (f0.flowInertia[i] + f1.flowInertia[i]).dot(d);
            }
        }
        const double seabedLoss = -0.5 * (seabed0[i] + seabed1[i]).dot(d);
        if (uniform) {
            drag += dragLoss;
            seabed += seabedLoss;
        } else {
            const std::size_t k = std::size_t(layout.sectionOfNode(int(i)));
            e.drag[k] += dragLoss;
            e.seabed[k] += seabedLoss;
        }
        if (mn0[i] == mn1[i] && mt0[i] == mt1[i]) {
            // the masses as they were (under water), turned with the
            // tangent: v' dM v = (mn - mt) ((v . t0)^2 - (v . t1)^2); 0 at
            // the ends (no mass) and without added mass
            if (mn0[i] != mt0[i]) {
                const double a0 = v0[i].dot(t0[i]), b0 = v0[i].dot(t1[i]);
                const double a1 = v1[i].dot(t0[i]), b1 = v1[i].dot(t1[i]);
                added += 0.25 * (mn0[i] - mt0[i])
                    * (a0 * a0 - b0 * b0 + a1 * a1 - b1 * b1);
            }
        } else {
            added += massChange(mn0[i], mt0[i], t0[i], mn1[i], mt1[i], t1[i],
                                v0[i], v1[i]);
        }
    }
    e.water += fromWater;
    e.addedMass += added;
    if (uniform) {
        e.axial[0] += axial;
        e.drag[0] += drag;
        e.seabed[0] += seabed;
    }
}

} // namespace

void addTrapezoidStep(const LineLayout& layout, const LineSnapshot& start,
                      const LineSnapshot& end,
                      const std::vector<StartSegment>& segments, double h,
                      const WaterMotion* water, LineEnergy& e)
{
    const int N = layout.N;
    const std::size_t n = std::size_t(N);
    const NodeForces& f0 = start.f;
    const NodeForces& f1 = end.f;
    const bool moving = water
        && (water->current || !water->flow.empty()
            || !water->flowAcceleration.empty());
    const bool uniform = layout.sections.size() == 1;
    // through raw pointers (as nodeForces)
    const Vector3* const r0 = start.r.data();
    const Vector3* const r1 = end.r.data();
    const StartSegment* const S = segments.data();
    const double* const damping0 = f0.damping.data();
    const double* const damping1 = f1.damping.data();
    const Vector3* const q0 = f0.q.data();
    const Vector3* const q1 = f1.q.data();
    // Segments: the damping's mean pull times the segment's stretch (each
    // section's dissipation), and at the ends the discrete gradient's and
    // the damping's mean pull
    double axial = 0.0;
    Vector3 pullQ = Vector3::Zero(), pullP = Vector3::Zero();
    for (std::size_t j = 0; j < n; ++j) {
        const Vector3 dr = r1[j + 1] - r1[j];
        const Vector3 damping
            = 0.5 * (damping0[j] * q0[j] + damping1[j] * q1[j]);
        const double dissipated = damping.dot(dr - S[j].dr);
        if (uniform) {
            axial += dissipated;
        } else {
            e.axial[std::size_t(layout.segmentSection[j])] += dissipated;
        }
        if (j != 0 && j + 1 != n) {
            continue;
        }
        const LineLayout::Section& c = layout.ofSegment(int(j));
        const double L = S[j].length + f1.stretched[j];
        Vector3 pull = damping;
        if (L > 0.0) {
            const double strain = f1.stretched[j] * c.inverseL - 1.0;
            pull += axialGradient(c.EA, S[j].strain, strain).tension / L
                * (S[j].dr + dr);
        }
        (j == 0 ? pullQ : pullP) = pull;
        if (n == 1) {
            pullP = pull;
        }
    }
    // The bodies push the end nodes (massless) against the mean of the
    // forces on them
    const Vector3 onQ = pullQ + 0.5 * (f0.external[0] + f1.external[0]);
    const Vector3 onP = -pullP + 0.5 * (f0.external[n] + f1.external[n]);
    e.anchor -= onQ.dot(r1[0] - r0[0]);
    e.fairlead -= onP.dot(r1[n] - r0[n]);
    // Nodes: drag, seabed, the water's work, the added mass's
    if (uniform && !moving) {
        nodeTerms<false>(layout, start, end, h, water, e, axial);
    } else {
        nodeTerms<true>(layout, start, end, h, water, e, axial);
    }
    for (std::size_t k = 0; k < e.seabed.size(); ++k) {
        e.seabed[k] -= f1.sectionSeabedEnergy[k] - f0.sectionSeabedEnergy[k];
    }
}

void energyRates(const MooringLineParameters& p, const LineLayout& layout,
                 const std::vector<Vector3>& r, const std::vector<Vector3>& v,
                 const NodeForces& f, double zb, const WaterMotion* water,
                 LineEnergy& rates)
{
    const std::size_t n = std::size_t(layout.N);
    rates.clear(layout.sections.size());
    const auto section = [&](std::size_t i) {
        return std::size_t(layout.sectionOfNode(int(i)));
    };
    // the bodies' push on the end nodes (massless) times their velocities
    rates.anchor = -(f.T[0] * f.q[0] + f.external[0]).dot(v[0]);
    rates.fairlead = (f.T[n - 1] * f.q[n - 1] - f.external[n]).dot(v[n]);
    for (std::size_t j = 0; j < n; ++j) {
        rates.axial[std::size_t(layout.segmentSection[j])]
            += f.damping[j] * f.q[j].dot(v[j + 1] - v[j]);
    }
    const bool moving = water
        && (water->current || !water->flow.empty()
            || !water->flowAcceleration.empty());
    for (std::size_t i = 0; i <= n; ++i) {
        const std::size_t k = section(i);
        // the drag's power on the motion relative to the water, u
        rates.drag[k] += f.drag[i].dot(f.relative[i]);
        if (moving) {
            rates.water += f.drag[i].dot(f.relative[i] + v[i]);
        }
        if (!f.flowInertia.empty()) {
            rates.water += f.flowInertia[i].dot(v[i]);
        }
        // what the seabed's penalty energy loses beyond the work of its
        // push and friction on the node
        const double depth = zb - r[i][2];
        rates.seabed[k] -= f.seabed[i].dot(v[i]);
        if (p.seabedContact && i != 0 && depth > 0.0) {
            rates.seabed[k]
                += layout.nodes[i].contact(p.seabedStiffness * depth) * v[i][2];
        }
        if (i == 0 || i == n) {
            continue;
        }
        // the added mass: v' dM/dt v / 2, M = mn (I - t t') + mt t t'
        const LineLayout::Node& node = layout.nodes[i];
        const double mn = f.normalMass[i], mt = f.tangentialMass[i];
        double phiRate = 0.0; // d phi/dt within the free surface's ramp
        if (p.freeSurface && f.submerged[i] > 0.0 && f.submerged[i] < 1.0) {
            phiRate = -v[i][2] / node.ramp;
        }
        const Vector3 chord = r[i + 1] - r[i - 1];
        const double length = chord.norm();
        const Vector3& t = f.tangent[i];
        Vector3 tangentRate = Vector3::Zero();
        if (length > 0.0) {
            const Vector3 d = v[i + 1] - v[i - 1];
            tangentRate = (d - d.dot(t) * t) / length;
        }
        const double along = v[i].dot(t);
        const double mnRate = node.addedN * phiRate;
        const double mtRate = node.addedT * phiRate;
        rates.addedMass += 0.5
            * (mnRate * v[i].squaredNorm() + (mtRate - mnRate) * along * along
               + 2.0 * (mt - mn) * along * v[i].dot(tangentRate));
    }
}

std::vector<double> kineticEnergy(const LineLayout& layout,
                                  const std::vector<Vector3>& v,
                                  const NodeForces& f)
{
    std::vector<double> K(layout.sections.size(), 0.0);
    const bool uniform = K.size() == 1;
    for (int i = 1; i < layout.N; ++i) {
        const std::size_t k = std::size_t(i);
        const double along = v[k].dot(f.tangent[k]);
        const double Ki = 0.5
            * (f.normalMass[k] * v[k].squaredNorm()
               + (f.tangentialMass[k] - f.normalMass[k]) * along * along);
        K[uniform ? 0 : std::size_t(layout.sectionOfNode(i))] += Ki;
    }
    return K;
}

} // namespace connectors
