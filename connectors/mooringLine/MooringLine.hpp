// Dynamic lumped-mass mooring line (after MoorDyn's line model, Hall and
// Goupee 2015) between a fairlead P fixed in body A and a point Q fixed in
// body B (an anchor on the seabed, or a fairlead on a second body).
//
// The unstretched length L is cut into N segments of l = L/N; node 0 is Q,
// node N is P (both prescribed), nodes 1..N-1 are free, each with the mass
// of one segment, the ends with half of one. With d the diameter,
// A = pi d^2/4, rho the water density, g gravity, mu the dry mass per
// unstretched length and phi_i the submerged fraction of node i (1, or with
// freeSurface: 1 below waterLevel - l/2, 0 above waterLevel + l/2, linear
// between), its line length lambda_i = l (l/2 at the ends) and stretched
// length sigma_i = (s_i-1 + s_i)/2 (s_0/2, s_N-1/2 at the ends):
//
//   segment j (nodes j, j+1): q = unit(r_j+1 - r_j), strain e = |r_j+1 - r_j|/l - 1
//     T = EA max(e, 0) + BA de/dt                 (no compression; BA [N.s])
//   node i: m_n (I - t t') + m_t t t' times a = F, t = unit(r_i+1 - r_i-1)
//     m_n = mu l + Can rho A l phi,  m_t = mu l + Cat rho A l phi (added mass)
//     F = T_i q_i - T_i-1 q_i-1 + E_i
//     E_i = -(mu g - rho g A phi) lambda z^                 weight, buoyancy
//         + seabed: (kb (zb - z) - cb s dz/dt) d lambda z^ when z < zb, never
//           pulling, s = min((zb - z)/(w/(kb d)), 1): the damping engages
//           over the depth at which the stiffness carries the weight
//         + friction on the seabed: -mu Fn s(|v_h|) (v_t + r v_a)/max(|v_h|, v_f)
//           (v_a, v_t along and across the line, r = axialFrictionRatio,
//           s = staticFrictionScale below v_f, 1 above 2 v_f), Fn the
//           seabed's push, v_h the horizontal velocity
//         + drag: phi (1/2 rho d sigma Cdn |un| un + 1/2 rho pi d sigma Cdt |ut| ut)
//           with un, ut the normal and tangential parts of u = U - v_i, U the
//           current (currentSurface at waterLevel, currentSeabed at zb,
//           linear in z between) plus the flow given at points along the line
//         + the flow's inertia (Froude-Krylov and added mass, MoorDyn's Ap,
//           Aq): phi rho A lambda ((1 + Can) a_n + (1 + Cat) a_t), a_n, a_t
//           the normal and tangential parts of the flow's acceleration given
//           at points along the line (a point: phi rho V (1 + Ca) a)
//
// Sections (MooringLineParameters::sections, LineLayout.hpp): the line may
// be made of sections from Q to P, each with its own l, EA, BA, mu, d and
// Morison coefficients, and a point (clump weight or buoy: mass, volume,
// CdA, Ca) at each joint, whose node carries half a segment of each
// section and the point. On the seabed the point's net weight J rests on
// its own contact area J min(d/w) (LineLayout::Node::pointContact), so
// that it sinks as deep as the line beside it at any segment length.
//
// The seabed (seabedContact) is the horizontal plane through Q. The 6(N-1)
// states (position and velocity of each free node) are integrated by the
// implicit trapezoidal rule (default; MoorDyn's implicit Newmark): per
// step one Newton solve, on the end positions, with the block tridiagonal
// matrix M + h^2/4 S + h/2 D (LineStatics.hpp); or by CVODE's BDF method
// (CvodeBdf) with a banded direct solver. Over a step the ends follow the
// cubic Hermite path through their positions and velocities at both ends
// of the step (those saved in the state at its start, the kinematics given
// at its end); the trapezoidal rule sees them at the step's ends (and
// substeps'), CVODE also inside it. At the end of the step the velocity is
// the given one, which `evaluate` uses for the end segments' damping. A
// step depends on the node state alone (the trapezoidal rule keeps
// nothing from one step to the next; CVODE is restarted, order 1, at every
// step), so a step repeated from a saved state gives the same result to
// the last bit.
//
// Loads: the end nodes' own forces act on the bodies (MoorDyn's coupled
// fairleads), with their inertia (endInertia; a_P, a_Q the attachment
// points' accelerations at the step's end, from the Hermite path, kept in
// the state; M_i the half segment's mass and added mass about t_i):
//   F_A = -T_N-1 q_N-1 + E_N - M_N a_P,   F_B = T_0 q_0 + E_0 - M_0 a_Q
// (at Q the seabed carries the half segment's weight with seabedContact).
#ifndef CONNECTORS_MOORINGLINE_MOORINGLINE_HPP
#define CONNECTORS_MOORINGLINE_MOORINGLINE_HPP

