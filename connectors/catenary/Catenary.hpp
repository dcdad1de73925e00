// Quasi-static elastic catenary mooring line between a fairlead P fixed in
// body A and a point Q fixed in body B: an anchor on the seabed (B the fixed
// world, seabedContact) or a fairlead on a second body (no seabed).
//
// The line lies in the vertical plane through P and Q (z is the global
// vertical); with e_h the horizontal unit vector from Q towards P, the
// profile (CatenaryProfile.hpp) is solved for the horizontal span
// x = |(P - Q)_h| and the vertical span z = (P - Q)_z, and
//
//   force on A at P:  F_A = -H e_h - V z^            [N]
//   force on B at Q:  F_B = +HA e_h + VA z^          [N]
//   moments about the reference points:  M_A = (R_A p_A) x F_A, likewise B
//
// F_A + F_B = -w L z^ when no part lies on the seabed (the bodies carry the
// line's weight; for a line of sections, its sections' and joint points'
// weight); the seabed carries the rest otherwise. Diagnostics:
// fairlead tension sqrt(H^2 + V^2), anchor tension sqrt(HA^2 + VA^2), the
// grounded length, potentialEnergy = strain energy + weight potential
// (heights from global z = 0); the quasi-static line dissipates nothing.
// tension (interface diagnostic) is the fairlead tension; length is |P - Q|.
#ifndef CONNECTORS_CATENARY_CATENARY_HPP
#define CONNECTORS_CATENARY_CATENARY_HPP

#include <vector>

#include "catenary/CatenaryProfile.hpp"
#include "common/Kinematics.hpp"

namespace connectors {

struct CatenaryParameters {
    //- Fairlead P on A, A's frame, from A's reference point [m]
    Vector3 p_AoP_A = Vector3::Zero();
    //- Anchor or second fairlead Q on B, B's frame [m]
    Vector3 p_BoQ_B = Vector3::Zero();
    //- Unstretched length, weight, stiffness, seabed model; sections after
    //  the first (from Q towards P) with the points at their joints
    CatenaryLine line;
};

struct CatenaryOutput {
    //- Loads and the interface diagnostics
    ConnectorResult loads;
    //- End tensions, grounded length, regime, Newton iterations
    CatenarySolution solution;
    //- |tension| at P and at Q [N]
    double fairleadTension = 0.0;
    double anchorTension = 0.0;
    //- Points along the line from P (first) to Q (last), equally spaced in
    //  unstretched arc length, global frame [m]
    std::vector<Vector3> shape;
    //- Effective tension at the shape points [N] (catenaryTension)
    std::vector<double> shapeTension;
    //- Per section from Q, the tension at its end towards Q (lower) and
    //  towards P (upper) [N] (a uniform line: its one section, the anchor
    //  and fairlead tensions); the positions of the joints from Q, global
    //  frame [m] (none for a uniform line)
    std::vector<double> sectionLowerTension, sectionUpperTension;
    std::vector<Vector3> joints;
};

class Catenary final : public ConnectorLaw {
public:
    //- Validates the parameters; throws ParameterError naming the first bad one
    explicit Catenary(const CatenaryParameters& parameters);

    //- Cold start, no shape points
    ConnectorResult evaluate(const BodyKinematics& A,
                             const BodyKinematics& B) const override;

    //- Warm started from `guess` (null: cold), with `shapePoints` points
    //  (0, or >= 2) along the line
    CatenaryOutput evaluate(const BodyKinematics& A, const BodyKinematics& B,
                            const CatenaryGuess* guess, int shapePoints,
                            const CatenaryOptions& options = {}) const;

    const CatenaryParameters& parameters() const { return parameters_; }

private:
    CatenaryParameters parameters_;
};

} // namespace connectors

#endif
