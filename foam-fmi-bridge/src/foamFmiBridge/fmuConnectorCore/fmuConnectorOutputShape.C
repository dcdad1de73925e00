// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "fmuConnectorOutput.H"
#include "Time.H"
#include "OSspecific.H"
#include "OStringStream.H"
#include "foamVtkSeriesWriter.H"
#include "restartFiles.H"

#include <algorithm>
#include <string>

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The joints of a line of sections whose connector reports them as
//  outputs: joint k (of sections k and k + 1, from B) at joint.x/y/z[k]
//  (an FMI 3.0 FMU: the rows of the array joint, joint[k,1..3]), the
//  tension at the lower end of section k + 1 above it; none when any of
//  them is not an output
void lineJoints
(
    const Foam::fmuConnectorCore& fmu,
    const Foam::label nJoints,
    Foam::pointField& joints,
    Foam::scalarField& tension
)
{
    using namespace Foam;
    const wordList& names = fmu.outputNames();
    auto output = [&names](const std::string& name)
    {
        return names.find(word(name, false));
    };
    auto indexed = [](const std::string& base, const label k)
    {
        return base + '[' + std::to_string(k) + ']';
    };

    joints.setSize(nJoints);
    tension.setSize(nJoints);
    for (label k = 1; k <= nJoints; ++k)
    {
        label i[4] =
        {
            output(indexed("joint.x", k)),
            output(indexed("joint.y", k)),
            output(indexed("joint.z", k)),
            output(indexed("section.lowerTension", k + 1))
        };
        for (label d = 0; d < 3; ++d)
        {
            if (i[d] < 0)
            {
                i[d] = output
                (
                    "joint[" + std::to_string(k) + ','
                  + std::to_string(d + 1) + ']'
                );
            }
        }
        if (std::min({i[0], i[1], i[2], i[3]}) < 0)
        {
            joints.clear();
            tension.clear();
            return;
        }
        const scalarList& values = fmu.outputs();
        joints[k - 1] = point(values[i[0]], values[i[1]], values[i[2]]);
        tension[k - 1] = values[i[3]];
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::fmuConnectorOutput::writeShape() const
{
    const label n = fmu_.line().nPoints();
    if (n < 2)
    {
        return;
    }

    const Time& runTime = time();
    const fileName dir(runTime.globalPath()/"VTK"/"fmuConnectors");
    mkDir(dir);
    const word file
    (
        name_ + '_' + Foam::name(runTime.timeIndex()) + ".vtk"
    );

    // A line of sections: its joints after the shape points, when reported
    labelList sections;
    pointField joints;
    scalarField jointTension;
    if (fmu_.line().reportsSections())
    {
        sections = fmu_.line().sections();
        lineJoints(fmu_, max(sections), joints, jointTension);
    }
    const label nJoints = joints.size();

    const std::string when
    (
        " of connector " + name_ + " at t = "
      + std::string(runTime.timeName()) + " s"
    );
    {
        OStringStream os;
        os.precision(IOstream::defaultPrecision());
        os  << "# vtk DataFile Version 2.0" << nl
            << "connector " << name_ << " at t = " << runTime.timeName() << nl
            << "ASCII" << nl
            << "DATASET POLYDATA" << nl
            << "POINTS " << n + nJoints << " double" << nl;
        for (const point& p : fmu_.shapePoints())
        {
            os  << p.x() << ' ' << p.y() << ' ' << p.z() << nl;
        }
        for (const point& p : joints)
        {
            os  << p.x() << ' ' << p.y() << ' ' << p.z() << nl;
        }
        if (nJoints)
        {
            os  << "VERTICES " << nJoints << ' ' << 2*nJoints << nl;
            for (label k = 0; k < nJoints; ++k)
            {
                os  << "1 " << n + k << nl;
            }
        }
        os  << "LINES 1 " << n + 1 << nl << n;
        for (label k = 0; k < n; ++k)
        {
            os  << ' ' << k;
        }
        os  << nl;

        if (fmu_.line().reportsTension() || fmu_.line().reportsSections())
        {
            os  << "POINT_DATA " << n + nJoints << nl;
        }
        if (fmu_.line().reportsTension())
        {
            os  << "SCALARS tension double 1" << nl
                << "LOOKUP_TABLE default" << nl;
            for (const scalar T : fmu_.shapeTension())
            {
                os  << T << nl;
            }
            for (const scalar T : jointTension)
            {
                os  << T << nl;
            }
        }
        if (fmu_.line().reportsSections())
        {
            os  << "SCALARS section int 1" << nl
                << "LOOKUP_TABLE default" << nl;
            for (const label k : sections)
            {
                os  << k << nl;
            }
            for (label k = 1; k <= nJoints; ++k)
            {
                os  << k << nl;
            }
        }
        // To a temporary name, renamed: a reader never sees half a file
        restartFiles::writeText(dir/file, os.str(), "the line shape" + when);
    }

    // The series: the entries of earlier times (a restarted run drops
    // those from its start on), then this one
    const fileName series(dir/(name_ + ".vtk.series"));
    vtk::seriesWriter entries;
    entries.load
    (
        series,
        false,
        runTime.value() - 0.5*runTime.deltaTValue()
    );
    entries.append(runTime.value(), file);

    OStringStream os;
    os.precision(IOstream::defaultPrecision());
    entries.print(os);
    restartFiles::writeText(series, os.str(), "the VTK series" + when);
}


// ************************************************************************* //
