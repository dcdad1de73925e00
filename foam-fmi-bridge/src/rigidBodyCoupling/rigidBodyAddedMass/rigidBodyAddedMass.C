// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "rigidBodyAddedMass.H"
#include "fvm.H"
#include "fvc.H"
#include "fixedGradientFvPatchFields.H"
#include "fixedValueFvPatchFields.H"
#include "zeroGradientFvPatchFields.H"
#include "spatialVector.H"
#include "unregisteredIO.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::wordList Foam::rigidBodyAddedMass::patchTypes() const
{
    const volScalarField& p = mesh_.lookupObject<volScalarField>(pName_);

    wordList types(mesh_.boundary().size());

    forAll(types, patchi)
    {
        const fvPatchScalarField& pp = p.boundaryField()[patchi];

        bool onBody = false;
        for (const labelHashSet& patches : bodyPatches_)
        {
            onBody = onBody || patches.found(patchi);
        }

        if (onBody)
        {
            types[patchi] = fixedGradientFvPatchScalarField::typeName;
        }
        else if (pp.coupled())
        {
            types[patchi] = pp.type();
        }
        else if (pp.fixesValue())
        {
            types[patchi] = fixedValueFvPatchScalarField::typeName;
        }
        else if (pp.type() == "empty" || pp.type() == "wedge"
              || pp.type() == "symmetry" || pp.type() == "symmetryPlane")
        {
            types[patchi] = pp.type();
        }
        else
        {
            types[patchi] = zeroGradientFvPatchScalarField::typeName;
        }
    }

    return types;
}


Foam::IOobject Foam::rigidBodyAddedMass::fieldIO(const word& name) const
{
    return unregisteredIO(mesh_, name);
}


Foam::tmp<Foam::surfaceScalarField>
Foam::rigidBodyAddedMass::faceDensity() const
{
    if (mesh_.foundObject<volScalarField>(rhoName_))
    {
        return fvc::interpolate
        (
            mesh_.lookupObject<volScalarField>(rhoName_)
        );
    }

    return tmp<surfaceScalarField>::New
    (
        fieldIO("rigidBodyAddedMass.rhof"),
        mesh_,
        dimensionedScalar("rhoInf", dimDensity, rhoInf_)
    );
}


void Foam::rigidBodyAddedMass::setUnitAcceleration
(
    volScalarField& p,
    const label b,
    const label k,
    const vector& c
)
{
    volScalarField::Boundary& pbf = p.boundaryFieldRef();

    forAll(bodyPatches_, bi)
    {
        for (const label patchi : bodyPatches_[bi])
        {
            fixedGradientFvPatchScalarField& pp =
                refCast<fixedGradientFvPatchScalarField>(pbf[patchi]);

            if (bi != b)
            {
                pp.gradient() = 0;
                continue;
            }

            const fvPatch& patch = mesh_.boundary()[patchi];
            const vectorField nf(patch.nf());
            const scalarField rhop(rhoPatch(patchi));

            // Acceleration of the face centres in the unit mode [m/s^2]
            vector e(Zero);
            e[k % 3] = 1;
            const vectorField a
            (
                k < 3
              ? vectorField(e ^ (patch.Cf() - c))
              : vectorField(patch.size(), e)
            );

            // (1/rho) dp/dn = -a.n: the fluid at the wall moves with it
            pp.gradient() = -rhop*(a & nf);
        }
    }
}


