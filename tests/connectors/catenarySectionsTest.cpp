// The quasi-static catenary of a line of sections (CatenaryLine::sections)
// with points at its joints: equal sections are the uniform line; a chain,
// a rope and a clump weight (or a buoy), suspended, with touchdown, with
// the clump on the seabed and slack, against the cable's equilibrium
// integrated numerically here; F = -grad(potentialEnergy); the refusals.
#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>

#include "LawTestSupport.hpp"
#include "catenary/Catenary.hpp"
#include "common/ConnectorError.hpp"

namespace {

using namespace lawTest;
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
        for (int iteration = 0; iteration < 60; ++iteration) {
            const Eigen::Vector2d r = miss(H, p);
            if (r.norm() < 1e-11 * std::hypot(X, Z)) {
                return;
            }
            const double dH = 1e-6 * H, dp = 1e-6 * (std::abs(p) + 1.0);
            Eigen::Matrix2d Jac;
            Jac.col(0) = (miss(H + dH, p) - r) / dH;
            Jac.col(1) = (miss(H, p + dp) - r) / dp;
            const Eigen::Vector2d step = -Jac.fullPivLu().solve(r);
            double a = 1.0;
            while (a > 1e-6
                   && !(H + a * step[0] > 0.0
                        && miss(H + a * step[0], p + a * step[1]).norm()
                            < r.norm())) {
                a *= 0.5;
            }
            H += a * step[0];
            p += a * step[1];
        }
        FAIL() << "the reference did not converge";
    }
};

//- A line of one section: length [m], EA [N], w [N/m], seabed, friction
CatenaryLine uniformLine(double length, double EA, double weight, bool seabed,
                         double friction)
{
    CatenaryLine l;
    l.length = length;
    l.EA = EA;
    l.weight = weight;
    l.seabedContact = seabed;
    l.seabedFriction = friction;
    return l;
}

//- Chain (section 1, from the anchor), rope (section 2), a point between
CatenaryLine chainRope(double jointWeight, bool seabed, double friction = 0.0)
{
    CatenaryLine l = uniformLine(60.0, 5e8, 700.0, seabed, friction);
    CatenarySection rope;
    rope.length = 60.0;
    rope.EA = 5e7;
    rope.weight = 50.0;
    rope.jointWeight = jointWeight;
    l.sections = {rope};
    return l;
}

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

CatenaryParameters mooring(const CatenaryLine& line)
{
    CatenaryParameters p;
    p.p_AoP_A = Vector3(2.0, -1.0, -3.0);
    p.p_BoQ_B = Vector3(0.5, 0.2, 0.0);
    p.line = line;
    return p;
}

TEST(CatenarySections, ForceIsMinusTheEnergyGradient)
{
    // Without friction the line is conservative: F = -grad E at both
    // ends. Central differences over 1e-4 m: truncation h^2 E''' and the
    // Gauss quadrature of the weight's potential (1e-10 relative) give
    // ~1e-6 of the tension; 1e-4 as in the uniform line's test
    const CatenaryLine lines[] = {chainRope(2e4, true), chainRope(2e4, false),
                                  chainRope(-3.5e4, true)};
    for (const CatenaryLine& line : lines) {
        const Catenary law(mooring(line));
        const BodyKinematics A
            = body(Vector3(95, 30, 43), rotation(0.2, Vector3(1, 1, 0)));
        const BodyKinematics B
            = body(Vector3(0, 0, line.seabedContact ? 0 : -10));
        const CatenaryOutput out = law.evaluate(A, B, nullptr, 0);
        // -dE/dr_i with the body `moved` (A: 0, B: 1) displaced along i
        const auto minusGradient = [&](int moved, int i) {
            BodyKinematics k[2][2] = {{A, B}, {A, B}};
            k[0][moved].p_WKo_W[i] += 1e-4;
            k[1][moved].p_WKo_W[i] -= 1e-4;
            return (law.evaluate(k[1][0], k[1][1]).potentialEnergy
                    - law.evaluate(k[0][0], k[0][1]).potentialEnergy)
                / 2e-4;
        };
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(minusGradient(0, i), out.loads.A.f_W[i],
                        1e-4 * out.fairleadTension)
                << regimeName(out.solution.regime) << " " << i;
            if (!(line.seabedContact && i == 2)) { // the seabed moves with B
                EXPECT_NEAR(minusGradient(1, i), out.loads.B.f_W[i],
                            1e-4 * out.fairleadTension)
                    << regimeName(out.solution.regime) << " " << i;
            }
        }
        // off the seabed the bodies carry the whole weight
        if (out.solution.groundedLength == 0.0) {
            const Vector3 sum = out.loads.A.f_W + out.loads.B.f_W;
            const double W
                = 700.0 * 60.0 + 50.0 * 60.0 + line.sections[0].jointWeight;
            expectVectorNear(sum, -W * Vector3::UnitZ(),
                             1e-9 * out.fairleadTension);
        }
        ASSERT_EQ(out.joints.size(), 1u);
        ASSERT_EQ(out.sectionUpperTension.size(), 2u);
        EXPECT_NEAR(out.sectionUpperTension[1], out.fairleadTension,
                    1e-9 * out.fairleadTension);
        EXPECT_NEAR(out.sectionLowerTension[0], out.anchorTension,
                    1e-9 * out.fairleadTension);
    }
}

