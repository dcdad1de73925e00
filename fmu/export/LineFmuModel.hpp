// LineFmuModel: the connector FMU model of a mooring line (catenary.fmu,
// mooringLine.fmu). Beyond the interface it words A.p as the fairlead and
// B.p as the anchor, and adds the line's outputs: end tensions, grounded
// length, H, V and a fixed number of points along the line with the
// tension there; optionally, as local variables, the section of each of
// those points (LineSections.hpp).
#ifndef FMU_EXPORT_LINEFMUMODEL_HPP
#define FMU_EXPORT_LINEFMUMODEL_HPP

#include <vector>

#include "ConnectorFmuModel.hpp"

namespace fmuExport {

//- What a line law gives its outputs
struct LineOutputs {
    connectors::ConnectorResult loads;
    double fairleadTension = 0.0, anchorTension = 0.0, groundedLength = 0.0;
    double H = 0.0, V = 0.0;
    //- LineFmuModel::shapePoints points from the fairlead P to Q, global
    //  frame [m], and the line's effective tension there [N]
    std::vector<connectors::Vector3> shape;
    std::vector<double> tension;
    //- Unstretched lengths of the line's sections from B.p [m] (empty: one
    //  section), for shape.section
    std::vector<double> sectionLengths;
};

class LineFmuModel : public ConnectorFmuModel {
public:
    //- Points along the line in the shape outputs (fixed at build time)
    static constexpr int shapePoints = 11;

protected:
    explicit LineFmuModel(ModelIdentity identity);

    //- The interface outputs, then fairleadTension, anchorTension,
    //  groundedLength, H, V (depending on `d.loads`), shape.x[1..N],
    //  shape.y[1..N], shape.z[1..N], shape.tension[1..N]
    void declareLineOutputs(const OutputDependencies& d);

    //- Declares the locals shape.section[1..N] (after every output)
    void declareShapeSections();

    //- The outputs in declaration order, and shape.section when declared
    //  (the first locals); throws std::logic_error for a shape or tension
    //  of other than shapePoints points
    ConnectorOutputs outputs(const LineOutputs& line) const;

    //- The H and V outputs (the solution of the previous evaluation)
    Block H, V;

private:
    bool shapeSections_ = false;
};

} // namespace fmuExport

#endif
