// Static stiffness of the lumped-mass line and the block tridiagonal solve
// used by MooringLine's damped Newton for the start equilibrium, and the
// Newton matrix of its implicit trapezoidal step.
//
// With F_i the static force on free node i (segment tensions, submerged
// weight, seabed penalty; no velocities), S = -dF/dr is block tridiagonal
// in the free nodes 1..N-1 (3 x 3 blocks). Segment j (nodes j, j+1,
// stretched length s, unit vector q, tension T) contributes
//   k_j = EA/l q q' + max(T, w l)/s (I - q q')
// to the diagonal blocks of j and j+1 and -k_j to the coupling block; a node
// below the seabed adds kb d l to its zz entry. Each segment and node takes
// its own section's l, EA, w and d (LineLayout). A slack segment keeps EA/l
// along q and the floor w l in the transverse term: the residual is the
// true law, these floors only keep the Newton matrix regular.
#ifndef CONNECTORS_MOORINGLINE_LINESTATICS_HPP
#define CONNECTORS_MOORINGLINE_LINESTATICS_HPP

#include <memory>
#include <vector>

#include "common/Kinematics.hpp"
#include "mooringLine/LineLayout.hpp"

namespace connectors {

struct MooringLineParameters;
struct NodeForces;

//- Symmetric block tridiagonal matrix over the free nodes 1..N-1
struct BlockTridiagonal {
    //- diagonal[i - 1] = S_ii, upper[i - 1] = S_i,i+1 (lower = transpose)
    std::vector<Matrix3> diagonal, upper;

    //- Solves S x = b (block Thomas elimination; S symmetric positive
    //  definite here, so no pivoting between blocks is needed)
    std::vector<Vector3> solve(const std::vector<Vector3>& b) const;

    //- Block LU factors: `diagonal` becomes the inverses of the pivots
    //  D'_i = D_i - U'_i-1 D'^-1_i-1 U_i-1, `lower` the multipliers
    //  U'_i-1 D'^-1_i-1; after it solveFactored solves S x = b in place
    void factorize();
    void solveFactored(std::vector<Vector3>& x) const;

    std::vector<Matrix3> lower;
};

//- S = -dF/dr at node positions r (0..N) with the seabed at height zb
BlockTridiagonal staticStiffness(const MooringLineParameters& p,
                                 const LineLayout& layout,
                                 const std::vector<Vector3>& r, double zb);

//- Newton matrix of a trapezoidal step of h [s] in the positions at its
//  end, M + h^2/4 S + h/2 D at node positions r (0..N), with
//  f = nodeForces there (its segment lengths, node tangents, masses, drag
//  factors and relative velocities): M the nodes' mass with added mass,
//  S = staticStiffness, D = -dF/dv of the axial damping (BA/l q q' per
//  segment), the drag, the seabed damping and friction. Symmetric positive
//  definite; it omits the change of M, of the drag's direction and of the
//  damping force's direction with the positions, so Newton converges
//  linearly (fast: these are small). Block tridiagonal over the free
//  nodes: diagonal blocks D_i, and the coupling block of segment j between
//  free nodes j and j + 1, U_j = -(a_j q_j q_j' + b_j I), kept as a_j, b_j
//  and q_j (q_j q_j' and I are symmetric, so U_j is).
struct TrapezoidMatrix {
    //- A symmetric 3 x 3 matrix by its upper triangle
    struct Symmetric {
        double xx = 0.0, xy = 0.0, xz = 0.0, yy = 0.0, yz = 0.0, zz = 0.0;