#include <memory>
#include <vector>

#include "catenary/CatenaryProfile.hpp"
#include "common/Kinematics.hpp"
#include "mooringLine/CvodeBdf.hpp"
#include "mooringLine/LineEnergy.hpp"
#include "mooringLine/LineLayout.hpp"
#include "mooringLine/LineForces.hpp"
#include "mooringLine/LineStatics.hpp"

namespace connectors {

//- A point at the joint of two sections (MoorDyn's point): a clump weight
//  or a buoy, moving with the node there
struct LinePoint {
    //- Dry mass m [kg] and displaced volume V [m3]
    double mass = 0.0, volume = 0.0;
    //- Drag coefficient times frontal area CdA [m2] (drag 1/2 rho CdA |u| u,
    //  the same in every direction) and added-mass coefficient Ca [-]
    //  (added mass Ca rho V)
    double dragArea = 0.0, addedMass = 0.0;
};

//- A section of the line after the first (whose properties are those of
//  MooringLineParameters itself), with the point at its joint with the
//  section before it
struct LineSection {
    LinePoint joint;
    //- As MooringLineParameters' length, EA, axialDamping, massPerLength,
    //  diameter, Morison coefficients and segments (at least 1)
    double length = 1.0, EA = 1.0, axialDamping = 0.0;
    double massPerLength = 1.0, diameter = 0.0;
    double normalDrag = 0.0, tangentialDrag = 0.0;
    double normalAddedMass = 0.0, tangentialAddedMass = 0.0;
    int segments = 10;
};

struct MooringLineParameters {
    Vector3 p_AoP_A = Vector3::Zero();
    Vector3 p_BoQ_B = Vector3::Zero();
    //- Unstretched length L [m], axial stiffness EA [N], axial damping BA [N.s]
    double length = 1.0, EA = 1.0, axialDamping = 0.0;
    //- Dry mass per unstretched length mu [kg/m], diameter d [m]
    double massPerLength = 1.0, diameter = 0.0;
    //- Water density rho [kg/m3], gravity g [m/s2]
    double waterDensity = 1025.0, gravity = 9.81;
    //- Morison coefficients in still water [-]
    double normalDrag = 0.0, tangentialDrag = 0.0;
    double normalAddedMass = 0.0, tangentialAddedMass = 0.0;
    //- Seabed through Q, penalty stiffness kb [Pa/m] and damping cb [Pa.s/m]
    bool seabedContact = false;
    double seabedStiffness = 3e6, seabedDamping = 3e5;
    //- Number of segments N (2 to 1000)
    int segments = 20;
    //- Time integration: the implicit trapezoidal rule, one Newton solve
    //  on the block tridiagonal line per step (trapezoid), or CVODE's BDF
    //  with error control (cvode)
    enum class Integrator { trapezoid, cvode };
    Integrator integrator = Integrator::trapezoid;
    //- Longest trapezoidal step [s]: a coupling step is cut into equal
    //  substeps no longer than this (0: one step per coupling step)
    double maxStep = 0.0;
    //- CVODE tolerances (relative [-], absolute [m, m/s]); Integrator::cvode
    //  only
    double relativeTolerance = 1e-6, absoluteTolerance = 1e-6;
    //- The ends' path over a step: the cubic Hermite curve through the
    //  positions and velocities at both ends (true), or straight lines
    //  between the positions at the step's mean velocity (false)
    bool hermiteEnds = true;
    //- Free surface: no buoyancy, drag or added mass above the still water
    //  level waterLevel [m] (global z), a node's submerged fraction ramping
    //  from 1 at waterLevel - l/2 to 0 at waterLevel + l/2 (false: the
    //  whole line is submerged)
    bool freeSurface = false;
    double waterLevel = 0.0;
    //- Current [m/s], global frame: currentSurface at waterLevel,
    //  currentSeabed at the seabed (the height of Q), linear in z between
    //  them, constant beyond
    Vector3 currentSurface = Vector3::Zero(), currentSeabed = Vector3::Zero();
    //- Seabed Coulomb friction coefficient mu [-] (0: none) on the
    //  horizontal velocity of nodes on the seabed, regularised below the
    //  speed frictionVelocity [m/s]: F = -mu Fn v / max(|v|, frictionVelocity)
    //  (across the line; along it axialFrictionRatio times that)
    double seabedFriction = 0.0, frictionVelocity = 0.01;
    //- mu along the line over mu across it [-] (>= 0; 1: isotropic, as
    //  before; MoorDyn-F's mu_kA/mu_kT) and the static friction's scale
    //  mu_s/mu [-] (>= 1; MoorDyn's StatDynFricScale): below
    //  frictionVelocity the friction is the damping that reaches mu_s Fn
    //  there, falling linearly to mu Fn at twice that speed (MoorDyn's
    //  drops at once: a jump the trapezoidal step's Newton would chase)
    double axialFrictionRatio = 1.0, staticFrictionScale = 1.0;
    //- The end nodes' inertia on the bodies: their half segment's mass and
    //  added mass times the end's acceleration (true), or none (false:
    //  default; explicit in the coupling, it can destabilise a body whose
    //  mass is not large against it, README)
    bool endInertia = false;
    //- Whether `advance` keeps the energy account (stepEnergy): true, or
    //  false, where stepEnergy stays zero and a step leaves out the
    //  account's sums (about 10 % of the law's step, 6 % of the FMU's:
    //  bench/mooringLine/README.md); the motion is the same either way
    bool energyAccount = true;
    //- Sections 2, 3, ... from Q towards P after the first (the fields
    //  above: length, EA, ..., segments), each with the point at its lower
    //  joint; empty: a uniform line
    std::vector<LineSection> sections;

