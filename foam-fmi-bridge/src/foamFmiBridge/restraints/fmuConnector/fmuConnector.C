// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "fmuConnector.H"
#include "fmuConnectorOutput.H"
#include "rigidBodyModel.H"
#include "jointBody.H"
#include "Time.H"
#include "OStringStream.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
namespace restraints
{
    defineTypeNameAndDebug(fmuConnector, 0);

    addToRunTimeSelectionTable
    (
        restraint,
        fmuConnector,
        dictionary
    );
}
}
}


// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The model's bodies that a restraint can name: without the bodies made
//  for composite joints
Foam::wordList restrainableBodies(const Foam::RBD::rigidBodyModel& model)
{
    Foam::wordList names;
    for (Foam::label i = 1; i < model.nBodies(); ++i)
    {
        if (!Foam::isType<Foam::RBD::jointBody>(model.bodies()[i]))
        {
            names.append(model.name(i));
        }
    }
    return names;
}


//- The restraint dictionary, once its entry 'key' is known to name a body
//  of the model (the base class would fail without naming the restraint)
const Foam::dictionary& checkBody
(
    const Foam::word& restraintName,
    const Foam::dictionary& dict,
    const Foam::RBD::rigidBodyModel& model,
    const Foam::word& key
)
{
    using namespace Foam;

    const wordList bodies(restrainableBodies(model));
    const word body(dict.getOrDefault<word>(key, word::null));

    if (!dict.found(key, keyType::LITERAL) || !bodies.found(body))
    {
        FatalIOErrorInFunction(dict)
            << "restraint " << restraintName << ": entry " << key;
        if (dict.found(key, keyType::LITERAL))
        {
            FatalIOError
                << " names " << body << ", which is not a body of the model";
        }
        else
        {
            FatalIOError<< " is missing";
        }
        FatalIOError
            << "; the model's bodies are "
            << fmuConnectorCore::listed(bodies).c_str() << exit(FatalIOError);
    }

    return dict;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::fmuConnectorCore::kinematics
Foam::RBD::restraints::fmuConnector::bodyKinematics(const label bodyID) const
{
    // X0 maps global to body coordinates: x_body = E (x - r)
    const spatialTransform X0(model_.X0(bodyID));
    const spatialVector v(model_.v(bodyID, Zero));

    return fmuConnectorCore::kinematics{X0.r(), X0.E().T(), v.l(), v.w()};
}


Foam::fmuConnectorCore::massProperties
Foam::RBD::restraints::fmuConnector::massProperties(const label bodyID) const
{
    // A restraint names bodies that are not merged into others; bodies
    // merged into this one are in its inertia
    // (bodies() returns a copy of the list)
    const PtrList<rigidBody> bodies(model_.bodies());
    const rigidBody& body = bodies[model_.master(bodyID)];
    const vector c(body.c());
    const tensor J(body.Ic());

    return fmuConnectorCore::massProperties{body.m(), c, J};
}


void Foam::RBD::restraints::fmuConnector::load()
{
    const Time& runTime = model_.time();
    fmu_.reset
    (
        new fmuConnectorCore(runTime, name_, coeffs_, entries_, runTime.value())
    );
    fmu_->checkBodyB(bodyBName_, coeffs_);

    // The bodies where the run starts (the model is initialised before the
    // first time step), for the water velocity at a line's start shape
    fmu_->setStartKinematics
    (
        [this]()
        {
            return std::make_pair
            (
                bodyKinematics(bodyID_),
                bodyBName_.empty()
              ? fmuConnectorCore::kinematics::world()
              : bodyKinematics(bodyBID_)
            );
        }
    );

    // The mass inputs the FMU declares (A.m, A.c, A.J, B's when B is a
    // body); nothing is set for an FMU that declares none
    fmu_->setMassProperties
    (
        massProperties(bodyID_),
        massProperties(bodyBName_.empty() ? bodyID_ : bodyBID_),
        !bodyBName_.empty()
    );

    stateIO_.reset
    (
        new fmuConnectorState
        (
            name_,
            runTime,
            *fmu_,
            entries_.restart == fmuConnectorCore::restartMode::fresh,
            coeffs_
        )
    );

    const word bodyB(bodyBName_.empty() ? word("world") : bodyBName_);

    OStringStream description;
    description
        << "Connector " << name_ << ": FMU " << fmu_->file() << ", body A "
        << model_.name(bodyID_) << ", body B " << bodyB;

    fmu_->record
    (
        new fmuConnectorOutput
        (
            name_,
            runTime,
            *fmu_,
            description.str(),
            word::null,
            entries_.report ? wordList({model_.name(bodyID_), bodyB}) : wordList()
        )
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::restraints::fmuConnector::fmuConnector
(
    const word& name,
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    restraint(name, checkBody(name, dict, model, "body"), model),
    bodyBID_(-1),
    bodyBIndex_(-1)
{
    read(dict);

    if (Pstream::master())
    {
        load();
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::RBD::restraints::fmuConnector::~fmuConnector()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::RBD::restraints::fmuConnector::restrain
(
    scalarField& tau,
    Field<spatialVector>& fx,
    const rigidBodyModelState& state
) const
{
    if (!fmu_.valid())
    {
        return;
    }
    stateIO_->reportUnused();

    const fmuConnectorCore::kinematics A(bodyKinematics(bodyID_));
    const fmuConnectorCore::kinematics B
    (
        bodyBName_.empty()
      ? fmuConnectorCore::kinematics::world()
      : bodyKinematics(bodyBID_)
    );

    fmu_->evaluate(model_.time().timeIndex(), state.t(), state.deltaT(), A, B);

    // OpenFOAM's spatial forces carry the moment about the global origin
    const fmuConnectorCore::loads loadsA(fmu_->loadsA());
    fx[bodyIndex_] += spatialVector(loadsA.M + (A.r ^ loadsA.F), loadsA.F);

    if (!bodyBName_.empty())
    {
        const fmuConnectorCore::loads loadsB(fmu_->loadsB());
        fx[bodyBIndex_] +=
            spatialVector(loadsB.M + (B.r ^ loadsB.F), loadsB.F);
    }
}


bool Foam::RBD::restraints::fmuConnector::read
(
    const dictionary& dict
)
{
    restraint::read(dict);

    fmuConnectorCore::checkEntries(name_, coeffs_, "type");

    entries_.read(name_, coeffs_);

    bodyBName_ = coeffs_.lookupOrDefault<word>("bodyB", word::null);
    bodyBID_ = -1;
    bodyBIndex_ = -1;

    if (coeffs_.found("bodyB"))
    {
        checkBody(name_, coeffs_, model_, "bodyB");
        bodyBID_ = model_.bodyID(bodyBName_);
        bodyBIndex_ = model_.master(bodyBID_);
    }

    return true;
}


void Foam::RBD::restraints::fmuConnector::write
(
    Ostream& os
) const
{
    restraint::write(os);

    os.writeEntry("fmu", entries_.fmu);
    if (!bodyBName_.empty())
    {
        os.writeEntry("bodyB", bodyBName_);
    }
    entries_.write(os);
}


// ************************************************************************* //
