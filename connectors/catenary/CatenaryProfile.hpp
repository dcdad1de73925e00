// The elastic catenary in its vertical plane (Irvine, "Cable Structures",
// 1981, ch. 2; the same relations as MAP++ and MoorDyn's Catenary routine).
//
// A line of unstretched length L [m], axial stiffness EA [N] and weight per
// unstretched length w [N/m] (submerged weight; w < 0 for a buoyant line,
// w = 0 for a weightless one) runs from its lower end, the anchor, at the
// origin of the plane to the fairlead at horizontal span x >= 0 [m] and
// vertical span z [m] (z up). Unknowns: H >= 0 [N], the horizontal tension
// (constant along the suspended part), and V [N], the vertical tension at the
// fairlead (the line pulls the fairlead down by V). With
// a = V/H, b = (V - wL)/H:
//
//   suspended:  x = (H/w)(asinh a - asinh b) + H L/EA
//               z = (H/w)(sqrt(1+a^2) - sqrt(1+b^2)) + (V L - w L^2/2)/EA
//
// With seabed contact (the anchor on the seabed, w > 0, V < wL) a length
// Lb = L - V/w lies on the seabed, with Coulomb friction coefficient CB:
//
//   touchdown:  x = Lb + (H/w) asinh a + H L/EA
//                   + CB w/(2EA) [-Lb^2 + (Lb - H/(CB w)) max(Lb - H/(CB w), 0)]
//               z = (H/w)(sqrt(1+a^2) - 1) + V^2/(2 EA w)
//
// Both are evaluated in forms without 1/w cancellation (divided
// differences), so w -> 0 and w < 0 use the same expressions. The two
// unknowns are found with a damped Newton method (analytic Jacobian,
// backtracking on the residual norm, H kept > 0), warm started from a
// previous solution when one is given.
//
// Regimes handled in closed form, without Newton:
//  - slackOnSeabed: anchor on the seabed, line so long that it hangs
//    vertically below the fairlead and the rest lies on the seabed without
//    horizontal tension (H = 0); the grounded part is drawn heaped at the
//    touchdown point;
//  - vertical: fairlead directly above (or below) the anchor, taut (H = 0);
//  - folded: both ends on one vertical, slack and off the seabed (H = 0):
//    one strand hangs (or, buoyant, floats) from each end to a fold where
//    the tension vanishes, the H -> 0 limit of the suspended relations;
//  - slackWeightless: w = 0 and the chord shorter than L: no tension, the
//    shape is undefined and drawn as the straight chord.
// A fairlead below the seabed is UndefinedStateError; so is a Newton
// failure, whose message gives the regime and the residual.
//
// A line of sections (CatenaryLine::sections; CatenarySections.hpp): the
// sections follow each other from the anchor to the fairlead, each with
// its own L_k, EA_k and w_k, a point load J_k at each joint (a clump
// weight's or a buoy's net submerged weight). H is the same along the
// suspended part; the vertical tension falls by w_k L_k along a section
// and by J_k across a joint on the way from the fairlead down, and each
// suspended piece is the closed form above. With seabed contact the
// touchdown point is the highest point where the vertical tension would
// reach zero; everything below it lies on the seabed (possibly several
// sections, the touchdown possibly at a joint whose point the seabed then
// partly carries), the tension falling there by CB w_k per m and by CB
// times the seabed's reaction at each grounded point.
#ifndef CONNECTORS_CATENARY_CATENARYPROFILE_HPP
#define CONNECTORS_CATENARY_CATENARYPROFILE_HPP

#include <Eigen/Core>
#include <vector>

