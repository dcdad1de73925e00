// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
/*---------------------------------------------------------------------------*\
Description
    The added-mass coupling of addedMassRigidBodyMeshMotion: loads, body
    accelerations, the Newton iterations and the residual.
\*---------------------------------------------------------------------------*/

#include "addedMassRigidBodyMeshMotion.H"
#include "forces.H"
#include "fvMesh.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

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


Foam::tensorField Foam::addedMassRigidBodyMeshMotion::bodyAxes() const
{
    tensorField E(bodyMeshes_.size());

    forAll(bodyMeshes_, bi)
    {
        E[bi] = model_.X0(bodyMeshes_[bi].bodyID_).E();
    }

    return E;
}


void Foam::addedMassRigidBodyMeshMotion::updateAddedMass()
{
    const tensorField E(bodyAxes());

    // From a state file without the body-axes matrix: the matrix in use,
    // in the axes of the state's orientation, which is this step's start
    if (Mbody_.m() == 0 && M_.m())
    {
        Mbody_ = rigidBodyAddedMass::rotate(M_, E);
    }

    if
    (
        Mbody_.m() == 0
     || mesh().time().timeIndex() % addedMassInterval_ == 0
    )
    {
        M_ = addedMassEstimate_->matrix(origins_);
        Mbody_ = rigidBodyAddedMass::rotate(M_, E);
        newEstimate_ = true;
    }
    else
    {
        // Body to global axes: the transposes of E
        M_ = rigidBodyAddedMass::rotate(Mbody_, E.T());
    }
}


void Foam::addedMassRigidBodyMeshMotion::readAddedMass
(
    const dictionary& state
)
{
    const word key
    (
        state.found("addedMassBody", keyType::LITERAL)
      ? "addedMassBody"
      : "addedMass"
    );

    scalarSquareMatrix M;
    if (!state.readIfPresent(key, M))
    {
        return;
    }

    if (M.m() != 6*bodyMeshes_.size())
    {
        FatalIOErrorInFunction(state)
            << "addedMassRigidBodyMotion: the state's added-mass matrix '"
            << key << "' has " << M.m() << " rows, "
            << 6*bodyMeshes_.size() << " expected (6 for each of the "
            << bodyMeshes_.size() << " bodies with patches): the state was"
            << " written for other bodies" << exit(FatalIOError);
    }

    if (key == "addedMassBody")
    {
        Mbody_ = M;
    }
    else
    {
        M_ = M;
    }
}


Foam::scalarField
Foam::addedMassRigidBodyMeshMotion::bodyAccelerations() const
{
    scalarField c(6*bodyMeshes_.size());

    forAll(bodyMeshes_, bi)
    {
        const label bodyID = bodyMeshes_[bi].bodyID_;
        const spatialTransform X0(model_.X0(bodyID));

        // Angular acceleration and acceleration of the body's origin, in
        // global axes (OpenFOAM's a() carries -g: the base accelerates up)
        const spatialVector a
        (
            spatialTransform(X0.E().T(), Zero) & model_.a(bodyID)
        );
        const vector linear(a.l() + (a.w() ^ (origins_[bi] - X0.r())));

        for (direction r = 0; r < 3; ++r)
        {
            c[6*bi + r] = a.w()[r];
            c[6*bi + 3 + r] = linear[r];
        }
    }

    return c;
}


Foam::scalarField Foam::addedMassRigidBodyMeshMotion::solveWith
(
    const RBD::rigidBodyModelState& start,
    const Field<spatialVector>& fx,
    const scalarField& fAdd
)
{
    Field<spatialVector> f(fx);

    forAll(bodyMeshes_, bi)
    {
        const vector moment(fAdd[6*bi], fAdd[6*bi + 1], fAdd[6*bi + 2]);
        const vector force(fAdd[6*bi + 3], fAdd[6*bi + 4], fAdd[6*bi + 5]);

        // OpenFOAM's loads are about the global origin
        f[bodyMeshes_[bi].bodyID_] +=
            spatialVector(moment + (origins_[bi] ^ force), force);
    }

    // The restraints read the bodies' kinematics from the model's cache of
    // the last solve, not from the state: bring both back to the start
    const Time& t = mesh().time();
    model_.state() = start;
    model_.forwardDynamicsCorrection(start);
    model_.solve
    (
        t.value(),
        t.deltaTValue(),
        scalarField(model_.nDoF(), Zero),
        f
    );

    return bodyAccelerations();
}


