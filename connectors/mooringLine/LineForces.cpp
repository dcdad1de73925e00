#include "mooringLine/LineForces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mooringLine/MooringLine.hpp"

namespace connectors {

namespace {

constexpr double pi = 3.14159265358979323846;
const Vector3 zHat = Vector3::UnitZ();

} // namespace

NodeForces nodeForces(const MooringLineParameters& p, double w,
                      const std::vector<Vector3>& r,
                      const std::vector<Vector3>& v, double zb,
                      const WaterMotion* water)
{
    NodeForces f;
    nodeForces(p, w, r, v, zb, f, water);
    return f;
}

double submergedFraction(const MooringLineParameters& p, double z)
{
    if (!p.freeSurface) {
        return 1.0;
    }
    const double l = p.length / p.segments;
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
//  the fraction): the buoyancy's potential is -rho g A l times it
double submergedHeight(const MooringLineParameters& p, double z)
{
    if (!p.freeSurface) {
        return z;
    }
    const double l = p.length / p.segments;
    const double bottom = p.waterLevel - 0.5 * l;
    const double u = std::clamp((z - bottom) / l, 0.0, 1.0);
    return std::min(z, bottom) + l * (u - 0.5 * u * u);
}

} // namespace

void nodeForces(const MooringLineParameters& p, double w,
                const std::vector<Vector3>& r, const std::vector<Vector3>& v,
                double zb, NodeForces& f, const WaterMotion* water)
{
    const int N = p.segments;
    const std::size_t n = std::size_t(N + 1);
    const double l = p.length / N, d = p.diameter, rho = p.waterDensity;
    const double area = 0.25 * pi * d * d;
    // Penetration at which the seabed stiffness carries the submerged
    // weight; where that is zero (a buoyant line, no stiffness or no
    // diameter) the damping acts from the floor on
    const double support = p.seabedStiffness * d;
    const double restDepth = support > 0.0 && w > 0.0
        ? w / support
        : std::numeric_limits<double>::min();
    f.T.resize(std::size_t(N));
    f.q.resize(std::size_t(N));
    f.stretched.resize(std::size_t(N));
    f.tangent.resize(n);
    f.a.assign(n, Vector3::Zero());
    f.F.assign(n, Vector3::Zero());
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
    f.strainEnergy = f.seabedEnergy = f.dissipatedPower = f.gravityEnergy = 0.0;
    f.groundedSegments = 0;
    // the ends count as grounded with seabedContact
    const auto onSeabed = [&](int i) {
        return p.seabedContact && (i == 0 || i == N || r[i][2] <= zb);
    };
    const double inverseL = 1.0 / l;
    const double cn = 0.5 * rho * d * p.normalDrag;
    const double ct = 0.5 * rho * pi * d * p.tangentialDrag;
    const double dryWeight = p.massPerLength * p.gravity;
    const double buoyancy = rho * area * p.gravity; // per submerged length
    for (int j = 0; j < N; ++j) {
        const Vector3 dr = r[j + 1] - r[j];
        const double stretched = dr.norm();
        f.stretched[j] = stretched;
        if (stretched < 1e-12 * l) {
            f.q[j].setZero();
            f.T[j] = 0.0;
            continue;
        }
        f.q[j] = dr * (1.0 / stretched);
        const double strain = stretched * inverseL - 1.0;
        const double strainRate = f.q[j].dot(v[j + 1] - v[j]) * inverseL;
        f.T[j] = p.EA * std::max(strain, 0.0) + p.axialDamping * strainRate;
        f.strainEnergy
            += 0.5 * p.EA * std::max(strain, 0.0) * std::max(strain, 0.0) * l;
        f.dissipatedPower += p.axialDamping * strainRate * strainRate * l;
    }
    // Every node carries the line around it: a segment (free nodes) or
    // half a segment (the ends), of length `share` unstretched and
    // `stretchedShare` stretched (drag acts on the stretched length)
    double heights = 0.0, wetHeights = 0.0;
    for (int i = 0; i <= N; ++i) {
        const bool end = i == 0 || i == N;
        const double share = end ? 0.5 * l : l;
        const double stretchedShare = i == 0 ? 0.5 * f.stretched[0]
            : i == N                         ? 0.5 * f.stretched[N - 1]
                     : 0.5 * (f.stretched[i - 1] + f.stretched[i]);
        const double phi = p.freeSurface ? submergedFraction(p, r[i][2]) : 1.0;
        f.submerged[i] = phi;
        // With seabedContact the seabed carries the anchor's half segment
        const bool carried = i == 0 && p.seabedContact;
        Vector3 E = Vector3::Zero();
        if (!carried) {
            E[2] -= (dryWeight - buoyancy * phi) * share;
        }
        heights += share * r[i][2];
        if (p.freeSurface) {
            wetHeights += share * submergedHeight(p, r[i][2]);
        }
        if (onSeabed(i) && i != 0) {
            const double depth = zb - r[i][2];
            // The damping engages over the depth at which the stiffness
            // carries the line's weight, so that the force grows from zero
            // as a node lands: a force that jumped to cb d l |vz| at the
            // floor made CVODE's error test fail there
            const double damping
                = p.seabedDamping * std::clamp(depth / restDepth, 0.0, 1.0);
            const double push = std::max(
                (p.seabedStiffness * depth - damping * v[i][2]) * d * share,
                0.0);
            E[2] += push;
            if (depth > 0.0) {
                f.seabedEnergy
                    += 0.5 * p.seabedStiffness * depth * depth * d * share;
            }
            f.dissipatedPower
                += std::min(damping * v[i][2] * v[i][2] * d * share,
                            std::abs(push * v[i][2]));
            // Coulomb friction on the horizontal velocity, regularised:
            // mu push v / max(|v|, frictionVelocity)
            if (p.seabedFriction > 0.0 && push > 0.0) {
                const Vector3 vh(v[i][0], v[i][1], 0.0);
                const double speed = vh.norm();
                const double c = p.seabedFriction * push
                    / std::max(speed, p.frictionVelocity);
                f.friction[i] = c;
                if (speed > p.frictionVelocity) {
                    f.sliding[i] = vh / speed;
                }
                E -= c * vh;
                f.dissipatedPower += c * vh.squaredNorm();
            }
        }
        Vector3 t = i == 0 ? f.q[0]
            : i == N       ? f.q[N - 1]
                           : Vector3(r[i + 1] - r[i - 1]);
        const double tn = t.norm();
        t = tn > 0.0 ? Vector3(t * (1.0 / tn)) : Vector3::Zero();
        f.tangent[i] = t;
        Vector3 u = -v[i]; // water velocity relative to the node
        if (water) {
            if (water->current) {
                u += currentAt(p, r[i][2], zb);
            }
            if (!water->flow.empty()) {
                u += water->flow[std::size_t(i)];
            }
        }
        f.relative[i] = u;
        const double along = u.dot(t); // |ut| (t is a unit vector or 0)
        const Vector3 ut = along * t, un = u - ut;
        const double wet = phi * stretchedShare;
        f.normalDrag[i] = cn * wet * un.norm();
        f.tangentialDrag[i] = ct * wet * std::abs(along);
        const Vector3 drag = f.normalDrag[i] * un + f.tangentialDrag[i] * ut;
        E += drag;
        // power the drag takes from the line's motion relative to the water
        f.dissipatedPower += drag.dot(u);
        f.external[i] = E;
    }
    f.gravityEnergy = dryWeight * heights
        - buoyancy * (p.freeSurface ? wetHeights : heights);
    const double mass = p.massPerLength * l;
    const double addedN = p.normalAddedMass * rho * area * l;
    const double addedT = p.tangentialAddedMass * rho * area * l;
    // all submerged (no free surface): the same masses at every node
    double inverseMn = 1.0 / (mass + addedN), inverseMt = 1.0 / (mass + addedT);
    f.normalMass[0] = f.tangentialMass[0] = f.normalMass[N]
        = f.tangentialMass[N] = 0.0;
    for (int i = 1; i < N; ++i) {
        const Vector3 F
            = f.T[i] * f.q[i] - f.T[i - 1] * f.q[i - 1] + f.external[i];
        f.F[i] = F;
        const double mn = mass + addedN * f.submerged[i];
        const double mt = mass + addedT * f.submerged[i];
        f.normalMass[i] = mn;
        f.tangentialMass[i] = mt;
        if (p.freeSurface) {
            inverseMn = 1.0 / mn;
            inverseMt = 1.0 / mt;
        }
        const Vector3& t = f.tangent[i];
        // (mn (I - t t') + mt t t')^-1 F
        f.a[i] = inverseMn * F + ((inverseMt - inverseMn) * F.dot(t)) * t;
    }
    for (int j = 0; j < N; ++j) {
        f.groundedSegments += onSeabed(j) && onSeabed(j + 1);
    }
}

void unpack(const std::vector<double>& nodes, int N, std::vector<Vector3>& r,
            std::vector<Vector3>& v)
{
    for (int i = 1; i < N; ++i) {
        const double* y = nodes.data() + 6 * (i - 1);
        r[i] = Vector3(y[0], y[1], y[2]);
        v[i] = Vector3(y[3], y[4], y[5]);
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
