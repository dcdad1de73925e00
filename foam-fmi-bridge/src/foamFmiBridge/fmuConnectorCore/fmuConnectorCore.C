// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "fmuConnectorCore.H"
#include "fmuConnectorOutput.H"
#include "Time.H"
#include "error.H"
#include "messageStream.H"
#include "debug.H"

#include <cctype>
#include <cfenv>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(fmuConnectorCore, 0);
}


// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- For its scope, OpenFOAM's messages at the level the run started with
//  (DebugSwitches level, default 2), whatever the solve that evaluates the
//  connector has set: the solves of the added-mass coupling under
//  sixDoFRigidBodyMotion are silent (messageStream::level 0, the motion's
//  report once for the converged one), and a connector's lines of a run,
//  such as its state restored at the first evaluation, are no part of that
//  report
class runMessageLevel
{
    //- The level set by the solve
    const int level_;

public:

    runMessageLevel()
    :
        level_(Foam::messageStream::level)
    {
        Foam::messageStream::level = Foam::debug::debugSwitch("level", 2);
    }

    ~runMessageLevel()
    {
        Foam::messageStream::level = level_;
    }
};

//- Masks the calling thread's x87 traps for good, its SSE traps left as
//  they are. OpenFOAM's FOAM_SIGFPE enables the traps of both units, and
//  OpenFOAM computes in double precision with SSE instructions (it has no
//  long double arithmetic): its x87 traps guard nothing of its own.
//  fmuImport::MaskFpTraps masks both units around the FMU calls of every
//  evaluation, and switching the x87 unit and back (fnstenv, fldenv) is
//  most of that; with the x87 traps masked it switches the SSE unit alone.
//  An FMU that computes in long double is still kept from trapping
void maskX87Traps()
{
#if defined(__x86_64__) && defined(__GNUC__)
    // the exception masks are the control word's bits 0-5, in the order
    // of the FE_ flags
    unsigned short control;
    __asm__ __volatile__("fnstcw %0" : "=m"(control));
    if ((control & FE_ALL_EXCEPT) != FE_ALL_EXCEPT)
    {
        control |= FE_ALL_EXCEPT;
        __asm__ __volatile__("fldcw %0" : : "m"(control));
    }
#endif
}

} // End anonymous namespace

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

std::string Foam::fmuConnectorCore::where() const
{
    return
        "FMU " + std::string(file_) + " of restraint "
      + std::string(restraintName_) + ": ";
}


void Foam::fmuConnectorCore::restorePending
(
    const kinematics& A,
    const kinematics& B
)
{
    if (restoreBytes_.empty())
    {
        return;
    }

    try
    {
        instance_->setState(instance_->deserializeState(restoreBytes_));
    }
    catch (const fmuImport::Error& err)
    {
        FatalErrorInFunction
            << "restraint " << restraintName_ << ": cannot restore the"
            << " state written at t = " << restoreTime_ << " in "
            << restoreSource_ << ": " << err.what() << exit(FatalError);
    }

    // The state carries the inputs it was written with
    setInputs(A, B);

    const runMessageLevel audible;

    Info<< "Connector " << restraintName_ << ": FMU state restored at t = "
        << restoreTime_ << " from " << restoreSource_ << endl;

    parameters_->checkRestored(*instance_, restoreSource_);

    restoreBytes_.clear();
}


