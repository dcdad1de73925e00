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

#include <vector>

#include "common/Kinematics.hpp"

namespace connectors {

struct MooringLineParameters;
struct NodeForces;
struct LineLayout;

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
//  segment), the drag, the seabed damping and friction. Symmetric positive definite; it omits the change of M, of the
//  drag's direction and of the damping force's direction with the
//  positions, so Newton converges linearly (fast: these are small).
void trapezoidMatrix(const MooringLineParameters& p, const LineLayout& layout,
                     const std::vector<Vector3>& r, const NodeForces& f,
                     double zb, double h, BlockTridiagonal& J);

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
