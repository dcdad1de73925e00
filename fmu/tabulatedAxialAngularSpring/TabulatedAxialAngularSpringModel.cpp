// tabulatedAxialAngularSpring.fmu: connectors::TabulatedAxialAngularSpring
// behind the connector FMU interface. The variable table below is the only
// list of its variables. FMI 2.0 fixes the variables in
// modelDescription.xml, so the table has a variable for each of its
// maxPoints points; table.points says how many are used.
#include <string>

#include "LawFmuModel.hpp"
#include "common/ConnectorError.hpp"
#include "tabulatedAxialAngularSpring/TabulatedAxialAngularSpring.hpp"

namespace {

using connectors::ParameterError;
using connectors::Refusal;
using fmuExport::Block;
using fmuExport::Shape;
using Parameters = connectors::TabulatedAxialAngularSpringParameters;

const char* const modelName = "tabulatedAxialAngularSpring";

//- The most points the table can have
constexpr int maxPoints = 64;

//- The start table: a spring of 10 N.m/rad over +-1 rad
constexpr double startAngle[] = {-1.0, 1.0}, startMoment[] = {10.0, -10.0};

const char* const lawHtml = R"(<p>OpenFOAM's sixDoF
tabulatedAxialAngularSpring restraint between A and B: a moment about the
axis <code>B.axis</code> (fixed in B), looked up in a table of (angle,
moment) points from the turn of A about the axis away from its reference
orientation <code>referenceOrientation</code> relative to B. The angle
theta is that of axialAngularSpring.fmu (OpenFOAM's
linearAxialAngularSpring) with its sign; in B's frame, with n the unit
axis:</p>
<pre>
x = theta (angleInDegrees = 0) or theta 180/pi (angleInDegrees = 1)
M = the table's value at x: linear between table.angle[k], table.moment[k],
    k = 1 .. table.points; outside, by outOfBounds
A.M = B.R ((M - damping (w_rel . n)) n),  B.M = -A.M;  A.F = B.F = 0
w_rel = B.R^T (A.omega - B.omega)
potentialEnergy = -integral of M from 0 to theta,
dissipatedPower = damping (w_rel . n)^2
</pre>
<p>A moment that turns A back has the sign opposite to the angle's.
outOfBounds as OpenFOAM's: 0 error (an angle outside the table fails the
step), 1 warn (here as clamp, without warning), 2 clamp (the end moments),
3 repeat (the table repeated above its last angle, its first moment below
its first angle, as OpenFOAM does). The angles strictly increasing, from 2
to 64 points, the unused ones 0; damping finite and &ge; 0; B.axis finite
and not zero, referenceOrientation a rotation tensor as OpenFOAM checks it
(checked in fmi2ExitInitializationMode).</p>)";

std::string indexed(const char* name, int k)
{
    return std::string(name) + "[" + std::to_string(k) + "]";
}

class TabulatedAxialAngularSpringModel final
    : public fmuExport::LawFmuModel<connectors::TabulatedAxialAngularSpring,
                                    Parameters> {
public:
    TabulatedAxialAngularSpringModel()
        : LawFmuModel({modelName,
                       "OpenFOAM's tabulatedAxialAngularSpring: a moment from "
                       "a table of the turn about an axis fixed in B from a "
                       "reference orientation",
                       "1.0.0", lawHtml})
    {
        declareBodies({1, 0, 0});
        fmuExport::VariableTable& t = table();
        const Block axis
            = parameter(&Parameters::axis_B, "B.axis", "1",
                        "the axis n, B's frame (normalised)", {0, 0, 1});
        const Block reference = referenceOrientation();
        table_.first = fmi2ValueReference(t.size());
        t.parameter("table.points", Shape::scalar, "1",
                    "number of points of the table, an integer from 2 to "
                        + std::to_string(maxPoints),
                    {2.0});
        for (int k = 1; k <= maxPoints; ++k) {
            t.parameter(indexed("table.angle", k), Shape::scalar, "1",
                        "angle of point " + std::to_string(k)
                            + " of the table, rad (deg with angleInDegrees "
                              "= 1), above the point before; 0 beyond "
                              "table.points",
                        {k <= 2 ? startAngle[k - 1] : 0.0});
        }
        for (int k = 1; k <= maxPoints; ++k) {
            t.parameter(indexed("table.moment", k), Shape::scalar, "N.m",
                        "moment about n on A at table.angle["
                            + std::to_string(k) + "]; 0 beyond table.points",
                        {k <= 2 ? startMoment[k - 1] : 0.0});
        }
        degrees_ = t.parameter("angleInDegrees", Shape::scalar, "1",
                               "1: the table's angles in degrees, 0: in "
                               "radians (OpenFOAM's angleFormat)",
                               {0.0});
        outOfBounds_ = t.parameter(
            "outOfBounds", Shape::scalar, "1",
            "outside the table's angles, as OpenFOAM's outOfBounds: 0 error, "
            "1 warn (as clamp), 2 clamp, 3 repeat",
            {2.0});
        table_.size = t.size() - table_.first;
        const Block damping = parameter(&Parameters::damping, "damping",
                                        "N.m.s/rad", "damping c, >= 0", 0.0);
        OutputDependencies d
            = pointToPointDependencies({axis, reference, table_, damping});
        d.tension = {};
        d.potentialEnergy = join(positionBlocks(), {axis, reference, table_});
        declareOutputs(d);
        declareStartAtRest();
    }

private:
    //- The table, its angle format and outOfBounds
    void setOtherParameters(const double* values, Parameters& p) const override
    {
        const fmi2ValueReference points = table_.first;
        const int n
            = integer(values, points, 2, maxPoints,
                      "an integer from 2 to " + std::to_string(maxPoints));
        p.angle.clear();
        p.moment.clear();
        for (int k = 1; k <= maxPoints; ++k) {
            const fmi2ValueReference angle = points + k;
            const fmi2ValueReference moment = angle + maxPoints;
            if (k <= n) {
                p.angle.push_back(values[angle]);
                p.moment.push_back(values[moment]);
                continue;
            }
            for (const fmi2ValueReference vr : {angle, moment}) {
                if (values[vr] != 0.0) {
                    refuse(Refusal::inconsistent, values, vr,
                           "0 beyond table.points = " + std::to_string(n)
                               + ": the table is its first table.points "
                                 "points");
                }
            }
        }
        p.angleInDegrees = flag(values, degrees_);
        p.outOfBounds = connectors::OutOfBounds(
            integer(values, outOfBounds_.first, 0, 3,
                    "0 (error), 1 (warn), 2 (clamp) or 3 (repeat)"));
    }

    //- values[vr] as an integer from lo to hi; ParameterError (outOfRange)
    //  saying `allowed` otherwise
    int integer(const double* values, fmi2ValueReference vr, int lo, int hi,
                const std::string& allowed) const
    {
        const double value = values[vr];
        if (!(value >= lo && value <= hi && value == int(value))) {
            refuse(Refusal::outOfRange, values, vr, allowed);
        }
        return int(value);
    }

    [[noreturn]] void refuse(Refusal code, const double* values,
                             fmi2ValueReference vr,
                             const std::string& allowed) const
    {
        const fmuExport::ScalarVariable& v = variables().variables()[vr];
        throw ParameterError(code, modelName, v.name, values[vr], v.unit,
                             allowed);
    }

    Block table_, degrees_, outOfBounds_;
};

} // namespace

std::unique_ptr<fmuExport::Model> fmuExport::createModel()
{
    return std::make_unique<TabulatedAxialAngularSpringModel>();
}
