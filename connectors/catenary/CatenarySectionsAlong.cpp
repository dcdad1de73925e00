// The shape, tensions and energy along a solved line of sections
// (CatenarySections.hpp): each piece's closed form at an arc length.
#include <algorithm>
#include <cmath>

#include "catenary/CatenarySections.hpp"
#include "catenary/CatenarySectionsDetail.hpp"

namespace connectors {
namespace catenarySections {

namespace {

using detail::count;
using detail::jointAbove;
using detail::pointOf;
using detail::properties;

//- The piece holding arc (the upper one at a joint) and the arc within it
const Piece& locate(const std::vector<Piece>& ps, double& arc)
{
    std::size_t i = 0;
    while (i + 1 < ps.size() && arc >= ps[i + 1].s0) {
        ++i;
    }
    arc = std::clamp(arc - ps[i].s0, 0.0, ps[i].length);
    return ps[i];
}

double tensionOf(const Piece& p, double H, double t)
{
    switch (p.kind) {
    case Piece::Kind::suspended:
        return std::hypot(H, p.Va + p.w * t);
    case Piece::Kind::grounded:
        return std::max(p.Ttop - p.friction * (p.length - t), 0.0);
    case Piece::Kind::vertical:
        return std::abs(p.Va + p.w * t);
    }
    return 0.0;
}

} // namespace

Eigen::Vector2d point(const CatenaryLine& line, const CatenarySolution& s,
                      double x, double z, double arc)
{
    const double L = totalLength(line);
    if (s.regime == CatenaryRegime::slackWeightless) {
        return Eigen::Vector2d(x, z) * (std::clamp(arc, 0.0, L) / L);
    }
    const std::vector<Piece> ps = pieces(line, s, x);
    const Piece& p = locate(ps, arc);
    return pointOf(p, s.H, arc);
}

double tension(const CatenaryLine& line, const CatenarySolution& s, double arc)
{
    if (s.regime == CatenaryRegime::slackWeightless) {
        return 0.0;
    }
    const std::vector<Piece> ps = pieces(line, s, 0.0);
    const Piece& p = locate(ps, arc);
    return tensionOf(p, s.H, arc);
}

double energy(const CatenaryLine& line, const CatenarySolution& s, double x)
{
    if (s.regime == CatenaryRegime::slackWeightless) {
        return 0.0;
    }
    const std::vector<Piece> ps = pieces(line, s, x);
    double strain = 0.0, weight = 0.0;
    for (const Piece& p : ps) {
        const double m = p.length;
        if (p.kind == Piece::Kind::grounded) {
            // T falls linearly from Ttop over m0 <= m, then is 0
            const double c = p.friction;
            const double m0 = c > 0.0 ? std::min(m, p.Ttop / c) : m;
            const double T0 = p.Ttop - c * m0;
            strain += m0 * (T0 * T0 + T0 * p.Ttop + p.Ttop * p.Ttop) / 3.0
                / (2.0 * p.EA);
            continue;
        }
        const double H = p.kind == Piece::Kind::suspended ? s.H : 0.0;
        const double Va = p.Va, Vb = p.Va + p.w * m;
        strain += (H * H * m + m * (Va * Va + Va * Vb + Vb * Vb) / 3.0)
            / (2.0 * p.EA);
        weight += p.w
            * catenarySpan::integrate(
                      [&](double t) { return pointOf(p, s.H, t)[1]; }, 0.0, m);
    }
    // the joints' points at the tops of sections 1 .. n-1
    for (std::size_t k = 0; k + 1 < count(line); ++k) {
        const double J = jointAbove(line, k);
        if (J != 0.0) {
            double arc = 0.0;
            for (std::size_t i = 0; i <= k; ++i) {
                arc += properties(line, i).length;
            }
            double t = arc;
            const Piece& below = locate(ps, t); // the piece above the joint
            weight += J * pointOf(below, s.H, t)[1];
        }
    }
    return strain + weight;
}

CatenarySectionTensions sectionTensions(const CatenaryLine& line,
                                        const CatenarySolution& s, double x)
{
    CatenarySectionTensions t;
    t.lower.assign(count(line), 0.0);
    t.upper = t.lower;
    if (s.regime == CatenaryRegime::slackWeightless) {
        return t;
    }
    // the pieces from the anchor up: a section's first gives its lower
    // end, its last its upper end
    const std::vector<Piece> ps = pieces(line, s, x);
    for (std::size_t i = 0; i < ps.size(); ++i) {
        const Piece& p = ps[i];
        if (i == 0 || ps[i - 1].section != p.section) {
            t.lower[p.section] = tensionOf(p, s.H, 0.0);
        }
        t.upper[p.section] = tensionOf(p, s.H, p.length);
    }
    return t;
}

} // namespace catenarySections
} // namespace connectors