TEST(CatenarySections, OutputsGiveTheJointsTensionsAndPositions)
{
    // The law's outputs for a turned and moved fairlead body, suspended,
    // with touchdown and with a buoy lifting the joint (60 m of chain, 60 m
    // of rope): the tension at the sections' ends at the joint is the
    // closed form T = sqrt(H^2 + V^2), V the fairlead's less the rope's
    // weight (above the joint) and less the point's too (below it), and the
    // tension along the line there (catenaryTension, above the joint; 1 nm
    // below it); the joint in the global frame is the law's profile point
    // at its arc placed in the plane of P and Q, and the sixth of 11 shape
    // points (12 m of arc apart: 60 m from the anchor)
    struct Case {
        CatenaryLine line;
        double x, z; // spans from Q to P [m]
    };
    // the regimes of the tests against the reference above
    const Case cases[] = {{chainRope(2e4, false), 105.0, 30.0},
                          {chainRope(2e4, true), 108.0, 40.0},
                          {chainRope(-3.5e4, true), 100.0, 30.0}};
    for (const Case& c : cases) {
        const CatenaryLine& line = c.line;
        const Catenary law(mooring(line));
        const BodyKinematics B = body(Vector3(3, -2, -10));
        const Vector3 Q0 = B.p_WKo_W + Vector3(0.5, 0.2, 0.0);
        const Matrix3 R_A = rotation(0.2, Vector3(1, 1, 0));
        const Vector3 P0
            = Q0 + c.x * Vector3(0.6, 0.8, 0.0) + c.z * Vector3::UnitZ();
        const BodyKinematics A
            = body(Vector3(P0 - R_A * Vector3(2.0, -1.0, -3.0)), R_A);
        const CatenaryOutput out = law.evaluate(A, B, nullptr, 11);
        const CatenarySolution& s = out.solution;
        const double T = out.fairleadTension, J = line.sections[0].jointWeight;
        ASSERT_EQ(out.sectionLowerTension.size(), 2u);
        ASSERT_EQ(out.sectionUpperTension.size(), 2u);
        ASSERT_EQ(out.joints.size(), 1u);
        // the joint hangs (suspended pieces on both sides): round-off only
        const double above = s.V - 50.0 * 60.0, below = above - J;
        EXPECT_NEAR(out.sectionLowerTension[1], std::hypot(s.H, above),
                    1e-12 * T);
        EXPECT_NEAR(out.sectionUpperTension[0], std::hypot(s.H, below),
                    1e-12 * T);
        EXPECT_NEAR(out.sectionLowerTension[1],
                    connectors::catenaryTension(line, s, 60.0), 1e-12 * T);
        // 1e-9 m down the chain: its tension changes by w 1e-9 = 7e-7 N
        EXPECT_NEAR(out.sectionUpperTension[0],
                    connectors::catenaryTension(line, s, 60.0 - 1e-9),
                    1e-9 * T);
        // the profile plane: from Q, e_h horizontal towards P, z up
        const Vector3 P = A.p_WKo_W + A.R_WK * Vector3(2.0, -1.0, -3.0);
        const Vector3 Q = B.p_WKo_W + B.R_WK * Vector3(0.5, 0.2, 0.0);
        const Vector3 chord = P - Q;
        const double x = std::hypot(chord[0], chord[1]);
        const Vector3 eH(chord[0] / x, chord[1] / x, 0.0);
        const Eigen::Vector2d j
            = connectors::catenaryPoint(line, s, x, chord[2], 60.0);
        const Vector3 joint = Q + j[0] * eH + j[1] * Vector3::UnitZ();
        expectVectorNear(out.joints[0], joint, 1e-12 * 120.0);
        expectVectorNear(out.shape[5], out.joints[0], 1e-12 * 120.0);
        std::cout << regimeName(s.regime) << ": T at the joint "
                  << out.sectionUpperTension[0] << " N below, "
                  << out.sectionLowerTension[1] << " N above, joint at ("
                  << joint.transpose() << ") m\n";
    }
    // a uniform line is one section from the anchor to the fairlead
    const Catenary uniform(mooring(uniformLine(120.0, 5e8, 700.0, true, 0.0)));
    const CatenaryOutput u = uniform.evaluate(
        body(Vector3(95, 30, 43), rotation(0.2, Vector3(1, 1, 0))),
        body(Vector3::Zero()), nullptr, 0);
    EXPECT_EQ(u.sectionLowerTension, std::vector<double> {u.anchorTension});
    EXPECT_EQ(u.sectionUpperTension, std::vector<double> {u.fairleadTension});
    EXPECT_TRUE(u.joints.empty());
}

