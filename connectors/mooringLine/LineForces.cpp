#include "mooringLine/LineForces.hpp"

#include <algorithm>
#include <cmath>

#include "mooringLine/LineLayout.hpp"
#include "mooringLine/MooringLine.hpp"

namespace connectors {

namespace {

const Vector3 zHat = Vector3::UnitZ();

} // namespace

NodeForces nodeForces(const MooringLineParameters& p, double w,
                      const std::vector<Vector3>& r,
                      const std::vector<Vector3>& v, double zb,
                      const WaterMotion* water)
{
    NodeForces f;
    nodeForces(p, lineLayout(p, w), r, v, zb, f, water);
    return f;
}

void nodeForces(const MooringLineParameters& p, double w,
                const std::vector<Vector3>& r, const std::vector<Vector3>& v,
                double zb, NodeForces& f, const WaterMotion* water)
{
    nodeForces(p, lineLayout(p, w), r, v, zb, f, water);
}

double submergedFraction(const MooringLineParameters& p, double z)
{
    return submergedFraction(p, z, p.length / p.segments);
}

double submergedFraction(const MooringLineParameters& p, double z, double l)
{
    if (!p.freeSurface) {
        return 1.0;
    }
    return std::clamp((p.waterLevel + 0.5 * l - z) / l, 0.0, 1.0);
}

Vector3 currentAt(const MooringLineParameters& p, double z, double zb)
{
    const double depth = p.waterLevel - zb;
    const double up
        = depth > 0.0 ? std::clamp((z - zb) / depth, 0.0, 1.0) : 1.0;
    return p.currentSeabed + up * (p.currentSurface - p.currentSeabed);
}

namespace {

//- Integral of submergedFraction over height up to z (its derivative is
//  the fraction), ramp length l: the buoyancy's potential is -rho g A l
//  times it
double submergedHeight(const MooringLineParameters& p, double z, double l)
{
    if (!p.freeSurface) {
        return z;
    }
    const double bottom = p.waterLevel - 0.5 * l;
    const double u = std::clamp((z - bottom) / l, 0.0, 1.0);
    return std::min(z, bottom) + l * (u - 0.5 * u * u);
}

//- The seabed's friction on a node [N] pushed by `push` [N], moving at
//  the horizontal velocity vh [m/s], its tangent t: Coulomb friction mu
//  push, regularised below frictionVelocity v_f (a damping c = mu s push /
//  v_f there, s the static scale; s falls linearly to 1 from v_f to
//  2 v_f) and axialFrictionRatio r times it along the horizontal part of
//  t. Sets the transverse damping c [N.s/m] and, above v_f, the sliding
//  direction; adds the power it takes to *dissipated
Vector3 seabedFriction(const MooringLineParameters& p, double push,
                       const Vector3& vh, const Vector3& t, double& c,
                       Vector3& sliding, double* dissipated)
{
    const double speed = vh.norm(), vf = p.frictionVelocity;
    double scale = 1.0;
    if (speed < 2.0 * vf) {
        scale = p.staticFrictionScale
            - (p.staticFrictionScale - 1.0) * std::max(speed - vf, 0.0) / vf;
    }
    c = p.seabedFriction * push * scale / std::max(speed, vf);
    if (speed > vf) {
        sliding = vh / speed;
    }
    Vector3 F = c * vh;
    double power = c * vh.squaredNorm();
    const Vector3 th(t[0], t[1], 0.0);
    const double thn = th.norm();
    if (p.axialFrictionRatio != 1.0 && thn > 0.0) {
        const double along = vh.dot(th) / thn;
        F += (p.axialFrictionRatio - 1.0) * c * along * th / thn;
        power += (p.axialFrictionRatio - 1.0) * c * along * along;
    }
    if (dissipated) {
        *dissipated += power;
    }
    return F;
}

} // namespace

namespace {

//- nodeForces; general false: a line of one section (no joints, no
//  points) without free surface, seabed friction or water motion, whose
//  terms for those are left out at compile time (the same arithmetic);
//  diagnostics as nodeForces' argument
template <bool general, bool diagnostics>
void forces(const MooringLineParameters& p, const LineLayout& layout,
            const std::vector<Vector3>& r, const std::vector<Vector3>& v,
            double zb, NodeForces& f, const WaterMotion* givenWater)
{
    const bool freeSurface = general && p.freeSurface;
    const bool friction = general && p.seabedFriction > 0.0;
    const WaterMotion* const water = general ? givenWater : nullptr;
    const int N = layout.N;
    const std::size_t n = std::size_t(N + 1);
    const std::size_t sections = layout.sections.size();
    f.T.resize(std::size_t(N));
    f.q.resize(std::size_t(N));
    f.stretched.resize(std::size_t(N));
    f.tangent.resize(n);
    // written for every free node below; the ends' are zero
    f.a.resize(n);
    f.F.resize(n);
    f.a[0].setZero();
    f.a[N].setZero();
    f.F[0].setZero();
    f.F[N].setZero();
    // written for every node below
    f.external.resize(n);
    f.submerged.resize(n);
    f.normalDrag.resize(n);
    f.tangentialDrag.resize(n);
    f.relative.resize(n);
    f.normalMass.resize(n);
    f.tangentialMass.resize(n);
    // set on the seabed only (zero without friction)
    if (p.seabedFriction > 0.0 || f.friction.size() != n) {
        f.friction.assign(n, 0.0);
        f.sliding.assign(n, Vector3::Zero());
    }
    if (diagnostics) {
        f.drag.resize(n);
        f.seabed.resize(n);
        if (water && !water->flowAcceleration.empty()) {
            f.flowInertia.assign(n, Vector3::Zero());
        } else {
            f.flowInertia.clear();
        }
        f.damping.resize(std::size_t(N));
        f.sectionSeabedEnergy.assign(sections, 0.0);
    }
    // f's and the positions' storage through raw pointers (Eigen's packet
    // stores may alias anything: the vectors' data pointers would be
    // reloaded after every store)
    const Vector3* const R = r.data();
    const Vector3* const V = v.data();
    double* const fT = f.T.data();
    Vector3* const fQ = f.q.data();
    double* const fStretched = f.stretched.data();
    Vector3* const fTangent = f.tangent.data();
    Vector3* const fA = f.a.data();
    Vector3* const fF = f.F.data();
    Vector3* const fExternal = f.external.data();
    double* const fSubmerged = f.submerged.data();
    double* const fNormalDrag = f.normalDrag.data();
    double* const fTangentialDrag = f.tangentialDrag.data();
    Vector3* const fRelative = f.relative.data();
    double* const fNormalMass = f.normalMass.data();
    double* const fTangentialMass = f.tangentialMass.data();
    double* const fFriction = f.friction.data();
    Vector3* const fSliding = f.sliding.data();
    // accumulated in locals (f's fields would be reloaded after every
    // store through f's vectors)
    double strainEnergy = 0.0, seabedEnergy = 0.0, dissipatedPower = 0.0;
    // the ends count as grounded with seabedContact
    const auto onSeabed = [&](int i) {
        return p.seabedContact && (i == 0 || i == N || R[i][2] <= zb);
    };
    // section by section, its constants in locals
    for (const LineLayout::Section& section : layout.sections) {
        const LineLayout::Section c = section;
        for (int j = c.firstSegment; j < c.firstSegment + c.segments; ++j) {
            const double l = c.l;
            const Vector3 dr = R[j + 1] - R[j];
            const double stretched = dr.norm();
            fStretched[j] = stretched;
            if (stretched < 1e-12 * l) {
                fQ[j].setZero();
                fT[j] = 0.0;
                if (diagnostics) {
                    f.damping[std::size_t(j)] = 0.0;
                }
                continue;
            }
            const double inverseL = c.inverseL;
            fQ[j] = dr * (1.0 / stretched);
            const double strain = stretched * inverseL - 1.0;
            const double strainRate = fQ[j].dot(V[j + 1] - V[j]) * inverseL;
            fT[j] = c.EA * std::max(strain, 0.0) + c.BA * strainRate;
            if (diagnostics) {
                strainEnergy += 0.5 * c.EA * std::max(strain, 0.0)
                    * std::max(strain, 0.0) * l;
                dissipatedPower += c.BA * strainRate * strainRate * l;
                f.damping[std::size_t(j)] = c.BA * strainRate;
            }
        }
    }
    // Every node carries the line around it: a segment (free nodes) or
    // half a segment (the ends), of length `share` unstretched and
    // `stretchedShare` stretched (drag acts on the stretched length); a
    // joint half a segment of each section, and its point
    double heights[8] = {}, wetHeights[8] = {};
    std::vector<double> manyHeights, manyWetHeights;
    double* height = heights;
    double* wetHeight = wetHeights;
    if (sections > 8) {
        manyHeights.assign(sections, 0.0);
        manyWetHeights.assign(sections, 0.0);
        height = manyHeights.data();
        wetHeight = manyWetHeights.data();
    }
    double pointEnergy = 0.0;
    // the nodes' unit tangents first: a short loop whose square roots and
    // divisions overlap from node to node
    for (int i = 0; i <= N; ++i) {
        Vector3 t = i == 0 ? fQ[0]
            : i == N       ? fQ[N - 1]
                           : Vector3(R[i + 1] - R[i - 1]);
        const double tn = t.norm();
        fTangent[i] = tn > 0.0 ? Vector3(t * (1.0 / tn)) : Vector3::Zero();
    }
    for (int i = 0; i <= N; ++i) {
        const LineLayout::Node& node = layout.nodes[std::size_t(i)];
        const double phi
            = freeSurface ? submergedFraction(p, R[i][2], node.ramp) : 1.0;
        fSubmerged[i] = phi;
        // With seabedContact the seabed carries the anchor's half segment
        const bool carried = i == 0 && p.seabedContact;
        Vector3 E = Vector3::Zero();
        double wetHeightOfNode = 0.0;
        if (freeSurface) {
            wetHeightOfNode = submergedHeight(p, R[i][2], node.ramp);
        }
        for (int k = 0; k < (general ? node.pieces : 1); ++k) {
            const LineLayout::Node::Piece& c = node.piece[k];
            if (!carried) {
                E[2] -= (c.dryWeight - c.buoyancy * phi) * c.share;
            }
            if (diagnostics) {
                height[c.section] += c.share * R[i][2];
                if (freeSurface) {
                    wetHeight[c.section] += c.share * wetHeightOfNode;
                }
            }
        }
        if (general && node.point >= 0) {
            E[2] -= node.pointWeight - node.pointBuoyancy * phi;
            pointEnergy += node.pointWeight * R[i][2]
                - node.pointBuoyancy
                    * (freeSurface ? wetHeightOfNode : R[i][2]);
        }
        Vector3 seabed = Vector3::Zero(); // push and friction
        if (onSeabed(i) && i != 0) {
            const double depth = zb - R[i][2];
            // The damping engages over the depth at which the stiffness
            // carries the line's weight, so that the force grows from zero
            // as a node lands: a force that jumped to cb d l |vz| at the
            // floor made CVODE's error test fail there
            const double damping = p.seabedDamping
                * std::clamp(depth / node.restDepth, 0.0, 1.0);
            const double push = std::max(
                node.contact(p.seabedStiffness * depth - damping * V[i][2]),
                0.0);
            E[2] += push;
            seabed[2] = push;
            if (diagnostics) {
                if (depth > 0.0) {
                    const double energy
                        = node.contact(0.5 * p.seabedStiffness * depth * depth);
                    seabedEnergy += energy;
                    f.sectionSeabedEnergy[std::size_t(
                        node.piece[node.pieces - 1].section)]
                        += energy;
                }
                // what the penalty's energy loses beyond the work the push
                // does on the node: the damping's c vz^2 while it pushes,
                // the whole stored energy's rate when a node leaving the
                // seabed faster than the spring relaxes is not pushed
                dissipatedPower
                    += node.contact(p.seabedStiffness * depth) * V[i][2]
                    - push * V[i][2];
            }
            if (friction && push > 0.0) {
                const Vector3 F
                    = seabedFriction(p, push, Vector3(V[i][0], V[i][1], 0.0),
                                     fTangent[i], fFriction[i], fSliding[i],
                                     diagnostics ? &dissipatedPower : nullptr);
                E -= F;
                seabed -= F;
            }
        }
        if (diagnostics) {
            f.seabed[std::size_t(i)] = seabed;
        }
        const Vector3 t = fTangent[i];
        Vector3 u = -V[i]; // water velocity relative to the node
        if (water) {
            if (water->current) {
                u += currentAt(p, R[i][2], zb);
            }
            if (!water->flow.empty()) {
                u += water->flow[std::size_t(i)];
            }
        }
        fRelative[i] = u;
        const double along = u.dot(t); // |ut| (t is a unit vector or 0)
        const Vector3 ut = along * t, un = u - ut;
        // drag factors of the pieces: c phi (stretched share)
        double cn = 0.0, ct = 0.0;
        if (!general || node.pieces == 1) {
            const LineLayout::Node::Piece& c = node.piece[0];
            const double stretchedShare = i == 0 ? 0.5 * fStretched[0]
                : i == N                         ? 0.5 * fStretched[N - 1]
                         : 0.5 * (fStretched[i - 1] + fStretched[i]);
            const double wet = phi * stretchedShare;
            cn = c.cn * wet;
            ct = c.ct * wet;
        } else {
            const LineLayout::Node::Piece& below = node.piece[0];
            const LineLayout::Node::Piece& above = node.piece[1];
            const double wetBelow = phi * (0.5 * fStretched[i - 1]);
            const double wetAbove = phi * (0.5 * fStretched[i]);
            cn = below.cn * wetBelow + above.cn * wetAbove;
            ct = below.ct * wetBelow + above.ct * wetAbove;
        }
        fNormalDrag[i] = cn * un.norm();
        fTangentialDrag[i] = ct * std::abs(along);
        if (general && node.point >= 0) {
            // the point's drag, the same in every direction
            const double c = node.pointDrag * phi * u.norm();
            fNormalDrag[i] += c;
            fTangentialDrag[i] += c;
        }
        const Vector3 drag = fNormalDrag[i] * un + fTangentialDrag[i] * ut;
        E += drag;
        // power the drag takes from the line's motion relative to the water
        if (diagnostics) {
            dissipatedPower += drag.dot(u);
            f.drag[std::size_t(i)] = drag;
        }
        if (water && !water->flowAcceleration.empty()) {
            // The flow's inertia (Froude-Krylov and added mass, as MoorDyn's
            // Ap, Aq): phi (rho V (1 + Can) a_n + rho V (1 + Cat) a_t); work
            // of the water on the line, not dissipation
            const Vector3& a = water->flowAcceleration[std::size_t(i)];
            const double aAlong = a.dot(t);
            const Vector3 inertia = phi
                * (node.flowInertiaN * (a - aAlong * t)
                   + node.flowInertiaT * aAlong * t);
            E += inertia;
            if (diagnostics) {
                f.flowInertia[std::size_t(i)] = inertia;
            }
        }
        fExternal[i] = E;
    }
    f.strainEnergy = strainEnergy;
    f.seabedEnergy = seabedEnergy;
    f.dissipatedPower = diagnostics ? dissipatedPower : 0.0;
    f.gravityEnergy = 0.0;
    f.groundedSegments = 0;
    if (diagnostics) {
        for (std::size_t k = 0; k < sections; ++k) {
            const LineLayout::Section& c = layout.sections[k];
            f.gravityEnergy += c.dryWeight * height[k]
                - c.buoyancy * (freeSurface ? wetHeight[k] : height[k]);
        }
        f.gravityEnergy += pointEnergy;
        for (int j = 0; j < N; ++j) {
            f.groundedSegments += onSeabed(j) && onSeabed(j + 1);
        }
    }
    fNormalMass[0] = fTangentialMass[0] = fNormalMass[N] = fTangentialMass[N]
        = 0.0;
    // the inverses of the last node's masses: the same at every node of a
    // section under water
    double mn1 = 0.0, mt1 = 0.0, inverseMn = 0.0, inverseMt = 0.0;
    for (int i = 1; i < N; ++i) {
        const LineLayout::Node& node = layout.nodes[std::size_t(i)];
        const Vector3 F = fT[i] * fQ[i] - fT[i - 1] * fQ[i - 1] + fExternal[i];
        fF[i] = F;
        const double mn = node.mass + node.addedN * fSubmerged[i];
        const double mt = node.mass + node.addedT * fSubmerged[i];
        fNormalMass[i] = mn;
        fTangentialMass[i] = mt;
        if (mn != mn1 || mt != mt1) {
            mn1 = mn;
            mt1 = mt;
            inverseMn = 1.0 / mn;
            inverseMt = 1.0 / mt;
        }
        const Vector3& t = fTangent[i];
        // (mn (I - t t') + mt t t')^-1 F
        fA[i] = inverseMn * F + ((inverseMt - inverseMn) * F.dot(t)) * t;
    }
}

} // namespace

void nodeForces(const MooringLineParameters& p, const LineLayout& layout,
                const std::vector<Vector3>& r, const std::vector<Vector3>& v,
                double zb, NodeForces& f, const WaterMotion* water,
                bool diagnostics)
{
    const bool still = !water
        || (!water->current && water->flow.empty()
            && water->flowAcceleration.empty());
    if (layout.sections.size() == 1 && !p.freeSurface
        && !(p.seabedFriction > 0.0) && still) {
        if (diagnostics) {
            forces<false, true>(p, layout, r, v, zb, f, water);
        } else {
            forces<false, false>(p, layout, r, v, zb, f, water);
        }
    } else if (diagnostics) {
        forces<true, true>(p, layout, r, v, zb, f, water);
    } else {
        forces<true, false>(p, layout, r, v, zb, f, water);
    }
}

void unpack(const std::vector<double>& nodes, int N, std::vector<Vector3>& r,
            std::vector<Vector3>& v)
{
    // through raw pointers (as nodeForces)
    Vector3* const R = r.data();
    Vector3* const V = v.data();
    for (int i = 1; i < N; ++i) {
        const double* y = nodes.data() + 6 * (i - 1);
        R[i] = Vector3(y[0], y[1], y[2]);
        V[i] = Vector3(y[3], y[4], y[5]);
    }
}

double largestForce(const NodeForces& f)
{
    double largest = 0.0;
    for (std::size_t i = 1; i + 1 < f.F.size(); ++i) {
        largest = std::max(largest, f.F[i].lpNorm<Eigen::Infinity>());
    }
    return largest;
}

} // namespace connectors
