// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "sixDoFConnector.H"
#include "fmuConnectorOutput.H"
#include "Time.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(sixDoFConnector, 0);
}


// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The entries of a dictionary as text, without its name
Foam::string entriesOf(const Foam::dictionary& dict)
{
    Foam::OStringStream os;
    dict.write(os, false);
    return os.str();
}


} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

const Foam::word& Foam::sixDoFConnector::bodyName(const label side) const
{
    return side == 0 ? bodyA_ : bodyB_;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::sixDoFConnector::sixDoFConnector
(
    const word& name,
    const dictionary& dict,
    const Time& runTime,
    const word& startTimeName,
    const scalar startTime
)
:
    regIOobject
    (
        IOobject
        (
            "sixDoFConnector." + name,
            runTime.timeName(),
            runTime,
            IOobject::NO_READ,
            IOobject::NO_WRITE
        )
    ),
    name_(name),
    dict_(dict),
    bodyA_(dict.get<word>("body")),
    bodyB_(dict.getOrDefault<word>("bodyB", word::null)),
    report_(dict.getOrDefault<Switch>("report", false)),
    motion_{nullptr, nullptr},
    start_{fmuConnectorCore::kinematics::world(), fmuConnectorCore::kinematics::world()},
    mass_{},
    massSet_(false),
    registered_{false, false},
    pending_(-1),
    stepIndex_(runTime.startTimeIndex()),
    stepTime_(startTimeName.empty() ? runTime.value() : startTime),
    evaluated_{true, true},
    compared_(false)
{
    if (!Pstream::master())
    {
        return;
    }

    fmuConnectorCore::restraintEntries entries;
    entries.read(name_, dict_);

    fmu_.reset
    (
        new fmuConnectorCore(runTime, name_, dict_, entries, stepTime_)
    );
    fmu_->checkBodyB(bodyB_, dict_);

    // The bodies where they start (registerSide), for the water velocity
    // at a line's start shape
    fmu_->setStartKinematics
    (
        [this]()
        {
            return std::make_pair
            (
                start_[0],
                bodyB_.empty() ? fmuConnectorCore::kinematics::world() : start_[1]
            );
        }
    );

    const bool fresh =
        entries.restart == fmuConnectorCore::restartMode::fresh;

    stateIO_.reset
    (
        new fmuConnectorState
        (
            name_, runTime, *fmu_, fresh, dict_, startTimeName
        )
    );

    OStringStream description;
    description
        << "Connector " << name_ << ": FMU " << fmu_->file() << ", body A "
        << bodyA_ << ", body B "
        << (bodyB_.empty() ? word("world") : bodyB_)
        << " (sixDoFRigidBodyMotion)";

    fmu_->record
    (
        new fmuConnectorOutput
        (
            name_, runTime, *fmu_, description.str(), startTimeName
        )
    );
}


std::shared_ptr<Foam::sixDoFConnector> Foam::sixDoFConnector::New
(
    const word& name,
    const dictionary& dict,
    const Time& runTime,
    const word& startTimeName,
    const scalar startTime
)
{
    const word key("sixDoFConnector." + name);

    sixDoFConnector* found =
        runTime.getObjectPtr<sixDoFConnector>(key);

    if (found)
    {
        if (entriesOf(found->dict_) != entriesOf(dict))
        {
            FatalIOErrorInFunction(dict)
                << "restraint " << name << ": restraints of one name in"
                << " two motions are one connector between two bodies (its"
                << " state file and output are named after it), so they"
                << " must be the same connector, but they differ; give"
                << " separate connectors separate names. First:" << nl
                << entriesOf(found->dict_).c_str() << nl
                << "this one:" << nl << entriesOf(dict).c_str()
                << exit(FatalIOError);
        }
        return found->shared_from_this();
    }

    return std::make_shared<sixDoFConnector>
    (
        name, dict, runTime, startTimeName, startTime
    );
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::sixDoFConnector::~sixDoFConnector()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::fmuConnectorCore::kinematics Foam::sixDoFConnector::kinematics
(
    const sixDoFRigidBodyMotion& motion
)
{
    // The reference point is the centre of rotation, which v() is the
    // velocity of and about which sixDoFRigidBodyMotion takes the moments;
    // the body frame is that of orientation() (Q, body to global)
    return fmuConnectorCore::kinematics
    {
        motion.centreOfRotation(),
        motion.orientation(),
        motion.v(),
        motion.omega()
    };
}


Foam::fmuConnectorCore::massProperties Foam::sixDoFConnector::massProperties
(
    const sixDoFRigidBodyMotion& motion
)
{
    const scalar m = motion.mass();
    const vector c
    (
        motion.orientation().T()
      & (motion.centreOfMass() - motion.centreOfRotation())
    );
    const tensor J
    (
        (motion.momentOfInertia() & tensor::I) - m*(magSqr(c)*tensor::I - sqr(c))
    );
    return fmuConnectorCore::massProperties{m, c, J};
}


void Foam::sixDoFConnector::registerSide
(
    const label side,
    const fmuConnectorCore::kinematics& start,
    const fmuConnectorCore::massProperties& mass,
    const dictionary& dict
)
{
    if (registered_[side])
    {
        FatalIOErrorInFunction(dict)
            << "restraint " << name_ << ": a second restraint of this name"
            << " in the motion of body " << bodyName(side) << "; the"
            << " restraint belongs once in the motion of " << bodyA_
            << (bodyB_.empty() ? "" : " and once in that of ")
            << bodyB_ << exit(FatalIOError);
    }
    registered_[side] = true;
    start_[side] = start;
    mass_[side] = mass;
}


Foam::fmuConnectorCore::loads Foam::sixDoFConnector::restrain
(
    const label side,
    const sixDoFRigidBodyMotion& motion
)
{
    if (!fmu_.valid())
    {
        return fmuConnectorCore::loads{Zero, Zero};
    }
    stateIO_->reportUnused();

    const Time& runTime = motion.time();
    const scalar t = runTime.value();
    const bool twoBody = !bodyB_.empty();
    const label other = 1 - side;

    if (runTime.timeIndex() != stepIndex_)
    {
        // A new time step: in the previous one both bodies must have taken
        // their loads, or one of them has no restraint of this name
        if (twoBody && !(evaluated_[0] && evaluated_[1]))
        {
            const label missing = evaluated_[0] ? 1 : 0;
            FatalErrorInFunction
                << "restraint " << name_ << ": the motion of body "
                << bodyName(missing) << " did not evaluate it in the time"
                << " step ending at t = " << stepTime_ << ", so the"
                << " connector's loads on " << bodyName(missing) << " were"
                << " lost. The restraint belongs once in the motion of each"
                << " body (" << bodyA_ << ", " << bodyB_ << ")"
                << exit(FatalError);
        }
        stepIndex_ = runTime.timeIndex();
        stepTime_ = t;
        evaluated_[0] = evaluated_[1] = false;
        pending_ = -1;
    }

    motion_[side] = &motion;
    evaluated_[side] = true;

    if (pending_ == side)
    {
        // The other body's restraint evaluated the FMU in this solve round
        pending_ = -1;
    }
    else
    {
        const fmuConnectorCore::kinematics own(kinematics(motion));
        fmuConnectorCore::kinematics otherKin(fmuConnectorCore::kinematics::world());
        if (twoBody)
        {
            otherKin =
                motion_[other] ? kinematics(*motion_[other]) : start_[other];
        }

        if (!massSet_)
        {
            // Constant: given once, set with the inputs of every evaluation
            mass_[side] = massProperties(motion);
            fmu_->setMassProperties(mass_[0], mass_[1], twoBody);
            massSet_ = true;
        }

        // sixDoFRigidBodyMotion has named the restraint when it reports:
        // the first evaluation's start report goes on lines of its own, and
        // the restraint is named again for the report line
        const bool starting = motion.report() && !fmu_->initialised();
        if (starting)
        {
            Info<< "its first evaluation" << endl;
        }

        if (side == 0)
        {
            fmu_->evaluate
            (
                runTime.timeIndex(), t, runTime.deltaTValue(), own, otherKin
            );
        }
        else
        {
            fmu_->evaluate
            (
                runTime.timeIndex(), t, runTime.deltaTValue(), otherKin, own
            );
        }

        pending_ = twoBody ? other : -1;

        if (starting)
        {
            Info<< "Restraint " << name_ << ": ";
        }
    }

    const fmuConnectorCore::loads loads
    (
        side == 0 ? fmu_->loadsA() : fmu_->loadsB()
    );

    // A motion that reports has named the restraint and waits for its line,
    // as OpenFOAM's restraints give it
    if (report_ || motion.report())
    {
        // sixDoFRigidBodyMotion names the restraint first when it reports
        if (!motion.report())
        {
            Info<< "Restraint " << name_ << ": ";
        }
        Info<< "t = " << t;
        fmu_->writeDiagnostics(Info);
        Info<< " force on " << bodyName(side) << ' ' << loads.F
            << " moment " << loads.M << endl;
    }

    return loads;
}


// ************************************************************************* //