        //- += c v v'
        void addOuter(double c, const Vector3& v)
        {
            const double cx = c * v[0], cy = c * v[1], cz = c * v[2];
            xx += cx * v[0];
            xy += cx * v[1];
            xz += cx * v[2];
            yy += cy * v[1];
            yz += cy * v[2];
            zz += cz * v[2];
        }
        //- += c I
        void addDiagonal(double c)
        {
            xx += c;
            yy += c;
            zz += c;
        }
        void add(const Symmetric& m)
        {
            xx += m.xx;
            xy += m.xy;
            xz += m.xz;
            yy += m.yy;
            yz += m.yz;
            zz += m.zz;
        }
        //- The inverse (cofactors over the determinant)
        Matrix3 inverse() const
        {
            const double c00 = yy * zz - yz * yz, c01 = xz * yz - xy * zz,
                         c02 = xy * yz - xz * yy, c11 = xx * zz - xz * xz,
                         c12 = xy * xz - xx * yz, c22 = xx * yy - xy * xy;
            const double d = 1.0 / (xx * c00 + xy * c01 + xz * c02);
            Matrix3 m;
            m << c00 * d, c01 * d, c02 * d, c01 * d, c11 * d, c12 * d, c02 * d,
                c12 * d, c22 * d;
            return m;
        }
    };
    //- The diagonal blocks D_i (free node i at i - 1), overwritten by the
    //  pivots D'_i
    std::vector<Symmetric> diagonal;
    //- Block LU factors: per free node i (at i - 1) the inverse of the
    //  pivot D'_i = D_i - U_i-1 D'^-1_i-1 U_i-1 and G_i = D'^-1_i U_i
    //  (none for the last); U_i-1 D'^-1_i-1 = G_i-1' is the multiplier
    std::vector<Matrix3> pivotInverse, G;
    //- a_j, b_j [kg], q_j of the coupling blocks (at the upper free node
    //  j's index j - 1)
    std::vector<double> a, b;
    std::vector<Vector3> q;
    //- What the matrix was formed with, for telling whether it still
    //  serves a later step: the step h [s]; per free node (at i - 1) the
    //  seabed's stiffness and damping terms in its zz entry and its normal
    //  mass [kg]; per segment j (at j) its unit vector and the stiffness
    //  and damping along it, alpha [kg]
    double h = 0.0;
    std::vector<double> seabed, mass;
    std::vector<Vector3> segmentQ;
    std::vector<double> alpha;

    //- Solves J x = b in place (b given in x)
    void solve(std::vector<Vector3>& x) const;

    //- Values of a saved matrix of a line of N segments: h, then per free
    //  node the pivot's inverse and G (9 values each, row by row), seabed
    //  and mass, then per segment segmentQ and alpha
    static std::size_t savedSize(int N)
    {
        return 1 + 20 * std::size_t(N - 1) + 4 * std::size_t(N);
    }
    //- Appends J's savedSize(N) values to `out` (none: zeros)
    static void save(const TrapezoidMatrix* J, int N, std::vector<double>& out);
    //- The matrix saved at `data` (null where its h is 0: none saved)
    static std::shared_ptr<const TrapezoidMatrix> load(const double* data,
                                                       int N);
};

//- A segment at the start of a trapezoidal step: node j to j + 1 [m],
//  its length [m], strain [-] and elastic pull on node j, EA max(e, 0)
//  times the unit vector to j + 1 [N]
struct StartSegment {
    Vector3 dr = Vector3::Zero();
    double length = 0.0, strain = 0.0;
    Vector3 pull = Vector3::Zero();
};

//- The segments of the node positions r0 (0..N), f0 = nodeForces there
//  (its segment lengths and unit vectors), into `segments`
void startSegments(const LineLayout& layout, const std::vector<Vector3>& r0,
                   const NodeForces& f0, std::vector<StartSegment>& segments);

//- Assembles J (TrapezoidMatrix) and factorizes it; the elastic tension
//  is the discrete gradient from the step's start segments `start` to r
//  (AxialGradient.hpp): its stiffness along a segment dG/dl at r, across
//  it G over the mean length, 2 G/(l0 + l)
void trapezoidMatrix(const MooringLineParameters& p, const LineLayout& layout,
                     const std::vector<Vector3>& r, const NodeForces& f,
                     double zb, double h, TrapezoidMatrix& J,
                     const std::vector<StartSegment>& start);

//- The seabed's terms in the zz entry of the Newton matrix of a step of h
//  [s] of a free node at height z on (or below) the seabed at zb [m]:
//  h^2/4 times its penalty stiffness, h/2 times its damping [kg]
double seabedTerms(const MooringLineParameters& p, const LineLayout::Node& node,
                   double z, double zb, double h);

//- Damped Newton on the static forces of the free nodes (no velocities),
//  from r (ends r[0], r[N] held). The forces are minus the gradient of the
//  potential energy and the Newton matrix is positive definite, so every
//  Newton step descends: a step is halved until the energy decreases
//  (Armijo), or taken whole when it reduces the largest node force (near
//  the solution, where the energy's change is below its round-off).
//  r becomes the iterate with the smallest largest node force; returns
//  whether that fell below 1e-11 of the line's weight plus its largest
//  tension (plus the round-off of a tension, 16 eps EA |r| / l).
bool solveStatics(const MooringLineParameters& p, const LineLayout& layout,
                  std::vector<Vector3>& r, double zb);

} // namespace connectors

#endif
