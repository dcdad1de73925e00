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
                      const std::vector<Vector3>& v, double zb)
{
    const int N = p.segments;
    const double l = p.length / N, d = p.diameter, rho = p.waterDensity;
    const double area = 0.25 * pi * d * d;
    // Penetration at which the seabed stiffness carries the submerged
    // weight; where that is zero (a buoyant line, no stiffness or no
    // diameter) the damping acts from the floor on
    const double support = p.seabedStiffness * d;
    const double restDepth = support > 0.0 && w > 0.0
        ? w / support
        : std::numeric_limits<double>::min();
    NodeForces f;
    f.T.resize(std::size_t(N));
    f.q.resize(std::size_t(N));
    f.a.assign(std::size_t(N + 1), Vector3::Zero());
    f.F.assign(std::size_t(N + 1), Vector3::Zero());
    for (int j = 0; j < N; ++j) {
        const Vector3 dr = r[j + 1] - r[j];
        const double stretched = dr.norm();
        if (stretched < 1e-12 * l) {
            f.q[j].setZero();
            f.T[j] = 0.0;
            continue;
        }
        f.q[j] = dr / stretched;
        const double strain = stretched / l - 1.0;
        const double strainRate = f.q[j].dot(v[j + 1] - v[j]) / l;
        f.T[j] = p.EA * std::max(strain, 0.0) + p.axialDamping * strainRate;
        f.strainEnergy
            += 0.5 * p.EA * std::max(strain, 0.0) * std::max(strain, 0.0) * l;
        f.dissipatedPower += p.axialDamping * strainRate * strainRate * l;
    }
    std::vector<bool> onSeabed(std::size_t(N + 1), p.seabedContact);
    for (int i = 1; i < N; ++i) {
        Vector3 F = f.T[i] * f.q[i] - f.T[i - 1] * f.q[i - 1] - w * l * zHat;
        onSeabed[i] = p.seabedContact && r[i][2] <= zb;
        if (onSeabed[i]) {
            const double depth = zb - r[i][2];
            // The damping engages over the depth at which the stiffness
            // carries the line's weight, so that the force grows from zero
            // as a node lands: a force that jumped to cb d l |vz| at the
            // floor made CVODE's error test fail there
            const double damping
                = p.seabedDamping * std::min(depth / restDepth, 1.0);
            const double push = std::max(
                (p.seabedStiffness * depth - damping * v[i][2]) * d * l, 0.0);
            F[2] += push;
            f.seabedEnergy += 0.5 * p.seabedStiffness * depth * depth * d * l;
            f.dissipatedPower += std::min(damping * v[i][2] * v[i][2] * d * l,
                                          std::abs(push * v[i][2]));
        }
        Vector3 t = r[i + 1] - r[i - 1];
        const double tn = t.norm();
        t = tn > 0.0 ? Vector3(t / tn) : Vector3::Zero();
        const Vector3 vRel = -v[i]; // still water
        const Vector3 vt = vRel.dot(t) * t, vn = vRel - vt;
        const Vector3 drag = 0.5 * rho * d * l * p.normalDrag * vn.norm() * vn
            + 0.5 * rho * pi * d * l * p.tangentialDrag * vt.norm() * vt;
        F += drag;
        f.F[i] = F;
        f.dissipatedPower += -drag.dot(v[i]);
        const double mn
            = p.massPerLength * l + p.normalAddedMass * rho * area * l;
        const double mt
            = p.massPerLength * l + p.tangentialAddedMass * rho * area * l;
        const Vector3 Ft = F.dot(t) * t;
        f.a[i] = (F - Ft) / mn + Ft / mt;
    }
    for (int j = 0; j < N; ++j) {
        f.groundedSegments += onSeabed[j] && onSeabed[j + 1];
    }
    return f;
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
