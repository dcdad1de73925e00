// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
/*---------------------------------------------------------------------------*\
    The construction, mesh morphing and state I/O follow OpenFOAM v1912's
    rigidBodyMeshMotion (src/rigidBodyMeshMotion, GPL v3, OpenCFD Ltd. and
    the OpenFOAM Foundation); solve() adds the added-mass coupling.
\*---------------------------------------------------------------------------*/

#include "addedMassRigidBodyMeshMotion.H"
#include "addToRunTimeSelectionTable.H"
#include "polyMesh.H"
#include "bodyMorphing.H"
#include "unregisteredIO.H"
#include "uniformDimensionedFields.H"
#include "forces.H"
#include "OneConstant.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(addedMassRigidBodyMeshMotion, 0);

    addToRunTimeSelectionTable
    (
        motionSolver,
        addedMassRigidBodyMeshMotion,
        dictionary
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::addedMassRigidBodyMeshMotion::bodyMesh::bodyMesh
(
    const polyMesh& mesh,
    const word& name,
    const label bodyID,
    const dictionary& dict
)
:
    name_(name),
    bodyID_(bodyID),
    patches_(dict.lookup("patches")),
    patchSet_(mesh.boundaryMesh().patchSet(patches_)),
    di_(dict.get<scalar>("innerDistance")),
    do_(dict.get<scalar>("outerDistance")),
    distanceScale_(bodyMorphing::readDistanceScale(dict)),
    weight_
    (
        unregisteredIO(mesh, name_ + ".motionScale"),
        pointMesh::New(mesh),
        dimensionedScalar(dimless, Zero)
    )
{}


Foam::addedMassRigidBodyMeshMotion::addedMassRigidBodyMeshMotion
(
    const polyMesh& mesh,
    const IOdictionary& dict
)
:
    addedMassMotionSolver
    (
        mesh, dict, typeName, "rigidBodyMotionState", "rigid-body state"
    ),
    model_
    (
        mesh.time(),
        restartCoeffs
        (
            {"q", "qDot", "qDdot", "t", "deltaT"},
            "the rigid-body state of addedMassRigidBodyMotion"
        ),
        initialState()
    ),
    test_(coeffDict().lookupOrDefault("test", false)),
    rhoInf_(1.0),
    rhoName_(coeffDict().lookupOrDefault<word>("rho", "rho")),
    ramp_(nullptr),
    curTimeIndex_(-1),
    start_(model_.state())
{
    readCoupling();

    if (rhoName_ == "rhoInf")
    {
        // From the coefficients, where rho is; else, as OpenFOAM's
        // rigidBodyMotion reads it, from the top level of dynamicMeshDict
        if (!coeffDict().readIfPresent("rhoInf", rhoInf_))
        {
            readEntry("rhoInf", rhoInf_);
        }
    }

    if (coeffDict().found("ramp"))
    {
        ramp_ = Function1<scalar>::New("ramp", coeffDict());
    }
    else
    {
        ramp_.reset(new Function1Types::OneConstant<scalar>("ramp"));
    }

    const dictionary& bodiesDict = coeffDict().subDict("bodies");

    for (const entry& dEntry : bodiesDict)
    {
        const keyType& bodyName = dEntry.keyword();
        const dictionary& bodyDict = dEntry.dict();

        if (bodyDict.found("patches"))
        {
            const label bodyID = model_.bodyID(bodyName);

            if (bodyID == -1)
            {
                FatalErrorInFunction
                    << "Body " << bodyName
                    << " has been merged with another body"
                       " and cannot be assigned a set of patches"
                    << exit(FatalError);
            }

            bodyMeshes_.append
            (
                new bodyMesh
                (
                    mesh,
                    bodyName,
                    bodyID,
                    bodyDict
                )
            );
        }
    }

    readCouplingState(bodyMeshes_.size());

    List<labelHashSet> bodyPatches(bodyMeshes_.size());
    forAll(bodyMeshes_, bi)
    {
        bodyPatches[bi] = bodyMeshes_[bi].patchSet_;
    }
    coupling_.setPatches(bodyPatches, rhoName_, rhoInf_);

    // Calculate scaling factor everywhere for each meshed body
    forAll(bodyMeshes_, bi)
    {
        bodyMorphing::weights
        (
            bodyMeshes_[bi].weight_,
            bodyMeshes_[bi].patchSet_,
            points0(),
            bodyMeshes_[bi].di_,
            bodyMeshes_[bi].do_,
            bodyMeshes_[bi].distanceScale_
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::addedMassRigidBodyMeshMotion::solve()
{
    const Time& t = mesh().time();

    checkPoints();

    // Store the motion state at the beginning of the time-step
    if (curTimeIndex_ != this->db().time().timeIndex())
    {
        model_.newTime();
        curTimeIndex_ = this->db().time().timeIndex();
        coupling_.newTime();
    }

    const scalar ramp = ramp_->value(t.value());

    if (t.foundObject<uniformDimensionedVectorField>("g"))
    {
        model_.g() =
            ramp*t.lookupObject<uniformDimensionedVectorField>("g").value();
    }

    if (test_)
    {
        const label nIter(coeffDict().get<label>("nIter"));

        for (label i=0; i<nIter; i++)
        {
            model_.solve
            (
                t.value(),
                t.deltaTValue(),
                scalarField(model_.nDoF(), Zero),
                Field<spatialVector>(model_.nBodies(), Zero)
            );
        }
    }
    else
    {
        const label nIter(coeffDict().lookupOrDefault("nIter", 1));

        couplingBodies bodies(*this);

        for (label i=0; i<nIter; i++)
        {
            // The accelerations the fluid of the last corrector moved with
            model_.forwardDynamicsCorrection(model_.state());
            fx_ = fluidLoads(ramp);
            coupling_.correct(bodies, ramp);
        }
    }

    if (Pstream::master() && model_.report())
    {
        forAll(bodyMeshes_, bi)
        {
            model_.status(bodyMeshes_[bi].bodyID_);
        }
    }

    // Update the displacements
    if (bodyMeshes_.size() == 1)
    {
        pointDisplacement_.primitiveFieldRef() = model_.transformPoints
        (
            bodyMeshes_[0].bodyID_,
            bodyMeshes_[0].weight_,
            points0()
        ) - points0();
    }
    else
    {
        labelList bodyIDs(bodyMeshes_.size());
        List<const scalarField*> weights(bodyMeshes_.size());
        forAll(bodyIDs, bi)
        {
            bodyIDs[bi] = bodyMeshes_[bi].bodyID_;
            weights[bi] = &bodyMeshes_[bi].weight_;
        }

        pointDisplacement_.primitiveFieldRef() =
            model_.transformPoints(bodyIDs, weights, points0()) - points0();
    }

    // Displacement has changed. Update boundary conditions
    constrainDisplacement();
}


void Foam::addedMassRigidBodyMeshMotion::readMotion()
{
    model_.read(coeffDict());
}


void Foam::addedMassRigidBodyMeshMotion::writeMotionState
(
    dictionary& state
) const
{
    model_.state().write(state);
}


// ************************************************************************* //
