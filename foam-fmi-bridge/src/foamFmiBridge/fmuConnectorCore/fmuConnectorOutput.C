// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "fmuConnectorOutput.H"
#include "Time.H"
#include "OSspecific.H"
#include "DynamicList.H"

#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <iostream>

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


// ************************************************************************* //
