// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "fmuConnectorFlow.H"
#include "restartFiles.H"
#include "fmuConnectorCore.H"
#include "interpolation.H"
#include "volFields.H"
#include "IFstream.H"
#include "OFstream.H"
#include "OStringStream.H"
#include "addToRunTimeSelectionTable.H"

#include <cerrno>
#include <cstring>
#include <unistd.h>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace functionObjects
{
    defineTypeNameAndDebug(fmuConnectorFlow, 0);
    addToRunTimeSelectionTable(functionObject, fmuConnectorFlow, dictionary);
}
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::fileName Foam::functionObjects::fmuConnectorFlow::statePath
(
    const word& timeName
) const
{
    return time_.path()/timeName/"uniform"/"fmuConnectorFlow"/name();
}


bool Foam::functionObjects::fmuConnectorFlow::restoreFlow()
{
    // When the run starts (read() is called again when the dictionary
    // changes), on the master, where the connectors are
    const fileName path(statePath(time_.timeName()));
    if (!Pstream::master() || time_.timeIndex() != time_.startTimeIndex())
    {
        return false;
    }

    // A run restarted from a time written by an earlier run needs the
    // velocities written with it, complete
    if (!fresh_)
    {
        wordList entries(connectors_);
        if (acceleration_)
        {
            entries.append("acceleration");
        }
        restartFiles::require
        (
            time_,
            time_.timeName(),
            fileName("uniform")/"fmuConnectorFlow"/name(),
            entries,
            "function object " + name() + ": the water velocity at the"
            " lines",
            " (or, when the function object or one of its connectors is new"
            " since that time, set 'restart fresh;' in the function object:"
            " the lines then take still water in their first time step)"
        );
    }
    if (fresh_ || !isFile(path))
    {
        return false;
    }

    IFstream is(path);
    const dictionary flows(is);
    const dictionary* accelerations = flows.findDict("acceleration");
    for (const word& connector : connectors_)
    {
        vectorField flow;
        if (flows.readIfPresent(connector, flow))
        {
            fmuConnectorCore::find(time_, connector)->setFlow(flow);
        }
        if (acceleration_ && accelerations)
        {
            vectorField a;
            if (accelerations->readIfPresent(connector, a))
            {
                fmuConnectorCore::find(time_, connector)->setAcceleration(a);
            }
        }
    }
    Info<< "Function object " << name() << ": water velocity at the lines"
        << " restored from " << path << endl;
    return true;
}


void Foam::functionObjects::fmuConnectorFlow::startFlow(const bool restored)
{
    // When the run starts, on every processor (the sampling is collective)
    if (time_.timeIndex() != time_.startTimeIndex())
    {
        return;
    }

    // The start shapes of the connectors that start from one, known on
    // the master
    List<pointField> points(connectors_.size());
    if (Pstream::master() && !restored)
    {
        forAll(connectors_, i)
        {
            points[i] =
                fmuConnectorCore::find(time_, connectors_[i])
                    ->startShapePoints();
        }
    }
    // Pstream::scatter is deprecated from v2406 for broadcast (in v2312)
    #if OPENFOAM >= 2312
    Pstream::broadcast(points);
    #else
    Pstream::scatter(points);
    #endif

    bool any = false;
    forAll(points, i)
    {
        any = any || points[i].size();
    }
    if (!any || !foundObject<volVectorField>(UName_))
    {
        return;
    }

    const FixedList<List<vectorField>, 2> flows(sampleFlow(points));
    if (Pstream::master())
    {
        forAll(connectors_, i)
        {
            if (points[i].size())
            {
                setFlow(i, flows);
                Info<< "Function object " << name() << ": water velocity"
                    << (acceleration_ ? " and acceleration" : "") << " at"
                    << " the start shape of " << connectors_[i]
                    << " set for the first time step" << endl;
            }
        }
    }
}


