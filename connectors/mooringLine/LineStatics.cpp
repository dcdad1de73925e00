#include "mooringLine/LineStatics.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "mooringLine/MooringLine.hpp"

namespace connectors {

std::vector<Vector3>
BlockTridiagonal::solve(const std::vector<Vector3>& b) const
{
    const std::size_t n = diagonal.size();
    std::vector<Matrix3> inverse(n);
    std::vector<Vector3> x(b);
    // forward: D'_i = D_i - U'_i-1 D'^-1_i-1 U_i-1, b'_i likewise
    for (std::size_t i = 0; i < n; ++i) {
        Matrix3 d = diagonal[i];
        if (i > 0) {
            const Matrix3 m = upper[i - 1].transpose() * inverse[i - 1];
            d -= m * upper[i - 1];
            x[i] -= m * x[i - 1];
        }
        inverse[i] = d.inverse();
    }
    for (std::size_t k = n; k-- > 0;) {
        if (k + 1 < n) {
            x[k] -= upper[k] * x[k + 1];
        }
        x[k] = inverse[k] * x[k];
    }
    return x;
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

} // namespace connectors
