#include "SectionVariables.hpp"

#include <cmath>

#include "common/ConnectorError.hpp"

namespace mooringLineFmu {

namespace {

using fmuExport::Block;
using fmuExport::Shape;

struct Field {
    const char* name;
    const char* unit;
    const char* description;
    double start;
    double connectors::LineSection::*member; // null: segments
};

// A section's properties, as the first section's parameters of the same
// names (start values too, but the length: 0, no section)
const Field sectionFields[] = {
    {"unstretchedLength", "m", "unstretched length, >= 0 (0: no such section)",
     0.0, &connectors::LineSection::length},
    {"EA", "N", "axial stiffness, > 0", 1e4, &connectors::LineSection::EA},
    {"axialDamping", "N.s", "axial damping (tension per strain rate), >= 0",
     10.0, &connectors::LineSection::axialDamping},
    {"massPerLength", "kg/m", "dry mass per unstretched length, > 0", 0.5,
     &connectors::LineSection::massPerLength},
    {"diameter", "m",
     "volume-equivalent diameter, >= 0 (> 0 with seabedContact = 1)", 0.01,
     &connectors::LineSection::diameter},
    {"normalDrag", "1", "transverse drag coefficient, >= 0", 1.2,
     &connectors::LineSection::normalDrag},
    {"tangentialDrag", "1", "tangential drag coefficient, >= 0", 0.05,
     &connectors::LineSection::tangentialDrag},
    {"normalAddedMass", "1", "transverse added-mass coefficient, >= 0", 1.0,
     &connectors::LineSection::normalAddedMass},
    {"tangentialAddedMass", "1", "tangential added-mass coefficient, >= 0", 0.0,
     &connectors::LineSection::tangentialAddedMass},
    {"segments", "1",
     "number of segments, an integer from 1 to 1000 (all "
     "sections together at most 1000)",
     10.0, nullptr},
};

struct PointField {
    const char* name;
    const char* unit;
    const char* description;
    double connectors::LinePoint::*member;
};

const PointField jointFields[] = {
    {"mass", "kg", "dry mass of the point (clump weight, buoy), >= 0",
     &connectors::LinePoint::mass},
    {"volume", "m3", "displaced volume of the point, >= 0",
     &connectors::LinePoint::volume},
    {"dragArea", "m2",
     "drag coefficient times frontal area CdA of the point, >= 0 (drag 1/2 "
     "rho CdA |u| u)",
     &connectors::LinePoint::dragArea},
    {"addedMass", "1",
     "added-mass coefficient Ca of the point, >= 0 (added mass Ca rho "
     "volume)",
     &connectors::LinePoint::addedMass},
};
constexpr std::size_t jointCount = sizeof jointFields / sizeof jointFields[0];

std::string number(int k)
{
    return std::to_string(k);
}

} // namespace

void SectionVariables::declareParameters(fmuExport::VariableTable& t)
{
    all_.first = fmi2ValueReference(t.size());
    for (int k = 2; k <= maxSections; ++k) {
        const std::string joint = "joint" + number(k - 1);
        const std::string between = "joint " + number(k - 1) + " (of sections "
            + number(k - 1) + " and " + number(k) + " from B.p): ";
        Block b;
        for (const PointField& f : jointFields) {
            const Block one
                = t.parameter(joint + "." + f.name, Shape::scalar, f.unit,
                              between + f.description, {0.0});
            b.first = b.size == 0 ? one.first : b.first;
            b.size += one.size;
        }
        joint_.push_back(b);
        const std::string section = "section" + number(k);
        b = Block {};
        for (const Field& f : sectionFields) {
            const Block one
                = t.parameter(section + "." + f.name, Shape::scalar, f.unit,
                              std::string("section ") + number(k)
                                  + " (from B.p): " + f.description,
                              {f.start});
            b.first = b.size == 0 ? one.first : b.first;
            b.size += one.size;
        }
        section_.push_back(b);
    }
    all_.size = t.size() - all_.first;
}

void SectionVariables::read(const double* values,
                            const fmuExport::VariableTable& t,
                            connectors::MooringLineParameters& p) const
{
    const auto name
        = [&](fmi2ValueReference vr) { return t.variables()[vr].name; };
    const auto refuse
        = [&](connectors::Refusal code, fmi2ValueReference vr,
              const std::string& unit, const std::string& allowed) {
              throw connectors::ParameterError(code, "mooringLine", name(vr),
                                               values[vr], unit, allowed);
          };
    p.sections.clear();
    bool ended = false; // a section was missing
    for (std::size_t k = 0; k < section_.size(); ++k) {
        const fmi2ValueReference s = section_[k].first;
        const double length = values[s];
        if (!(std::isfinite(length) && length >= 0.0)) {
            refuse(std::isfinite(length) ? connectors::Refusal::negative
                                         : connectors::Refusal::notFinite,
                   s, "m",
                   "finite and >= 0; 0: no section " + number(int(k) + 2));
        }
        const bool present = length > 0.0;
        if (present && ended) {
            refuse(connectors::Refusal::inconsistent, s, "m",
                   "0 while an earlier section's unstretchedLength is 0: the "
                   "sections follow each other from B.p, without gaps");
        }
        // the joint below section k + 2: between two sections only
        const Block j = joint_[k];
        for (std::size_t f = 0; f < jointCount && !present; ++f) {
            if (values[j.first + f] != 0.0) {
                refuse(connectors::Refusal::inconsistent,
                       fmi2ValueReference(j.first + f), jointFields[f].unit,
                       "0 without section " + number(int(k) + 2)
                           + ": a joint lies between two sections");
            }
        }
        ended = ended || !present;
        if (!present) {
            continue;
        }
        connectors::LineSection section;
        for (std::size_t f = 0; f < jointCount; ++f) {
            section.joint.*jointFields[f].member = values[j.first + f];
        }
        for (std::size_t f = 0; f < section_[k].size; ++f) {
            const double value = values[s + f];
            if (sectionFields[f].member) {
                section.*sectionFields[f].member = value;
            } else if (!(value >= 1.0 && value <= 1000.0
                         && value == std::floor(value))) {
                refuse(connectors::Refusal::outOfRange,
                       fmi2ValueReference(s + f), "1",
                       "an integer from 1 to 1000");
            } else {
                section.segments = int(value);
            }
        }
        p.sections.push_back(section);
    }
}

std::vector<SectionVariables::Output> SectionVariables::outputs()
{
    return fmuExport::lineSections::endVariables(maxSections,
                                                 " in its segment");
}

std::vector<double>
SectionVariables::values(const connectors::MooringLineOutput& m)
{
    return fmuExport::lineSections::endValues(
        maxSections, m.sectionLowerTension, m.sectionUpperTension, m.joints);
}

std::vector<double>
SectionVariables::lengths(const connectors::MooringLineParameters& p)
{
    std::vector<double> l = {p.length};
    for (const connectors::LineSection& s : p.sections) {
        l.push_back(s.length);
    }
    return l;
}

} // namespace mooringLineFmu
