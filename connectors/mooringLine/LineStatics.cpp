#include "mooringLine/LineStatics.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "mooringLine/LineForces.hpp"
#include "mooringLine/LineLayout.hpp"
#include "mooringLine/MooringLine.hpp"

namespace connectors {

namespace {

//- Potential energy of the line held still: strain, seabed, weight and
//  buoyancy [J]
double staticEnergy(const NodeForces& f)
{
    return f.strainEnergy + f.seabedEnergy + f.gravityEnergy;
}

//- -dF_z/dz of node i's buoyancy where it crosses the free surface
//  (its submerged fraction falls by 1/ramp per m up there) [N/m]
double surfaceStiffness(const MooringLineParameters& p,
                        const LineLayout& layout, int i, double z)
{
    if (!p.freeSurface) {
        return 0.0;
    }
    const LineLayout::Node& node = layout.nodes[std::size_t(i)];
    const double phi = submergedFraction(p, z, node.ramp);
    return phi > 0.0 && phi < 1.0 ? node.surfaceStiffness : 0.0;
}

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

BlockTridiagonal staticStiffness(const MooringLineParameters& p,
                                 const LineLayout& layout,
                                 const std::vector<Vector3>& r, double zb)
{
    const int N = layout.N;
    BlockTridiagonal S;
    S.diagonal.assign(std::size_t(N - 1), Matrix3::Zero());
    S.upper.assign(std::size_t(std::max(N - 2, 0)), Matrix3::Zero());
    // section by section, its constants in locals
    for (const LineLayout::Section& section : layout.sections) {
        const LineLayout::Section c = section;
        for (int j = c.firstSegment; j < c.firstSegment + c.segments; ++j) {
            const double l = c.l;
            const Vector3 dr = r[std::size_t(j + 1)] - r[std::size_t(j)];
            const double s = dr.norm();
            if (!(s > 1e-12 * l)) {
                continue;
            }
            const Vector3 q = dr / s;
            const double T = c.EA * std::max(s / l - 1.0, 0.0);
            const Matrix3 qq = q * q.transpose();
            const double geometric = std::max(T, std::abs(c.w) * l) / s;
            const Matrix3 k = (s > l ? c.EA / l : geometric) * qq
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
    }
    for (int i = 1; i < N; ++i) {
        S.diagonal[std::size_t(i - 1)](2, 2)
            += surfaceStiffness(p, layout, i, r[std::size_t(i)][2]);
        if (p.seabedContact && r[std::size_t(i)][2] <= zb) {
            S.diagonal[std::size_t(i - 1)](2, 2)
                += layout.nodes[std::size_t(i)].contact(p.seabedStiffness);
        }
    }
    return S;
}

void trapezoidMatrix(const MooringLineParameters& p, const LineLayout& layout,
                     const std::vector<Vector3>& r, const NodeForces& f,
                     double zb, double h, BlockTridiagonal& J)
{
    const int N = layout.N;
    const double stiffness = 0.25 * h * h, damping = 0.5 * h;
    J.diagonal.assign(std::size_t(N - 1), Matrix3::Zero());
    J.upper.assign(std::size_t(std::max(N - 2, 0)), Matrix3::Zero());
    // Segment j: h^2/4 times staticStiffness's k_j plus h/2 BA/l q q',
    // alpha q q' + beta I
    // section by section, its constants in locals
    for (const LineLayout::Section& section : layout.sections) {
        const LineLayout::Section c = section;
        for (int j = c.firstSegment; j < c.firstSegment + c.segments; ++j) {
            const double l = c.l;
            const double s = f.stretched[std::size_t(j)];
            if (!(s > 1e-12 * l)) {
                continue;
            }
            const Vector3& q = f.q[std::size_t(j)];
            const double T = c.EA * std::max(s / l - 1.0, 0.0);
            const double geometric = std::max(T, std::abs(c.w) * l) / s;
            const double axial = s > l ? c.EA / l : geometric;
            const double alpha
                = stiffness * (axial - geometric) + damping * c.BA / l;
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
    }
    for (int i = 1; i < N; ++i) {
        const double restDepth = layout.nodes[std::size_t(i)].restDepth;
        const std::size_t k = std::size_t(i);
        const Vector3& t = f.tangent[k];
        // mass mn (I - t t') + mt t t'; drag c |u| u of u = U - v (normal
        // and tangential parts): -dF/dv = c (|u| P + u u'/|u|)
        const Vector3& u = f.relative[k];
        const Vector3 un = u - u.dot(t) * t; // t is a unit vector or 0
        const double mn = f.normalMass[k], mt = f.tangentialMass[k];
        const double cn = damping * f.normalDrag[k];
        const double ct = damping * f.tangentialDrag[k];
        Matrix3& b = J.diagonal[k - 1];
        b.diagonal().array() += mn + cn;
        b += (mt - mn - cn + 2.0 * ct) * t * t.transpose();
        const double un2 = un.squaredNorm();
        if (un2 > 0.0) {
            b += (cn / un2) * un * un.transpose();
        }
        b(2, 2) += stiffness * surfaceStiffness(p, layout, i, r[k][2]);
        if (p.seabedContact && r[k][2] <= zb) {
            const double depth = zb - r[k][2];
            b(2, 2) += layout.nodes[std::size_t(i)].contact(stiffness
                                                            * p.seabedStiffness)
                + layout.nodes[std::size_t(i)].contact(
                    damping * p.seabedDamping
                    * std::min(depth / restDepth, 1.0));
            // friction: c v below the regularisation speed, of constant
            // magnitude above it (damping only across the sliding
            // direction e: c (I - e e') in the horizontal plane)
            const Vector3& e = f.sliding[k];
            Matrix3 friction = Matrix3::Zero();
            friction(0, 0) = friction(1, 1) = 1.0;
            friction -= e * e.transpose();
            b += damping * f.friction[k] * friction;
        }
    }
}

bool solveStatics(const MooringLineParameters& p, const LineLayout& layout,
                  std::vector<Vector3>& r, double zb)
{
    const int N = layout.N;
    const std::vector<Vector3> still(std::size_t(N + 1), Vector3::Zero());
    std::vector<Vector3> x(r), trial(r);
    NodeForces f;
    nodeForces(p, layout, x, still, zb, f);
    double residual = largestForce(f), energy = staticEnergy(f);
    // Once below the tolerance, iterates on to the round-off floor (three
    // steps without a smaller largest force): a force left on a node
    // starts it moving
    double extent = 0.0; // largest coordinate [m]
    for (const Vector3& ri : r) {
        extent = std::max(extent, ri.lpNorm<Eigen::Infinity>());
    }
    // the round-off of a tension from a strain: coordinates carry eps |r|,
    // a segment's strain eps |r| / l
    double roundOff = 0.0;
    for (const LineLayout::Section& c : layout.sections) {
        roundOff = std::max(roundOff,
                            16.0 * std::numeric_limits<double>::epsilon() * c.EA
                                * extent / c.l);
    }
    const auto tolerance = [&](const NodeForces& forces) {
        double tension = 0.0;
        for (const double T : forces.T) {
            tension = std::max(tension, std::abs(T));
        }
        return 1e-11 * (layout.absoluteWeight + tension) + roundOff;
    };
    int stalled = 0;
    double best = residual, bestTolerance = tolerance(f);
    for (int iteration = 0;
         iteration < 200 && !(best <= bestTolerance && stalled >= 3);
         ++iteration) {
        const std::vector<Vector3> b(f.F.begin() + 1, f.F.end() - 1);
        const std::vector<Vector3> dx
            = staticStiffness(p, layout, x, zb).solve(b);
        double slope = 0.0; // d energy / d alpha = -F . dx < 0
        for (int i = 1; i < N; ++i) {
            slope -= b[std::size_t(i - 1)].dot(dx[std::size_t(i - 1)]);
        }
        bool accepted = false;
        for (double alpha = 1.0; alpha > 1e-12 && !accepted; alpha *= 0.5) {
            for (int i = 1; i < N; ++i) {
                trial[std::size_t(i)]
                    = x[std::size_t(i)] + alpha * dx[std::size_t(i - 1)];
            }
            NodeForces next;
            nodeForces(p, layout, trial, still, zb, next);
            const double nextResidual = largestForce(next);
            const double nextEnergy = staticEnergy(next);
            if (!std::isfinite(nextResidual) || !std::isfinite(nextEnergy)) {
                continue;
            }
            accepted = nextEnergy <= energy + 1e-4 * alpha * slope
                || (alpha == 1.0 && nextResidual < residual);
            if (accepted) {
                x.swap(trial);
                f = std::move(next);
                residual = nextResidual;
                energy = nextEnergy;
            }
        }
        if (!accepted) {
            break; // no descent left
        }
        if (residual < best) {
            best = residual;
            bestTolerance = tolerance(f);
            r = x;
            stalled = 0;
        } else {
            ++stalled;
        }
    }
    return best <= bestTolerance;
}

} // namespace connectors
