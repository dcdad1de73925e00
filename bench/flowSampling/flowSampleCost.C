// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
/*---------------------------------------------------------------------------*\
Application
    flowSampleCost

Description
    Benchmark: the cost of giving a line the water velocity, as the function
    object fmuConnectorFlow samples it after every time step, on the case's
    mesh without a solver: a velocity field U set in the code (a wave-like
    field), the interpolation of U built once per step (cellPoint: the
    field interpolated to the mesh points), then for each of n points the
    cell that holds it (polyMesh::findCell) and U interpolated there. The
    points lie at equal steps on a straight line across the mesh's bounding
    box, as a line's shape points lie. Each part is timed over rounds, the
    fastest round counts.

Usage
    flowSampleCost [-points <n>] [-rounds <n>] [-case <dir>]
\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "fvMesh.H"
#include "volFields.H"
#include "interpolation.H"

#include <chrono>

using namespace Foam;

namespace
{

scalar seconds
(
    const std::chrono::steady_clock::time_point& start,
    const std::chrono::steady_clock::time_point& end
)
{
    return std::chrono::duration<scalar>(end - start).count();
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addOption("points", "n", "points sampled per round (101)");
    argList::addOption("rounds", "n", "rounds, the fastest counts (20)");

    #include "setRootCase.H"
    #include "createTime.H"
    fvMesh mesh
    (
        IOobject
        (
            fvMesh::defaultRegion,
            runTime.timeName(),
            runTime,
            IOobject::MUST_READ
        )
    );

    const label nPoints = args.getOrDefault<label>("points", 101);
    const label nRounds = args.getOrDefault<label>("rounds", 20);

    // A wave-like velocity field: U = (cos(k x), 0, sin(k x)) exp(k z)
    volVectorField U
    (
        IOobject("U", runTime.timeName(), mesh),
        mesh,
        dimensionedVector(dimVelocity, Zero)
    );
    const scalar k = 2.0;
    forAll(U, celli)
    {
        const point& c = mesh.C()[celli];
        U[celli] =
            vector(Foam::cos(k*c.x()), 0, Foam::sin(k*c.x()))
           *Foam::exp(k*(c.z() - 1));
    }
    U.correctBoundaryConditions();

    // Points along a line across the box, from near a bottom corner to
    // near the opposite top one, as a line's shape points lie
    const boundBox& box = mesh.bounds();
    const point from(box.min() + 0.05*box.span());
    const point to(box.max() - 0.05*box.span());
    pointField points(nPoints);
    forAll(points, i)
    {
        points[i] = from + (to - from)*scalar(i)/max(nPoints - 1, 1);
    }

    // The cell tree is built by the first search: once per run
    mesh.findCell(points[0]);

    scalar setup = GREAT, perPoint = GREAT;
    vector sum(Zero);
    label found = 0;
    for (label round = 0; round < nRounds; ++round)
    {
        const auto t0 = std::chrono::steady_clock::now();
        autoPtr<interpolation<vector>> interp
        (
            interpolation<vector>::New("cellPoint", U)
        );
        // cellPoint interpolates to the mesh points when first used
        sum += interp->interpolate(mesh.C()[0], 0);
        const auto t1 = std::chrono::steady_clock::now();
        found = 0;
        forAll(points, i)
        {
            const label celli = mesh.findCell(points[i]);
            if (celli >= 0)
            {
                sum += interp->interpolate(points[i], celli);
                ++found;
            }
        }
        const auto t2 = std::chrono::steady_clock::now();
        setup = min(setup, seconds(t0, t1));
        perPoint = min(perPoint, seconds(t1, t2)/nPoints);
    }

    Info<< "cells " << mesh.nCells()
        << " points " << nPoints << " (in the mesh: " << found << ")"
        << " setup_s " << setup
        << " per_point_s " << perPoint
        << " checksum " << mag(sum) << endl;

    return 0;
}


// ************************************************************************* //