//- The call throws UndefinedStateError with each of `parts` in its message
template <class Call>
void expectRefusal(Call&& call, const std::vector<std::string>& parts)
{
    try {
        call();
        ADD_FAILURE() << "no exception";
    } catch (const connectors::UndefinedStateError& e) {
        for (const std::string& part : parts) {
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
                << e.what();
        }
    }
}

TEST(CatenarySections, TwoTouchdownsAreRefused)
{
    // a buoy on the grounded chain would lift it off the seabed between
    // two touchdown points
    CatenaryLine l = chainRope(0.0, true);
    CatenarySection chain;
    chain.length = 60.0;
    chain.EA = 5e8;
    chain.weight = 700.0;
    chain.jointWeight = -500.0;
    l.sections.insert(l.sections.begin(), chain); // chain, chain, rope
    l.sections[1].jointWeight = 0.0;
    expectRefusal([&] { solveCatenary(l, 120.0, 20.0); },
                  {"the buoy at joint 1 (between sections 1 and 2) (net "
                   "weight -500 N, allowed >= 0 on the seabed) lies on the "
                   "seabed below the touchdown point",
                   "touch the seabed twice"});
    // a buoyant first section would rise from the seabed as well
    CatenaryLine buoyant = chainRope(0.0, true);
    buoyant.weight = -10.0;
    buoyant.sections[0].jointWeight = 4e4; // pins the joint to the seabed
    expectRefusal([&] { solveCatenary(buoyant, 110.0, 20.0); },
                  {"section 1 (weight -10 N/m, allowed > 0 on the seabed)"});
    // a buoy holding up a long heavy rope whose sag would go through the
    // seabed between the buoy and the fairlead
    CatenaryLine sag = chainRope(-2e4, true);
    sag.length = 30.0;
    sag.sections[0].length = 90.0;
    sag.sections[0].weight = 200.0;
    expectRefusal([&] { solveCatenary(sag, 110.0, 20.0); },
                  {"catenary: the line would reach 1.4393",
                   "m below the seabed at 65.119",
                   "m from the anchor (section 2), held up on both sides: "
                   "it would touch the seabed twice"});
    EXPECT_EQ(solveCatenary(sag, 116.0, 20.0).regime,
              CatenaryRegime::touchdown); // taut enough to clear it
    // a slack line of sections folded on one vertical
    expectThrowWithMessage<connectors::UndefinedStateError>(
        [&] { solveCatenary(chainRope(2e4, false), 0.0, 10.0); },
        "catenary: the fairlead is straight above or below the anchor "
        "(horizontal span 0 m, vertical span 10 m) and the line of sections "
        "is slack there: a folded line of sections is not solved by the "
        "quasi-static catenary");
}

TEST(CatenarySections, ParametersAreCheckedByName)
{
    CatenaryParameters p = mooring(chainRope(2e4, true));
    p.line.sections[0].length = -1.0;
    expectThrowWithMessage<connectors::ParameterError>(
        [&] { Catenary law(p); },
        "catenary: parameter section2.unstretchedLength = -1 m is out of "
        "range (allowed: finite and > 0)");
    p = mooring(chainRope(2e4, true));
    p.line.sections[0].EA = 0.0;
    expectThrowWithMessage<connectors::ParameterError>(
        [&] { Catenary law(p); },
        "catenary: parameter section2.EA = 0 N is out of range (allowed: "
        "finite and > 0)");
    p = mooring(chainRope(std::nan(""), true));
    expectThrowWithMessage<connectors::ParameterError>(
        [&] { Catenary law(p); },
        "catenary: parameter joint1.weight = nan N is out of range (allowed: "
        "finite)");
}

} // namespace
