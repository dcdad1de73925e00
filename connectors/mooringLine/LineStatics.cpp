#include "mooringLine/LineStatics.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "mooringLine/AxialGradient.hpp"
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

double seabedTerms(const MooringLineParameters& p, const LineLayout::Node& node,
                   double z, double zb, double h)
{
    const double depth = zb - z;
    return node.contact(0.25 * h * h * p.seabedStiffness)
        + node.contact(0.5 * h * p.seabedDamping
                       * std::min(depth / node.restDepth, 1.0));
}

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

void TrapezoidMatrix::solve(std::vector<Vector3>& x) const
{
    const std::size_t n = pivotInverse.size();
    // through raw pointers: the data pointers are not reloaded after each
    // store (Eigen's packet stores may alias anything)
    Vector3* const X = x.data();
    const Matrix3* const Gs = G.data();
    const Matrix3* const inverses = pivotInverse.data();
    for (std::size_t i = 1; i < n; ++i) {
        X[i] -= Gs[i - 1].transpose() * X[i - 1];
    }
    for (std::size_t k = n; k-- > 0;) {
        Vector3 y = inverses[k] * X[k];
        if (k + 1 < n) {
            y -= Gs[k] * X[k + 1];
        }
        X[k] = y;
    }
}

void trapezoidMatrix(const MooringLineParameters& p, const LineLayout& layout,
                     const std::vector<Vector3>& r, const NodeForces& f,
                     double zb, double h, TrapezoidMatrix& J,
                     const std::vector<StartSegment>& start)
{
    const int N = layout.N;
    const std::size_t n = std::size_t(N - 1);
    const double stiffness = 0.25 * h * h, damping = 0.5 * h;
    // the diagonal blocks D_i
    J.diagonal.assign(n, TrapezoidMatrix::Symmetric());
    TrapezoidMatrix::Symmetric* D = J.diagonal.data();
    J.pivotInverse.resize(n);
    J.G.resize(n);
    J.a.assign(n, 0.0);
    J.b.assign(n, 0.0);
    J.q.assign(n, Vector3::Zero());
    J.h = h;
    J.seabed.assign(n, 0.0);
    J.mass.resize(n);
    J.segmentQ.assign(std::size_t(N), Vector3::Zero());
    J.alpha.assign(std::size_t(N), 0.0);
    // Segment j: h^2/4 times staticStiffness's k_j plus h/2 BA/l q q',
    // alpha q q' + beta I
    // section by section, its constants in locals
    for (const LineLayout::Section& section : layout.sections) {
        const LineLayout::Section c = section;
        for (int j = c.firstSegment; j < c.firstSegment + c.segments; ++j) {
            const double l = c.l;
            const double s = f.stretched[std::size_t(j)];
            const Vector3& q = f.q[std::size_t(j)];
            if (j >= 1 && j + 1 <= N - 1) {
                J.q[std::size_t(j - 1)] = q;
            }
            if (!(s > 1e-12 * l)) {
                continue;
            }
            // the discrete gradient G, which replaces the average of the
            // elastic tensions at the step's ends: its stiffness along the
            // segment 2 dG/dl, across it G/((l0 + l)/2) (EA/l and T/l
            // where the segment is taut throughout, as the trapezoidal
            // rule's); along a slack segment at least the geometric one
            const StartSegment& s0 = start[std::size_t(j)];
            const AxialGradient g
                = axialGradient(c.EA, s0.strain, s * c.inverseL - 1.0);
            const double geometric = std::max(g.tension, std::abs(c.w) * l)
                / (0.5 * (s0.length + s));
            const double axial
                = std::max(2.0 * g.derivative * c.inverseL, geometric);
            const double alpha
                = stiffness * (axial - geometric) + damping * c.BA * c.inverseL;
            const double beta = stiffness * geometric;
            J.segmentQ[std::size_t(j)] = q;
            J.alpha[std::size_t(j)] = alpha;
            TrapezoidMatrix::Symmetric k;
            k.addOuter(alpha, q);
            k.addDiagonal(beta);
            if (j >= 1) {
                D[j - 1].add(k); // node j
            }
            if (j + 1 <= N - 1) {
                D[j].add(k); // node j + 1
            }
            if (j >= 1 && j + 1 <= N - 1) {
                J.a[std::size_t(j - 1)] = alpha;
                J.b[std::size_t(j - 1)] = beta;
            }
        }
    }
    for (int i = 1; i < N; ++i) {
        const std::size_t k = std::size_t(i);
        const Vector3& t = f.tangent[k];
        // mass mn (I - t t') + mt t t'; drag c |u| u of u = U - v (normal
        // and tangential parts): -dF/dv = c (|u| P + u u'/|u|)
        const Vector3& u = f.relative[k];
        const Vector3 un = u - u.dot(t) * t; // t is a unit vector or 0
        const double mn = f.normalMass[k], mt = f.tangentialMass[k];
        const double cn = damping * f.normalDrag[k];
        const double ct = damping * f.tangentialDrag[k];
        TrapezoidMatrix::Symmetric& b = D[k - 1];
        b.addDiagonal(mn + cn);
        b.addOuter(mt - mn - cn + 2.0 * ct, t);
        const double un2 = un.squaredNorm();
        if (un2 > 0.0) {
            b.addOuter(cn / un2, un);
        }
        if (p.freeSurface) {
            b.zz += stiffness * surfaceStiffness(p, layout, i, r[k][2]);
        }
        J.mass[k - 1] = mn;
        if (p.seabedContact && r[k][2] <= zb) {
            const LineLayout::Node& node = layout.nodes[k];
            J.seabed[k - 1] = seabedTerms(p, node, r[k][2], zb, h);
            b.zz += J.seabed[k - 1];
            // friction: c v below the regularisation speed, of constant
            // magnitude above it (damping only across the sliding
            // direction e: c (I - e e') in the horizontal plane)
            if (f.friction[k] != 0.0) {
                const double c = damping * f.friction[k];
                b.xx += c;
                b.yy += c;
                b.addOuter(-c, f.sliding[k]);
            }
        }
    }
    // Block LU: with U = -(a q q' + b I) and w = D'^-1 q,
    // U D'^-1 U = a^2 (q'w) q q' + a b (q w' + w q') + b^2 D'^-1
    // and G = D'^-1 U = -(a w q' + b D'^-1)
    for (std::size_t i = 0; i < n; ++i) {
        TrapezoidMatrix::Symmetric& d = D[i];
        if (i > 0) {
            const Matrix3& previous = J.pivotInverse[i - 1];
            const double a = J.a[i - 1], b = J.b[i - 1];
            const Vector3& q = J.q[i - 1];
            const Vector3 w = previous * q;
            const double A = a * a * q.dot(w), B = a * b, C = b * b;
            d.addOuter(-A, q);
            d.xx -= 2.0 * B * q[0] * w[0] + C * previous(0, 0);
            d.xy -= B * (q[0] * w[1] + w[0] * q[1]) + C * previous(0, 1);
            d.xz -= B * (q[0] * w[2] + w[0] * q[2]) + C * previous(0, 2);
            d.yy -= 2.0 * B * q[1] * w[1] + C * previous(1, 1);
            d.yz -= B * (q[1] * w[2] + w[1] * q[2]) + C * previous(1, 2);
            d.zz -= 2.0 * B * q[2] * w[2] + C * previous(2, 2);
            J.G[i - 1] = -(a * w * q.transpose() + b * previous);
        }
        J.pivotInverse[i] = d.inverse();
    }
    if (n > 0) {
        J.G[n - 1].setZero(); // no block beyond the last free node
    }
}

