// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
/*---------------------------------------------------------------------------*\
Description
    OpenFOAM's rigidBodyMotion as the added-mass coupling sees it: its
    entries, the fluid loads, and the solves and accelerations of the
    bodies with patches.
\*---------------------------------------------------------------------------*/

#include "addedMassRigidBodyMeshMotion.H"
#include "forces.H"
#include "fvMesh.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- OpenFOAM v1912's rigidBodyMotion entries at the coefficients' level:
//  read by rigidBodyMeshMotion (test, nIter, rho, ramp, bodies; rampCoeffs
//  for the Function1's older form; rhoInf, which v1912 reads from the top
//  level of dynamicMeshDict and this solver from the coefficients first),
//  rigidBodyModel (bodies,
//  restraints), rigidBodyMotion (solver, g, accelerationRelaxation,
//  accelerationDamping, report) and rigidBodyModelState (q, qDot, qDdot,
//  t, deltaT: the initial state when no state file is read)
const Foam::wordList openFoamEntries
({
    "bodies", "restraints", "solver", "g", "report",
    "accelerationRelaxation", "accelerationDamping", "test", "nIter",
    "rho", "rhoInf", "ramp", "rampCoeffs", "q", "qDot", "qDdot", "t",
    "deltaT"
});

} // End anonymous namespace


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::addedMassRigidBodyMeshMotion::readCoupling()
{
    coupling_.readSolver
    (
        *this,
        coeffDict(),
        "rigidBodyMotion",
        openFoamEntries
    );
}


Foam::Field<Foam::spatialVector>
Foam::addedMassRigidBodyMeshMotion::fluidLoads(const scalar ramp) const
{
    Field<spatialVector> fx(model_.nBodies(), Zero);

    forAll(bodyMeshes_, bi)
    {
        const label bodyID = bodyMeshes_[bi].bodyID_;

        dictionary forcesDict;
        forcesDict.add("type", functionObjects::forces::typeName);
        forcesDict.add("patches", bodyMeshes_[bi].patches_);
        forcesDict.add("rhoInf", rhoInf_);
        forcesDict.add("rho", rhoName_);
        forcesDict.add("CofR", vector::zero);

        functionObjects::forces f("forces", db(), forcesDict);
        #if OPENFOAM >= 2206
        f.calcForcesMoments();
        #else
        f.calcForcesMoment();
        #endif

        fx[bodyID] = ramp*spatialVector(f.momentEff(), f.forceEff());
    }

    return fx;
}


// * * * * * * * * * * * * * * * The coupling's view  * * * * * * * * * * * //

Foam::label Foam::addedMassRigidBodyMeshMotion::couplingBodies::size() const
{
    return motion_.bodyMeshes_.size();
}


Foam::word Foam::addedMassRigidBodyMeshMotion::couplingBodies::name
(
    const label i
) const
{
    return motion_.bodyMeshes_[i].name_;
}


bool Foam::addedMassRigidBodyMeshMotion::couplingBodies::report() const
{
    return motion_.model_.report();
}


Foam::List<Foam::vector>
Foam::addedMassRigidBodyMeshMotion::couplingBodies::origins() const
{
    List<vector> r(size());
    forAll(r, bi)
    {
        r[bi] = motion_.model_.X0(motion_.bodyMeshes_[bi].bodyID_).r();
    }
    return r;
}


Foam::tensorField
Foam::addedMassRigidBodyMeshMotion::couplingBodies::axes() const
{
    // The E of OpenFOAM's X0: global to body
    tensorField E(size());
    forAll(E, bi)
    {
        E[bi] = motion_.model_.X0(motion_.bodyMeshes_[bi].bodyID_).E();
    }
    return E;
}


Foam::scalar Foam::addedMassRigidBodyMeshMotion::couplingBodies::mass
(
    const label i
) const
{
    return motion_.model_.I(motion_.bodyMeshes_[i].bodyID_).m();
}


Foam::scalar
Foam::addedMassRigidBodyMeshMotion::couplingBodies::inertiaTrace
(
    const label i
) const
{
    return tr(motion_.model_.I(motion_.bodyMeshes_[i].bodyID_).Ic());
}


Foam::vector Foam::addedMassRigidBodyMeshMotion::couplingBodies::g() const
{
    return motion_.model_.g();
}


Foam::vector
Foam::addedMassRigidBodyMeshMotion::couplingBodies::accelerationOffset() const
{
    // OpenFOAM's accelerations carry -g: the base accelerates up
    return -motion_.model_.g();
}


void Foam::addedMassRigidBodyMeshMotion::couplingBodies::saveState()
{
    motion_.start_ = motion_.model_.state();
}


void Foam::addedMassRigidBodyMeshMotion::couplingBodies::solveWith
(
    const List<vector>& origins,
    const scalarField& fAdd
)
{
    Field<spatialVector> f(motion_.fx_);

    forAll(motion_.bodyMeshes_, bi)
    {
        const vector moment(fAdd[6*bi], fAdd[6*bi + 1], fAdd[6*bi + 2]);
        const vector force(fAdd[6*bi + 3], fAdd[6*bi + 4], fAdd[6*bi + 5]);

        // OpenFOAM's loads are about the global origin
        f[motion_.bodyMeshes_[bi].bodyID_] +=
            spatialVector(moment + (origins[bi] ^ force), force);
    }

    // The restraints read the bodies' kinematics from the model's cache of
    // the last solve, not from the state: bring both back to the start
    const Time& t = motion_.mesh().time();
    motion_.model_.state() = motion_.start_;
    motion_.model_.forwardDynamicsCorrection(motion_.start_);
    motion_.model_.solve
    (
        t.value(),
        t.deltaTValue(),
        scalarField(motion_.model_.nDoF(), Zero),
        f
    );
}


void Foam::addedMassRigidBodyMeshMotion::couplingBodies::solveFluidLoads()
{
    const Time& t = motion_.mesh().time();
    motion_.model_.solve
    (
        t.value(),
        t.deltaTValue(),
        scalarField(motion_.model_.nDoF(), Zero),
        motion_.fx_
    );
}


Foam::scalarField
Foam::addedMassRigidBodyMeshMotion::couplingBodies::accelerations
(
    const List<vector>& origins
) const
{
    const RBD::rigidBodyMotion& model = motion_.model_;
    scalarField c(6*size());

    forAll(motion_.bodyMeshes_, bi)
    {
        const label bodyID = motion_.bodyMeshes_[bi].bodyID_;
        const spatialTransform X0(model.X0(bodyID));

        // Angular acceleration and acceleration of the body's origin, in
        // global axes (OpenFOAM's a() carries -g: the base accelerates up)
        const spatialVector a
        (
            spatialTransform(X0.E().T(), Zero) & model.a(bodyID)
        );
        const vector linear(a.l() + (a.w() ^ (origins[bi] - X0.r())));

        for (direction r = 0; r < 3; ++r)
        {
            c[6*bi + r] = a.w()[r];
            c[6*bi + 3 + r] = linear[r];
        }
    }

    return c;
}


// ************************************************************************* //
