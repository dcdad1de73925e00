#include "LineSections.hpp"

namespace fmuExport {
namespace lineSections {

std::vector<Variable> endVariables(int maxSections, const std::string& where)
{
    std::vector<Variable> v;
    for (const char* end : {"lower", "upper"}) {
        for (int k = 1; k <= maxSections; ++k) {
            const std::string n = std::to_string(k);
            v.push_back(
                {std::string("section.") + end + "Tension[" + n + "]", "N",
                 "tension of section " + n + " (from B.p)" + where + " at its "
                     + (end[0] == 'l' ? "lower end (towards B.p)"
                                      : "upper end (towards A.p)")
                     + "; 0 without the section"});
        }
    }
    for (const char* axis : {"x", "y", "z"}) {
        for (int k = 1; k < maxSections; ++k) {
            const std::string n = std::to_string(k);
            v.push_back({std::string("joint.") + axis + "[" + n + "]", "m",
                         std::string(axis) + " of the joint of sections " + n
                             + " and " + std::to_string(k + 1)
                             + " (global frame); 0 without it"});
        }
    }
    return v;
}

std::vector<double> endValues(int maxSections,
                              const std::vector<double>& lowerTension,
                              const std::vector<double>& upperTension,
                              const std::vector<connectors::Vector3>& joints)
{
    std::vector<double> v;
    for (const std::vector<double>* tensions : {&lowerTension, &upperTension}) {
        for (std::size_t k = 0; k < std::size_t(maxSections); ++k) {
            v.push_back(k < tensions->size() ? (*tensions)[k] : 0.0);
        }
    }
    for (int axis = 0; axis < 3; ++axis) {
        for (std::size_t k = 0; k + 1 < std::size_t(maxSections); ++k) {
            v.push_back(k < joints.size() ? joints[k][axis] : 0.0);
        }
    }
    return v;
}

std::vector<Variable> shapeVariables(int shapePoints)
{
    std::vector<Variable> v;
    const std::string n = std::to_string(shapePoints);
    for (int i = 1; i <= shapePoints; ++i) {
        const std::string point = std::to_string(i);
        v.push_back({"shape.section[" + point + "]", "1",
                     "number of the section (1: the one at B.p) that point "
                         + point + " of " + n
                         + " (shape.x, shape.y, shape.z) lies in; at a "
                           "joint, the section towards A.p"});
    }
    return v;
}

std::vector<double> shapeSections(const std::vector<double>& lengths,
                                  int shapePoints)
{
    // the arcs of the sections' lower ends from B.p, and the whole length
    std::vector<double> start;
    double total = 0.0;
    for (const double length : lengths) {
        start.push_back(total);
        total += length;
    }
    std::vector<double> sections;
    for (int i = 0; i < shapePoints; ++i) {
        // as the laws place the shape points
        const double arc = total * (1.0 - double(i) / (shapePoints - 1));
        std::size_t k = 0;
        while (k + 1 < start.size() && arc >= start[k + 1]) {
            ++k;
        }
        sections.push_back(double(k + 1));
    }
    return sections;
}

} // namespace lineSections
} // namespace fmuExport
