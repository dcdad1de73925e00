// The elastic catenary of a line of sections (CatenaryLine::sections), the
// part of the profile solver (CatenaryProfile.hpp) that a uniform line does
// not use. Internal to the catenary law.
//
// Sections k = 0..n-1 from the anchor Q to the fairlead P (L_k, EA_k, w_k),
// the point at the top of section k (k < n-1) of net weight J_k. For H > 0
// and V at the fairlead, from the top down: V_top(n-1) = V,
// V_bottom(k) = V_top(k) - w_k L_k, V_top(k-1) = V_bottom(k) - J_(k-1).
// Each suspended piece is the closed form of CatenarySpan.hpp; the spans
// and their derivatives in (H, V) are sums over the pieces. With seabed
// contact the touchdown point is the highest point where V would reach
// zero: inside a section of w_k > 0 at V_top(k)/w_k below its top, or at
// a joint (V_top(k) <= 0 < V_bottom(k+1): the line carries V_bottom(k+1)
// of the point, the seabed the rest). Below it everything lies on the
// seabed; the tension falls from H towards the anchor by CB w_k per m and
// by CB times the seabed's reaction at each grounded point, never below 0.
//
// Closed-form regimes without Newton: slackOnSeabed (H = 0, the suspended
// part hanging vertically: within a section the height is quadratic in
// the hanging length, across a joint linear in the share of the point the
// line carries), vertical (taut, H = 0, z linear in V). Refused
// (UndefinedStateError naming the section or joint): a buoyant section or
// a buoy below the touchdown point (the line would rise from the seabed
// and touch it again: two touchdowns), a folded line of sections.
#ifndef CONNECTORS_CATENARY_CATENARYSECTIONS_HPP
#define CONNECTORS_CATENARY_CATENARYSECTIONS_HPP

#include <vector>

#include "catenary/CatenaryProfile.hpp"
#include "catenary/CatenarySpan.hpp"

namespace connectors {
namespace catenarySections {

//- A stretch of one section in one state: suspended (H > 0), grounded, or
//  vertical (H = 0), from arc s0 (from the anchor) over `length`
struct Piece {
    enum class Kind { suspended, grounded, vertical };
    Kind kind = Kind::suspended;
    //- Section index from the anchor
    std::size_t section = 0;
    double s0 = 0.0, length = 0.0, EA = 1.0, w = 0.0;
    //- suspended, vertical: vertical tension at the lower end [N]
    double Va = 0.0;
    //- vertical: +1 rising towards the fairlead, -1 falling
    double direction = 1.0;
    //- grounded: tension at the upper end [N], fall per m CB w [N/m];
    //  heaped (slackOnSeabed): drawn gathered below the fairlead
    double Ttop = 0.0, friction = 0.0;
    bool heaped = false;
    //- heaped: the horizontal span below which they gather [m]
    double reach = 0.0;
    //- Lower end's position from the anchor (horizontal, vertical) [m]
    double x0 = 0.0, z0 = 0.0;
    //- For Newton: derivatives of Va (suspended) or Ttop (grounded) and of
    //  length in (H, V); partial: a suspended piece from the touchdown point
    double dTdH = 0.0, dTdV = 0.0, dLengthdV = 0.0;
    bool partial = false;
};

//- The pieces from the anchor up, positioned, for the line's H and V in
//  the Newton regimes (suspended, touchdown)
std::vector<Piece> pieces(const CatenaryLine& line, double H, double V);

//- The pieces of a solution (any regime but slackWeightless), x the
//  horizontal span
std::vector<Piece> pieces(const CatenaryLine& line, const CatenarySolution& s,
                          double x);

//- Span and Jacobian of the line of sections (Newton's residual)
catenarySpan::Span span(const CatenaryLine& line, double H, double V);

//- True when V puts part of the line on the seabed
bool grounded(const CatenaryLine& line, double V);

//- HA, VA, groundedLength of a Newton solution; throws UndefinedStateError
//  for a buoyant section or a buoy below the touchdown point
void fillEnds(const CatenaryLine& line, CatenarySolution& s);

//- The slackOnSeabed and vertical regimes; false when neither applies
//  (Newton then). Throws UndefinedStateError for a folded line.
bool closedForm(const CatenaryLine& line, double x, double z,
                CatenarySolution& s);

//- A uniform line of the same length, weight and elongation under a
//  uniform tension (for Newton's first iterate)
CatenaryLine equivalentUniform(const CatenaryLine& line);

Eigen::Vector2d point(const CatenaryLine& line, const CatenarySolution& s,
                      double x, double z, double arc);
double tension(const CatenaryLine& line, const CatenarySolution& s, double arc);
double energy(const CatenaryLine& line, const CatenarySolution& s, double x);
CatenarySectionTensions sectionTensions(const CatenaryLine& line,
                                        const CatenarySolution& s, double x);

} // namespace catenarySections
} // namespace connectors

#endif
