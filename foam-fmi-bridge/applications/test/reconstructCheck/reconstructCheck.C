// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
/*---------------------------------------------------------------------------*\
Application
    reconstructCheck

Group
    grpTest

Description
    Direct check of fvc::reconstruct (docs/floating-stability.md): sets the
    face flux of a uniform velocity U0, phi = U0 & Sf, reconstructs the cell
    velocity U = fvc::reconstruct(phi) and prints the largest error
    max |U - U0| over the cells.

    The reconstruction of a uniform field is exact on any mesh in exact
    arithmetic: with T = sum(Sf Sf/|Sf|) and b = sum(Sf/|Sf| phi) over the
    faces of a cell, b = T & U0 and U = inv(T) & b = U0.  The error is then
    round-off, about 1e-15 |U0|.  Debian's v1912 build (GCC 12, -O3) writes
    inv(T) & b over the storage of b while the field loops declare their
    operands __restrict__, so on a cell whose faces are not aligned with the
    axes (T not diagonal) the later components of U are computed from the
    already overwritten earlier ones (a velocity taken for a component of b,
    a flux): an error of order |U0|/|Sf|, which grows as the mesh is
    refined.

    fvc::reconstruct and the field operators are templates instantiated in
    this compilation unit, so the flags this application is built with
    decide the result, not those of the libraries it links:

      - reconstructCheck (Make/options): -D__restrict__=, as
        interFoamAliasSafe;
      - reconstructCheckDebianFlags (debianFlags/): the flags of Debian's
        own build (wmake's Opt rules of Debian's source tree: dpkg-buildflags
        and -O3).

    Also printed: the number of faces whose normal is along a coordinate
    axis (the defect cannot show on a cell whose faces all are).

Usage
    reconstructCheck [-U0 '(1 0.5 0.3)'] [-case <dir>]

    The last line is "max |U - U0| = <error> m/s".
\*---------------------------------------------------------------------------*/

#include "fvCFD.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Reconstructs the cell velocity from the face flux of a uniform"
        " velocity U0 and prints the largest error max |U - U0|"
    );
    argList::noParallel();
    argList::addOption
    (
        "U0",
        "vector",
        "the uniform velocity, m/s (default (1 0.5 0.3))"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    #include "createMesh.H"

    const vector U0(args.getOrDefault<vector>("U0", vector(1, 0.5, 0.3)));

    // Faces whose unit normal is along a coordinate axis (to round-off)
    const vectorField nf(mesh.Sf().primitiveField()/mesh.magSf().primitiveField());
    label nAligned = 0;
    forAll(nf, facei)
    {
        if (cmptMax(cmptMag(nf[facei])) > 1 - 1e-9)
        {
            ++nAligned;
        }
    }
    forAll(mesh.boundary(), patchi)
    {
        const vectorField& Sfp = mesh.Sf().boundaryField()[patchi];
        forAll(Sfp, facei)
        {
            if (cmptMax(cmptMag(Sfp[facei]/mag(Sfp[facei]))) > 1 - 1e-9)
            {
                ++nAligned;
            }
        }
    }

    Info<< "Mesh: " << mesh.nCells() << " cells, " << mesh.nFaces()
        << " faces, " << nAligned << " of them along a coordinate axis" << nl
        << "U0 = " << U0 << " m/s, |U0| = " << mag(U0) << " m/s" << nl;

    // The flux of U0 on every face, internal and boundary
    const surfaceScalarField phi
    (
        "phi",
        dimensionedVector("U0", dimVelocity, U0) & mesh.Sf()
    );

    const volVectorField U("U", fvc::reconstruct(phi));

    const scalarField error(mag(U.primitiveField() - U0));
    label worst = 0;
    forAll(error, celli)
    {
        if (error[celli] > error[worst])
        {
            worst = celli;
        }
    }

    Info<< "Largest error in cell " << worst << ": U = " << U[worst]
        << " m/s" << nl
        << "max |U - U0| = " << error[worst] << " m/s" << nl << endl;

    return 0;
}


// ************************************************************************* //