void TrapezoidMatrix::save(const TrapezoidMatrix* J, int N,
                           std::vector<double>& out)
{
    const std::size_t start = out.size();
    out.resize(start + savedSize(N), 0.0);
    if (!J) {
        return;
    }
    double* data = out.data() + start;
    *data++ = J->h;
    for (std::size_t i = 0; i + 1 < std::size_t(N); ++i) {
        for (int row = 0; row < 3; ++row) {
            for (int column = 0; column < 3; ++column) {
                data[3 * row + column] = J->pivotInverse[i](row, column);
                data[9 + 3 * row + column] = J->G[i](row, column);
            }
        }
        data[18] = J->seabed[i];
        data[19] = J->mass[i];
        data += 20;
    }
    for (std::size_t j = 0; j < std::size_t(N); ++j) {
        for (int k = 0; k < 3; ++k) {
            data[k] = J->segmentQ[j][k];
        }
        data[3] = J->alpha[j];
        data += 4;
    }
}

std::shared_ptr<const TrapezoidMatrix> TrapezoidMatrix::load(const double* data,
                                                             int N)
{
    if (data[0] == 0.0) {
        return nullptr;
    }
    auto J = std::make_shared<TrapezoidMatrix>();
    const std::size_t n = std::size_t(N - 1);
    J->h = *data++;
    J->pivotInverse.resize(n);
    J->G.resize(n);
    J->seabed.resize(n);
    J->mass.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        for (int row = 0; row < 3; ++row) {
            for (int column = 0; column < 3; ++column) {
                J->pivotInverse[i](row, column) = data[3 * row + column];
                J->G[i](row, column) = data[9 + 3 * row + column];
            }
        }
        J->seabed[i] = data[18];
        J->mass[i] = data[19];
        data += 20;
    }
    J->segmentQ.resize(std::size_t(N));
    J->alpha.resize(std::size_t(N));
    for (std::size_t j = 0; j < std::size_t(N); ++j) {
        J->segmentQ[j] = Vector3(data[0], data[1], data[2]);
        J->alpha[j] = data[3];
        data += 4;
    }
    return J;
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
