// Static stiffness of the lumped-mass line and the block tridiagonal solve
// used by MooringLine's damped Newton for the start equilibrium.
//
// With F_i the static force on free node i (segment tensions, submerged
// weight, seabed penalty; no velocities), S = -dF/dr is block tridiagonal
// in the free nodes 1..N-1 (3 x 3 blocks). Segment j (nodes j, j+1,
// stretched length s, unit vector q, tension T) contributes
//   k_j = EA/l q q' + max(T, w l)/s (I - q q')
// to the diagonal blocks of j and j+1 and -k_j to the coupling block; a node
// below the seabed adds kb d l to its zz entry. A slack segment keeps EA/l
// along q and the floor w l in the transverse term: the residual is the
// true law, these floors only keep the Newton matrix regular.
#ifndef CONNECTORS_MOORINGLINE_LINESTATICS_HPP
#define CONNECTORS_MOORINGLINE_LINESTATICS_HPP

#include <vector>

#include "common/Kinematics.hpp"

namespace connectors {

struct MooringLineParameters;

//- Symmetric block tridiagonal matrix over the free nodes 1..N-1
struct BlockTridiagonal {
    //- diagonal[i - 1] = S_ii, upper[i - 1] = S_i,i+1 (lower = transpose)
    std::vector<Matrix3> diagonal, upper;

    //- Solves S x = b (block Thomas elimination; S symmetric positive
    //  definite here, so no pivoting between blocks is needed)
    std::vector<Vector3> solve(const std::vector<Vector3>& b) const;
};

//- S = -dF/dr at node positions r (0..N) with the seabed at height zb
BlockTridiagonal staticStiffness(const MooringLineParameters& p, double weight,
                                 const std::vector<Vector3>& r, double zb);

} // namespace connectors

#endif