    //- Submerged weight per unstretched length w = (mu - rho A) g [N/m]
    //  (of the first section)
    double weight() const;
    //- Segments of all sections, N
    int totalSegments() const;
    //- Section k from Q (0: the fields above, k > 0: sections[k - 1])
    LineSection section(std::size_t k) const;
};

//- Everything needed to continue the integration (the FMU state)
struct MooringLineState {
    //- Time of the state [s]
    double time = 0.0;
    //- End positions Q (node 0) and P (node N) at `time` [m]
    Vector3 Q = Vector3::Zero(), P = Vector3::Zero();
    //- End velocities of Q and P at `time` [m/s] (the Hermite path's start)
    Vector3 vQ = Vector3::Zero(), vP = Vector3::Zero();
    //- End accelerations of Q and P at `time` [m/s2] (the end of the last
    //  step's path; zero at the start)
    Vector3 aQ = Vector3::Zero(), aP = Vector3::Zero();
    //- Free nodes 1..N-1: x, y, z, vx, vy, vz each [m, m/s]
    std::vector<double> nodes;
    //- The trapezoidal rule's factorised Newton matrix, kept from step to
    //  step while it serves (MooringLineTrapezoid.cpp); shared between
    //  copies, never changed (a step that forms a new one replaces it);
    //  null: none, the next step forms one
    std::shared_ptr<const TrapezoidMatrix> newton;

    //- Values of a saved state of a line of N segments: time, Q, P, vQ,
    //  vP, aQ, aP, the nodes, the Newton matrix
    //  (TrapezoidMatrix::savedSize)
    static std::size_t serializedSize(int segments);
    std::vector<double> serialize() const;
    //- The same appended to `out` (a caller that saves into the same
    //  vector every step allocates nothing after the first)
    void serialize(std::vector<double>& out) const;
    //- Throws std::invalid_argument unless `data` holds a state of N segments
    static MooringLineState deserialize(const std::vector<double>& data,
                                        int segments);
    //- The same for the line's N = totalSegments()
    static MooringLineState deserialize(const std::vector<double>& data,
                                        const MooringLineParameters& p)
    {
        return deserialize(data, p.totalSegments());
    }
};

struct MooringLineOutput {
    ConnectorResult loads;
    double fairleadTension = 0.0, anchorTension = 0.0, groundedLength = 0.0;
    //- Horizontal and (downward) vertical load of the line on A [N]
    double H = 0.0, V = 0.0;
    //- Points from P to Q, equal steps of unstretched length [m], and the
    //  effective tension there [N]: fairleadTension and anchorTension at
    //  the ends, the segments' tensions at their middles, linear between
    std::vector<Vector3> shape;
    std::vector<double> shapeTension;
    //- Per section from Q: the tension of its segment at the end towards
    //  Q (lower) and towards P (upper) [N]
    std::vector<double> sectionLowerTension, sectionUpperTension;
    //- Positions of the joints between sections, from Q [m]
    std::vector<Vector3> joints;
    //- Kinetic energy of the free nodes, v' M v / 2 with the added mass
    //  about each node's tangent [J], of the line and per section from Q
    //  (a joint's node in the section above it)
    double kineticEnergy = 0.0;
    std::vector<double> sectionKineticEnergy;
};

class MooringLine {
public:
    //- Largest strain a line may start with [-]: beyond the breaking
    //  strain of mooring materials (chain and wire about 0.02, polyester
    //  0.1 to 0.15, nylon 0.2 to 0.3), where the linear elastic law means
    //  nothing; a taut line with a pretension starts below it
    static constexpr double maxStartStrain = 0.3;

