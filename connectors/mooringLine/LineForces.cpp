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
    NodeForces f;
    nodeForces(p, w, r, v, zb, f);
    return f;
}

void nodeForces(const MooringLineParameters& p, double w,
                const std::vector<Vector3>& r, const std::vector<Vector3>& v,
                double zb, NodeForces& f)
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
    f.T.resize(std::size_t(N));
    f.q.resize(std::size_t(N));
    f.stretched.resize(std::size_t(N));
    f.tangent.assign(std::size_t(N + 1), Vector3::Zero());
    f.a.assign(std::size_t(N + 1), Vector3::Zero());
    f.F.assign(std::size_t(N + 1), Vector3::Zero());
    f.strainEnergy = f.seabedEnergy = f.dissipatedPower = 0.0;
    f.groundedSegments = 0;
    // the ends count as grounded with seabedContact
    const auto onSeabed = [&](int i) {
        return p.seabedContact && (i == 0 || i == N || r[i][2] <= zb);
    };
    const double inverseL = 1.0 / l;
    const double cn = 0.5 * rho * d * l * p.normalDrag;
    const double ct = 0.5 * rho * pi * d * l * p.tangentialDrag;
    const double mn = p.massPerLength * l + p.normalAddedMass * rho * area * l;
    const double mt
        = p.massPerLength * l + p.tangentialAddedMass * rho * area * l;
    const double inverseMn = 1.0 / mn, inverseMt = 1.0 / mt;
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
    for (int i = 1; i < N; ++i) {
        Vector3 F = f.T[i] * f.q[i] - f.T[i - 1] * f.q[i - 1] - w * l * zHat;
        if (onSeabed(i)) {
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
        t = tn > 0.0 ? Vector3(t * (1.0 / tn)) : Vector3::Zero();
        f.tangent[i] = t;
        const Vector3 vRel = -v[i]; // still water
        const double along = vRel.dot(t); // |vt| (t is a unit vector or 0)
        const Vector3 vt = along * t, vn = vRel - vt;
        const Vector3 drag = cn * vn.norm() * vn + ct * std::abs(along) * vt;
        F += drag;
        f.F[i] = F;
        f.dissipatedPower += -drag.dot(v[i]);
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
