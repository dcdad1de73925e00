// The lines of the tests of a catenary of sections (catenarySections*Test):
// a chain and a rope with a point at their joint, and its mooring.
#ifndef TESTS_CONNECTORS_CATENARYSECTIONSLINES_HPP
#define TESTS_CONNECTORS_CATENARYSECTIONSLINES_HPP

#include "LawTestSupport.hpp"
#include "catenary/Catenary.hpp"

namespace catenarySectionsTest {

using connectors::CatenaryLine;
using connectors::CatenaryParameters;
using connectors::CatenarySection;
using lawTest::Vector3;

//- A line of one section: length [m], EA [N], w [N/m], seabed, friction
inline CatenaryLine uniformLine(double length, double EA, double weight,
                                bool seabed, double friction)
{
    return {length, EA, weight, friction, seabed, {}}; // the members' order
}

//- Chain (section 1, from the anchor), rope (section 2), a point between
inline CatenaryLine chainRope(double jointWeight, bool seabed,
                              double friction = 0.0)
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

//- The line between A (fairlead A.p) and B (anchor B.p)
inline CatenaryParameters mooring(const CatenaryLine& line)
{
    CatenaryParameters p;
    p.p_AoP_A = Vector3(2.0, -1.0, -3.0);
    p.p_BoQ_B = Vector3(0.5, 0.2, 0.0);
    p.line = line;
    return p;
}

} // namespace catenarySectionsTest

#endif
