// The two reference lines of issue 15, for the dynamic line's tests and
// bench/mooringLine: a lab chain (1.2 m in 0.5 m of water) and the OC4
// semi-submersible's line (835.5 m in 200 m), with the fairlead and
// anchor positions [m] of the measurements.
#ifndef TESTS_CONNECTORS_MOORINGLINEREFERENCES_HPP
#define TESTS_CONNECTORS_MOORINGLINEREFERENCES_HPP

#include "mooringLine/MooringLine.hpp"

namespace connectors {
namespace references {

struct ReferenceLine {
    const char* name;
    MooringLineParameters p;
    Vector3 anchor, fairlead;
};

//- Lab chain: 1.2 m in 0.5 m of water
inline ReferenceLine lab(int segments)
{
    ReferenceLine r {
        "lab chain", {}, Vector3(-1.0, 0.0, -0.5), Vector3(0.0, 0.0, -0.05)};
    MooringLineParameters& p = r.p;
    p.length = 1.2;
    p.massPerLength = 0.0796;
    p.EA = 3.416e5;
    p.diameter = 3.6e-3;
    p.normalDrag = 1.33;
    p.normalAddedMass = 1.0;
    p.tangentialDrag = 0.2;
    p.tangentialAddedMass = 0.5;
    p.axialDamping = 2.473;
    p.seabedContact = true;
    p.seabedStiffness = 3e5;
    p.seabedDamping = 3e3;
    p.segments = segments;
    return r;
}

//- OC4 semi-submersible line: 835.5 m in 200 m of water
inline ReferenceLine oc4(int segments)
{
    ReferenceLine r {"OC4 line",
                     {},
                     Vector3(-837.6, 0.0, -200.0),
                     Vector3(-40.868, 0.0, -14.0)};
    MooringLineParameters& p = r.p;
    p.length = 835.5;
    p.massPerLength = 113.35;
    p.EA = 7.536e8;
    p.diameter = 0.0766;
    p.normalDrag = 2.0;
    p.normalAddedMass = 0.8;
    p.tangentialDrag = 0.4;
    p.tangentialAddedMass = 0.25;
    p.axialDamping = 3.052e6;
    p.seabedContact = true;
    p.seabedStiffness = 3e6;
    p.seabedDamping = 3e5;
    p.segments = segments;
    return r;
}

} // namespace references
} // namespace connectors

#endif