void Foam::fmuConnectorCore::doStep(const scalar t, const scalar deltaT)
{
    typedef fmuImport::Instance::StepResult result;

    const result r = instance_->tryDoStep(stepStartTime_, deltaT);
    if (r == result::completed)
    {
        return;
    }

    // A connector cannot be stepped again with a shorter step here: both
    // are the end of the run, with the connector's reason
    const std::string reason(instance_->lastMessage());
    if (r == result::terminated)
    {
        FatalErrorInFunction
            << where().c_str() << "the connector asks to end the simulation"
            << " at t = " << t - deltaT << " (fmi2Terminated)"
            << (reason.empty() ? "" : ": ") << reason.c_str()
            << exit(FatalError);
    }
    FatalErrorInFunction
        << where().c_str() << "the connector refused the step from t = "
        << t - deltaT << " to " << t << " (fmi2Discard)"
        << (reason.empty() ? "" : ": ") << reason.c_str()
        << ". A shorter time step (maxDeltaT) may let it through"
        << exit(FatalError);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::fmuConnectorCore::fmuConnectorCore
(
    const Time& runTime,
    const word& restraintName,
    const dictionary& restraintDict,
    const restraintEntries& entries,
    const scalar startTime
)
:
    regIOobject(registryIO(runTime, restraintName)),
    file_(caseFile(entries.fmu, runTime)),
    restraintName_(restraintName),
    bodyNames_
    ({
        restraintDict.getOrDefault<word>("body", word::null),
        restraintDict.getOrDefault<word>("bodyB", "world")
    }),
    canRollback_(false),
    initialised_(false),
    stepStartTime_(startTime),
    stepEndTime_(startTime - 1),
    stepIndex_(-1),
    warnedNoRollback_(false),
    restoreTime_(startTime)
{
    file_.expand();
    maskX87Traps();

    // How the importer reports an FMU that crashes, hangs or exits in a
    // call in this process: in OpenFOAM's words, before the solver dies
    fmuImport::setReports
    ({
        "\n--> FOAM FATAL ERROR: ",
        " (the restraint's timeout entry)",
        1,
        1
    });

    try
    {
        if (!entries.run.sha256.empty())
        {
            const std::string actual(fmuImport::fileSha256(file_));
            if (actual != entries.run.sha256)
            {
                FatalIOErrorInFunction(restraintDict)
                    << "restraint " << restraintName_ << ": FMU " << file_
                    << " has SHA-256 " << actual.c_str() << ", but entry"
                    << " sha256 expects " << entries.run.sha256.c_str() << ": it is"
                    << " not the file the case was set up with. An FMU is"
                    << " native code run with the solver's rights: check"
                    << " where this file came from before changing sha256"
                    << exit(FatalIOError);
            }
        }

        fmuImport::FmuOptions options;
        options.isolation =
            entries.run.isolation == isolationMode::process
          ? fmuImport::Isolation::process
          : fmuImport::Isolation::none;
        options.timeout = entries.run.timeout;
        options.owner = "restraint " + restraintName_;
        fmu_.reset(new fmuImport::Fmu(file_, options));

        const fmuImport::ModelDescription& md = fmu_->modelDescription();
        canRollback_ = md.canGetAndSetFMUstate;

        if (!md.canHandleVariableCommunicationStepSize)
        {
            FatalIOErrorInFunction(restraintDict)
                << where().c_str() << "the FMU cannot handle a variable step size"
                << " (canHandleVariableCommunicationStepSize is false)"
                << exit(FatalIOError);
        }

        parameters_.reset
        (
            new fmuConnectorParameters
            (
                *fmu_, entries.parameters, restraintName_, file_, where()
            )
        );

        lookupVariables();

        parameters_->check(restraintDict, startTime);

        const word instanceName(restraintName_);
        instance_.reset
        (
            new fmuImport::Instance
            (
                *fmu_,
                instanceName,
                [instanceName]
                (
                    const std::string&,
                    int status,
                    const std::string& category,
                    const std::string& message
                )
                {
                    // Errors reach the user through the exception that
                    // follows them; warnings and information are logged
                    if (status == 1)
                    {
                        WarningInFunction
                            << "connector " << instanceName << " ("
                            << category.c_str() << "): " << message.c_str()
                            << endl;
                    }
                    else if (status == 0)
                    {
                        Info<< "connector " << instanceName << ": "
                            << message.c_str() << endl;
                    }
                }
            )
        );

        instance_->setupExperiment(startTime);
        instance_->enterInitializationMode();
        parameters_->set(*instance_);
        reportSetup(*instance_);
    }
    catch (const fmuImport::Error& err)
    {
        FatalIOErrorInFunction(restraintDict)
            << "restraint " << restraintName_ << ": " << err.what()
            << exit(FatalIOError);
    }

    // Registered once loaded. The first core of a name is the one found by
    // name: the registry keeps it when another of that name checks in (the
    // two restraints of a sixDoF connector share one core)
    checkIn();

    if (!canRollback_)
    {
        WarningInFunction
            << where().c_str() << "the FMU cannot get and set its state: it is"
            << " stepped once per time step, and repeated solves within a"
            << " step only update its inputs" << endl;
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::fmuConnectorCore::~fmuConnectorCore()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::fmuConnectorCore::evaluate
(
    const label timeIndex,
    const scalar t,
    const scalar deltaT,
    const kinematics& A,
    const kinematics& B
)
{
    // A new time step: the earlier one is complete, its row is published
    // for the file before the FMU is called (which may fail, crash or hang)
    if (output_.valid() && deltaT > 0 && timeIndex != stepIndex_)
    {
        output_->stepBegins(timeIndex);
    }

    // One switch of OpenFOAM's floating-point traps for all the calls
    const fmuImport::MaskFpTraps masked;

    try
    {
        const bool newStep = (deltaT > 0 && timeIndex != stepIndex_);
        const bool repeatedSolve =
            deltaT > 0 && !newStep && initialised_ && canRollback_;

        if (newStep && initialised_ && stepEndTime_ >= stepStartTime_)
        {
            // The previous step is complete: its end is the new start
            stepStartTime_ = stepEndTime_;
        }
        if (newStep && initialised_ && canRollback_)
        {
            instance_->getState(stepStartState_);
        }
        if (repeatedSolve)
        {
            // Back to the start of the step, before the inputs are set
            instance_->setState(stepStartState_);
        }

        setInputs(A, B);

        if (!initialised_)
        {
            instance_->exitInitializationMode();
            initialised_ = true;
            restorePending(A, B);
            {
                const runMessageLevel audible;
                reportStart(A, B);
            }
            if (newStep && canRollback_)
            {
                instance_->getState(stepStartState_);
            }
        }

        if (newStep)
        {
            stepIndex_ = timeIndex;
            stepEndTime_ = stepStartTime_ + deltaT;
            doStep(t, deltaT);
        }
        else if (repeatedSolve)
        {
            doStep(t, deltaT);
        }
        else if (deltaT > 0 && !warnedNoRollback_)
        {
            warnedNoRollback_ = true;
            const runMessageLevel audible;
            WarningInFunction
                << where().c_str() << "repeated solve at t = " << t
                << " without rollback: the FMU is not stepped again"
                << endl;
        }

        readOutputs();
    }
    catch (const fmuImport::Error& err)
    {
        FatalErrorInFunction
            << "restraint " << restraintName_ << " at t = " << t << ": "
            << err.what() << exit(FatalError);
    }

    if (output_.valid() && deltaT > 0)
    {
        output_->record(timeIndex, t);
    }
}


void Foam::fmuConnectorCore::checkBodyB
(
    const word& bodyB,
    const dictionary& dict
) const
{
    if (!declaresBodyB() && !bodyB.empty())
    {
        FatalIOErrorInFunction(dict)
            << "restraint " << restraintName_ << ": entry bodyB names "
            << bodyB << " but FMU " << file_
            << " connects one body to the fixed world (it declares no B."
            << " inputs)" << exit(FatalIOError);
    }
}


void Foam::fmuConnectorCore::record(fmuConnectorOutput* output)
{
    output_.reset(output);
}


bool Foam::fmuConnectorCore::canSerialize() const
{
    return fmu_->modelDescription().canSerializeFMUstate && canRollback_;
}


std::vector<char> Foam::fmuConnectorCore::serialize(scalar& time) const
{
    time = stepEndTime_ >= stepStartTime_ ? stepEndTime_ : stepStartTime_;

    try
    {
        return instance_->serializeState(instance_->getState());
    }
    catch (const fmuImport::Error& err)
    {
        FatalErrorInFunction
            << "restraint " << restraintName_ << ": " << err.what()
            << exit(FatalError);
    }
    return std::vector<char>();
}


void Foam::fmuConnectorCore::deserialize
(
    const std::vector<char>& bytes,
    const scalar time,
    const fileName& source
)
{
    if (initialised_)
    {
        FatalErrorInFunction
            << where().c_str() << "a restart state can only be restored"
            << " before the first evaluation" << abort(FatalError);
    }
    restoreBytes_ = bytes;
    restoreTime_ = time;
    restoreSource_ = source;
    stepStartTime_ = time;
    stepEndTime_ = time - 1;
}


// ************************************************************************* //
