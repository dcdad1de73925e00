// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
/*---------------------------------------------------------------------------*\
    The construction, mapping and output follow OpenFOAM v1912's
    sixDoFRigidBodyDisplacementPointPatchVectorField
    (src/sixDoFRigidBodyMotion, GPL v3, OpenCFD Ltd. and the OpenFOAM
    Foundation); updateCoeffs() adds the added-mass coupling.
\*---------------------------------------------------------------------------*/

#include "addedMassSixDoFRigidBodyDisplacementPointPatchVectorField.H"
#include "pointPatchFields.H"
#include "addToRunTimeSelectionTable.H"
#include "Time.H"
#include "fvMesh.H"
#include "volFields.H"
#include "uniformDimensionedFields.H"
#include "restartFiles.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- OpenFOAM v1912's entries of sixDoFRigidBodyDisplacement: the
//  condition's (type, value, patchType, initialPoints, rho, rhoInf, g),
//  sixDoFRigidBodyMotion's and its state's, as it reads and writes them
const Foam::wordList openFoamEntries
({
    "type", "value", "patchType", "initialPoints", "rho", "rhoInf", "g",
    "mass", "centreOfMass", "initialCentreOfMass", "momentOfInertia",
    "orientation", "initialOrientation", "report", "solver", "restraints",
    "constraints", "accelerationRelaxation", "accelerationDamping",
    "centreOfRotation", "velocity", "acceleration", "angularMomentum",
    "torque"
});

//- The added mass as the condition writes it (and the body's means:
//  sixDoFCouplingBody::meanEntries)
const Foam::wordList stateEntries({"addedMass", "addedMassBody"});

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

std::shared_ptr<Foam::addedMassCoupling>
Foam::addedMassSixDoFRigidBodyDisplacementPointPatchVectorField::newCoupling
(
    const dictionary& dict
) const
{
    auto coupling = std::make_shared<addedMassCoupling>
    (
        typeName,
        refCast<const fvMesh>(this->internalField().mesh()()),
        "rigidBodyCoupling." + this->patch().name()
    );
    wordList written(stateEntries);
    written.append(sixDoFCouplingBody::meanEntries);
    coupling->read(dict, "sixDoFRigidBodyDisplacement", openFoamEntries,
        written);
    coupling->readState(dict, 1);

    coupling->setPatches
    (
        List<labelHashSet>(1, labelHashSet({this->patch().index()})),
        rhoName_,
        rhoInf_
    );
    return coupling;
}


