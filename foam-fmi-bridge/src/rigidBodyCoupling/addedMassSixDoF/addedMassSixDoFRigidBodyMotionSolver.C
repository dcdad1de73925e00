// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
/*---------------------------------------------------------------------------*\
    The construction, mesh morphing and state I/O follow OpenFOAM v1912's
    sixDoFRigidBodyMotionSolver (src/sixDoFRigidBodyMotion, GPL v3, OpenCFD
    Ltd. and the OpenFOAM Foundation); solve() adds the added-mass coupling.
\*---------------------------------------------------------------------------*/

#include "addedMassSixDoFRigidBodyMotionSolver.H"
#include "addToRunTimeSelectionTable.H"
#include "polyMesh.H"
#include "fvMesh.H"
#include "bodyMorphing.H"
#include "unregisteredIO.H"
#include "uniformDimensionedFields.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(addedMassSixDoFRigidBodyMotionSolver, 0);

    addToRunTimeSelectionTable
    (
        motionSolver,
        addedMassSixDoFRigidBodyMotionSolver,
        dictionary
    );
}


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{

//- OpenFOAM v1912's sixDoFRigidBodyMotion entries at the coefficients'
//  level: read by sixDoFRigidBodyMotionSolver (patches, innerDistance,
//  outerDistance, test, rho, rhoInf, CofGvelocity, g), sixDoFRigidBodyMotion
//  (mass, centreOfMass, initialCentreOfMass, momentOfInertia, orientation,
//  initialOrientation, report, solver, restraints, constraints,
//  accelerationRelaxation, accelerationDamping) and its state (the
//  initial state when no state file is read); and this solver's
//  distanceScale (bodyMorphing::readDistanceScale)
const Foam::wordList openFoamEntries
({
    "distanceScale",
    "patches", "innerDistance", "outerDistance", "test", "rho", "rhoInf",
    "CofGvelocity", "g", "mass", "centreOfMass", "initialCentreOfMass",
    "momentOfInertia", "orientation", "initialOrientation", "report",
    "solver", "restraints", "constraints", "accelerationRelaxation",
    "accelerationDamping", "centreOfRotation", "velocity", "acceleration",
    "angularMomentum", "torque"
});

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::addedMassSixDoFRigidBodyMotionSolver::readCoupling()
{
    coupling_.readSolver
    (
        *this,
        coeffDict(),
        "sixDoFRigidBodyMotion",
        openFoamEntries
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::addedMassSixDoFRigidBodyMotionSolver::
addedMassSixDoFRigidBodyMotionSolver
(
    const polyMesh& mesh,
    const IOdictionary& dict
)
:
    addedMassMotionSolver
    (
        mesh,
        dict,
        typeName,
        "sixDoFRigidBodyMotionState",
        "six-DoF state"
    ),
    motion_
    (
        restartCoeffs
        (
            sixDoFCouplingBody::motionStateEntries,
            "the six-DoF state of addedMassSixDoFRigidBodyMotion"
        ),
        initialState(),
        mesh.time()
    ),
    patches_(coeffDict().get<wordRes>("patches")),
    patchSet_(mesh.boundaryMesh().patchSet(patches_)),
    di_(coeffDict().get<scalar>("innerDistance")),
    do_(coeffDict().get<scalar>("outerDistance")),
    distanceScale_(bodyMorphing::readDistanceScale(coeffDict())),
    test_(coeffDict().lookupOrDefault("test", false)),
    rhoInf_(1.0),
    rhoName_(coeffDict().lookupOrDefault<word>("rho", "rho")),
    scale_
    (
        unregisteredIO(mesh, "motionScale"),
        pointMesh::New(mesh),
        dimensionedScalar(dimless, Zero)
    ),
    curTimeIndex_(-1),
    CofGvelocity_(coeffDict().lookupOrDefault<word>("CofGvelocity", "none")),
    body_(motion_, typeName)
{
    readCoupling();

    if (rhoName_ == "rhoInf")
    {
        coeffDict().readEntry("rhoInf", rhoInf_);
    }

    readCouplingState(1);
    if (stateIO().typeHeaderOk<IOdictionary>(true))
    {
        body_.readRestartState
        (
            IOdictionary(stateIO()),
            stateIO().objectPath()
        );
    }
    coupling_.setPatches
    (
        List<labelHashSet>(1, patchSet_),
        rhoName_,
        rhoInf_
    );

    bodyMorphing::weights
    (
        scale_, patchSet_, points0(), di_, do_, distanceScale_
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::addedMassSixDoFRigidBodyMotionSolver::solve()
{
    const Time& t = mesh().time();

    checkPoints();

    // Store the motion state at the beginning of the time-step
    bool firstIter = false;
    if (curTimeIndex_ != t.timeIndex())
    {
        body_.newTime();
        coupling_.newTime();
        curTimeIndex_ = t.timeIndex();
        firstIter = true;
    }

    dimensionedVector g("g", dimAcceleration, Zero);

    if (t.foundObject<uniformDimensionedVectorField>("g"))
    {
        g = t.lookupObject<uniformDimensionedVectorField>("g");
    }
    else
    {
        coeffDict().readIfPresent("g", g);
    }

    if (test_)
    {
        body_.setLoads(Zero, Zero, g.value(), firstIter);
        body_.solveFluidLoads();
    }
    else
    {
        body_.setFluidLoads
        (
            db(),
            patches_,
            rhoName_,
            rhoInf_,
            g.value(),
            firstIter
        );
        coupling_.correct(body_, 1);
        if (coupling_.addedMass())
        {
            body_.reportSolve();
        }

        if (CofGvelocity_ != "none")
        {
            if (t.foundObject<uniformDimensionedVectorField>(CofGvelocity_))
            {
                t.lookupObjectRef<uniformDimensionedVectorField>
                (
                    CofGvelocity_
                ) = motion_.v();
            }
        }
    }

    // Update the displacements
    pointDisplacement_.primitiveFieldRef() =
        motion_.transform(points0(), scale_) - points0();

    // Displacement has changed. Update boundary conditions
    constrainDisplacement();
}


void Foam::addedMassSixDoFRigidBodyMotionSolver::writeMotionState
(
    dictionary& state
) const
{
    motion_.state().write(state);
    body_.writeState(state);
}


void Foam::addedMassSixDoFRigidBodyMotionSolver::readMotion()
{
    motion_.read(coeffDict());
}


// ************************************************************************* //