    //- Validates the parameters (ParameterError naming the first bad one;
    //  with seabedContact, diameter and seabedStiffness must be > 0)
    explicit MooringLine(const MooringLineParameters& parameters);
    ~MooringLine();

    //- At rest in the static equilibrium of the discrete line through the
    //  attachment points of A and B (damped Newton from the quasi-static
    //  elastic catenary shape; that shape where Newton finds none).
    //  UndefinedStateError for a fairlead below the seabed, and for ends
    //  farther apart than (1 + maxStartStrain) L.
    MooringLineState initialState(const BodyKinematics& A,
                                  const BodyKinematics& B, double time) const;

    //- Advances `state` by h > 0, the ends moving along the cubic Hermite
    //  path from their positions and velocities in `state` to those of the
    //  attachment points of A and B (the kinematics at state.time + h).
    //  Throws UndefinedStateError (naming the integrator's failure) on
    //  failure, leaving `state` unchanged.
    //  `flow`: the water's velocity [m/s] at points from P to Q at equal
    //  steps of unstretched length (empty: none, else at least 2), held
    //  over the step, interpolated linearly along the line to its nodes
    //  and added to the current.
    //  `flowAcceleration`: the flow's acceleration [m/s2] at the same
    //  points (empty: none, else as many as `flow`'s, or at least 2 when
    //  `flow` is empty), held and interpolated as the flow.
    void advance(MooringLineState& state, const BodyKinematics& A,
                 const BodyKinematics& B, double h,
                 const std::vector<Vector3>& flow = {},
                 const std::vector<Vector3>& flowAcceleration = {});

    //- What `evaluate` computes: everything, or the loads (the interface
    //  diagnostics, fairleadTension, anchorTension, groundedLength, H and
    //  V) and not the shape, the sections' tensions, the joints or the
    //  kinetic energy (left empty and zero)
    enum class Detail { all, loads };

    //- Loads and diagnostics of `state` with the ends at A's and B's
    //  attachment points, in the water's `flow` and `flowAcceleration` (as
    //  in advance); shapePoints 0 or >= 2. The shape, the tensions, the
    //  joints and the kinetic energy do not depend on the water.
    MooringLineOutput
    evaluate(const MooringLineState& state, const BodyKinematics& A,
             const BodyKinematics& B, int shapePoints,
             const std::vector<Vector3>& flow = {},
             const std::vector<Vector3>& flowAcceleration = {},
             Detail detail = Detail::all) const;

    //- Integrator counters since construction
    CvodeBdf::Statistics statistics() const;

    //- The energy account of the last `advance` (LineEnergy.hpp): the
    //  work done on the line by its ends, by the water and by the added
    //  mass, and the energy it dissipated, per section, in the
    //  integrator's own terms (the trapezoidal rule: the mean forces over
    //  each step times the nodes' displacements; CVODE: the trapezoidal
    //  rule's integral of the rates over its internal steps). The ends'
    //  work leaves out their inertia (endInertia). The loads at the
    //  steps' ends, whose sampled power misses what happens between them
    //  (a snap shorter than the step), do not give it.
    const LineEnergy& stepEnergy() const { return stepEnergy_; }
    //- Work done on the line by its two ends over the last `advance` [J]
    double stepWork() const
    {
        return stepEnergy_.fairlead + stepEnergy_.anchor;
    }

