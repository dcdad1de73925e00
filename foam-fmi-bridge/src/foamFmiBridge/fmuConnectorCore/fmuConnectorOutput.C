// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "fmuConnectorOutput.H"
#include "Time.H"
#include "OSspecific.H"
#include "DynamicList.H"
#include "OStringStream.H"
#include "restartFiles.H"
#include "IFstream.H"
#include "foamVtkSeriesWriter.H"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <iostream>
#include <vector>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(fmuConnectorOutput, 0);
}


// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The outputs that exist: a FatalError ends the process with exit(), which
//  destroys no restraint, so an exit handler writes their completed rows.
//  Never destroyed, as the handler may run after static destructors.
Foam::DynamicList<Foam::fmuConnectorOutput*>& liveOutputs()
{
    static auto* live = new Foam::DynamicList<Foam::fmuConnectorOutput*>;
    return *live;
}

//- The latest time index any connector has begun: a pending row of an
//  earlier step is final (the exit handler needs it without OpenFOAM's
//  Time, which may be gone by then)
Foam::label& latestTimeIndex()
{
    static Foam::label index = -1;
    return index;
}

//- Whether the process is ending (the exit handler runs, or a destructor
//  while an exception unwinds): a row that cannot be written is then
//  reported on the standard error, not as a FatalError
bool& ending()
{
    static bool value = false;
    return value;
}

void writeCompletedRows()
{
    ending() = true;
    for (Foam::fmuConnectorOutput* output : liveOutputs())
    {
        output->flush(false);
    }
}

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

void Foam::fmuConnectorOutput::commit()
{
    if (!pending_)
    {
        return;
    }

    rowFile::appendNumber(buffer_, pendingTime_);
    for (const scalar value : pendingValues_)
    {
        buffer_ += ' ';
        rowFile::appendNumber(buffer_, value);
    }
    buffer_ += '\n';
    pending_ = false;

    writeBuffer(rowOf(pendingTime_));
}


std::function<std::string()> Foam::fmuConnectorOutput::rowOf
(
    const scalar t
) const
{
    // The message of a failure, made only then
    return [this, t]()
    {
        std::string what("the row of t = ");
        rowFile::appendNumber(what, t);
        return what + " s of connector " + name_;
    };
}


void Foam::fmuConnectorOutput::writeBuffer
(
    const std::function<std::string()>& what
)
{
    // Flushed: the row is in the file before the next step calls the FMU
    if (!ending() && !std::uncaught_exceptions())
    {
        file_->append(buffer_, what);
    }
    else if (const int error = file_->tryAppend(buffer_))
    {
        std::cerr
            << "--> FOAM Serious Error: cannot write " << what() << " to "
            << file_->path() << ": " << std::strerror(error)
            << " (a full disk, or a file-size limit: ulimit -f)" << std::endl;
    }
    buffer_.clear();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fmuConnectorOutput::fmuConnectorOutput
(
    const word& name,
    const Time& runTime,
    const fmuConnectorCore& fmu,
    const string& description,
    const word& startTimeName,
    const wordList& reportBodies
)
:
    regIOobject
    (
        IOobject
        (
            "fmuConnectorOutput." + name,
            startTimeName.empty() ? runTime.timeName() : startTimeName,
            runTime,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        )
    ),
    fmu_(fmu),
    pending_(false),
    pendingIndex_(-1),
    pendingTime_(0),
    provisionalSize_(-1),
    name_(name),
    reportBodies_(reportBodies)
{
    const fileName dir
    (
        runTime.globalPath()/"postProcessing"/"fmuConnectors"
       /(startTimeName.empty() ? runTime.timeName() : startTimeName)
    );
    mkDir(dir);
    file_.reset(new rowFile(dir/(name + ".dat")));

    buffer_ = "# " + description + "\n# Time";
    for (const word& output : fmu_.outputNames())
    {
        buffer_ += ' ' + output;
    }
    buffer_ += '\n';
    writeBuffer([this]() { return "the header of connector " + name_; });

    static const bool handlerInstalled =
        (std::atexit(writeCompletedRows) == 0);
    if (!handlerInstalled)
    {
        WarningInFunction
            << "cannot install the exit handler: a run ended by an error"
            << " may lose the last completed row of " << file_->path() << endl;
    }
    liveOutputs().append(this);
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::fmuConnectorOutput::~fmuConnectorOutput()
{
    DynamicList<fmuConnectorOutput*>& live = liveOutputs();
    const label i = live.find(this);
    if (i >= 0)
    {
        live.remove(i);
    }

    flush(true);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fmuConnectorOutput::stepBegins(const label timeIndex)
{
    latestTimeIndex() = max(latestTimeIndex(), timeIndex);
    if (timeIndex != pendingIndex_)
    {
        commit();
        provisionalSize_ = -1;
    }
}


void Foam::fmuConnectorOutput::record(const label timeIndex, const scalar t)
{
    stepBegins(timeIndex);

    // A further solve of a step whose row is in the file already (a write
    // time's): its row replaces that one
    const bool replace = provisionalSize_ >= 0 && timeIndex == pendingIndex_;
    if (replace)
    {
        file_->cutTo(provisionalSize_, rowOf(t));
    }
    provisionalSize_ = -1;

    pending_ = true;
    pendingIndex_ = timeIndex;
    pendingTime_ = t;
    pendingValues_ = fmu_.outputs();

    // The step's time is written once its last solve is done: the row goes
    // to the file now, before the time folder is begun, so that a kill
    // while the time is written loses no row the bodies' files have (each
    // further solve replaces it)
    const Time& runTime = time();
    if (runTime.writeTime() && timeIndex == runTime.timeIndex())
    {
        provisionalSize_ = file_->size();
        commit();
    }

    if (reportBodies_.size())
    {
        const fmuConnectorCore::loads A(fmu_.loadsA());
        const fmuConnectorCore::loads B(fmu_.loadsB());
        Info<< "Restraint " << name_ << ": t = " << t;
        fmu_.writeDiagnostics(Info);
        Info<< " force on " << reportBodies_[0] << ' ' << A.F
            << " moment " << A.M
            << " force on " << reportBodies_[1] << ' ' << B.F
            << " moment " << B.M << endl;
    }
}


void Foam::fmuConnectorOutput::flush(const bool final)
{
    if (final || latestTimeIndex() > pendingIndex_)
    {
        commit();
    }
}


#if OPENFOAM >= 2006
bool Foam::fmuConnectorOutput::writeObject(IOstreamOption, const bool) const
#else
bool Foam::fmuConnectorOutput::writeObject
(
    IOstream::streamFormat,
    IOstream::versionNumber,
    IOstream::compressionType,
    const bool
) const
#endif
{
    // The time is written after the step's last solve: its row is final
    const_cast<fmuConnectorOutput&>(*this).flush(true);
    writeShape();
    return true;
}


void Foam::fmuConnectorOutput::writeShape() const
{
    const label n = fmu_.nShapePoints();
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
    if (fmu_.reportsShapeSections())
    {
        sections = fmu_.shapeSections();
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

        if (fmu_.reportsShapeTension() || fmu_.reportsShapeSections())
        {
            os  << "POINT_DATA " << n + nJoints << nl;
        }
        if (fmu_.reportsShapeTension())
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
        if (fmu_.reportsShapeSections())
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
