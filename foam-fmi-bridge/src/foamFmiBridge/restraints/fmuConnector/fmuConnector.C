/*---------------------------------------------------------------------------*\
  foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics
-------------------------------------------------------------------------------
License
    This file is part of foam-fmi-bridge, free software under the GNU General
    Public License version 3 or later (see LICENSE at the project's top).

\*---------------------------------------------------------------------------*/

#include "fmuConnector.H"
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


const Foam::Enum
<
    Foam::RBD::restraints::fmuConnector::restartMode
>
Foam::RBD::restraints::fmuConnector::restartModeNames
({
    { restartMode::exact, "exact" },
    { restartMode::fresh, "fresh" },
});


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
            << "; the model's bodies are " << bodies << exit(FatalIOError);
    }

    return dict;
}

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::connectorFmu::kinematics
Foam::RBD::restraints::fmuConnector::bodyKinematics(const label bodyID) const
{
    // X0 maps global to body coordinates: x_body = E (x - r)
    const spatialTransform X0(model_.X0(bodyID));
    const spatialVector v(model_.v(bodyID, Zero));

    return connectorFmu::kinematics{X0.r(), X0.E().T(), v.l(), v.w()};
}


Foam::connectorFmu::massProperties
Foam::RBD::restraints::fmuConnector::massProperties(const label bodyID) const
{
    // A restraint names bodies that are not merged into others; bodies
    // merged into this one are in its inertia
    // (bodies() returns a copy of the list)
    const PtrList<rigidBody> bodies(model_.bodies());
    const rigidBody& body = bodies[model_.master(bodyID)];
    const vector c(body.c());
    const tensor J(body.Ic());

    return connectorFmu::massProperties{body.m(), c, J};
}


void Foam::RBD::restraints::fmuConnector::load()
{
    const Time& runTime = model_.time();

    fileName file(fmuFile_);
    file.expand();
    if (!file.isAbsolute())
    {
        file = runTime.globalPath()/file;
    }

    fmu_.reset
    (
        new connectorFmu(file, name_, coeffs_, parameters_, runTime.value())
    );

    if (!fmu_->declaresBodyB() && !bodyBName_.empty())
    {
        FatalIOErrorInFunction(coeffs_)
            << "restraint " << name_ << ": entry bodyB names "
            << bodyBName_ << " but FMU " << file
            << " connects one body to the fixed world (it declares no B.r)"
            << exit(FatalIOError);
    }

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
            restart_ == restartMode::fresh,
            coeffs_
        )
    );

    if (!fmu_->canSerialize() && restart_ != restartMode::fresh)
    {
        WarningInFunction
            << "restraint " << name_ << ": FMU " << file << " cannot"
            << " serialize its state, so none is written for restarts; a"
            << " run restarted from a written time needs 'restart fresh;'"
            << " in this restraint" << endl;
    }

    OStringStream description;
    description
        << "Connector " << name_ << ": FMU " << file << ", body A "
        << model_.name(bodyID_) << ", body B "
        << (bodyBName_.empty() ? word("world") : bodyBName_);

    output_.reset
    (
        new fmuConnectorOutput(name_, runTime, *fmu_, description.str())
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
    bodyBIndex_(-1),
    restart_(restartMode::exact)
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

    const connectorFmu::kinematics A(bodyKinematics(bodyID_));
    const connectorFmu::kinematics B
    (
        bodyBName_.empty()
      ? connectorFmu::kinematics::world()
      : bodyKinematics(bodyBID_)
    );

    fmu_->evaluate(state.t(), state.deltaT(), A, B);

    if (state.deltaT() > 0)
    {
        output_->record(state.t());
    }

    // OpenFOAM's spatial forces carry the moment about the global origin
    const connectorFmu::loads loadsA(fmu_->loadsA());
    fx[bodyIndex_] += spatialVector(loadsA.M + (A.r ^ loadsA.F), loadsA.F);

    const connectorFmu::loads loadsB(fmu_->loadsB());
    if (!bodyBName_.empty())
    {
        fx[bodyBIndex_] +=
            spatialVector(loadsB.M + (B.r ^ loadsB.F), loadsB.F);
    }

    if (report_)
    {
        Info<< "Restraint " << name_ << ": t = " << state.t();
        for (const word diagnostic : {"length", "tension"})
        {
            if (fmu_->outputNames().found(diagnostic))
            {
                Info<< ' ' << diagnostic << ' '
                    << fmu_->output(diagnostic, 0);
            }
        }
        Info<< " force on " << model_.name(bodyID_) << ' ' << loadsA.F
            << " moment " << loadsA.M
            << " force on "
            << (bodyBName_.empty() ? word("world") : bodyBName_) << ' '
            << loadsB.F << " moment " << loadsB.M << endl;
    }
}


bool Foam::RBD::restraints::fmuConnector::read
(
    const dictionary& dict
)
{
    restraint::read(dict);

    // A misspelt keyword would silently leave an FMU default in place or
    // connect the body to the world instead of bodyB
    static const wordList keywords
    ({
        "type", "body", "bodyB", "fmu", "parameters", "report", "restart"
    });
    for (const entry& e : coeffs_)
    {
        if (!keywords.found(e.keyword()))
        {
            FatalIOErrorInFunction(coeffs_)
                << "restraint " << name_ << ": unknown entry '"
                << e.keyword() << "'; the entries of an fmuConnector"
                << " restraint are " << keywords << exit(FatalIOError);
        }
    }

    coeffs_.readEntry("fmu", fmuFile_);

    if (coeffs_.found("parameters") && !coeffs_.isDict("parameters"))
    {
        FatalIOErrorInFunction(coeffs_)
            << "restraint " << name_ << ": entry 'parameters' must be a"
            << " dictionary of the FMU's parameters, e.g."
            << " parameters { stiffness 100; }" << exit(FatalIOError);
    }
    parameters_ = coeffs_.subOrEmptyDict("parameters");
    report_ = coeffs_.lookupOrDefault<Switch>("report", false);
    restart_ =
        restartModeNames.getOrDefault("restart", coeffs_, restartMode::exact);

    bodyBName_ = coeffs_.lookupOrDefault<word>("bodyB", word::null);
    bodyBID_ = -1;
    bodyBIndex_ = -1;

    if (coeffs_.found("bodyB"))
    {
        checkBody(name_, coeffs_, model_, "bodyB");
        bodyBID_ = model_.bodyID(bodyBName_);
        bodyBIndex_ = model_.master(bodyBID_);

        if (bodyBID_ == bodyID_)
        {
            FatalIOErrorInFunction(coeffs_)
                << "restraint " << name_ << ": body and bodyB are the same"
                << " body " << bodyBName_ << exit(FatalIOError);
        }
    }

    return true;
}


void Foam::RBD::restraints::fmuConnector::write
(
    Ostream& os
) const
{
    restraint::write(os);

    os.writeEntry("fmu", fmuFile_);
    if (!bodyBName_.empty())
    {
        os.writeEntry("bodyB", bodyBName_);
    }
    os.writeEntry("report", report_);
    os.writeEntry("restart", restartModeNames[restart_]);
    os.beginBlock("parameters");
    parameters_.write(os, false);
    os.endBlock();
}


// ************************************************************************* //
