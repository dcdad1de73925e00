// The quasi-static catenary of a line of sections (CatenaryLine::sections)
// with points at its joints: equal sections are the uniform line; a chain,
// a rope and a clump weight (or a buoy), suspended, with touchdown, with
// the clump on the seabed and slack, against the cable's equilibrium
// integrated numerically here. Loads, outputs and refusals:
// catenarySectionsLoadsTest.cpp.
#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>

#include "CatenarySectionsLines.hpp"
#include "LawTestSupport.hpp"
#include "catenary/Catenary.hpp"
#include "common/ConnectorError.hpp"

namespace {

using namespace lawTest;
using namespace catenarySectionsTest;
using connectors::Catenary;
using connectors::CatenaryLine;
using connectors::CatenaryOutput;
using connectors::CatenaryParameters;
using connectors::CatenaryRegime;
using connectors::CatenarySection;
using connectors::CatenarySolution;
using connectors::solveCatenary;

// ---------------------------------------------------------------------------
// Reference: the equilibrium of an elastic cable, integrated numerically
// from its lower end up, independent of the law's closed forms (which go
// from the fairlead down). Along the unstretched arc s the vertical tension
// V(s) rises by w per m and by J across a joint, H is constant, and
//   dx/ds = H/T + H/EA,   dz/ds = V/T + V/EA,   T = sqrt(H^2 + V^2);
// on the seabed below the touchdown point dx/ds = 1 + T/EA with T falling
// from H by CB w per m and CB J at each point towards the anchor (never
// below 0; a point at the touchdown point counts with the seabed's
// reaction). Simpson's rule on 4000 steps a section: its error, h^4 times
// the fourth derivative of the integrand (curvature radius H/w >= 20 m
// here), is below 1e-12 m; the kink of the friction-clamped tension, h^2 c,
// below 1e-9 m.
struct Reference {
    std::vector<double> L, EA, w, J; // J[k]: point at the top of section k

    double arcOf(std::size_t k) const
    {
        double s = 0.0;
        for (std::size_t i = 0; i < k; ++i) {
            s += L[i];
        }
        return s;
    }

    //- Vertical tension just above arc s when it is Vs just above sStart
    double verticalAt(double s, double sStart, double Vs) const
    {
        double V = Vs, arc = 0.0;
        for (std::size_t k = 0; k < L.size(); ++k) {
            const double a = std::max(arc, sStart), b = std::min(arc + L[k], s);
            if (b > a) {
                V += w[k] * (b - a);
            }
            arc += L[k];
            if (k < J.size() && arc > sStart && arc <= s) {
                V += J[k];
            }
        }
        return V;
    }

    //- Simpson's rule of f over section pieces from a to b
    double integrate(const std::function<double(double)>& f, double a,
                     double b) const
    {
        double sum = 0.0, arc = 0.0;
        for (std::size_t k = 0; k < L.size(); ++k) {
            const double lo = std::max(arc, a), hi = std::min(arc + L[k], b);
            arc += L[k];
            if (!(hi > lo)) {
                continue;
            }
            const int n = 4000;
            const double h = (hi - lo) / n;
            double part = f(lo) + f(hi - 1e-12 * h);
            for (int i = 1; i < n; ++i) {
                part += (i % 2 ? 4.0 : 2.0) * f(lo + i * h);
            }
            sum += part * h / 3.0;
        }
        return sum;
    }

    std::size_t sectionAt(double s) const
    {
        std::size_t k = 0;
        double arc = L[0];
        while (k + 1 < L.size() && s >= arc) {
            arc += L[++k];
        }
        return k;
    }

    //- Top of the line when it leaves the seabed at sStart (0: the anchor)
    //  with vertical tension Vs just above it; CB the friction
    Eigen::Vector2d top(double H, double sStart, double Vs, double CB) const
    {
        const double total = arcOf(L.size());
        const auto V = [&](double s) { return verticalAt(s, sStart, Vs); };
        const double x = integrate(
            [&](double s) {
                const double T = std::hypot(H, V(s));
                return H / T + H / EA[sectionAt(s)];
            },
            sStart, total);
        const double z = integrate(
            [&](double s) {
                const double v = V(s), T = std::hypot(H, v);
                return v / T + v / EA[sectionAt(s)];
            },
            sStart, total);
        // grounded: the tension falls from H towards the anchor
        const double grounded = integrate(
            [&](double s) {
                double fall = 0.0;
                for (std::size_t k = 0; k < L.size(); ++k) {
                    const double a = std::max(arcOf(k), s);
                    const double b = std::min(arcOf(k + 1), sStart);
                    fall += b > a ? CB * w[k] * (b - a) : 0.0;
                    if (k < J.size() && arcOf(k + 1) > s
                        && arcOf(k + 1) <= sStart) {
                        fall += CB * J[k];
                    }
                }
                return 1.0 + std::max(H - fall, 0.0) / EA[sectionAt(s)];
            },
            0.0, sStart);
        return {x + grounded, z};
    }