void Foam::functionObjects::fmuConnectorFlow::writeFlow
(
    const FixedList<List<vectorField>, 2>& flows
) const
{
    const fileName path(statePath(time_.timeName()));
    OStringStream os;
    // Every digit: the restarted run sets the same inputs
    os.precision(17);
    forAll(connectors_, i)
    {
        os.writeEntry(connectors_[i], flows[0][i]);
    }
    if (acceleration_)
    {
        os.beginBlock("acceleration");
        forAll(connectors_, i)
        {
            os.writeEntry(connectors_[i], flows[1][i]);
        }
        os.endBlock();
    }
    // To a temporary name, renamed: a kill never leaves half of it
    restartFiles::writeText
    (
        path,
        os.str(),
        "the water velocity at the lines of t = "
      + std::string(time_.timeName()) + " s (function object "
      + std::string(name()) + ')'
    );
}


void Foam::functionObjects::fmuConnectorFlow::appendRows
(
    const label i,
    const std::string& rows,
    const std::string& what
)
{
    std::ostream& os = files(i).stdStream();
    const std::streamoff whole = os.tellp();
    errno = 0;
    os.write(rows.data(), std::streamsize(rows.size()));
    os.flush();
    if (os.good())
    {
        return;
    }

    const int error = errno ? errno : EIO;
    if (whole >= 0 && ::truncate(files(i).name().c_str(), off_t(whole)) != 0)
    {
        WarningInFunction
            << "cannot cut " << files(i).name() << " back to its last whole"
            << " row: " << std::strerror(errno) << endl;
    }
    FatalErrorInFunction
        << "function object " << name() << ": cannot write " << what.c_str()
        << " to " << files(i).name() << ": " << std::strerror(error)
        << " (a full disk, or a file-size limit: ulimit -f)."
        << " The file keeps every whole row written before"
        << exit(FatalError);
}


