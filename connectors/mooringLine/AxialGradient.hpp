// The elastic tension of a segment over a time step as a discrete gradient
// (Gonzalez, 1996) of its strain energy V(l) = EA l_u max(e, 0)^2 / 2,
// e = l/l_u - 1: the trapezoidal rule's average of the tension at the
// step's ends does work (T0 + T1)/2 (l1 - l0), which is not V(l1) - V(l0)
// where the tension's kink at e = 0 lies inside the step (a segment going
// taut or slack); the difference quotient is.
#ifndef CONNECTORS_MOORINGLINE_AXIALGRADIENT_HPP
#define CONNECTORS_MOORINGLINE_AXIALGRADIENT_HPP

#include <algorithm>

namespace connectors {

//- The tension G = (V(l1) - V(l0))/(l1 - l0) [N] of a segment of
//  stiffness EA [N] from strain e0 to e1 [-], and its derivative
//  dG/de1 [N]. Evaluated in closed form, without the difference's
//  cancellation: EA (e0 + e1)/2 (= V'(l_mid)) while the segment is taut
//  at both ends, 0 while it is slack at both, EA e1^2 / (2 (e1 - e0)) or
//  EA e0^2 / (2 (e0 - e1)) across the kink.
struct AxialGradient {
    double tension = 0.0, derivative = 0.0;
};

inline AxialGradient axialGradient(double EA, double e0, double e1)
{
    if (e0 > 0.0 && e1 > 0.0) {
        return {0.5 * EA * (e0 + e1), 0.5 * EA};
    }
    if (e1 > 0.0) { // taut at the end only: e1 - e0 >= e1 > 0
        const double d = e1 - e0;
        return {0.5 * EA * e1 * e1 / d,
                0.5 * EA * e1 * (e1 - 2.0 * e0) / (d * d)};
    }
    if (e0 > 0.0) { // taut at the start only: e0 - e1 >= e0 > 0
        const double d = e0 - e1;
        return {0.5 * EA * e0 * e0 / d, 0.5 * EA * e0 * e0 / (d * d)};
    }
    return {};
}

} // namespace connectors

#endif
