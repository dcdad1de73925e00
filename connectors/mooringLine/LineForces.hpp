// The force model of the lumped-mass line (MooringLine.hpp gives the
// equations): node forces and accelerations for given node positions and
// velocities, shared by the line's dynamics (MooringLine::rhs, evaluate)
// and its start equilibrium.
#ifndef CONNECTORS_MOORINGLINE_LINEFORCES_HPP
#define CONNECTORS_MOORINGLINE_LINEFORCES_HPP

#include <cstring>
#include <utility>
#include <vector>

#include "common/Kinematics.hpp"

namespace connectors {

struct MooringLineParameters;
struct LineLayout;

//- The water's motion seen by the line: the current profile of the
//  parameters (MooringLineParameters::currentSurface, currentSeabed) plus
//  a flow velocity at every node 0..N (empty: none), global frame [m/s],
//  and the flow's acceleration at every node 0..N (empty: none) [m/s2]
struct WaterMotion {
    bool current = false;
    std::vector<Vector3> flow;
    std::vector<Vector3> flowAcceleration;
};

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
    //- Forces on every node 0..N other than the segment tensions (weight,
    //  buoyancy, seabed, friction, drag, the flow's inertia) [N]; the end
    //  nodes' half segments
    //  (the loads on the bodies take them)
    std::vector<Vector3> external;
    //- Per node 0..N: submerged fraction [-] (1 without freeSurface), the
    //  water's velocity relative to the node [m/s], the normal and
    //  tangential drag factors c |u| of the drag c |u| u [N.s/m], the
    //  seabed friction's damping (friction force over horizontal speed)
    //  [N.s/m], and the free nodes' normal and tangential mass with added
    //  mass [kg]
    std::vector<double> submerged, normalDrag, tangentialDrag, friction;
    std::vector<double> normalMass, tangentialMass;
    std::vector<Vector3> relative;
    //- Per node: the unit horizontal velocity where the seabed friction
    //  is saturated (|v| above frictionVelocity; its magnitude then does
    //  not change with the speed), else zero
    std::vector<Vector3> sliding;
    //- With diagnostics only (else left as they were), the parts of
    //  `external` that do work other than gravity's, per node 0..N [N]:
    //  the drag, the seabed's push and friction, the flow's inertia; the
    //  damping part BA de/dt of each segment's tension [N] (flowInertia
    //  empty without the flow's acceleration); the seabed
    //  penalty's energy per section [J] (a joint's node counts in the
    //  section above it, towards P). The energy account of a time step
    //  (LineEnergy.hpp) takes them at its start and its end.
    std::vector<Vector3> drag, seabed, flowInertia;
    std::vector<double> damping, sectionSeabedEnergy;
    //- Potential of gravity and buoyancy of all nodes (the ends' half
    //  segments), heights from z = 0 [J]
    double gravityEnergy = 0.0;
    double strainEnergy = 0.0, seabedEnergy = 0.0, dissipatedPower = 0.0;
    int groundedSegments = 0;

    //- Exchanges every field with `o` (the storage's pointers: cheaper
    //  than std::swap's three moves; a field added above goes here too)
    void swap(NodeForces& o) noexcept
    {
        T.swap(o.T);
        stretched.swap(o.stretched);
        submerged.swap(o.submerged);
        normalDrag.swap(o.normalDrag);
        tangentialDrag.swap(o.tangentialDrag);
        friction.swap(o.friction);
        normalMass.swap(o.normalMass);
        tangentialMass.swap(o.tangentialMass);
        damping.swap(o.damping);
        sectionSeabedEnergy.swap(o.sectionSeabedEnergy);
        q.swap(o.q);
        tangent.swap(o.tangent);
        F.swap(o.F);
        a.swap(o.a);
        external.swap(o.external);
        relative.swap(o.relative);
        sliding.swap(o.sliding);
        drag.swap(o.drag);
        seabed.swap(o.seabed);
        flowInertia.swap(o.flowInertia);
        std::swap(gravityEnergy, o.gravityEnergy);
        std::swap(strainEnergy, o.strainEnergy);
        std::swap(seabedEnergy, o.seabedEnergy);
        std::swap(dissipatedPower, o.dissipatedPower);
        std::swap(groundedSegments, o.groundedSegments);
    }
};

//- Forces on the nodes at positions r and velocities v (0..N) of the
//  line laid out in `layout` (its sections and joint points), with the
//  seabed at height zb [m] (also the current profile's lower end), in
//  still water (water null) or the given water motion, into f (its
//  storage reused). diagnostics false: the energies, the dissipated
//  power and the grounded segments are left zero (a time step's Newton
//  iteration needs the forces, accelerations and drag factors only)
void nodeForces(const MooringLineParameters& p, const LineLayout& layout,
                const std::vector<Vector3>& r, const std::vector<Vector3>& v,
                double zb, NodeForces& f, const WaterMotion* water = nullptr,
                bool diagnostics = true);
//- The same for the parameters' layout with the first section's submerged
//  weight per length w [N/m]
NodeForces nodeForces(const MooringLineParameters& p, double w,
                      const std::vector<Vector3>& r,
                      const std::vector<Vector3>& v, double zb,
                      const WaterMotion* water = nullptr);
void nodeForces(const MooringLineParameters& p, double w,
                const std::vector<Vector3>& r, const std::vector<Vector3>& v,
                double zb, NodeForces& f, const WaterMotion* water = nullptr);

//- Submerged fraction of a node at height z [m] (freeSurface): 1 below
//  waterLevel - l/2, 0 above waterLevel + l/2, linear between; l the
//  length of the node's ramp (LineLayout::Node::ramp), by default the
//  first section's segment
double submergedFraction(const MooringLineParameters& p, double z);
double submergedFraction(const MooringLineParameters& p, double z, double l);
//- The current of the parameters at height z [m], seabed at zb [m]
Vector3 currentAt(const MooringLineParameters& p, double z, double zb);

//- Positions and velocities of the free nodes 1..N-1 from the state vector
void unpack(const std::vector<double>& nodes, int N, std::vector<Vector3>& r,
            std::vector<Vector3>& v);

//- Largest component of a free node's net force [N]
double largestForce(const NodeForces& f);

//- Whether a and b hold the same vectors, bit for bit
inline bool sameBits(const std::vector<Vector3>& a,
                     const std::vector<Vector3>& b)
{
    static_assert(sizeof(Vector3) == 3 * sizeof(double),
                  "Vector3 is 3 doubles");
    return a.size() == b.size()
        && (a.empty()
            || std::memcmp(a.data(), b.data(), a.size() * sizeof(Vector3))
                == 0);
}

} // namespace connectors

#endif
