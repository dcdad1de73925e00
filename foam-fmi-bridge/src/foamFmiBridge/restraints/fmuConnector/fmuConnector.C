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
#include "OSspecific.H"
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


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::connectorFmu::kinematics
Foam::RBD::restraints::fmuConnector::bodyKinematics(const label bodyID) const
{
    // X0 maps global to body coordinates: x_body = E (x - r)
    const spatialTransform X0(model_.X0(bodyID));
    const spatialVector v(model_.v(bodyID, Zero));

    return connectorFmu::kinematics{X0.r(), X0.E().T(), v.l(), v.w()};
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

    stateIO_.reset(new fmuConnectorState(name_, runTime, *fmu_));

    const fileName dir
    (
        runTime.globalPath()/"postProcessing"/"fmuConnectors"
       /runTime.timeName()
    );
    mkDir(dir);
    outputFile_.reset(new OFstream(dir/(name_ + ".dat")));

    OFstream& os = *outputFile_;
    os  << "# Connector " << name_ << ": FMU " << file << ", body A "
        << model_.name(bodyID_) << ", body B "
        << (bodyBName_.empty() ? word("world") : bodyBName_) << nl
        << "# Time";
    for (const word& output : fmu_->outputNames())
    {
        os  << ' ' << output;
    }
    os  << endl;
}


void Foam::RBD::restraints::fmuConnector::writeOutputs() const
{
    if (outputFile_.valid() && pendingTime_ > -GREAT)
    {
        OFstream& os = *outputFile_;
        os  << pendingTime_;
        for (const scalar value : fmu_->outputs())
        {
            os  << ' ' << value;
        }
        os  << endl;
        pendingTime_ = -GREAT;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::restraints::fmuConnector::fmuConnector
(
    const word& name,
    const dictionary& dict,
    const rigidBodyModel& model
)
:
    restraint(name, dict, model),
    bodyBID_(-1),
    bodyBIndex_(-1),
    pendingTime_(-GREAT)
{
    read(dict);

    if (Pstream::master())
    {
        load();
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::RBD::restraints::fmuConnector::~fmuConnector()
{
    writeOutputs();
}


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

    // A new time step: the outputs of the previous one are final
    if (state.deltaT() > 0 && state.t() != pendingTime_)
    {
        writeOutputs();
    }

    fmu_->evaluate(state.t(), state.deltaT(), A, B);

    if (state.deltaT() > 0)
    {
        pendingTime_ = state.t();
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

    coeffs_.readEntry("fmu", fmuFile_);
    parameters_ = coeffs_.subOrEmptyDict("parameters");
    report_ = coeffs_.lookupOrDefault<Switch>("report", false);

    bodyBName_ = coeffs_.lookupOrDefault<word>("bodyB", word::null);
    bodyBID_ = -1;
    bodyBIndex_ = -1;

    if (!bodyBName_.empty())
    {
        // The model's bodies, without those made for composite joints
        wordList bodyNames;
        for (label i = 1; i < model_.nBodies(); ++i)
        {
            if (!isType<jointBody>(model_.bodies()[i]))
            {
                bodyNames.append(model_.name(i));
            }
        }
        if (!bodyNames.found(bodyBName_))
        {
            FatalIOErrorInFunction(coeffs_)
                << "restraint " << name_ << ": bodyB " << bodyBName_
                << " is not a body of the model; its bodies are "
                << bodyNames << exit(FatalIOError);
        }
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
    os.beginBlock("parameters");
    parameters_.write(os, false);
    os.endBlock();
}


// ************************************************************************* //
