// The line's sections and joint points laid out on its nodes and segments:
// what the force model (LineForces), the statics and the trapezoidal step
// (LineStatics) read per segment and per node, computed once from the
// parameters.
//
// Sections 1..n run from Q (node 0) to P (node N); section k has N_k
// segments of l_k = L_k/N_k. A node inside a section (or an end) carries
// one piece of line: a segment l_k (half of one at the ends); a node at the
// joint of sections k and k+1 carries two, l_k/2 of one and l_k+1/2 of the
// other, and the point there (clump weight or buoy). For a line of one
// section every quantity is computed as the uniform line computed it, so
// that its results are the same to the bit.
#ifndef CONNECTORS_MOORINGLINE_LINELAYOUT_HPP
#define CONNECTORS_MOORINGLINE_LINELAYOUT_HPP

#include <vector>

#include "common/Kinematics.hpp"

namespace connectors {

struct MooringLineParameters;
struct LinePoint;

struct LineLayout {
    //- A section's constants per unit unstretched length
    struct Section {
        double l = 1.0; // segment length [m]
        double inverseL = 1.0; // 1/l [1/m]
        double EA = 0.0, BA = 0.0; // [N], [N.s]
        double massPerLength = 0.0, diameter = 0.0, area = 0.0;
        double w = 0.0; // submerged weight per length [N/m]
        double dryWeight = 0.0; // mu g [N/m]
        double buoyancy = 0.0; // rho A g [N/m]
        double cn = 0.0,
               ct = 0.0; // drag factors 1/2 rho d Cdn, 1/2 rho pi d Cdt [kg/m2]
        double addedN = 0.0, addedT = 0.0; // added mass of a segment l [kg]
        //- The flow's inertia per length, rho A (1 + Can) and
        //  rho A (1 + Cat) [kg/m] (Froude-Krylov and added mass)
        double flowInertiaN = 0.0, flowInertiaT = 0.0;
        int firstSegment = 0, segments = 0;
    };
    //- The line a node carries: one piece (inside a section, or an end)
    //  or two (a joint), each a section and a length of it [m]
    struct Node {
        //- A piece: its section, length [m], and that section's constants
        //  (copied here, where the force model reads them node by node)
        struct Piece {
            int section = 0;
            double share = 0.0, diameter = 0.0, dryWeight = 0.0, buoyancy = 0.0,
                   cn = 0.0, ct = 0.0;
        };
        int pieces = 1;
        Piece piece[2];

        //- x times the seabed contact, the sum over the pieces of x d share
        //  (x d share as the uniform line wrote it), and at a joint x times
        //  its point's contact area
        double contact(double x) const
        {
            double sum = x * piece[0].diameter * piece[0].share;
            if (pieces == 2) {
                sum += x * piece[1].diameter * piece[1].share
                    + x * pointContact;
            }
            return sum;
        }
        //- Joint point (index into points), or -1
        int point = -1;
        //- Length of the free surface's ramp around the node [m]
        double ramp = 1.0;
        //- Penetration at which the seabed carries the node's weight [m]
        double restDepth = 0.0;
        //- -dF_z/dz of its buoyancy while crossing the free surface [N/m]
        double surfaceStiffness = 0.0;
        //- Dry mass and added mass (normal, tangential; at phi = 1) [kg]
        double mass = 0.0, addedN = 0.0, addedT = 0.0;
        //- The point's drag factor 1/2 rho CdA [kg/m], its weight and
        //  buoyancy [N] (zero without a point)
        double pointDrag = 0.0, pointWeight = 0.0, pointBuoyancy = 0.0;
        //- The point's own seabed contact area [m2]: its net weight over
        //  the seabed's stiffness times the deeper rest depth w/(kb d) of
        //  the two sections beside it, so that a clump weight rests as
        //  deep as the line around it whatever the segments' length; 0
        //  for a buoy and beside two sections lighter than water
        double pointContact = 0.0;
        //- The flow's inertia on the node's pieces and point (at phi = 1),
        //  normal and tangential: the force of a flow accelerating at a is
        //  phi (flowInertiaN a_n + flowInertiaT a_t) [kg]
        double flowInertiaN = 0.0, flowInertiaT = 0.0;
    };

    int N = 0;
    std::vector<Section> sections;
    //- Section of each segment 0..N-1
    std::vector<int> segmentSection;
    std::vector<Node> nodes;
    //- Unstretched arc length from Q of each node [m]
    std::vector<double> arc;
    double length = 0.0;
    //- Shortest segment [m]
    double shortest = 0.0;
    //- |weight| of the line and its points [N]
    double absoluteWeight = 0.0;

    const Section& ofSegment(int j) const
    {
        return sections[std::size_t(segmentSection[std::size_t(j)])];
    }
    //- The section node i counts in: its own, at a joint the one above
    //  it (towards P), as the FMU's shape.section
    int sectionOfNode(int i) const
    {
        const Node& node = nodes[std::size_t(i)];
        return node.piece[node.pieces - 1].section;
    }
    //- Fractional node index (node i at i, linear between) of the point
    //  at `fromQ` (0 at Q, 1 at P) of the unstretched length
    double nodeCoordinate(double fromQ) const;
    //- Node indices of the joints between sections (n - 1 of them)
    std::vector<int> jointNodes() const;
    //- Segment tensions at each section's ends: lower (towards Q) and upper
    std::vector<double> sectionEnds(const std::vector<double>& T,
                                    bool upper) const;
};

//- The layout of the parameters' sections, section 1's submerged weight
//  per length being w [N/m]
LineLayout lineLayout(const MooringLineParameters& p, double w);

} // namespace connectors

#endif