    const MooringLineParameters& parameters() const { return parameters_; }

private:
    struct Ends {
        Vector3 Q0, P0, Q1, P1, vQ0, vP0, vQ1, vP1;
        double t0 = 0.0, h = 1.0;
    };
    int rhs(double t, const double* y, double* ydot) const;
    //- The energy account's rates (energyRates) of the free nodes' state
    //  y at time t of the step, the ends on their path, into `rates`
    void energyRatesAt(double t, const double* y, LineEnergy& rates);
    //- Positions and velocities of Q and P on the ends' path at the
    //  fraction s in [0, 1] of the step (exactly the given ones at 0, 1)
    void endsAt(double s, Vector3& rQ, Vector3& vQ, Vector3& rP,
                Vector3& vP) const;
    //- One trapezoidal step of `nodes` from the fraction s0 of the
    //  coupling step to s1; false (nodes unchanged) when Newton's first
    //  correction exceeds largestMiss segment lengths or Newton did not
    //  converge. `newton`: the Newton matrix kept from the steps before,
    //  used where it serves, else replaced by the step's own (on success)
    bool trapezoidStep(std::vector<double>& nodes, double s0, double s1,
                       double largestMiss,
                       std::shared_ptr<const TrapezoidMatrix>& newton);
    //- Trapezoidal steps over [s0, s1], halved where a step fails, down to
    //  1/1024 (depth: halvings so far); throws UndefinedStateError there
    void trapezoidInterval(std::vector<double>& nodes, double s0, double s1,
                           int depth,
                           std::shared_ptr<const TrapezoidMatrix>& newton);
    Vector3 attachment(const BodyKinematics& body, const Vector3& p) const;
    Vector3 attachmentVelocity(const BodyKinematics& body,
                               const Vector3& p) const;
    //- UndefinedStateError for a buoy that holds a joint of the start
    //  shape r above waterLevel (without freeSurface)
    void checkJointsSubmerged(const std::vector<Vector3>& r) const;
    //- The water's motion for `flow` and `flowAcceleration` (see advance)
    //  into `water`
    void waterMotion(const std::vector<Vector3>& flow,
                     const std::vector<Vector3>& flowAcceleration,
                     WaterMotion& water) const;
    //- Values at points from P to Q (at least 2) interpolated linearly
    //  along the unstretched arc to the nodes 0..N, into `atNodes`
    void alongLine(const std::vector<Vector3>& points,
                   std::vector<Vector3>& atNodes) const;

    MooringLineParameters parameters_;
    double weight_ = 0.0;
    LineLayout layout_;
    Ends ends_;
    //- The water's motion over the step being taken
    WaterMotion water_;
    std::unique_ptr<CvodeBdf> integrator_; // with Integrator::cvode
    CvodeBdf::Statistics trapezoidStatistics_;
    LineEnergy stepEnergy_;
    //- Node positions, velocities (ends included), seabed height and
    //  forces (with diagnostics) of the last `evaluate` or trapezoidal
    //  step's end: trapezoidStep takes them as its start's, and evaluate
    //  as its own, when they are exactly those positions and velocities
    mutable struct {
        std::vector<Vector3> r, v;
        double zb = 0.0;
        WaterMotion water;
        NodeForces f;
        //- evaluate's positions, velocities and water before the
        //  comparison (storage kept from call to call)
        std::vector<Vector3> nextR, nextV;
        WaterMotion nextWater;
    } lastEvaluated_;
    //- Storage of advance and trapezoidStep, overwritten by every step
    struct Workspace {
        //- the nodes over a coupling step (MooringLineState::nodes)
        std::vector<double> nodes;
        std::vector<Vector3> r0, v0, r, v, b;
        //- the start's forces (when not those of the last `evaluate` or
        //  step), Newton's
        NodeForces f0, f;
        //- the start's segments; the discrete gradient's corrections to
        //  the elastic forces at the start and the end of the step [N]
        std::vector<StartSegment> start;
        std::vector<Vector3> d0, d1;
        //- the correction by a kept Newton matrix
        std::vector<Vector3> chord;
        //- Newton matrices formed before, their storage reused by a step
        //  that forms one where no state holds them any more
        std::vector<std::shared_ptr<TrapezoidMatrix>> matrices;
        //- CVODE's energy rates at the start and the end of its last
        //  internal step
        LineEnergy rates0, rates1;
    } work_;
    //- Force evaluations of CVODE's energy account
    long energyEvaluations_ = 0;
};

} // namespace connectors

#endif
