// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "fmuConnectorLine.H"
#include "fmuConnectorSettings.H"
#include "error.H"

#include <cmath>
#include <string>

// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fmuConnectorLine::lookup
(
    const wordList& outputNames,
    const fmuImport::Fmu& fmu,
    const std::string& where
)
{
    auto indexed = [](const char* base, const label k)
    {
        return word(std::string(base) + '[' + std::to_string(k) + ']', false);
    };

    // The points: shape.x/y/z[k], in FMI 2.0 and 3.0 alike; or the rows
    // of an n x 3 array shape, shape[k,1..3], as the project's FMI 3.0
    // FMUs built before shape.x/y/z had it (an array that was also the
    // parent of shape.tension, which FMI 3.0's structured names forbid),
    // so that cases holding such a copy keep running and restarting
    for (label k = 1; ; ++k)
    {
        labelList xyz
        ({
            outputNames.find(indexed("shape.x", k)),
            outputNames.find(indexed("shape.y", k)),
            outputNames.find(indexed("shape.z", k))
        });
        if (min(xyz) < 0)
        {
            forAll(xyz, j)
            {
                xyz[j] = outputNames.find
                (
                    word
                    (
                        "shape[" + std::to_string(k) + ','
                      + std::to_string(j + 1) + ']',
                        false
                    )
                );
            }
        }
        if (min(xyz) < 0)
        {
            break;
        }
        shapeOut_.append(xyz);
    }
    const label n = nPoints();

    for (label k = 1; k <= n; ++k)
    {
        const label i = outputNames.find(indexed("shape.tension", k));
        if (i < 0)
        {
            tensionOut_.clear();
            break;
        }
        tensionOut_.append(i);
    }

    // The section of each shape point: outputs or local variables, read
    // with the outputs
    for (label k = 1; k <= n; ++k)
    {
        const word name(indexed("shape.section", k));
        if
        (
            !fmu.hasVariable(name)
         || fmu.variable(name).type != fmuImport::Type::Real
         || (
                fmu.variable(name).causality != fmuImport::Causality::output
             && fmu.variable(name).causality != fmuImport::Causality::local
            )
        )
        {
            sectionRefs_.clear();
            break;
        }
        sectionRefs_.push_back(fmu.variable(name).valueReference);
    }

    // The water's velocity and acceleration inputs: each all of them at
    // every shape point, or none
    lookupInputs(fmu, n, "shape.U", "water velocity", where, flowRefs_);
    flowValues_.assign(flowRefs_.size(), 0);
    lookupInputs
    (
        fmu, n, "shape.A", "water acceleration", where, accelerationRefs_
    );
    accelerationValues_.assign(accelerationRefs_.size(), 0);
}


void Foam::fmuConnectorLine::lookupInputs
(
    const fmuImport::Fmu& fmu,
    const label n,
    const std::string& base,
    const char* what,
    const std::string& where,
    std::vector<unsigned int>& refs
)
{
    auto indexed = [&base](const char axis, const label k)
    {
        return word(base + axis + '[' + std::to_string(k) + ']', false);
    };

    wordList missing;
    refs.clear();
    for (label k = 1; k <= max(n, label(1)); ++k)
    {
        for (const char axis : {'x', 'y', 'z'})
        {
            const word name(indexed(axis, k));
            if
            (
                fmu.hasVariable(name)
             && fmu.variable(name).causality == fmuImport::Causality::input
             && fmu.variable(name).type == fmuImport::Type::Real
            )
            {
                refs.push_back(fmu.variable(name).valueReference);
            }
            else
            {
                missing.append(name);
            }
        }
    }
    if (refs.empty())
    {
        return;
    }
    if (missing.size() || fmu.hasVariable(indexed('x', n + 1)))
    {
        FatalErrorInFunction
            << where.c_str() << "the FMU declares " << what << " inputs "
            << base.c_str() << "x/y/z but not as Real inputs at each of its "
            << n << " shape points (outputs shape.x/y/z[1.." << n << "])"
            << (missing.size() ? "; missing: " : "")
            << fmuConnectorSettings::listed(missing).c_str()
            << exit(FatalError);
    }
}


Foam::pointField Foam::fmuConnectorLine::points(const scalarList& outputs) const
{
    pointField points(nPoints());
    forAll(points, k)
    {
        for (direction d = 0; d < 3; ++d)
        {
            points[k][d] = outputs[shapeOut_[3*k + d]];
        }
    }
    return points;
}


Foam::scalarField Foam::fmuConnectorLine::tension
(
    const scalarList& outputs
) const
{
    return scalarField(outputs, tensionOut_);
}


Foam::labelList Foam::fmuConnectorLine::sections() const
{
    labelList sections(sectionValues_.size());
    forAll(sections, k)
    {
        sections[k] = label(std::lround(sectionValues_[k])) - 1;
    }
    return sections;
}


void Foam::fmuConnectorLine::setPoints
(
    const vectorField& v,
    std::vector<double>& values,
    const char* what,
    const std::string& where
)
{
    if (3*v.size() != label(values.size()))
    {
        FatalErrorInFunction
            << where.c_str() << v.size() << ' ' << what << " given for "
            << values.size()/3 << " inputs" << abort(FatalError);
    }
    forAll(v, k)
    {
        std::copy(v[k].cdata(), v[k].cdata() + 3, &values[3*k]);
    }
}


void Foam::fmuConnectorLine::setFlow
(
    const vectorField& U,
    const std::string& where
)
{
    setPoints(U, flowValues_, "water velocities", where);
}


void Foam::fmuConnectorLine::setAcceleration
(
    const vectorField& a,
    const std::string& where
)
{
    setPoints(a, accelerationValues_, "water accelerations", where);
}


void Foam::fmuConnectorLine::setInputs(fmuImport::Instance& instance) const
{
    if (!flowRefs_.empty())
    {
        instance.setReal(flowRefs_, flowValues_);
    }
    if (!accelerationRefs_.empty())
    {
        instance.setReal(accelerationRefs_, accelerationValues_);
    }
}


void Foam::fmuConnectorLine::readOutputs(fmuImport::Instance& instance)
{
    if (!sectionRefs_.empty())
    {
        instance.getReal(sectionRefs_, sectionValues_);
    }
}


// ************************************************************************* //