void Foam::functionObjects::fmuConnectorFlow::writeFileHeader
(
    const label i
)
{
    const fmuConnectorCore& core =
        *fmuConnectorCore::find(time_, connectors_[i]);

    OStringStream os;
    writeHeader
    (
        os,
        word(acceleration_ ? "Water velocity and acceleration" : "Water velocity")
      + " at the shape points of " + connectors_[i]
    );
    writeCommented(os, "Time");
    for (const char* c : {"U", "A"})
    {
        if (*c == 'A' && !acceleration_)
        {
            break;
        }
        for (label k = 1; k <= core.line().nPoints(); ++k)
        {
            for (const char axis : {'x', 'y', 'z'})
            {
                writeTabbed(os, word(c) + axis + '[' + Foam::name(k) + ']');
            }
        }
    }
    os  << nl;
    appendRows
    (
        i,
        os.str(),
        "the header, at t = " + std::string(time_.timeName()) + " s,"
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::functionObjects::fmuConnectorFlow::fmuConnectorFlow
(
    const word& name,
    const Time& runTime,
    const dictionary& dict
)
:
    fvMeshFunctionObject(name, runTime, dict),
    logFiles(obr_, name),
    fresh_(false),
    acceleration_(false),
    blendWidth_(0),
    horizontal_(false)
{
    read(dict);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::functionObjects::fmuConnectorFlow::read(const dictionary& dict)
{
    fvMeshFunctionObject::read(dict);

    connectors_ = dict.get<wordList>("connectors");
    UName_ = dict.getOrDefault<word>("U", "U");
    scheme_ = dict.getOrDefault<word>("interpolationScheme", "cellPoint");
    fresh_ =
        fmuConnectorCore::restartModeNames.getOrDefault
        (
            "restart",
            dict,
            fmuConnectorCore::restartMode::exact
        )
     == fmuConnectorCore::restartMode::fresh;

    acceleration_ = dict.getOrDefault<bool>("acceleration", false);

    // The wave beyond the mesh (collective: every processor makes the
    // patch's wave model), and the mesh's horizontal, solved directions
    wave_.clear();
    blendWidth_ = dict.getOrDefault<scalar>("blendWidth", 0);
    if (blendWidth_ < 0)
    {
        FatalIOErrorInFunction(dict)
            << "function object " << name() << ": entry blendWidth "
            << blendWidth_ << " is negative; expected the width (m) inside"
            << " the mesh's bounds over which the incident wave hands over"
            << " to the CFD's flow, 0 for none" << exit(FatalIOError);
    }
    if (dict.found("incidentWave"))
    {
        wave_.reset(new incidentWave(mesh_, dict, "incidentWave"));
        bounds_ = mesh_.bounds();
        const vector up(wave_->up());
        const Vector<label> solved(mesh_.geometricD());
        for (direction c = 0; c < vector::nComponents; ++c)
        {
            horizontal_[c] = solved[c] == 1 && mag(up[c]) < 0.5;
        }
        Info<< "Function object " << name() << ": the points of the lines"
            << " beyond the mesh's horizontal bounds " << bounds_
            << " take the " << wave_->describe().c_str() << ", handed over"
            << " to the CFD's flow over " << blendWidth_ << " m inside them"
            << endl;
    }
    else if (dict.found("blendWidth"))
    {
        FatalIOErrorInFunction(dict)
            << "function object " << name() << ": entry blendWidth without"
            << " incidentWave; expected incidentWave <patch> (the patch"
            << " whose waves the points beyond the mesh take) with it"
            << exit(FatalIOError);
    }

    if (connectors_.empty())
    {
        FatalIOErrorInFunction(dict)
            << "function object " << name() << ": entry connectors is empty;"
            << " expected the names of fmuConnector restraints whose FMUs"
            << " take the water velocity" << exit(FatalIOError);
    }

    // The connectors run on the master process, which checks them
    if (Pstream::master())
    {
        for (const word& connector : connectors_)
        {
            const fmuConnectorCore* core =
                fmuConnectorCore::find(time_, connector);
            if (!core)
            {
                FatalIOErrorInFunction(dict)
                    << "function object " << name() << ": entry connectors"
                    << " names " << connector << ", which is not an"
                    << " fmuConnector restraint of the case; the restraints"
                    << " with a connector FMU are: "
                    << fmuConnectorCore::listed(fmuConnectorCore::names(time_))
                       .c_str()
                    << exit(FatalIOError);
            }
            if (!core->line().takesFlow())
            {
                FatalIOErrorInFunction(dict)
                    << "function object " << name() << ": entry connectors"
                    << " names " << connector << ", whose FMU " << core->file()
                    << " declares no water velocity inputs (shape.Ux/Uy/Uz[k]"
                    << " at its shape points)" << exit(FatalIOError);
            }
            if (acceleration_ && !core->line().takesAcceleration())
            {
                FatalIOErrorInFunction(dict)
                    << "function object " << name() << ": entry acceleration"
                    << " is on, but connector " << connector << "'s FMU "
                    << core->file() << " declares no water acceleration"
                    << " inputs (shape.Ax/Ay/Az[k] at its shape points)"
                    << exit(FatalIOError);
            }
        }
    }

    resetNames(connectors_);
    startFlow(restoreFlow());
    if (Pstream::master())
    {
        forAll(connectors_, i)
        {
            writeFileHeader(i);
        }
    }

    return true;
}


bool Foam::functionObjects::fmuConnectorFlow::execute()
{
    // The shape points of every connector, known on the master
    List<pointField> points(connectors_.size());
    if (Pstream::master())
    {
        forAll(connectors_, i)
        {
            points[i] =
                fmuConnectorCore::find(time_, connectors_[i])->shapePoints();
        }
    }
    // Pstream::scatter is deprecated from v2406 for broadcast (in v2312)
    #if OPENFOAM >= 2312
    Pstream::broadcast(points);
    #else
    Pstream::scatter(points);
    #endif

    const FixedList<List<vectorField>, 2> flows(sampleFlow(points));
    if (Pstream::master())
    {
        forAll(connectors_, i)
        {
            setFlow(i, flows);

            // Formatted as the file's stream formats (initStream), the time
            // to the file's precision, not the time name's
            OStringStream os;
            initStream(os);
            os  << setw(charWidth()) << time_.value();
            for (const List<vectorField>& values : flows)
            {
                if (values.size())
                {
                    for (const vector& u : values[i])
                    {
                        os  << tab << u.x() << tab << u.y() << tab << u.z();
                    }
                }
            }
            os  << nl;
            appendRows
            (
                i,
                os.str(),
                "the row of t = " + std::string(time_.timeName()) + " s"
            );
        }

        // A run restarted from this time starts with these velocities
        if (time_.writeTime())
        {
            writeFlow(flows);
        }
    }

    return true;
}


bool Foam::functionObjects::fmuConnectorFlow::write()
{
    return true;
}


// ************************************************************************* //