void Foam::addedMassSixDoFRigidBodyDisplacementPointPatchVectorField::
checkRestart
(
    const dictionary& dict
) const
{
    const Time& t = db().time();
    if (!restartFiles::restarted(t, t.timeName()))
    {
        return;
    }

    wordList entries(sixDoFCouplingBody::motionStateEntries);
    if (coupling_->addedMass())
    {
        entries.append("addedMass");
    }

    for (const word& key : entries)
    {
        if (!dict.found(key, keyType::LITERAL))
        {
            FatalIOErrorInFunction(dict)
                << typeName << ": the restart from t = " << t.timeName()
                << " reads the field file "
                << this->internalField().objectPath() << ", whose entry of"
                << " patch '" << this->patch().name() << "' lacks '" << key
                << "': expected ";
            if (key == "addedMass")
            {
                FatalIOError
                    << "the added mass in use, a 6 x 6 matrix, which this"
                    << " condition writes with the coupling's addedMass on"
                    << " (a time written by OpenFOAM's"
                    << " sixDoFRigidBodyDisplacement has none)";
            }
            else
            {
                const wordList& state = sixDoFCouplingBody::motionStateEntries;
                FatalIOError<< "the motion's state (" << state[0];
                for (label i = 1; i < state.size(); ++i)
                {
                    FatalIOError<< ", " << state[i];
                }
                FatalIOError<< "), which this condition writes";
            }
            FatalIOError
                << ". Restart from a time written with the added-mass"
                << " coupling, or start the run anew from its initial time"
                << exit(FatalIOError);
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::addedMassSixDoFRigidBodyDisplacementPointPatchVectorField::
addedMassSixDoFRigidBodyDisplacementPointPatchVectorField
(
    const pointPatch& p,
    const DimensionedField<vector, pointMesh>& iF
)
:
    fixedValuePointPatchField<vector>(p, iF),
    motion_(db().time()),
    initialPoints_(p.localPoints()),
    rhoInf_(1.0),
    rhoName_("rho"),
    lookupGravity_(-1),
    g_(Zero),
    curTimeIndex_(-1),
    body_(motion_, p.name()),
    coupling_(newCoupling(dictionary()))
{}


Foam::addedMassSixDoFRigidBodyDisplacementPointPatchVectorField::
addedMassSixDoFRigidBodyDisplacementPointPatchVectorField
(
    const pointPatch& p,
    const DimensionedField<vector, pointMesh>& iF,
    const dictionary& dict
)
:
    fixedValuePointPatchField<vector>(p, iF, dict, false),
    motion_(dict, dict, db().time()),
    initialPoints_(p.localPoints()),
    rhoInf_(1.0),
    rhoName_(dict.lookupOrDefault<word>("rho", "rho")),
    lookupGravity_(-1),
    g_(Zero),
    curTimeIndex_(-1),
    couplingDict_(dict.subOrEmptyDict("coupling")),
    body_(motion_, p.name()),
    coupling_(nullptr)
{
    if (rhoName_ == "rhoInf")
    {
        dict.readEntry("rhoInf", rhoInf_);
    }

    if (dict.readIfPresent("g", g_))
    {
        lookupGravity_ = -2;
    }

    if (dict.found("initialPoints"))
    {
        initialPoints_ = vectorField("initialPoints", dict, p.size());
    }

    coupling_ = newCoupling(dict);
    checkRestart(dict);
    body_.readRestartState(dict, this->internalField().objectPath());

    // Without a value (fixedValuePointPatchField read it when given: a
    // second read of a written, nonuniform value fails), the displacement
    // of the motion's state; OpenFOAM's condition solves the motion for it,
    // which needs the fluid loads
    if (!dict.found("value"))
    {
        Field<vector>::operator=
        (
            motion_.transform(initialPoints_) - initialPoints_
        );
    }
}


Foam::addedMassSixDoFRigidBodyDisplacementPointPatchVectorField::
addedMassSixDoFRigidBodyDisplacementPointPatchVectorField
(
    const addedMassSixDoFRigidBodyDisplacementPointPatchVectorField& ptf,
    const pointPatch& p,
    const DimensionedField<vector, pointMesh>& iF,
    const pointPatchFieldMapper& mapper
)
:
    fixedValuePointPatchField<vector>(ptf, p, iF, mapper),
    motion_(ptf.motion_),
    initialPoints_(ptf.initialPoints_, mapper),
    rhoInf_(ptf.rhoInf_),
    rhoName_(ptf.rhoName_),
    lookupGravity_(ptf.lookupGravity_),
    g_(ptf.g_),
    curTimeIndex_(-1),
    couplingDict_(ptf.couplingDict_),
    body_(motion_, p.name(), ptf.body_),
    coupling_(ptf.coupling_)
{}


Foam::addedMassSixDoFRigidBodyDisplacementPointPatchVectorField::
addedMassSixDoFRigidBodyDisplacementPointPatchVectorField
(
    const addedMassSixDoFRigidBodyDisplacementPointPatchVectorField& ptf,
    const DimensionedField<vector, pointMesh>& iF
)
:
    fixedValuePointPatchField<vector>(ptf, iF),
    motion_(ptf.motion_),
    initialPoints_(ptf.initialPoints_),
    rhoInf_(ptf.rhoInf_),
    rhoName_(ptf.rhoName_),
    lookupGravity_(ptf.lookupGravity_),
    g_(ptf.g_),
    curTimeIndex_(-1),
    couplingDict_(ptf.couplingDict_),
    body_(motion_, ptf.patch().name(), ptf.body_),
    coupling_(ptf.coupling_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::addedMassSixDoFRigidBodyDisplacementPointPatchVectorField::autoMap
(
    const pointPatchFieldMapper& m
)
{
    fixedValuePointPatchField<vector>::autoMap(m);

    initialPoints_.autoMap(m);
}


void Foam::addedMassSixDoFRigidBodyDisplacementPointPatchVectorField::rmap
(
    const pointPatchField<vector>& ptf,
    const labelList& addr
)
{
    const addedMassSixDoFRigidBodyDisplacementPointPatchVectorField& sDoFptf =
        refCast
        <
            const addedMassSixDoFRigidBodyDisplacementPointPatchVectorField
        >(ptf);

    fixedValuePointPatchField<vector>::rmap(sDoFptf, addr);

    initialPoints_.rmap(sDoFptf.initialPoints_, addr);
}


void
Foam::addedMassSixDoFRigidBodyDisplacementPointPatchVectorField::updateCoeffs()
{
    if (this->updated())
    {
        return;
    }

    const Time& t = db().time();

    if (lookupGravity_ < 0)
    {
        if (t.foundObject<uniformDimensionedVectorField>("g"))
        {
            if (lookupGravity_ == -2)
            {
                FatalErrorInFunction
                    << "Specifying the value of g in this boundary condition "
                    << "when g is available from the database is considered "
                    << "a fatal error to avoid the possibility of inconsistency"
                    << exit(FatalError);
            }
            lookupGravity_ = 1;
        }
        else
        {
            lookupGravity_ = 0;
        }
    }

    // Store the motion state at the beginning of the time-step
    bool firstIter = false;
    if (curTimeIndex_ != t.timeIndex())
    {
        body_.newTime();
        coupling_->newTime();
        curTimeIndex_ = t.timeIndex();
        firstIter = true;
    }

    if (lookupGravity_ == 1)
    {
        g_ = t.lookupObject<uniformDimensionedVectorField>("g").value();
    }

    body_.setFluidLoads
    (
        db(),
        List<wordRe>(1, wordRe(this->patch().name())),
        rhoName_,
        rhoInf_,
        g_,
        firstIter
    );
    coupling_->correct(body_, 1);
    if (coupling_->addedMass())
    {
        body_.reportSolve();
    }

    Field<vector>::operator=
    (
        motion_.transform(initialPoints_) - initialPoints_
    );

    fixedValuePointPatchField<vector>::updateCoeffs();
}


void Foam::addedMassSixDoFRigidBodyDisplacementPointPatchVectorField::write
(
    Ostream& os
) const
{
    pointPatchField<vector>::write(os);

    os.writeEntry("rho", rhoName_);

    if (rhoName_ == "rhoInf")
    {
        os.writeEntry("rhoInf", rhoInf_);
    }

    if (lookupGravity_ == 0 || lookupGravity_ == -2)
    {
        os.writeEntry("g", g_);
    }

    motion_.write(os);

    if (couplingDict_.size())
    {
        couplingDict_.writeEntry("coupling", os);
    }
    coupling_->writeState(os);
    dictionary means;
    body_.writeState(means);
    for (const entry& e : means)
    {
        e.write(os);
    }

    initialPoints_.writeEntry("initialPoints", os);

    writeEntry("value", os);
}


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace Foam
{
    makePointPatchTypeField
    (
        pointPatchVectorField,
        addedMassSixDoFRigidBodyDisplacementPointPatchVectorField
    );
}


// ************************************************************************* //
