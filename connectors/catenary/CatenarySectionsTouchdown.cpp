// The line of sections held from above (CatenarySectionsDetail.hpp): the
// vertical tension profile for the fairlead's V and the point where the
// line leaves the seabed.
#include "catenary/CatenarySectionsDetail.hpp"

namespace connectors {
namespace catenarySections {
namespace detail {

Profile profile(const CatenaryLine& l, double V)
{
    const std::size_t n = count(l);
    Profile p;
    p.top.resize(n);
    p.bottom.resize(n);
    p.s0.resize(n);
    double s = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        p.s0[k] = s;
        s += properties(l, k).length;
    }
    double Vt = V;
    for (std::size_t k = n; k-- > 0;) {
        const Properties q = properties(l, k);
        p.top[k] = Vt;
        p.bottom[k] = Vt - q.w * q.length;
        Vt = p.bottom[k] - (k > 0 ? jointAbove(l, k - 1) : 0.0);
    }
    return p;
}

Touchdown touchdown(const CatenaryLine& l, const Profile& p)
{
    Touchdown t;
    if (!l.seabedContact) {
        return t;
    }
    const std::size_t n = count(l);
    for (std::size_t k = 0; k < n; ++k) {
        const Properties q = properties(l, k);
        if (p.bottom[k] >= 0.0) {
            if (k > 0) {
                // rising from the point at the top of section k - 1
                t.grounded = true;
                t.section = k - 1;
                t.atJoint = true;
                t.arc = p.s0[k];
            }
            return t;
        }
        if (q.w > 0.0 && (p.top[k] > 0.0 || k + 1 == n)) {
            t.grounded = true;
            t.section = k;
            t.hanging = p.top[k] / q.w;
            t.arc = p.s0[k] + q.length - t.hanging;
            return t;
        }
    }
    // a light top section and V <= 0: the fairlead on the seabed
    t.grounded = true;
    t.section = n - 1;
    t.atJoint = true;
    t.arc = p.s0[n - 1] + properties(l, n - 1).length;
    return t;
}

} // namespace detail
} // namespace catenarySections
} // namespace connectors
