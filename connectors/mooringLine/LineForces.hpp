// The force model of the lumped-mass line (MooringLine.hpp gives the
// equations): node forces and accelerations for given node positions and
// velocities, shared by the line's dynamics (MooringLine::rhs, evaluate)
// and its start equilibrium.
#ifndef CONNECTORS_MOORINGLINE_LINEFORCES_HPP
#define CONNECTORS_MOORINGLINE_LINEFORCES_HPP

#include <vector>

#include "common/Kinematics.hpp"

namespace connectors {

struct MooringLineParameters;

//- Forces on every node for given node positions and velocities
struct NodeForces {
    //- Segment tensions [N] and unit vectors from node j to j+1
    std::vector<double> T;
    std::vector<Vector3> q;
    //- Segment lengths [m]; unit tangents of the free nodes,
    //  unit(r_i+1 - r_i-1) (zero where the neighbours coincide)
    std::vector<double> stretched;
    std::vector<Vector3> tangent;
    //- Net forces [N] and accelerations of the free nodes (index 1..N-1;
    //  0 and N unused)
    std::vector<Vector3> F, a;
    double strainEnergy = 0.0, seabedEnergy = 0.0, dissipatedPower = 0.0;
    int groundedSegments = 0;
};

//- Forces on the nodes at positions r and velocities v (0..N), for the
//  submerged weight per length w [N/m] and the seabed at height zb [m]
NodeForces nodeForces(const MooringLineParameters& p, double w,
                      const std::vector<Vector3>& r,
                      const std::vector<Vector3>& v, double zb);
//- The same into f, reusing its storage
void nodeForces(const MooringLineParameters& p, double w,
                const std::vector<Vector3>& r, const std::vector<Vector3>& v,
                double zb, NodeForces& f);

//- Positions and velocities of the free nodes 1..N-1 from the state vector
void unpack(const std::vector<double>& nodes, int N, std::vector<Vector3>& r,
            std::vector<Vector3>& v);

//- Largest component of a free node's net force [N]
double largestForce(const NodeForces& f);

} // namespace connectors

#endif
