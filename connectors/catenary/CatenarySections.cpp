#include "catenary/CatenarySections.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "catenary/CatenarySectionsDetail.hpp"
#include "common/ConnectorError.hpp"

namespace connectors {
namespace catenarySections {

namespace {

using catenarySpan::Span;
using catenarySpan::suspendedSpan;
using detail::count;
using detail::groundedIntegral;
using detail::jointAbove;
using detail::pointOf;
using detail::Profile;
using detail::profile;
using detail::Properties;
using detail::properties;
using detail::Touchdown;
using detail::touchdown;

//- Span of one piece from its lower end, with its derivatives in (H, V)
Span pieceSpan(const Piece& p, double H)
{
    Span out;
    switch (p.kind) {
    case Piece::Kind::suspended: {
        const Span f = suspendedSpan(p.length, p.EA, p.w, H, p.Va);
        out = f;
        if (p.partial) {
            // the length V_top/w moves with V, the lower end's tension 0
            const double Vt = p.w * p.length, T = std::hypot(H, Vt);
            out.xV = (H / T + H / p.EA) / p.w;
            out.zV = (Vt / T + Vt / p.EA) / p.w;
        }
        return out;
    }
    case Piece::Kind::grounded: {
        const double m = p.length, T = p.Ttop, c = p.friction;
        out.x = m + groundedIntegral(T, c, m) / p.EA;
        const bool clamped = c > 0.0 && c * m > T;
        const double dIdT = clamped ? T / c : m;
        const double dIdm = clamped ? 0.0 : T - c * m;
        out.xH = dIdT * p.dTdH / p.EA;
        out.xV = p.dLengthdV + (dIdT * p.dTdV + dIdm * p.dLengthdV) / p.EA;
        return out;
    }
    case Piece::Kind::vertical:
        out.z = p.direction * p.length
            + (p.Va * p.length + 0.5 * p.w * p.length * p.length) / p.EA;
        return out;
    }
    return out;
}

//- Places the pieces end to end from the anchor (heaped pieces gathered
//  below the horizontal span x)
void position(std::vector<Piece>& pieces, double H, double x)
{
    double x0 = 0.0, z0 = 0.0;
    for (Piece& p : pieces) {
        p.x0 = p.heaped ? std::min(p.s0, x) : x0;
        p.reach = x;
        p.z0 = z0;
        const Span f = pieceSpan(p, H);
        x0 = p.heaped ? std::min(p.s0 + p.length, x) : x0 + f.x;
        z0 += f.z;
    }
}

//- The grounded pieces below the touchdown point, from the anchor up; T,
//  dTdH, dTdV: the tension at the touchdown point and its derivatives
std::vector<Piece> groundedPieces(const CatenaryLine& l, const Profile& p,
                                  const Touchdown& t, double T, double dTdH,
                                  double dTdV, bool heaped)
{
    const double CB = l.seabedFriction;
    std::vector<Piece> out;
    for (std::size_t k = t.section + 1; k-- > 0;) {
        const Properties q = properties(l, k);
        const bool top = k == t.section && !t.atJoint;
        Piece g;
        g.kind = Piece::Kind::grounded;
        g.section = k;
        g.heaped = heaped;
        g.EA = q.EA;
        g.w = q.w;
        g.s0 = p.s0[k];
        g.length = top ? q.length - t.hanging : q.length;
        g.dLengthdV = top ? -1.0 / q.w : 0.0;
        g.Ttop = T;
        g.dTdH = dTdH;
        g.dTdV = dTdV;
        g.friction = heaped ? 0.0 : CB * q.w;
        out.push_back(g);
        // the tension at its lower end, then across the point below it
        T -= g.friction * g.length + (k > 0 ? CB * jointAbove(l, k - 1) : 0.0);
        dTdV -= g.friction * g.dLengthdV;
        if (!(T > 0.0)) {
            T = dTdH = dTdV = 0.0;
        }
    }
    std::reverse(out.begin(), out.end());
    return out;
}

std::string sectionName(std::size_t k)
{
    return "section " + std::to_string(k + 1);
}

std::string jointName(std::size_t k)
{
    return "joint " + std::to_string(k + 1) + " (between sections "
        + std::to_string(k + 1) + " and " + std::to_string(k + 2) + ")";
}

//- Throws unless what lies below the touchdown point stays there: no
//  section lighter than water, no buoy
void requireGroundable(const CatenaryLine& l, const Touchdown& t, double H,
                       double V)
{
    const auto refuse = [&](const std::string& what) {
        throw UndefinedStateError(
            "catenary: " + what
            + " lies on the seabed below the touchdown point (at "
            + formatValue(t.arc)
            + " m from the anchor) and would rise from it: the line would "
              "touch the seabed twice, which the quasi-static catenary does "
              "not solve (H = "
            + formatValue(H) + " N, V = " + formatValue(V) + " N)");
    };
    for (std::size_t k = 0; k <= t.section; ++k) {
        const Properties q = properties(l, k);
        if (!(q.w > 0.0)) {
            refuse(sectionName(k) + " (weight " + formatValue(q.w)
                   + " N/m, allowed > 0 on the seabed)");
        }
        if (k < t.section && jointAbove(l, k) < 0.0) {
            refuse("the buoy at " + jointName(k) + " (net weight "
                   + formatValue(jointAbove(l, k))
                   + " N, allowed >= 0 on the seabed)");
        }
    }
}

//- Throws if the suspended part dips below the seabed (z = 0) at a low
//  point: inside a heavy piece where its vertical tension turns positive,
//  or at a joint (two touchdowns)
void requireAboveSeabed(const CatenaryLine& l, const std::vector<Piece>& ps,
                        double H)
{
    const double tolerance = 1e-9 * totalLength(l);
    for (const Piece& p : ps) {
        if (p.kind != Piece::Kind::suspended) {
            continue;
        }
        double t = 0.0;
        if (p.w > 0.0 && p.Va < 0.0 && p.Va + p.w * p.length > 0.0) {
            t = -p.Va / p.w;
        }
        const double z = t == 0.0 ? p.z0 : pointOf(p, H, t)[1];
        if (z < -tolerance) {
            throw UndefinedStateError(
                "catenary: the line would reach " + formatValue(-z)
                + " m below the seabed at " + formatValue(p.s0 + t)
                + " m from the anchor (" + sectionName(p.section)
                + "), held up on both sides: it would touch the seabed "
                  "twice, which the quasi-static catenary does not solve (H "
                  "= "
                + formatValue(H) + " N)");
        }
    }
}

} // namespace

std::vector<Piece> pieces(const CatenaryLine& l, double H, double V)
{
    const Profile p = profile(l, V);
    const Touchdown t = touchdown(l, p);
    const std::size_t n = count(l);
    std::vector<Piece> out;
    std::size_t firstSuspended = 0;
    if (t.grounded) {
        double T = H, dTdV = 0.0;
        if (t.atJoint) {
            // the seabed carries the point less what the line above holds
            const double held = t.section + 1 < n ? p.bottom[t.section + 1] : V;
            T -= l.seabedFriction * (jointAbove(l, t.section) - held);
            dTdV = l.seabedFriction;
        }
        out = T > 0.0 ? groundedPieces(l, p, t, T, 1.0, dTdV, false)
                      : groundedPieces(l, p, t, 0.0, 0.0, 0.0, false);
        firstSuspended = t.section + 1;
        if (!t.atJoint) {
            const Properties q = properties(l, t.section);
            Piece s;
            s.section = t.section;
            s.s0 = t.arc;
            s.length = t.hanging;
            s.EA = q.EA;
            s.w = q.w;
            s.partial = true;
            out.push_back(s);
        }
    }
    for (std::size_t k = firstSuspended; k < n; ++k) {
        const Properties q = properties(l, k);
        Piece s;
        s.section = k;
        s.s0 = p.s0[k];
        s.length = q.length;
        s.EA = q.EA;
        s.w = q.w;
        s.Va = p.bottom[k];
        s.dTdV = 1.0;
        out.push_back(s);
    }
    position(out, H, 0.0);
    return out;
}

std::vector<Piece> pieces(const CatenaryLine& l, const CatenarySolution& s,
                          double x)
{
    if (s.regime == CatenaryRegime::suspended
        || s.regime == CatenaryRegime::touchdown) {
        return pieces(l, s.H, s.V);
    }
    // H = 0: the line vertical above its touchdown point, if any
    const Profile p = profile(l, s.V);
    Touchdown t;
    if (s.regime == CatenaryRegime::slackOnSeabed) {
        t = touchdown(l, p);
    }
    std::vector<Piece> out;
    if (t.grounded) {
        out = groundedPieces(l, p, t, 0.0, 0.0, 0.0, true);
    }
    const double direction
        = s.regime == CatenaryRegime::vertical && s.V < 0.0 ? -1.0 : 1.0;
    for (std::size_t k = t.grounded ? t.section : 0; k < count(l); ++k) {
        const Properties q = properties(l, k);
        const bool partial = t.grounded && k == t.section;
        if (partial && t.atJoint) {
            continue;
        }
        Piece v;
        v.kind = Piece::Kind::vertical;
        v.section = k;
        v.s0 = partial ? t.arc : p.s0[k];
        v.length = partial ? t.hanging : q.length;
        v.EA = q.EA;
        v.w = q.w;
        v.Va = partial ? 0.0 : p.bottom[k];
        v.direction = direction;
        out.push_back(v);
    }
    position(out, 0.0, x);
    if (t.grounded) {
        // the hanging part stands on the seabed at the fairlead's span
        for (Piece& v : out) {
            v.x0 = v.kind == Piece::Kind::vertical ? x : v.x0;
        }
    }
    return out;
}

Span span(const CatenaryLine& line, double H, double V)
{
    Span out;
    for (const Piece& p : pieces(line, H, V)) {
        const Span f = pieceSpan(p, H);
        out.x += f.x;
        out.z += f.z;
        out.xH += f.xH;
        out.xV += f.xV;
        out.zH += f.zH;
        out.zV += f.zV;
    }
    return out;
}

bool grounded(const CatenaryLine& line, double V)
{
    return touchdown(line, profile(line, V)).grounded;
}

void fillEnds(const CatenaryLine& line, CatenarySolution& s)
{
    const Profile p = profile(line, s.V);
    const Touchdown t = touchdown(line, p);
    if (!t.grounded) {
        if (line.seabedContact) {
            requireAboveSeabed(line, pieces(line, s.H, s.V), s.H);
        }
        s.regime = CatenaryRegime::suspended;
        s.groundedLength = 0.0;
        s.HA = s.H;
        s.VA = p.bottom[0];
        return;
    }
    requireGroundable(line, t, s.H, s.V);
    requireAboveSeabed(line, pieces(line, s.H, s.V), s.H);
    s.regime = CatenaryRegime::touchdown;
    s.groundedLength = std::clamp(t.arc, 0.0, totalLength(line));
    const Piece& anchor = pieces(line, s.H, s.V).front();
    s.HA = std::max(anchor.Ttop - anchor.friction * anchor.length, 0.0);
    s.VA = 0.0;
}

bool closedForm(const CatenaryLine& l, double x, double z, CatenarySolution& s)
{
    const std::size_t n = count(l);
    const double L = totalLength(l), tiny = 1e-12 * L;
    bool weightless = true;
    for (std::size_t k = 0; k < n; ++k) {
        weightless = weightless && properties(l, k).w == 0.0
            && jointAbove(l, k) == 0.0;
    }
    if (weightless && std::hypot(x, z) <= L) {
        s.regime = CatenaryRegime::slackWeightless;
        return true;
    }
    if (l.seabedContact) {
        // Hanging vertically from the fairlead down to a touchdown point,
        // from the top: at section k's upper joint the line carries a
        // share of its point (z linear in it), inside section k a length d
        // (z = A + B d + C d^2). Z0, V0: height and fairlead tension with
        // the touchdown at the top of section k and none of its point
        // carried; R the compliance and Lh the length above it.
        const Profile p0 = profile(l, 0.0);
        double Z0 = 0.0, V0 = 0.0, R = 0.0, Lh = 0.0;
        for (std::size_t k = n; k-- > 0;) {
            const Properties q = properties(l, k);
            const double J = jointAbove(l, k);
            double V = 0.0, Ls = 0.0;
            bool found = false;
            Touchdown t; // at the top of section k, or d below it
            t.grounded = true;
            t.section = k;
            if (J != 0.0 && z > Z0) {
                if (J < 0.0) {
                    break; // a buoy on the hanging line: Newton
                }
                if (z <= Z0 + J * R) {
                    V = V0 + J * (z - Z0) / (J * R);
                    Ls = Lh;
                    t.atJoint = true;
                    found = true;
                }
            }
            const double A = Z0 + J * R;
            if (!found && z > A) {
                if (!(q.w > 0.0)) {
                    break; // a buoyant section on the hanging line: Newton
                }
                const double B = 1.0 + q.w * R, C = q.w / (2.0 * q.EA);
                if (z <= A + (B + C * q.length) * q.length) {
                    const double d = 2.0 * (z - A)
                        / (B + std::sqrt(B * B + 4.0 * C * (z - A)));
                    V = V0 + J + q.w * d;
                    Ls = Lh + d;
                    t.hanging = d;
                    found = true;
                }
            }
            if (!found && z <= A) {
                V = V0 + J;
                Ls = Lh;
                found = true;
            }
            if (found) {
                if (!(x <= L - Ls)) {
                    break;
                }
                t.arc = p0.s0[k] + q.length - t.hanging;
                requireGroundable(l, t, 0.0, V);
                s.regime = CatenaryRegime::slackOnSeabed;
                s.V = V;
                s.groundedLength = std::clamp(t.arc, 0.0, L);
                return true;
            }
            Z0 += (q.w * q.length + J) * R + q.length
                + 0.5 * q.w * q.length * q.length / q.EA;
            V0 += J + q.w * q.length;
            R += q.length / q.EA;
            Lh += q.length;
        }
    }
    if (!(x <= tiny)) {
        return false;
    }
    // Both ends on one vertical, taut: z = dir L + sum over the sections
    // of (V_bottom L + w L^2/2)/EA, linear in V
    const double direction = z > 0.0 ? 1.0 : -1.0;
    const Profile p0 = profile(l, 0.0);
    double R = 0.0, S = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const Properties q = properties(l, k);
        R += q.length / q.EA;
        S += (p0.bottom[k] + 0.5 * q.w * q.length) * q.length / q.EA;
    }
    s.regime = CatenaryRegime::vertical;
    s.V = (z - direction * L - S) / R;
    const Profile p = profile(l, s.V);
    bool taut = z != 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        taut = taut && direction * p.top[k] >= 0.0
            && direction * p.bottom[k] >= 0.0;
    }
    if (!taut) {
        throw UndefinedStateError(
            "catenary: the fairlead is straight above or below the anchor "
            "(horizontal span "
            + formatValue(x) + " m, vertical span " + formatValue(z)
            + " m) and the line of sections is slack there: a folded line "
              "of sections is not solved by the quasi-static catenary");
    }
    s.VA = p.bottom[0];
    return true;
}

CatenaryLine equivalentUniform(const CatenaryLine& line)
{
    CatenaryLine u = line;
    u.sections.clear();
    u.length = totalLength(line);
    u.weight = totalWeight(line) / u.length;
    double compliance = 0.0;
    for (std::size_t k = 0; k < count(line); ++k) {
        const Properties q = properties(line, k);
        compliance += q.length / q.EA;
    }
    u.EA = u.length / compliance;
    return u;
}

} // namespace catenarySections
} // namespace connectors
