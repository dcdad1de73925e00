// The energy account of the dynamic line (MooringLine.hpp): the work done
// on it and the energy it dissipates over a time step, in the integrator's
// own terms, so that over any run
//
//   W_P + W_Q + W_water + W_added = (K + V)(end) - (K + V)(start) + D
//
// K = sum over the free nodes of v' M v / 2 (M with the added mass about
// the node's tangent), V the potential energy (strain, gravity and
// buoyancy, seabed penalty), D = D_drag + D_seabed + D_axial.
//
// The trapezoidal step (MooringLineTrapezoid.cpp) moves node i by
// dx_i = h (v0_i + v1_i)/2 (the ends along their path) under the mean of
// the forces at its start and its end, the elastic tension replaced by the
// discrete gradient of the strain energy. Each force's work over the step
// is therefore the mean of its values at the step's ends times dx:
//   W_P = -(-G_N-1 - B_N-1 + E_N) . dx_N     the body's push on the end
//   W_Q = -(G_0 + B_0 + E_0) . dx_0          node, which has no mass
//     (G_j the discrete gradient's pull of segment j, B_j its damping's,
//     mean over the step; E the end node's other forces, mean)
//   D_axial = sum_j mean(B_j q_j) . (dx_j+1 - dx_j)
//   D_drag  = h mean(F_drag . U) - mean(F_drag) . dx    (U: the water)
//   D_seabed = -mean(F_seabed) . dx - (V_seabed(end) - V_seabed(start))
//   W_water = h mean(F_drag . U) + mean(F_flowInertia) . dx
//   W_added = sum_free (v0' dM v0 + v1' dM v1)/4,  dM = M(end) - M(start)
// The last is the work of the added mass turning with the line: MoorDyn's
// node equation M(x) a = F leaves out the d(M v)/dt - M a terms of the
// water's inertia, so its K changes by v' dM/dt v / 2 beyond the forces'
// work (the trapezoidal sum of that rate; zero without added mass and
// free surface). Gravity's mean force times dx is exactly V_gravity's
// change (constant forces), except within the free surface's ramp, where
// the buoyancy changes with the height (not accounted: the quadrature's
// error). CVODE's account is the trapezoidal rule's integral of the
// rates (energyRates) over its internal steps. Every dissipation is
// reported per section (a joint's node counts in the section above it,
// towards P).
#ifndef CONNECTORS_MOORINGLINE_LINEENERGY_HPP
#define CONNECTORS_MOORINGLINE_LINEENERGY_HPP

#include <cstddef>
#include <vector>

#include "common/Kinematics.hpp"

namespace connectors {

struct LineLayout;
struct MooringLineParameters;
struct NodeForces;
struct StartSegment;
struct WaterMotion;

struct LineEnergy {
    //- Work done on the line [J] by body A at the fairlead P and by body B
    //  at Q (an anchor does none)
    double fairlead = 0.0, anchor = 0.0;
    //- Work of the moving water on the line [J]: the drag's share that
    //  the current and the flow give (F_drag . U), and the flow's inertia;
    //  0 in still water
    double water = 0.0;
    //- Work of the added mass turning with the line [J] (above)
    double addedMass = 0.0;
    //- Dissipated energy per section from Q [J]: drag relative to the
    //  water, seabed (penalty damping and friction), axial damping
    std::vector<double> drag, seabed, axial;

    explicit LineEnergy(std::size_t sections = 1)
        : drag(sections, 0.0), seabed(sections, 0.0), axial(sections, 0.0)
    {
    }

    //- Everything zero, for `sections` sections
    void clear(std::size_t sections);
    //- Adds `e` (of as many sections)
    LineEnergy& operator+=(const LineEnergy& e);
    //- Adds the trapezoidal rule's integral over dt [s] of the rates
    //  (energyRates) a at its start and b at its end
    void addTrapezoid(const LineEnergy& a, const LineEnergy& b, double dt);

    double dragTotal() const { return sum(drag); }
    double seabedTotal() const { return sum(seabed); }
    double axialTotal() const { return sum(axial); }
    //- All dissipated energy [J]
    double dissipated() const
    {
        return dragTotal() + seabedTotal() + axialTotal();
    }
    //- Work done on the line from outside [J]: the ends, the water, the
    //  added mass
    double work() const { return fairlead + anchor + water + addedMass; }

    //- The account's values in a fixed order: fairlead, anchor, water,
    //  addedMass, then drag, seabed, axial of each section
    std::vector<double> values() const;
    //- The same appended to `out`
    void appendValues(std::vector<double>& out) const;
    //- From `values` (of values().size() for `sections` sections);
    //  throws std::invalid_argument otherwise
    static LineEnergy fromValues(const double* values, std::size_t count,
                                 std::size_t sections);

private:
    static double sum(const std::vector<double>& x);
};

//- The line at one end of a time step: node positions and velocities
//  0..N [m, m/s] and the forces there (nodeForces with diagnostics)
struct LineSnapshot {
    const std::vector<Vector3>& r;
    const std::vector<Vector3>& v;
    const NodeForces& f;
};

//- Adds to `e` the account of one trapezoidal step of h [s] from `start`
//  to `end` (above): `segments` are the step's start segments
//  (startSegments), `water` the water's motion over the step (null:
//  still)
void addTrapezoidStep(const LineLayout& layout, const LineSnapshot& start,
                      const LineSnapshot& end,
                      const std::vector<StartSegment>& segments, double h,
                      const WaterMotion* water, LineEnergy& e);

//- The rates of the account [W], into `rates` (a LineEnergy of rates):
//  the powers of the ends, the water and the added mass (v' dM/dt v / 2,
//  dM/dt from the tangents' and the submerged fractions' rates), and
//  the dissipated power per section, of the nodes at positions r and
//  velocities v 0..N with the forces f there (with diagnostics), the
//  seabed at height zb [m], in `water` (null: still)
void energyRates(const MooringLineParameters& p, const LineLayout& layout,
                 const std::vector<Vector3>& r, const std::vector<Vector3>& v,
                 const NodeForces& f, double zb, const WaterMotion* water,
                 LineEnergy& rates);

//- Kinetic energy of the free nodes per section, v' M v / 2 [J] (M with
//  the added mass about the node's tangent, from f)
std::vector<double> kineticEnergy(const LineLayout& layout,
                                  const std::vector<Vector3>& v,
                                  const NodeForces& f);

} // namespace connectors

#endif
