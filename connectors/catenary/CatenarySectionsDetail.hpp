// Helpers shared by the parts of the line of sections: the solver
// (CatenarySections.cpp), the vertical tension profile and the touchdown
// point (CatenarySectionsTouchdown.cpp), and the shape, tensions and energy
// along a solved line (CatenarySectionsAlong.cpp). Internal to the
// catenary law.
#ifndef CONNECTORS_CATENARY_CATENARYSECTIONSDETAIL_HPP
#define CONNECTORS_CATENARY_CATENARYSECTIONSDETAIL_HPP

#include <algorithm>
#include <cstddef>
#include <vector>

#include "catenary/CatenarySections.hpp"

namespace connectors {
namespace catenarySections {
namespace detail {

struct Properties {
    double length, EA, w;
};

inline std::size_t count(const CatenaryLine& l)
{
    return 1 + l.sections.size();
}

inline Properties properties(const CatenaryLine& l, std::size_t k)
{
    if (k == 0) {
        return {l.length, l.EA, l.weight};
    }
    const CatenarySection& s = l.sections[k - 1];
    return {s.length, s.EA, s.weight};
}

//- Net weight of the point at the top of section k (0 at the fairlead) [N]
inline double jointAbove(const CatenaryLine& l, std::size_t k)
{
    return k + 1 < count(l) ? l.sections[k].jointWeight : 0.0;
}

//- Integral of the grounded tension max(T - c u, 0) over the depth u from
//  a piece's top to m [N.m]
inline double groundedIntegral(double T, double c, double m)
{
    return c > 0.0 && c * m > T ? T * T / (2.0 * c) : m * T - 0.5 * c * m * m;
}

//- The point of a piece at arc t from its lower end (horizontal, vertical
//  from the anchor) [m]
inline Eigen::Vector2d pointOf(const Piece& p, double H, double t)
{
    switch (p.kind) {
    case Piece::Kind::suspended: {
        if (t == 0.0) {
            return {p.x0, p.z0};
        }
        const catenarySpan::Span f
            = catenarySpan::suspendedSpan(t, p.EA, p.w, H, p.Va);
        return {p.x0 + f.x, p.z0 + f.z};
    }
    case Piece::Kind::grounded:
        if (p.heaped) {
            return {std::min(p.s0 + t, p.reach), 0.0};
        }
        return {p.x0 + t
                    + (groundedIntegral(p.Ttop, p.friction, p.length)
                       - groundedIntegral(p.Ttop, p.friction, p.length - t))
                        / p.EA,
                0.0};
    case Piece::Kind::vertical:
        return {p.x0,
                p.z0 + p.direction * t + (p.Va * t + 0.5 * p.w * t * t) / p.EA};
    }
    return {p.x0, p.z0};
}

//- Vertical tension at the top and bottom of each section for the
//  fairlead's V (the line held from above alone), and the arcs of the
//  sections' lower ends from the anchor
struct Profile {
    std::vector<double> top, bottom, s0;
};

Profile profile(const CatenaryLine& l, double V);

//- Where the line leaves the seabed
struct Touchdown {
    bool grounded = false;
    //- Section holding the touchdown point
    std::size_t section = 0;
    //- At the top of `section` (its upper joint's point on the seabed)
    bool atJoint = false;
    //- Suspended length of `section` (inside it) [m]
    double hanging = 0.0;
    //- Arc of the touchdown point from the anchor [m]
    double arc = 0.0;
};

//- The lowest point from which the line rises (seabed contact only): going
//  up from the anchor, where the vertical tension of the line held from
//  above turns positive, inside a heavy section or at a joint. Below it
//  that tension is <= 0: the seabed carries the line there.
Touchdown touchdown(const CatenaryLine& l, const Profile& p);

} // namespace detail
} // namespace catenarySections
} // namespace connectors

#endif
