// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "fmuConnectorOutput.H"
#include "Time.H"
#include "OSspecific.H"
#include "DynamicList.H"

#include <algorithm>
#include <cstdlib>
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
    if (pending_)
    {
        rows_->publish();
        pending_ = false;
    }
}


void Foam::fmuConnectorOutput::drain()
{
    const int error = rows_->drain();
    if (error)
    {
        report(error, rows_->failedRow());
    }
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


void Foam::fmuConnectorOutput::report
(
    const int error,
    const std::string& what
)
{
    if (!error || failureReported_)
    {
        return;
    }
    failureReported_ = true;
    if (!ending() && !std::uncaught_exceptions())
    {
        file_->fatal(error, what);
    }
    std::cerr
        << "--> FOAM Serious Error: cannot write " << what << " to "
        << file_->path() << ": " << rowFile::cause(error) << std::endl;
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
    failureReported_(false),
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

    std::string header("# " + description + "\n# Time");
    for (const word& output : fmu_.outputNames())
    {
        header += ' ' + output;
    }
    header += '\n';
    report
    (
        file_->tryAppend(header),
        "the header of connector " + name_
    );
    rows_.reset
    (
        new fmuConnectorRows(*file_, name_, 1 + fmu_.outputNames().size())
    );

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

    // A row the writer thread could not write
    report(rows_->error(), rows_->failedRow());

    // A further solve of a step whose row is in the file already (a write
    // time's): its row replaces that one. The writer does not touch the
    // file: every published row is written
    const bool replace = provisionalSize_ >= 0 && timeIndex == pendingIndex_;
    if (replace)
    {
        file_->cutTo(provisionalSize_, rowOf(t));
    }
    provisionalSize_ = -1;

    // The row's numbers, straight into its room
    double* row = rows_->next();
    row[0] = t;
    const scalarList& values = fmu_.outputs();
    std::copy(values.cbegin(), values.cend(), row + 1);
    pending_ = true;
    pendingIndex_ = timeIndex;

    // The step's time is written once its last solve is done: the row goes
    // to the file now, before the time folder is begun, so that a kill
    // while the time is written loses no row the bodies' files have (each
    // further solve replaces it)
    const Time& runTime = time();
    if (runTime.writeTime() && timeIndex == runTime.timeIndex())
    {
        drain();
        provisionalSize_ = file_->size();
        commit();
        drain();
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
    drain();
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
