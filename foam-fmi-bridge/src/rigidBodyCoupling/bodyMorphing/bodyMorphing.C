// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "bodyMorphing.H"
#include "pointPatchDist.H"
#include "pointConstraints.H"
#include "polyMesh.H"
#include "mathematicalConstants.H"
#include "triSurface.H"
#include "triSurfaceSearch.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- Distance of every point of points0 to the faces of the patches in
//  patchSet (their points at points0), each coordinate multiplied by the
//  component of s first, up to within: GREAT beyond. The faces of every
//  processor, triangulated about their centres (as face::nearestPoint),
//  searched by OpenFOAM's octree (triSurfaceSearch)
Foam::tmp<Foam::scalarField> scaledDistance
(
    const Foam::polyMesh& mesh,
    const Foam::labelHashSet& patchSet,
    const Foam::pointField& points0,
    const Foam::vector& s,
    const Foam::scalar within
)
{
    using namespace Foam;

    // This processor's patch faces as triangles about their centres, the
    // points scaled
    DynamicList<point> localPoints;
    DynamicList<triFace> localTriangles;
    for (const label patchi : patchSet)
    {
        const polyPatch& pp = mesh.boundaryMesh()[patchi];
        const label offset = localPoints.size();
        for (const label pointi : pp.meshPoints())
        {
            localPoints.append(cmptMultiply(s, points0[pointi]));
        }
        for (const face& f : pp.localFaces())
        {
            // the face's points are the patch's, from offset on
            const point c
            (
                f.centre(SubList<point>(localPoints, pp.nPoints(), offset))
            );
            const label centre = localPoints.size();
            localPoints.append(c);
            forAll(f, i)
            {
                localTriangles.append
                (
                    triFace(centre, offset + f[i], offset + f.nextLabel(i))
                );
            }
        }
    }

    List<pointField> procPoints(Pstream::nProcs());
    List<triFaceList> procTriangles(Pstream::nProcs());
    procPoints[Pstream::myProcNo()] = localPoints;
    procTriangles[Pstream::myProcNo()] = localTriangles;
    // Pstream::scatterList is deprecated in v2506 for allGatherList (in
    // v2312)
    #if OPENFOAM >= 2312
    Pstream::allGatherList(procPoints);
    Pstream::allGatherList(procTriangles);
    #else
    Pstream::gatherList(procPoints);
    Pstream::scatterList(procPoints);
    Pstream::gatherList(procTriangles);
    Pstream::scatterList(procTriangles);
    #endif

    // All processors' triangles in one surface
    DynamicList<point> points;
    DynamicList<triFace> triangles;
    forAll(procPoints, proci)
    {
        const label offset = points.size();
        points.append(procPoints[proci]);
        for (const triFace& t : procTriangles[proci])
        {
            triangles.append
            (
                triFace(t[0] + offset, t[1] + offset, t[2] + offset)
            );
        }
    }

    tmp<scalarField> tdist(new scalarField(points0.size(), GREAT));
    if (triangles.empty())
    {
        return tdist;
    }
    const triSurface surface{triFaceList(triangles), pointField(points)};
    const triSurfaceSearch search(surface);

    const pointField samples(cmptMultiply(s, points0));
    List<pointIndexHit> nearest;
    search.findNearest
    (
        samples,
        scalarField(samples.size(), sqr(within)),
        nearest
    );

    scalarField& dist = tdist.ref();
    forAll(nearest, pointi)
    {
        if (nearest[pointi].hit())
        {
            dist[pointi] = mag(nearest[pointi].hitPoint() - samples[pointi]);
        }
    }
    return tdist;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::vector Foam::bodyMorphing::readDistanceScale(const dictionary& dict)
{
    const vector s
    (
        dict.lookupOrDefault<vector>("distanceScale", vector::one)
    );
    if (cmptMin(s) <= 0)
    {
        FatalIOErrorInFunction(dict)
            << "distanceScale " << s << " in " << dict.name()
            << ": expected the factors of the coordinates in the morphing"
            << " distance, each > 0 (default (1 1 1))"
            << exit(FatalIOError);
    }
    return s;
}


void Foam::bodyMorphing::weights
(
    pointScalarField& scale,
    const labelHashSet& patchSet,
    const pointField& points0,
    const scalar di,
    const scalar do_,
    const vector& distanceScale
)
{
    const pointMesh& pMesh = scale.mesh();

    tmp<scalarField> tdist;
    if (distanceScale == vector::one)
    {
        pointPatchDist pDist(pMesh, patchSet, points0);
        tdist = tmp<scalarField>::New(pDist.primitiveField());
    }
    else
    {
        // Beyond do_ the weight is 0 whatever the distance
        tdist =
            scaledDistance(pMesh(), patchSet, points0, distanceScale, do_);
    }

    // Scaling: 1 up to di then linear down to 0 at do away from patches
    scale.primitiveFieldRef() =
        min(max((do_ - tdist())/(do_ - di), scalar(0)), scalar(1));

    // Convert the scale function to a cosine
    scale.primitiveFieldRef() =
        min
        (
            max
            (
                0.5
              - 0.5
               *cos(scale.primitiveField()
               *Foam::constant::mathematical::pi),
                scalar(0)
            ),
            scalar(1)
        );

    pointConstraints::New(pMesh).constrain(scale);
}


// ************************************************************************* //
