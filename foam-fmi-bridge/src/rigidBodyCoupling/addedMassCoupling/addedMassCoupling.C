// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
/*---------------------------------------------------------------------------*\
Description
    The added-mass coupling: the added mass of a time step, the Newton
    iterations of an outer corrector and the residual.
\*---------------------------------------------------------------------------*/

#include "addedMassCoupling.H"
#include "fvMesh.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::addedMassCoupling::addedMassCoupling
(
    const word& solverType,
    const fvMesh& mesh,
    const word& defaultResidual
)
:
    solverType_(solverType),
    defaultResidual_(defaultResidual),
    mesh_(mesh),
    addedMass_(true),
    pName_("p_rgh"),
    residualName_(defaultResidual),
    maxIter_(10),
    tolerance_(1e-9),
    addedMassInterval_(10),
    corrector_(0),
    newEstimate_(false)
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::addedMassCoupling::updateAddedMass(const bodies& b)
{
    const tensorField E(b.axes());

    // From a state file without the body-axes matrix: the matrix in use,
    // in the axes of the state's orientation, which is this step's start
    if (Mbody_.m() == 0 && M_.m())
    {
        Mbody_ = rigidBodyAddedMass::rotate(M_, E);
    }

    if
    (
        Mbody_.m() == 0
     || mesh_.time().timeIndex() % addedMassInterval_ == 0
    )
    {
        M_ = estimate_->matrix(origins_);
        Mbody_ = rigidBodyAddedMass::rotate(M_, E);
        newEstimate_ = true;
    }
    else
    {
        // Body to global axes: the transposes of E
        M_ = rigidBodyAddedMass::rotate(Mbody_, E.T());
    }
}


Foam::label Foam::addedMassCoupling::coupledSolve
(
    bodies& b,
    const scalar ramp,
    const scalarField& c0,
    scalar& newtonResidual
)
{
    const label n = c0.size();
    b.saveState();

    // Accelerations from the saved state with the fluid loads plus f
    auto solveWith = [&](const scalarField& f)
    {
        b.solveWith(origins_, f);
        return b.accelerations(origins_);
    };

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

    const scalarField cFree(solveWith(scalarField(n, Zero)));

    // D = dC/df, the solver's acceleration response to a load, column by
    // column; a load step of 1e-4 of the body's weight (or of its weight
    // times its radius of gyration for a moment), with its added mass
    const scalar gMag = max(mag(b.g()), scalar(1));
    scalarSquareMatrix D(n, Zero);
    for (label bi = 0; bi < b.size(); ++bi)
    {
        const scalar mEff =
            b.mass(bi)
          + max(M_(6*bi + 3, 6*bi + 3), max(M_(6*bi + 4, 6*bi + 4),
                M_(6*bi + 5, 6*bi + 5)));
        const scalar IEff =
            b.inertiaTrace(bi)/3
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
            const scalarField c(solveWith(f));
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

        R = c - solveWith(addedLoad(c));

        newtonResidual = max(mag(R))/scale;
        if (newtonResidual < tolerance_)
        {
            break;
        }
    }

    return iter;
}


Foam::scalar Foam::addedMassCoupling::couplingResidual
(
    const bodies& b,
    const scalarField& c0,
    const scalarField& c
) const
{
    scalar change2 = 0;
    scalar size2 = 0;

    const vector offset(b.accelerationOffset());
    const scalar gMag = mag(b.g());

    for (label bi = 0; bi < b.size(); ++bi)
    {
        const scalar m = max(b.mass(bi), VSMALL);
        const scalar gyration = sqrt(b.inertiaTrace(bi)/(3*m));

        for (direction r = 0; r < 3; ++r)
        {
            const label w = 6*bi + r;
            const label l = 6*bi + 3 + r;
            change2 +=
                sqr(gyration*(c[w] - c0[w])) + sqr(c[l] - c0[l]);
            // the true acceleration
            size2 +=
                sqr(gyration*c[w]) + sqr(c[l] - offset[r]);
        }
    }

    return sqrt(change2)/(sqrt(size2) + 0.01*gMag + VSMALL);
}


void Foam::addedMassCoupling::reportResidual
(
    const bodies& b,
    const scalar r,
    const scalar newtonResidual,
    const label nIter
)
{
    const fvMesh& fvm = mesh_;

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

    if (b.report())
    {
        Info<< solverType_ << ": outer corrector " << corrector_
            << ", coupling residual " << r;
        if (addedMass_)
        {
            Info<< ", Newton iterations " << nIter
                << " (residual " << newtonResidual << ")";
            if (newEstimate_)
            {
                newEstimate_ = false;
                // The added masses of this step, body by body
                for (label bi = 0; bi < b.size(); ++bi)
                {
                    Info<< nl << "    added mass of " << b.name(bi)
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



// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::addedMassCoupling::setPatches
(
    const List<labelHashSet>& bodyPatches,
    const word& rhoName,
    const scalar rhoInf
)
{
    estimate_.reset
    (
        new rigidBodyAddedMass(mesh_, bodyPatches, pName_, rhoName, rhoInf)
    );
}


void Foam::addedMassCoupling::correct(bodies& b, const scalar ramp)
{
    ++corrector_;

    // The accelerations the fluid of the last corrector moved with, at the
    // origins of the step's start
    if (corrector_ == 1 || origins_.empty())
    {
        origins_ = b.origins();
    }
    const scalarField c0(b.accelerations(origins_));

    scalar newtonResidual = 0;
    label nNewton = 0;

    if (addedMass_)
    {
        if (corrector_ == 1 || M_.m() == 0)
        {
            updateAddedMass(b);
        }
        nNewton = coupledSolve(b, ramp, c0, newtonResidual);
    }
    else
    {
        b.solveFluidLoads();
    }

    reportResidual
    (
        b,
        couplingResidual(b, c0, b.accelerations(origins_)),
        newtonResidual,
        nNewton
    );
}


// ************************************************************************* //