Foam::label Foam::addedMassRigidBodyMeshMotion::coupledSolve
(
    const Field<spatialVector>& fx,
    const scalar ramp,
    const scalarField& c0,
    scalar& newtonResidual
)
{
    const label n = c0.size();
    const RBD::rigidBodyModelState start(model_.state());

    // The load answering a change of acceleration from c0: -ramp M (c - c0)
    auto addedLoad = [&](const scalarField& c)
    {
        scalarField f(n, Zero);
        for (label i = 0; i < n; ++i)
        {
            for (label j = 0; j < n; ++j)
            {
                f[i] -= ramp*M_(i, j)*(c[j] - c0[j]);
            }
        }
        return f;
    };

    const scalarField cFree(solveWith(start, fx, scalarField(n, Zero)));

    // D = dC/df, the solver's acceleration response to a load, column by
    // column; a load step of 1e-4 of the body's weight (or of its weight
    // times its radius of gyration for a moment), with its added mass
    const scalar gMag = max(mag(model_.g()), scalar(1));
    scalarSquareMatrix D(n, Zero);
    forAll(bodyMeshes_, bi)
    {
        const label bodyID = bodyMeshes_[bi].bodyID_;
        const scalar mEff =
            model_.I(bodyID).m()
          + max(M_(6*bi + 3, 6*bi + 3), max(M_(6*bi + 4, 6*bi + 4),
                M_(6*bi + 5, 6*bi + 5)));
        const scalar IEff =
            tr(model_.I(bodyID).Ic())/3
          + max(M_(6*bi, 6*bi), max(M_(6*bi + 1, 6*bi + 1),
                M_(6*bi + 2, 6*bi + 2)));
        const scalar gyration = sqrt(IEff/max(mEff, VSMALL));

        for (label k = 0; k < 6; ++k)
        {
            const label j = 6*bi + k;
            const scalar step =
                1e-4*mEff*gMag*(k < 3 ? gyration : scalar(1));

            scalarField f(n, Zero);
            f[j] = step;
            const scalarField c(solveWith(start, fx, f));
            for (label i = 0; i < n; ++i)
            {
                D(i, j) = (c[i] - cFree[i])/step;
            }
        }
    }

    // Newton on R(c) = c - C(f - M (c - c0)), Jacobian I + ramp D M
    scalarSquareMatrix J(n, Zero);
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            scalar DM = 0;
            for (label k = 0; k < n; ++k)
            {
                DM += D(i, k)*M_(k, j);
            }
            J(i, j) = (i == j ? 1 : 0) + ramp*DM;
        }
    }
    labelList pivots(n);
    label sign;
    LUDecompose(J, pivots, sign);

    const scalar scale = max(max(mag(c0)), max(mag(cFree))) + SMALL;

    scalarField c(c0);
    scalarField R(c0 - cFree);
    label iter = 0;

    while (iter < maxIter_)
    {
        ++iter;
        scalarField delta(-R);
        LUBacksubstitute(J, pivots, delta);
        c += delta;

        R = c - solveWith(start, fx, addedLoad(c));

        newtonResidual = max(mag(R))/scale;
        if (newtonResidual < tolerance_)
        {
            break;
        }
    }

    return iter;
}


Foam::scalar Foam::addedMassRigidBodyMeshMotion::couplingResidual
(
    const scalarField& c0,
    const scalarField& c
) const
{
    scalar change2 = 0;
    scalar size2 = 0;

    forAll(bodyMeshes_, bi)
    {
        const label bodyID = bodyMeshes_[bi].bodyID_;
        const scalar m = max(model_.I(bodyID).m(), VSMALL);
        const scalar gyration = sqrt(tr(model_.I(bodyID).Ic())/(3*m));

        for (direction r = 0; r < 3; ++r)
        {
            const label w = 6*bi + r;
            const label l = 6*bi + 3 + r;
            change2 +=
                sqr(gyration*(c[w] - c0[w])) + sqr(c[l] - c0[l]);
            // the true acceleration: OpenFOAM's carries -g
            size2 +=
                sqr(gyration*c[w]) + sqr(c[l] + model_.g()[r]);
        }
    }

    return sqrt(change2)/(sqrt(size2) + 0.01*mag(model_.g()) + VSMALL);
}


void Foam::addedMassRigidBodyMeshMotion::reportResidual
(
    const scalar r,
    const scalar newtonResidual,
    const label nIter
)
{
    const fvMesh& fvm = refCast<const fvMesh>(mesh());

    if (!residualField_.valid())
    {
        residualField_.reset
        (
            new volScalarField
            (
                IOobject
                (
                    residualName_,
                    fvm.time().timeName(),
                    fvm,
                    IOobject::NO_READ,
                    IOobject::NO_WRITE,
                    true
                ),
                fvm,
                dimensionedScalar("zero", dimless, Zero)
            )
        );
    }
    residualField_.ref() == dimensionedScalar("r", dimless, r);

    // PIMPLE's residualControl looks residuals up by the name of a
    // registered field: the coupling residual goes under residualName_.
    // The first corrector's change is the step's own change of
    // acceleration, not an iteration residual: it is not reported, so
    // that a time step does at least two correctors.
    if (corrector_ > 1)
    {
        // The mesh's solver-performance dictionary moved to mesh.data()
        // in v2312
        #if OPENFOAM >= 2312
        fvm.data().setSolverPerformance
        #else
        fvm.setSolverPerformance
        #endif
        (
            residualName_,
            SolverPerformance<scalar>
            (
                addedMass_ ? "addedMassNewton" : "fixedPoint",
                residualName_,
                r,
                r,
                nIter,
                !addedMass_ || newtonResidual < tolerance_
            )
        );
    }

    if (model_.report())
    {
        Info<< typeName << ": outer corrector " << corrector_
            << ", coupling residual " << r;
        if (addedMass_)
        {
            Info<< ", Newton iterations " << nIter
                << " (residual " << newtonResidual << ")";
            if (newEstimate_)
            {
                newEstimate_ = false;
                // The added masses of this step, body by body
                forAll(bodyMeshes_, bi)
                {
                    Info<< nl << "    added mass of " << bodyMeshes_[bi].name_
                        << ": rotation (" << M_(6*bi, 6*bi) << ' '
                        << M_(6*bi + 1, 6*bi + 1) << ' '
                        << M_(6*bi + 2, 6*bi + 2) << ") kg m^2,"
                        << " translation (" << M_(6*bi + 3, 6*bi + 3) << ' '
                        << M_(6*bi + 4, 6*bi + 4) << ' '
                        << M_(6*bi + 5, 6*bi + 5) << ") kg";
                }
            }
        }
        Info<< endl;
    }
}


// ************************************************************************* //
