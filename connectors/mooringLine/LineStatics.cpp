#include "mooringLine/LineStatics.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "mooringLine/LineForces.hpp"
#include "mooringLine/MooringLine.hpp"

namespace connectors {

namespace {

constexpr double pi = 3.14159265358979323846;

} // namespace

std::vector<Vector3>
BlockTridiagonal::solve(const std::vector<Vector3>& b) const
{
    BlockTridiagonal factors(*this);
    factors.factorize();
    std::vector<Vector3> x(b);
    factors.solveFactored(x);
    return x;
}

void BlockTridiagonal::factorize()
{
    const std::size_t n = diagonal.size();
    lower.resize(n > 0 ? n - 1 : 0);
    for (std::size_t i = 0; i < n; ++i) {
        if (i > 0) {
            lower[i - 1] = upper[i - 1].transpose() * diagonal[i - 1];
            diagonal[i] -= lower[i - 1] * upper[i - 1];
        }
        diagonal[i] = diagonal[i].inverse().eval();
    }
}

void BlockTridiagonal::solveFactored(std::vector<Vector3>& x) const
{
    const std::size_t n = diagonal.size();
    for (std::size_t i = 1; i < n; ++i) {
        x[i] -= lower[i - 1] * x[i - 1];
    }
    for (std::size_t k = n; k-- > 0;) {
        if (k + 1 < n) {
            x[k] -= upper[k] * x[k + 1];
        }
        x[k] = (diagonal[k] * x[k]).eval();
    }
}

BlockTridiagonal staticStiffness(const MooringLineParameters& p, double weight,
                                 const std::vector<Vector3>& r, double zb)
{
    const int N = p.segments;
    const double l = p.length / N;
    BlockTridiagonal S;
    S.diagonal.assign(std::size_t(N - 1), Matrix3::Zero());
    S.upper.assign(std::size_t(std::max(N - 2, 0)), Matrix3::Zero());
    for (int j = 0; j < N; ++j) {
        const Vector3 dr = r[std::size_t(j + 1)] - r[std::size_t(j)];
        const double s = dr.norm();
        if (!(s > 1e-12 * l)) {
            continue;
        }
        const Vector3 q = dr / s;
        const double T = p.EA * std::max(s / l - 1.0, 0.0);
        const Matrix3 qq = q * q.transpose();
        const double geometric = std::max(T, std::abs(weight) * l) / s;
        const Matrix3 k = (s > l ? p.EA / l : geometric) * qq
            + geometric * (Matrix3::Identity() - qq);
        if (j >= 1) {
            S.diagonal[std::size_t(j - 1)] += k; // node j
        }
        if (j + 1 <= N - 1) {
            S.diagonal[std::size_t(j)] += k; // node j + 1
        }
        if (j >= 1 && j + 1 <= N - 1) {
            S.upper[std::size_t(j - 1)] -= k;
        }
    }
    if (p.seabedContact) {
        for (int i = 1; i < N; ++i) {
            if (r[std::size_t(i)][2] <= zb) {
                S.diagonal[std::size_t(i - 1)](2, 2)
                    += p.seabedStiffness * p.diameter * l;
            }
        }
    }
    return S;
}

void trapezoidMatrix(const MooringLineParameters& p, double weight,
                     const std::vector<Vector3>& r,
                     const std::vector<Vector3>& v, const NodeForces& f,
                     double zb, double h, BlockTridiagonal& J)
{
    const int N = p.segments;
    const double l = p.length / N, d = p.diameter, rho = p.waterDensity;
    const double area = 0.25 * pi * d * d;
    const double stiffness = 0.25 * h * h, damping = 0.5 * h;
    J.diagonal.assign(std::size_t(N - 1), Matrix3::Zero());
    J.upper.assign(std::size_t(std::max(N - 2, 0)), Matrix3::Zero());
    // Segment j: h^2/4 times staticStiffness's k_j plus h/2 BA/l q q',
    // alpha q q' + beta I
    for (int j = 0; j < N; ++j) {
        const double s = f.stretched[std::size_t(j)];
        if (!(s > 1e-12 * l)) {
            continue;
        }
        const Vector3& q = f.q[std::size_t(j)];
        const double T = p.EA * std::max(s / l - 1.0, 0.0);
        const double geometric = std::max(T, std::abs(weight) * l) / s;
        const double axial = s > l ? p.EA / l : geometric;
        const double alpha
            = stiffness * (axial - geometric) + damping * p.axialDamping / l;
        Matrix3 k = alpha * q * q.transpose();
        k.diagonal().array() += stiffness * geometric;
        if (j >= 1) {
            J.diagonal[std::size_t(j - 1)] += k; // node j
        }
        if (j + 1 <= N - 1) {
            J.diagonal[std::size_t(j)] += k; // node j + 1
        }
        if (j >= 1 && j + 1 <= N - 1) {
            J.upper[std::size_t(j - 1)] = -k;
        }
    }
    const double support = p.seabedStiffness * d;
    const double restDepth = support > 0.0 && weight > 0.0
        ? weight / support
        : std::numeric_limits<double>::min();
    const double mn = p.massPerLength * l + p.normalAddedMass * rho * area * l;
    const double mt
        = p.massPerLength * l + p.tangentialAddedMass * rho * area * l;
    const double cn = damping * 0.5 * rho * d * l * p.normalDrag;
    const double ct = damping * 0.5 * rho * pi * d * l * p.tangentialDrag;
    for (int i = 1; i < N; ++i) {
        const std::size_t k = std::size_t(i);
        const Vector3& t = f.tangent[k];
        // mass mn (I - t t') + mt t t'; drag c |u| u of u = -v_n, -v_t:
        // -dF/dv = c (|u| P + u u'/|u|)
        const double along = v[k].dot(t); // t is a unit vector or 0
        const Vector3 vn = v[k] - along * t;
        const double un = vn.norm(), ut = std::abs(along);
        Matrix3& b = J.diagonal[k - 1];
        b.diagonal().array() += mn + cn * un;
        b += (mt - mn - cn * un + 2.0 * ct * ut) * t * t.transpose();
        if (un > 0.0) {
            b += (cn / un) * vn * vn.transpose();
        }
        if (p.seabedContact && r[k][2] <= zb) {
            const double depth = zb - r[k][2];
            b(2, 2) += stiffness * p.seabedStiffness * d * l
                + damping * p.seabedDamping * std::min(depth / restDepth, 1.0)
                    * d * l;
        }
    }
}

} // namespace connectors