    //- Solves top(H, p) = (X, Z) for H and p by Newton with a difference
    //  Jacobian; p is the vertical tension at the anchor, or the touchdown
    //  arc (V = 0 there), or the share of a joint's point the line holds
    //  (the joint on the seabed)
    enum class Unknown { anchorTension, touchdownArc, heldAtJoint };
    void solve(double X, double Z, double CB, Unknown unknown,
               std::size_t joint, double& H, double& p) const
    {
        const auto miss = [&](double h, double q) {
            Eigen::Vector2d t = top(h, 0.0, q, CB); // anchorTension
            if (unknown == Unknown::touchdownArc) {
                t = top(h, q, 0.0, CB);
            } else if (unknown == Unknown::heldAtJoint) {
                // the joint on the seabed: the friction there acts on the
                // seabed's reaction J - q
                Reference r = *this;
                r.J[joint] = J[joint] - q;
                t = r.top(h, arcOf(joint + 1), q, CB);
            }
            return Eigen::Vector2d(t - Eigen::Vector2d(X, Z));
        };
        const auto steps = [](double h, double q) {
            return Eigen::Vector2d(1e-6 * h, 1e-6 * (std::abs(q) + 1.0));
        };
        if (!dampedNewton(miss, steps, 1e-11 * std::hypot(X, Z), 60, H, p)) {
            FAIL() << "the reference did not converge";
        }
    }
};

Reference referenceOf(const CatenaryLine& l)
{
    Reference r;
    r.L = {l.length};
    r.EA = {l.EA};
    r.w = {l.weight};
    for (const CatenarySection& s : l.sections) {
        r.J.push_back(s.jointWeight);
        r.L.push_back(s.length);
        r.EA.push_back(s.EA);
        r.w.push_back(s.weight);
    }
    return r;
}

//- The law's solution against the reference's H, fairlead V, joint
//  position and section end tensions
void expectReference(const CatenaryLine& l, double x, double z,
                     const CatenarySolution& s, double Href, double Vref,
                     const Reference& r, double sStart, double Vstart,
                     double tolerance)
{
    const double scale = std::hypot(s.H, s.V);
    EXPECT_NEAR(s.H, Href, tolerance * scale);
    EXPECT_NEAR(s.V, Vref, tolerance * scale);
    // the joint: the reference's top of section 1
    Reference lower = r;
    lower.L.resize(1);
    lower.EA.resize(1);
    lower.w.resize(1);
    lower.J.clear();
    const double jointArc = r.L[0];
    const Eigen::Vector2d joint
        = connectors::catenaryPoint(l, s, x, z, jointArc);
    Eigen::Vector2d jointRef;
    if (sStart < jointArc) {
        jointRef = lower.top(Href, sStart, Vstart, l.seabedFriction);
    } else {
        // the section below lies on the seabed: the grounded part alone
        jointRef = lower.top(Href, jointArc, 0.0, l.seabedFriction);
    }
    EXPECT_NEAR(joint[0], jointRef[0], 1e-9 * x);
    EXPECT_NEAR(joint[1], jointRef[1], 1e-9 * x);
    const connectors::CatenarySectionTensions t
        = connectors::catenarySectionTensions(l, s, x);
    ASSERT_EQ(t.lower.size(), 2u);
    const double VtopChain = r.verticalAt(jointArc, sStart, Vstart)
        - r.J[0]; // just below the joint
    const double VbottomRope = VtopChain + r.J[0];
    EXPECT_NEAR(t.upper[0], std::hypot(Href, std::max(VtopChain, 0.0)),
                tolerance * scale);
    EXPECT_NEAR(t.lower[1], std::hypot(Href, VbottomRope), tolerance * scale);
    EXPECT_NEAR(t.upper[1], std::hypot(Href, Vref), tolerance * scale);
    std::cout << "x = " << x << ", z = " << z << ": " << regimeName(s.regime)
              << ", H = " << s.H << " N (reference " << Href << "), V = " << s.V
              << " N (" << Vref << "), off by "
              << std::max(std::abs(s.H - Href), std::abs(s.V - Vref)) / scale
              << " of the tension, grounded " << s.groundedLength
              << " m, joint at (" << joint[0] << ", " << joint[1]
              << "), section tensions " << t.lower[0] << ", " << t.upper[0]
              << ", " << t.lower[1] << ", " << t.upper[1] << " N\n";
}

// The law stops Newton at a residual of 1e-10 of the line's length (12 nm
// here) and the reference at 1e-11 of the chord; dx/dH ~ L/H ~ 1e-3 m/N:
// the tensions agree to ~1e-7 of the fairlead tension at worst; 1e-6
// leaves a margin (measured: 1e-13 to 2e-11, Newton's last step being
// quadratic).
constexpr double referenceTolerance = 1e-6;

TEST(CatenarySections, ChainRopeAndClumpWeightSuspendedMatchTheReference)
{
    // no seabed: anchor 10 m below, the line taut enough to clear it
    const CatenaryLine l = chainRope(2e4, false);
    const double x = 105.0, z = 30.0;
    const CatenarySolution s = solveCatenary(l, x, z);
    EXPECT_EQ(s.regime, CatenaryRegime::suspended);
    const Reference r = referenceOf(l);
    double H = s.H * 1.1, VA = s.VA + 0.1 * s.H;
    r.solve(x, z, 0.0, Reference::Unknown::anchorTension, 0, H, VA);
    const double Vref = r.verticalAt(r.arcOf(2), 0.0, VA);
    expectReference(l, x, z, s, H, Vref, r, 0.0, VA, referenceTolerance);
    EXPECT_NEAR(s.VA, VA, referenceTolerance * s.H);
    EXPECT_EQ(s.HA, s.H);
}

TEST(CatenarySections, ChainRopeAndClumpWeightWithTouchdownMatchTheReference)
{
    for (const double friction : {0.0, 0.5}) {
        // the clump lifted 4.5 m, a third of the chain on the seabed
        const CatenaryLine l = chainRope(2e4, true, friction);
        const double x = 108.0, z = 40.0;
        const CatenarySolution s = solveCatenary(l, x, z);
        EXPECT_EQ(s.regime, CatenaryRegime::touchdown);
        ASSERT_GT(s.groundedLength, 1.0);
        ASSERT_LT(s.groundedLength, 59.0); // inside the chain
        const Reference r = referenceOf(l);
        double H = 1.2 * s.H, arc = s.groundedLength - 3.0;
        r.solve(x, z, friction, Reference::Unknown::touchdownArc, 0, H, arc);
        EXPECT_NEAR(s.groundedLength, arc, 1e-6 * x);
        const double Vref = r.verticalAt(r.arcOf(2), arc, 0.0);
        expectReference(l, x, z, s, H, Vref, r, arc, 0.0, referenceTolerance);
        // the anchor: the friction takes CB w per m of the grounded chain
        EXPECT_NEAR(s.HA, std::max(H - friction * 700.0 * arc, 0.0),
                    referenceTolerance * s.H);
        EXPECT_EQ(s.VA, 0.0);
    }
}

TEST(CatenarySections, TheClumpWeightOnTheSeabedMatchesTheReference)
{
    // a heavy clump stops the touchdown point at the joint over a range
    // of spans: the line holds part of it, the seabed the rest
    const CatenaryLine l = chainRope(2e4, true, 0.3);
    const double x = 112.0, z = 30.0;
    const CatenarySolution s = solveCatenary(l, x, z);
    EXPECT_EQ(s.regime, CatenaryRegime::touchdown);
    EXPECT_NEAR(s.groundedLength, 60.0, 1e-12);
    const Reference r = referenceOf(l);
    double H = 1.2 * s.H, held = 0.5 * 2e4;
    r.solve(x, z, 0.3, Reference::Unknown::heldAtJoint, 0, H, held);
    EXPECT_GT(held, 0.0);
    EXPECT_LT(held, 2e4);
    const double Vref = held + 50.0 * 60.0;
    EXPECT_NEAR(s.H, H, referenceTolerance * s.H);
    EXPECT_NEAR(s.V, Vref, referenceTolerance * s.H);
    // the seabed's reaction at the clump: 2e4 - held; the friction on it
    // and on the chain
    EXPECT_NEAR(s.HA,
                std::max(H - 0.3 * (2e4 - held) - 0.3 * 700.0 * 60.0, 0.0),
                referenceTolerance * s.H);
    const Eigen::Vector2d joint = connectors::catenaryPoint(l, s, x, z, 60.0);
    EXPECT_EQ(joint[1], 0.0);
    std::cout << "clump on the seabed: H = " << s.H << " N (reference " << H
              << "), V = " << s.V << " N (" << Vref << "), the line holds "
              << held << " N of the clump\n";
    // the neighbouring spans: the rope lies on the seabed too (shorter
    // span) or the clump lifts off (longer). Each change located by
    // bisection to 1e-10 m: H and V on either side agree (dV/dx < 1e6 N/m
    // here: 1e-3 N; 1e-6 of V allowed)
    const auto atJoint = [&](double xs) {
        return solveCatenary(l, xs, z).groundedLength == 60.0;
    };
    EXPECT_FALSE(atJoint(108.0));
    EXPECT_FALSE(atJoint(114.0));
    for (double lo : {108.0, 112.0}) {
        double hi = lo == 108.0 ? 112.0 : 114.0;
        const bool startsAtJoint = atJoint(lo);
        while (hi - lo > 1e-10) {
            const double mid = 0.5 * (lo + hi);
            (atJoint(mid) == startsAtJoint ? lo : hi) = mid;
        }
        const CatenarySolution a = solveCatenary(l, lo, z);
        const CatenarySolution b = solveCatenary(l, hi, z);
        EXPECT_NE(a.groundedLength == 60.0, b.groundedLength == 60.0);
        EXPECT_NEAR(a.V, b.V, 1e-6 * a.V) << lo;
        EXPECT_NEAR(a.H, b.H, 1e-6 * a.V) << lo;
        std::cout << "the touchdown point reaches the clump at x = " << lo
                  << " m: V = " << a.V << " N, " << b.V << " N\n";
    }
}

TEST(CatenarySections, BuoyLiftsTheJointAsTheReference)
{
    // a net lift of 35 kN at the joint: the chain rises from the seabed
    // to the buoy, above the fairlead; the rope sags between them
    const CatenaryLine l = chainRope(-3.5e4, true);
    const double x = 100.0, z = 30.0;
    const CatenarySolution s = solveCatenary(l, x, z);
    EXPECT_EQ(s.regime, CatenaryRegime::touchdown);
    const Reference r = referenceOf(l);
    double H = 1.2 * s.H, arc = 0.5 * s.groundedLength;
    r.solve(x, z, 0.0, Reference::Unknown::touchdownArc, 0, H, arc);
    EXPECT_NEAR(s.groundedLength, arc, 1e-6 * x);
    const double Vref = r.verticalAt(r.arcOf(2), arc, 0.0);
    expectReference(l, x, z, s, H, Vref, r, arc, 0.0, referenceTolerance);
    const Eigen::Vector2d joint = connectors::catenaryPoint(l, s, x, z, 60.0);
    EXPECT_GT(joint[1], z); // lifted above the fairlead
}

TEST(CatenarySections, EqualSectionsAreTheUniformLine)
{
    // The uniform line of catenaryProfileTest (100 m of chain) cut into
    // three equal sections without points, in every regime but the folded
    // one (refused for sections): the same closed forms summed over the
    // pieces, Newton from the same cold guess; measured: H and V within
    // 6e-15 of the tension, 1e-12 allowed
    for (const double friction : {0.0, 0.4}) {
        for (const bool seabed : {false, true}) {
            const CatenaryLine uniform
                = uniformLine(100.0, 5e7, 700.0, seabed, friction);
            CatenaryLine cut = uniform;
            cut.length = 100.0 / 3.0;
            CatenarySection third;
            third.length = cut.length;
            third.EA = uniform.EA;
            third.weight = uniform.weight;
            cut.sections = {third, third};
            const double spans[][2]
                = {{85.0, 40.0}, {95.0, 20.0}, {30.0, 20.0},
                   {0.0, 100.5}, {99.0, 1.0},  {60.0, 75.0}};
            for (const auto& span : spans) {
                const double x = span[0], z = span[1];
                const CatenarySolution a = solveCatenary(uniform, x, z);
                const CatenarySolution b = solveCatenary(cut, x, z);
                const double T = std::hypot(a.H, a.V) + 1.0;
                EXPECT_EQ(a.regime, b.regime) << x << " " << z;
                EXPECT_NEAR(a.H, b.H, 1e-12 * T) << x << " " << z;
                EXPECT_NEAR(a.V, b.V, 1e-12 * T) << x << " " << z;
                EXPECT_NEAR(a.HA, b.HA, 1e-12 * T) << x << " " << z;
                EXPECT_NEAR(a.VA, b.VA, 1e-12 * T) << x << " " << z;
                EXPECT_NEAR(a.groundedLength, b.groundedLength, 1e-12 * 100.0)
                    << x << " " << z;
                // the weight's potential: 8-panel Gauss quadrature over the
                // uniform line, over each section of the cut one; measured
                // 1.2e-7 apart for the deep sag of x = 30 m without seabed
                // (H/w = 5 m), below 4e-14 elsewhere
                const double Ea = connectors::catenaryEnergy(uniform, a, x, z);
                EXPECT_NEAR(Ea, connectors::catenaryEnergy(cut, b, x, z),
                            1e-6 * std::abs(Ea) + 1e-9 * T * 100.0)
                    << x << " " << z;
                for (const double arc : {0.0, 10.0, 33.3, 50.0, 66.7, 99.0}) {
                    const Eigen::Vector2d pa
                        = connectors::catenaryPoint(uniform, a, x, z, arc);
                    const Eigen::Vector2d pb
                        = connectors::catenaryPoint(cut, b, x, z, arc);
                    EXPECT_NEAR((pa - pb).norm(), 0.0, 1e-12 * 100.0)
                        << x << " " << z << " " << arc;
                    EXPECT_NEAR(connectors::catenaryTension(uniform, a, arc),
                                connectors::catenaryTension(cut, b, arc),
                                1e-12 * T)
                        << x << " " << z << " " << arc;
                }
            }
        }
    }
}

TEST(CatenarySections, HangingSlackFromTheFairlead)
{
    const CatenaryLine l = chainRope(2e4, true, 0.3);
    // 30 m of the rope hang from the fairlead: z = Ls + w Ls^2/(2 EA)
    const double z = 30.0;
    const double Ls = (std::sqrt(1 + 2 * 50.0 * z / 5e7) - 1) * 5e7 / 50.0;
    for (const double x : {0.0, 40.0, 120.0 - Ls - 1e-9}) {
        const CatenarySolution s = solveCatenary(l, x, z);
        EXPECT_EQ(s.regime, CatenaryRegime::slackOnSeabed) << x;
        EXPECT_EQ(s.H, 0.0);
        EXPECT_NEAR(s.V, 50.0 * Ls, 1e-9 * 50.0 * Ls);
        EXPECT_NEAR(s.groundedLength, 120.0 - Ls, 1e-9);
        const Eigen::Vector2d top
            = connectors::catenaryPoint(l, s, x, z, 120.0);
        EXPECT_NEAR(top[0], x, 1e-12);
        EXPECT_NEAR(top[1], z, 1e-9);
    }
    // just beyond: touchdown with a small H, continuous with H = 0
    const CatenarySolution t = solveCatenary(l, 120.0 - Ls + 1e-3, z);
    EXPECT_EQ(t.regime, CatenaryRegime::touchdown);
    EXPECT_GT(t.H, 0.0);
    EXPECT_LT(t.H, 1e-2 * 50.0 * Ls);
    EXPECT_NEAR(t.V, 50.0 * Ls, 1e-2 * 50.0 * Ls);
    // the whole rope hanging, the clump on the seabed held in part: the
    // rope stretches by (held + w s) / EA along it, z linear in held
    const double zRope = 60.0 + 50.0 * 60.0 * 60.0 / (2.0 * 5e7);
    const double zHeld = zRope + 0.25 * 2e4 * 60.0 / 5e7;
    const CatenarySolution c = solveCatenary(l, 10.0, zHeld);
    EXPECT_EQ(c.regime, CatenaryRegime::slackOnSeabed);
    EXPECT_NEAR(c.V, 50.0 * 60.0 + 0.25 * 2e4, 1e-6 * c.V);
    EXPECT_NEAR(c.groundedLength, 60.0, 1e-12);
    const connectors::CatenarySectionTensions ct
        = connectors::catenarySectionTensions(l, c, 10.0);
    EXPECT_EQ(ct.upper[0], 0.0);
    EXPECT_NEAR(ct.lower[1], 0.25 * 2e4, 1e-6 * c.V);
    EXPECT_NEAR(ct.upper[1], c.V, 1e-9 * c.V);
    // and the taut vertical line: z = L + sum (V_bottom L + w L^2/2)/EA
    const CatenarySolution v = solveCatenary(l, 0.0, 121.0);
    EXPECT_EQ(v.regime, CatenaryRegime::vertical);
    const double ropeStretch
        = ((v.V - 50.0 * 60.0) * 60.0 + 0.5 * 50.0 * 3600.0) / 5e7;
    const double chainStretch = ((v.V - 50.0 * 60.0 - 2e4 - 700.0 * 60.0) * 60.0
                                 + 0.5 * 700.0 * 3600.0)
        / 5e8;
    EXPECT_NEAR(120.0 + ropeStretch + chainStretch, 121.0, 1e-9);
}

} // namespace
