// The sections of mooringLine.fmu after the first and the points at their
// joints: their parameters (section<k>.*, joint<k>.*), read into the law's
// MooringLineParameters::sections, and their outputs (the tension at each
// section's ends, the joints' positions). Declared once, here; the outputs'
// names are those of every line FMU (fmu/export/LineSections.hpp).
#ifndef FMU_MOORINGLINE_SECTIONVARIABLES_HPP
#define FMU_MOORINGLINE_SECTIONVARIABLES_HPP

#include <string>
#include <vector>

#include "LineSections.hpp"
#include "VariableTable.hpp"
#include "mooringLine/MooringLine.hpp"

namespace mooringLineFmu {

//- Sections of a line, the first (the FMU's unstretchedLength, EA, ...,
//  segments) included
constexpr int maxSections = 4;

class SectionVariables {
public:
    //- Declares, from B.p towards A.p, joint1.*, section2.*, joint2.*,
    //  ..., section<maxSections>.* (consecutive value references)
    void declareParameters(fmuExport::VariableTable& t);

    //- All of them, one block
    fmuExport::Block parameters() const { return all_; }

    //- The sections present (unstretchedLength > 0) into p.sections;
    //  throws connectors::ConnectorError naming the parameter for a
    //  section after a missing one, a joint without a section above it,
    //  a negative length or a segment count that is no integer from 1 to
    //  1000 (the law checks the rest)
    void read(const double* values, const fmuExport::VariableTable& t,
              connectors::MooringLineParameters& p) const;

    //- The outputs, in order: section.lowerTension[1..maxSections],
    //  section.upperTension[...], joint.x[1..maxSections - 1], joint.y,
    //  joint.z (named and described as catenary.fmu's, LineSections.hpp)
    using Output = fmuExport::lineSections::Variable;
    static std::vector<Output> outputs();
    //- Their values for the law's output (0 for absent sections and joints)
    static std::vector<double> values(const connectors::MooringLineOutput& m);
    //- The unstretched lengths of the sections from B.p [m]
    static std::vector<double>
    lengths(const connectors::MooringLineParameters& p);

private:
    //- Per section k = 2..maxSections: its joint's four parameters, then
    //  its own ten (fields() order)
    std::vector<fmuExport::Block> joint_, section_;
    fmuExport::Block all_;
};

} // namespace mooringLineFmu

#endif
