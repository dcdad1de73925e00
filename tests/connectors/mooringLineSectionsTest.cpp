// A line of sections with points at their joints (MooringLineParameters::
// sections): equal sections without points are the uniform line; the
// start shape of a chain and a rope with a clump weight, and with a buoy,
// against the multi-segment elastic catenary solved here by its own
// Newton on the closed-form pieces (converging as N grows); the energy of
// a two-section line swinging freely between fixed ends; the refusals.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <iostream>

#include "LawTestSupport.hpp"
#include "common/ConnectorError.hpp"
#include "mooringLine/MooringLine.hpp"
#include "MooringLineReferences.hpp"

namespace {

using namespace lawTest;
using connectors::LineSection;
using connectors::MooringLine;
using connectors::MooringLineParameters;
using connectors::MooringLineState;
using connectors::references::oc4;
using connectors::references::ReferenceLine;

// ---------------------------------------------------------------------------
// The elastic catenary of sections (Irvine 1981, each piece in closed form),
// independent of the law: from Q upwards the vertical tension is
// V(s) = VQ + w s along a piece, jumps by a point's net weight at a joint;
// the horizontal tension H is the same everywhere. A piece of length L,
// stiffness EA, submerged weight w, starting at vertical tension Va:
//   dx = H/w (asinh(Vb/H) - asinh(Va/H)) + H L/EA,      Vb = Va + w L
//   dz = H/w (sqrt(1 + (Vb/H)^2) - sqrt(1 + (Va/H)^2)) + (Va L + w L^2/2)/EA
struct Piece {
    double length, w, EA;
};

struct Catenary {
    std::vector<Piece> pieces;
    //- Net weight of the point at the top of piece k (k < pieces - 1) [N]
    std::vector<double> points;

    //- (x, z) of the top of every piece from Q for H and VQ; VP the
    //  vertical tension at the top
    std::vector<Eigen::Vector2d> ends(double H, double VQ,
                                      double* VP = nullptr) const
    {
        std::vector<Eigen::Vector2d> out;
        double x = 0.0, z = 0.0, V = VQ;
        for (std::size_t k = 0; k < pieces.size(); ++k) {
            const Piece& p = pieces[k];
            const double Vb = V + p.w * p.length;
            x += H / p.w * (std::asinh(Vb / H) - std::asinh(V / H))
                + H * p.length / p.EA;
            z += H / p.w
                    * (std::sqrt(1.0 + Vb * Vb / (H * H))
                       - std::sqrt(1.0 + V * V / (H * H)))
                + (V * p.length + 0.5 * p.w * p.length * p.length) / p.EA;
            out.emplace_back(x, z);
            V = Vb + (k < points.size() ? points[k] : 0.0);
        }
        if (VP != nullptr) {
            *VP = V; // no point above the last piece
        }
        return out;
    }

