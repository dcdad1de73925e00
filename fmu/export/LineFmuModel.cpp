#include "LineFmuModel.hpp"

#include <stdexcept>
#include <string>

#include "LineSections.hpp"

namespace fmuExport {

namespace {

ConnectorWording lineWording()
{
    ConnectorWording w;
    w.noun = "line";
    w.A_p = "fairlead on A";
    w.B_p = "anchor or fairlead on B";
    w.length = "distance between the attachment points (the chord)";
    w.lengthRate = "time derivative of the chord length";
    w.tension = "tension at the fairlead on A";
    w.potentialEnergy = "strain energy plus the potential of the line's "
                        "weight (heights from z = 0)";
    w.dissipatedPower = "power dissipated in the line, never negative";
    return w;
}

} // namespace

LineFmuModel::LineFmuModel(ModelIdentity identity)
    : ConnectorFmuModel(std::move(identity), lineWording())
{
}

void LineFmuModel::declareLineOutputs(const OutputDependencies& d)
{
    declareOutputs(d);
    extraOutput("fairleadTension", Shape::scalar, "N",
                "tension at the fairlead on A", d.loads);
    extraOutput("anchorTension", Shape::scalar, "N",
                "tension at the anchor or fairlead on B", d.loads);
    extraOutput("groundedLength", Shape::scalar, "m",
                "unstretched length of line lying on the seabed", d.loads);
    H = extraOutput("H", Shape::scalar, "N",
                    "horizontal tension at the fairlead on A", d.loads);
    V = extraOutput("V", Shape::scalar, "N",
                    "vertical tension at the fairlead on A (pulls it down "
                    "when positive)",
                    d.loads);
    const std::string n = std::to_string(shapePoints);
    for (const char* axis : {"x", "y", "z"}) {
        for (int i = 1; i <= shapePoints; ++i) {
            const std::string point = std::to_string(i);
            extraOutput(std::string("shape.") + axis + "[" + point + "]",
                        Shape::scalar, "m",
                        std::string(axis) + " of point " + point + " of " + n
                            + " along the line, from the fairlead on A (1) "
                              "to B ("
                            + n + "), global frame",
                        d.loads);
        }
    }
    for (int i = 1; i <= shapePoints; ++i) {
        const std::string point = std::to_string(i);
        extraOutput("shape.tension[" + point + "]", Shape::scalar, "N",
                    "effective tension of the line at point " + point + " of "
                        + n + " (shape.x, shape.y, shape.z)",
                    d.loads);
    }
}

void LineFmuModel::declareShapeSections()
{
    for (const lineSections::Variable& v :
         lineSections::shapeVariables(shapePoints)) {
        extraLocal(v.name, Shape::scalar, v.unit, v.description);
    }
    shapeSections_ = true;
}

ConnectorOutputs LineFmuModel::outputs(const LineOutputs& o) const
{
    if (o.shape.size() != std::size_t(shapePoints)
        || o.tension.size() != std::size_t(shapePoints)) {
        throw std::logic_error(
            identity().modelIdentifier + ": " + std::to_string(o.shape.size())
            + " shape points and " + std::to_string(o.tension.size())
            + " tensions, expected " + std::to_string(shapePoints));
    }
    std::vector<double> extra
        = {o.fairleadTension, o.anchorTension, o.groundedLength, o.H, o.V};
    for (int axis = 0; axis < 3; ++axis) {
        for (const connectors::Vector3& p : o.shape) {
            extra.push_back(p[axis]);
        }
    }
    extra.insert(extra.end(), o.tension.begin(), o.tension.end());
    std::vector<double> locals;
    if (shapeSections_) {
        locals = lineSections::shapeSections(o.sectionLengths, shapePoints);
    }
    return {o.loads, std::move(extra), std::move(locals)};
}

} // namespace fmuExport