namespace connectors {

//- A section of the line after the first (whose properties are those of
//  CatenaryLine itself), with the point at its joint with the section
//  before it
struct CatenarySection {
    //- Net submerged weight of the point at the section's lower joint [N]:
    //  > 0 a clump weight, < 0 a buoy (its buoyancy less its weight), 0 none
    double jointWeight = 0.0;
    //- Unstretched length [m] > 0, axial stiffness [N] > 0, submerged weight
    //  per unstretched length [N/m] (< 0: buoyant)
    double length = 1.0, EA = 1.0, weight = 0.0;
};

struct CatenaryLine {
    //- Unstretched length L [m], > 0
    double length = 1.0;
    //- Axial stiffness EA [N], > 0
    double EA = 1.0;
    //- Weight per unstretched length w [N/m] (submerged; < 0: buoyant)
    double weight = 0.0;
    //- Seabed friction coefficient CB [-], >= 0 (with seabed contact only)
    double seabedFriction = 0.0;
    //- True when the anchor lies on the seabed (the plane through it)
    bool seabedContact = false;
    //- Sections 2, 3, ... from the anchor towards the fairlead after the
    //  first (length, EA, weight above); empty: a uniform line
    std::vector<CatenarySection> sections;
};

//- Unstretched length of all sections together [m]
double totalLength(const CatenaryLine& line);

//- Weight of all sections and joint points together [N]
double totalWeight(const CatenaryLine& line);

enum class CatenaryRegime {
    suspended,
    touchdown,
    slackOnSeabed,
    vertical,
    folded,
    slackWeightless
};

//- "suspended", "touchdown", ...
const char* regimeName(CatenaryRegime regime);

struct CatenarySolution {
    CatenaryRegime regime = CatenaryRegime::suspended;
    //- Horizontal tension at the fairlead [N]
    double H = 0.0;
    //- Vertical tension at the fairlead (pulls it down when > 0) [N]
    double V = 0.0;
    //- Horizontal tension at the anchor (pulls it towards the fairlead) [N]
    double HA = 0.0;
    //- Vertical tension at the anchor (pulls it up when > 0) [N]
    double VA = 0.0;
    //- Unstretched length lying on the seabed [m]
    double groundedLength = 0.0;
    //- Newton iterations taken (0 for the closed-form regimes)
    int iterations = 0;
    //- Final residual |(x, z) - (x(H,V), z(H,V))| [m]
    double residual = 0.0;
};

//- Newton settings
struct CatenaryOptions {
    //- Converged when the residual is below tolerance * L [-]
    double tolerance = 1e-10;
    int maxIterations = 100;
};

//- H and V of a previous solution, used as the first Newton iterate
struct CatenaryGuess {
    double H = 0.0;
    double V = 0.0;
};

//- Solves for the end tensions; `guess` may be null (cold start). Throws
//  UndefinedStateError for the undefined cases listed above.
CatenarySolution solveCatenary(const CatenaryLine& line, double x, double z,
                               const CatenaryGuess* guess = nullptr,
                               const CatenaryOptions& options = {});

//- Point of the line at unstretched arc length s in [0, L] from the anchor
//  (L the total length),
//  as (horizontal, vertical) from the anchor [m]
Eigen::Vector2d catenaryPoint(const CatenaryLine& line,
                              const CatenarySolution& solution, double x,
                              double z, double s);

//- Effective tension [N] at unstretched arc length s in [0, L] from the
//  anchor: sqrt(H^2 + (VA + w s)^2) on a suspended line; on the seabed H,
//  falling by CB w per m towards the anchor (never below 0), and
//  sqrt(H^2 + (w (s - Lb))^2) above the touchdown point; the vertical
//  regimes |VA + w s| (H = 0); 0 on a slack weightless line. A line of
//  sections: the same per piece; at a joint, the section above it
double catenaryTension(const CatenaryLine& line,
                       const CatenarySolution& solution, double s);

//- Strain energy plus the weight's potential energy relative to the
//  anchor's height: integral of T^2/(2EA) + w z(s) over s, plus J_k z_k of
//  the joints' points [J]
double catenaryEnergy(const CatenaryLine& line,
                      const CatenarySolution& solution, double x, double z);

//- Effective tension at each section's lower (towards the anchor) and
//  upper end [N], sections from the anchor (one for a uniform line: the
//  anchor's and the fairlead's); x the horizontal span
struct CatenarySectionTensions {
    std::vector<double> lower, upper;
};
CatenarySectionTensions
catenarySectionTensions(const CatenaryLine& line,
                        const CatenarySolution& solution, double x);

} // namespace connectors

#endif