    //- H and VQ that put the top at (X, Z): Newton with a difference
    //  Jacobian, steps halved until the miss decreases, H kept positive
    void solve(double X, double Z, double& H, double& VQ) const
    {
        const auto miss = [&](double h, double v) {
            return Eigen::Vector2d(ends(h, v).back() - Eigen::Vector2d(X, Z));
        };
        const auto steps = [](double h, double v) {
            return Eigen::Vector2d(1e-7 * h, 1e-7 * (std::abs(v) + h));
        };
        if (!dampedNewton(miss, steps, 1e-12 * std::hypot(X, Z), 100, H, VQ)) {
            FAIL() << "the analytic catenary did not converge";
        }
    }
};

//- A chain (section 1, from the anchor Q) and a rope (section 2) of 40 m
//  each, N/2 segments each, in water, a point between them
MooringLineParameters chainAndRope(int N, double pointMass, double pointVolume)
{
    MooringLineParameters p;
    p.length = 40.0;
    p.EA = 5e8;
    p.massPerLength = 80.0;
    p.diameter = 0.1;
    p.segments = N / 2;
    LineSection rope = p.section(0); // as long, as thick, as many segments
    rope.EA = 5e7;
    rope.massPerLength = 10.0;
    rope.joint.mass = pointMass;
    rope.joint.volume = pointVolume;
    p.sections = {rope};
    p.waterLevel = 100.0; // the whole line under water
    return p;
}

//- Submerged weight per length of a section [N/m]
double submergedWeight(const MooringLineParameters& p, const LineSection& s)
{
    return (s.massPerLength
            - p.waterDensity * 0.25 * pi * s.diameter * s.diameter)
        * p.gravity;
}

Catenary analytic(const MooringLineParameters& p)
{
    Catenary c;
    const LineSection first = p.section(0);
    c.pieces.push_back({first.length, submergedWeight(p, first), first.EA});
    for (const LineSection& s : p.sections) {
        c.points.push_back((s.joint.mass - p.waterDensity * s.joint.volume)
                           * p.gravity);
        c.pieces.push_back({s.length, submergedWeight(p, s), s.EA});
    }
    return c;
}

const BodyKinematics anchor = body(Vector3::Zero());
const BodyKinematics fairlead = body(Vector3(60.0, 0.0, 30.0));

struct StartErrors {
    double joint = 0.0; // distance of the joint from the analytic one [m]
    double tension = 0.0; // relative error of the fairlead tension
    double anchor = 0.0; // relative error of the anchor tension
    double jointZ = 0.0; // the joint's height [m]
};

StartErrors startAgainstAnalytic(const MooringLineParameters& p, double& H,
                                 double& VQ)
{
    const Catenary c = analytic(p);
    c.solve(60.0, 30.0, H, VQ);
    double VP = 0.0;
    const std::vector<Eigen::Vector2d> ends = c.ends(H, VQ, &VP);
    MooringLine line(p);
    const MooringLineState s = line.initialState(fairlead, anchor, 0.0);
    const auto out = line.evaluate(s, fairlead, anchor, 0);
    EXPECT_EQ(out.joints.size(), 1u);
    StartErrors e;
    e.jointZ = out.joints[0][2];
    e.joint = std::hypot(out.joints[0][0] - ends[0][0], out.joints[0][1],
                         out.joints[0][2] - ends[0][1]);
    e.tension
        = std::abs(out.fairleadTension - std::hypot(H, VP)) / std::hypot(H, VP);
    e.anchor
        = std::abs(out.anchorTension - std::hypot(H, VQ)) / std::hypot(H, VQ);
    std::cout << "N = " << p.totalSegments() << ": joint at ("
              << out.joints[0][0] << ", " << out.joints[0][2]
              << ") m, analytic (" << ends[0][0] << ", " << ends[0][1]
              << "), off by " << e.joint << " m; fairlead tension "
              << out.fairleadTension << " N, analytic " << std::hypot(H, VP)
              << " N (" << e.tension << "); anchor " << out.anchorTension
              << " N, analytic " << std::hypot(H, VQ) << " N (" << e.anchor
              << ")\n";
    return e;
}

//- The start shape converges to the analytic one as N grows, second order
void expectConvergence(double pointMass, double pointVolume,
                       double jointTolerance, double tensionTolerance)
{
    double H = 2e4, VQ = 0.0;
    std::vector<StartErrors> errors;
    for (const int N : {10, 20, 40, 80}) {
        errors.push_back(startAgainstAnalytic(
            chainAndRope(N, pointMass, pointVolume), H, VQ));
    }
    for (std::size_t k = 1; k < errors.size(); ++k) {
        // halving the segments divides the error by about 4
        EXPECT_LT(errors[k].joint, 0.35 * errors[k - 1].joint) << k;
        EXPECT_LT(errors[k].tension, 0.35 * errors[k - 1].tension) << k;
    }
    EXPECT_LT(errors.back().joint, jointTolerance);
    EXPECT_LT(errors.back().tension, tensionTolerance);
    EXPECT_LT(errors.back().anchor, tensionTolerance);
}

TEST(MooringLineSections, ChainRopeAndClumpWeightStartOnTheAnalyticCatenary)
{
    // 2000 kg of 0.25 m3: 17.1 kN at the joint. Measured at N = 10, 20,
    // 40, 80: the joint 0.064, 0.016, 0.0040, 0.00099 m from the analytic
    // (37.283, -2.958) m, the fairlead tension 1.4e-3, 3.5e-4, 8.7e-5,
    // 2.2e-5 off the analytic 36460.6 N (anchor 25990.9 N: 2.1e-3 to
    // 3.2e-5): second order in the segment length
    expectConvergence(2000.0, 0.25, 1.5e-3, 4e-5);
}

TEST(MooringLineSections, BuoyLiftsTheJointAsTheAnalyticCatenary)
{
    // 500 kg of 4 m3: a net lift of 35.3 kN at the joint
    double H = 2e4, VQ = 0.0;
    const StartErrors without
        = startAgainstAnalytic(chainAndRope(80, 0, 0), H, VQ);
    // Measured: the joint at (20.159, 33.556) m, 0.0012 m from the
    // analytic (20.159, 33.555) m at N = 80 (0.074 at N = 10); fairlead
    // tension 4.9e-5 off the analytic 10386.8 N (3.3e-3 at N = 10)
    expectConvergence(500.0, 4.0, 1.5e-3, 6e-5);
    H = 2e4;
    VQ = 0.0;
    const StartErrors with
        = startAgainstAnalytic(chainAndRope(80, 500.0, 4.0), H, VQ);
    EXPECT_GT(with.jointZ, without.jointZ + 10.0);
}

TEST(MooringLineSections, EqualSectionsAreTheUniformLine)
{
    for (const bool cvode : {false, true}) {
        // the OC4 line (835.5 m in 200 m of water) in three equal sections
        const ReferenceLine reference = oc4(18);
        MooringLineParameters uniform = reference.p;
        if (cvode) {
            uniform.integrator = MooringLineParameters::Integrator::cvode;
            uniform.relativeTolerance = uniform.absoluteTolerance = 1e-9;
        }
        MooringLineParameters sections = uniform;
        sections.length = uniform.length / 3.0;
        sections.segments = 6;
        LineSection s = sections.section(0);
        sections.sections = {s, s};
        MooringLine one(uniform), three(sections);
        const auto A = [&](double t) {
            return body(
                reference.fairlead
                    + Vector3(2.0 * std::sin(0.5 * t), 0.0, std::sin(t)),
                Matrix3::Identity(),
                Vector3(std::cos(0.5 * t), 0.0, std::cos(t)));
        };
        const BodyKinematics B = body(reference.anchor);
        MooringLineState a = one.initialState(A(0.0), B, 0.0);
        MooringLineState b = three.initialState(A(0.0), B, 0.0);
        // measured: trapezoidal rule 2.1e-11 (nodes, m and m/s, on the
        // 836 m line) and 1.9e-12 (fairlead tension, relative); CVODE's
        // error control (tolerance 1e-9) carries the round-off differences
        // to 2.0e-7 and 2.4e-9
        const double tolerance = cvode ? 1e-6 : 1e-10;
        double node = 0.0, tension = 0.0;
        for (int k = 0; k <= 100; ++k) {
            if (k > 0) {
                one.advance(a, A(0.1 * k), B, 0.1);
                three.advance(b, A(0.1 * k), B, 0.1);
            }
            for (std::size_t i = 0; i < a.nodes.size(); ++i) {
                node = std::max(node, std::abs(a.nodes[i] - b.nodes[i]));
            }
            const auto ra = one.evaluate(a, A(0.1 * k), B, 11);
            const auto rb = three.evaluate(b, A(0.1 * k), B, 11);
            tension = std::max(tension,
                               std::abs(ra.fairleadTension - rb.fairleadTension)
                                   / ra.fairleadTension);
            for (std::size_t i = 0; i < ra.shape.size(); ++i) {
                EXPECT_LT((ra.shape[i] - rb.shape[i]).norm(), tolerance);
                EXPECT_NEAR(ra.shapeTension[i], rb.shapeTension[i],
                            tolerance * ra.fairleadTension);
            }
            EXPECT_NEAR(ra.groundedLength, rb.groundedLength, 1e-9);
            EXPECT_NEAR(ra.loads.potentialEnergy, rb.loads.potentialEnergy,
                        tolerance * std::abs(ra.loads.potentialEnergy));
        }
        std::cout << (cvode ? "CVODE" : "trapezoid")
                  << ": largest difference of the nodes' positions and "
                     "velocities "
                  << node << ", of the fairlead tension " << tension
                  << " (relative)\n";
        EXPECT_LT(node, tolerance);
        EXPECT_LT(tension, tolerance);
    }
}

TEST(MooringLineSections, SwingingFreelyItKeepsItsEnergy)
{
    // Both ends held; the start shape turned by 30 degrees about the chord
    // (no segment stretched) swings back and forth. No added mass (its
    // configuration dependent mass matrix is not energy consistent).
    for (const bool cvode : {false, true}) {
        MooringLineParameters p = chainAndRope(20, 2000.0, 0.25);
        p.normalDrag = 1.2;
        p.tangentialDrag = 0.05;
        p.axialDamping = 1e5;
        p.sections[0].normalDrag = 1.2;
        p.sections[0].axialDamping = 1e4;
        if (cvode) {
            p.integrator = MooringLineParameters::Integrator::cvode;
            p.relativeTolerance = p.absoluteTolerance = 1e-9;
        }
        MooringLine line(p);
        MooringLineState s = line.initialState(fairlead, anchor, 0.0);
        const Vector3 axis = (fairlead.p_WKo_W - anchor.p_WKo_W).normalized();
        const Matrix3 turn = rotation(pi / 6.0, axis);
        for (std::size_t i = 0; i + 5 < s.nodes.size(); i += 6) {
            const Vector3 r
                = turn * Vector3(s.nodes[i], s.nodes[i + 1], s.nodes[i + 2]);
            for (int k = 0; k < 3; ++k) {
                s.nodes[i + std::size_t(k)] = r[k];
            }
        }
        // node masses: mu l inside a section, the halves and the point at the joint
        const double l1 = 40.0 / 10, l2 = 40.0 / 10;
        const auto kinetic = [&](const MooringLineState& state) {
            double e = 0.0;
            for (std::size_t i = 0; i + 5 < state.nodes.size(); i += 6) {
                const std::size_t node = i / 6 + 1;
                const double m = node < 10 ? 80.0 * l1
                    : node > 10            ? 10.0 * l2
                                : 0.5 * (80.0 * l1 + 10.0 * l2) + 2000.0;
                e += 0.5 * m
                    * (state.nodes[i + 3] * state.nodes[i + 3]
                       + state.nodes[i + 4] * state.nodes[i + 4]
                       + state.nodes[i + 5] * state.nodes[i + 5]);
            }
            return e;
        };
        const double rest
            = line.evaluate(line.initialState(fairlead, anchor, 0.0), fairlead,
                            anchor, 0)
                  .loads.potentialEnergy;
        auto out = line.evaluate(s, fairlead, anchor, 0);
        const double energy0 = out.loads.potentialEnergy + kinetic(s);
        double dissipated = 0.0, worst = 0.0, largestKinetic = 0.0;
        const double h = 0.01;
        for (int k = 1; k <= 2000; ++k) {
            const double before = out.loads.dissipatedPower;
            line.advance(s, fairlead, anchor, h);
            out = line.evaluate(s, fairlead, anchor, 0);
            dissipated += 0.5 * h * (before + out.loads.dissipatedPower);
            const double energy
                = out.loads.potentialEnergy + kinetic(s) + dissipated;
            worst = std::max(worst, std::abs(energy - energy0));
            largestKinetic = std::max(largestKinetic, kinetic(s));
        }
        const double swing = energy0 - rest;
        std::cout << (cvode ? "CVODE" : "trapezoid") << ": swing energy "
                  << swing << " J, largest kinetic " << largestKinetic
                  << " J, dissipated in 20 s " << dissipated
                  << " J, largest imbalance " << worst << " J\n";
        // Measured: a swing of 84904 J (potential energy above the rest
        // shape), at most 14886 J kinetic, 84777 J dissipated in 20 s, the
        // balance off by at most 1.04 J (1.2e-5 of the swing; CVODE at 1e-9:
        // 0.34 J, 4.0e-6): the trapezoidal power integral over 0.01 s steps
        // and the integrator's own error
        EXPECT_GT(largestKinetic, 0.1 * swing); // it swings
        EXPECT_GT(dissipated, 0.5 * swing); // drag and damping did work
        EXPECT_LT(worst, 1e-4 * swing) << cvode;
    }
}

TEST(MooringLineSections, UnusableSectionsAndPointsAreNamed)
{
    using connectors::ConnectorError;
    using connectors::ParameterError;
    const MooringLineParameters valid = chainAndRope(20, 0.0, 0.0);
    expectChangeRefused<MooringLine, ParameterError>(
        valid,
        [](MooringLineParameters& p) { p.sections[0].joint.mass = -5.0; },
        "mooringLine: parameter joint1.mass = -5 kg is out of range (allowed: "
        "finite and >= 0)");
    expectChangeRefused<MooringLine, ParameterError>(
        valid,
        [](MooringLineParameters& p) { p.sections[0].joint.volume = -0.1; },
        "mooringLine: parameter joint1.volume = -0.1 m3 is out of range "
        "(allowed: finite and >= 0)");
    expectChangeRefused<MooringLine, ParameterError>(
        valid,
        [](MooringLineParameters& p) { p.sections[0].massPerLength = 0.0; },
        "mooringLine: parameter section2.massPerLength = 0 kg/m is out of "
        "range (allowed: finite and > 0)");
    expectChangeRefused<MooringLine, ConnectorError>(
        valid,
        [](MooringLineParameters& p) {
            p.segments = 600;
            p.sections[0].segments = 500;
        },
        "mooringLine: parameter section2.segments = 500 is out of range "
        "(allowed: an integer from 1 to 400: the sections' segments add up "
        "to at most 1000)");
    // A buoy of 40 m3 lifts the joint above the water (waterLevel 10 m):
    // without the free surface it would keep its buoyancy in the air
    MooringLineParameters p = chainAndRope(20, 500.0, 40.0);
    p.waterLevel = 10.0;
    MooringLine line(p);
    try {
        line.initialState(fairlead, anchor, 0.0);
        ADD_FAILURE() << "no error";
    } catch (const connectors::UndefinedStateError& e) {
        const std::string m = e.what();
        expectStartsWithAndContains(
            m,
            "mooringLine: the buoy at joint1 (joint1.volume = 40 m3, "
            "joint1.mass = 500 kg: a net lift of ",
            "above waterLevel = 10 m (allowed: a joint at or below "
            "waterLevel");
        // not "parameter joint1.volume": it depends on the inputs
        EXPECT_EQ(m.find("parameter"), std::string::npos) << m;
    }
    // with the free surface it floats there
    p.freeSurface = true;
    MooringLine floating(p);
    const auto out = floating.evaluate(
        floating.initialState(fairlead, anchor, 0.0), fairlead, anchor, 0);
    EXPECT_NEAR(out.joints[0][2], 10.0, 2.0);
}

} // namespace