Foam::tmp<Foam::scalarField>
Foam::rigidBodyAddedMass::rhoPatch(const label patchi) const
{
    if (mesh_.foundObject<volScalarField>(rhoName_))
    {
        return tmp<scalarField>::New
        (
            mesh_.lookupObject<volScalarField>(rhoName_)
           .boundaryField()[patchi]
        );
    }

    return tmp<scalarField>::New(mesh_.boundary()[patchi].size(), rhoInf_);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rigidBodyAddedMass::rigidBodyAddedMass
(
    const fvMesh& mesh,
    const List<labelHashSet>& bodyPatches,
    const word& pName,
    const word& rhoName,
    const scalar rhoInf
)
:
    mesh_(mesh),
    bodyPatches_(bodyPatches),
    pName_(pName),
    rhoName_(rhoName),
    rhoInf_(rhoInf)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalarSquareMatrix Foam::rigidBodyAddedMass::matrix
(
    const List<vector>& origins
)
{
    const label nBodies = bodyPatches_.size();

    if (pUnit_.empty())
    {
        if (!mesh_.foundObject<volScalarField>(pName_))
        {
            FatalErrorInFunction
                << "No pressure field " << pName_ << " on mesh "
                << mesh_.name() << ": the added-mass estimate takes the"
                << " pressure's boundary types; name the pressure field"
                << " with the entry 'pressure' of the coupling dictionary"
                << exit(FatalError);
        }

        const wordList types(patchTypes());
        pUnit_.setSize(6*nBodies);
        forAll(pUnit_, i)
        {
            pUnit_.set
            (
                i,
                new volScalarField
                (
                    fieldIO("rigidBodyAddedMass.p" + Foam::name(i)),
                    mesh_,
                    dimensionedScalar("zero", dimMass/sqr(dimLength), Zero),
                    types
                )
            );
        }
    }

    const surfaceScalarField rAf(1/faceDensity());

    scalarSquareMatrix M(6*nBodies, Zero);

    // The Poisson solves print nothing: six a body each time step
    const int debug0 = SolverPerformance<scalar>::debug;
    SolverPerformance<scalar>::debug = 0;

    for (label b = 0; b < nBodies; ++b)
    {
        for (label k = 0; k < 6; ++k)
        {
            volScalarField& p = pUnit_[6*b + k];
            setUnitAcceleration(p, b, k, origins[b]);

            fvScalarMatrix pEqn(fvm::laplacian(rAf, p));
            pEqn.setReference(Pstream::master() ? 0 : -1, 0);
            pEqn.solve(mesh_.solverDict(pName_));

            // Loads on every body about its origin: moments and forces
            for (label i = 0; i < nBodies; ++i)
            {
                vector moment(Zero);
                vector force(Zero);

                for (const label patchi : bodyPatches_[i])
                {
                    const fvPatch& patch = mesh_.boundary()[patchi];
                    const vectorField pSf
                    (
                        p.boundaryField()[patchi]*patch.Sf()
                    );
                    force += sum(pSf);
                    moment += sum((patch.Cf() - origins[i]) ^ pSf);
                }
                reduce(force, sumOp<vector>());
                reduce(moment, sumOp<vector>());

                for (direction r = 0; r < 3; ++r)
                {
                    M(6*i + r, 6*b + k) = -moment[r];
                    M(6*i + 3 + r, 6*b + k) = -force[r];
                }
            }
        }
    }

    SolverPerformance<scalar>::debug = debug0;

    return M;
}


Foam::scalarSquareMatrix Foam::rigidBodyAddedMass::rotate
(
    const scalarSquareMatrix& M,
    const List<tensor>& R
)
{
    const label nBodies = R.size();

    if (M.m() != 6*nBodies)
    {
        FatalErrorInFunction
            << "An added-mass matrix of " << M.m() << " rows for "
            << nBodies << " bodies: 6 a body expected" << exit(FatalError);
    }

    scalarSquareMatrix result(M.m(), Zero);

    // Each 3 x 3 block: moment or force of body i per angular or linear
    // acceleration of body j
    for (label i = 0; i < nBodies; ++i)
    {
        for (label j = 0; j < nBodies; ++j)
        {
            for (label row = 6*i; row < 6*i + 6; row += 3)
            {
                for (label col = 6*j; col < 6*j + 6; col += 3)
                {
                    tensor block(Zero);
                    for (direction r = 0; r < 3; ++r)
                    {
                        for (direction s = 0; s < 3; ++s)
                        {
                            block[3*r + s] = M(row + r, col + s);
                        }
                    }

                    block = R[i] & block & R[j].T();

                    for (direction r = 0; r < 3; ++r)
                    {
                        for (direction s = 0; s < 3; ++s)
                        {
                            result(row + r, col + s) = block[3*r + s];
                        }
                    }
                }
            }
        }
    }

    return result;
}


// ************************************************************************* //
