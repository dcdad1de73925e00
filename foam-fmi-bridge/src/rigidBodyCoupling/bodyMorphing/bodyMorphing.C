// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "bodyMorphing.H"
#include "pointPatchDist.H"
#include "pointConstraints.H"
#include "polyMesh.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- Distance of every point of points0 to the faces of the patches in
//  patchSet (their points at points0), each coordinate multiplied by the
//  component of s first; the faces of every processor
Foam::tmp<Foam::scalarField> scaledDistance
(
    const Foam::polyMesh& mesh,
    const Foam::labelHashSet& patchSet,
    const Foam::pointField& points0,
    const Foam::vector& s
)
{
    using namespace Foam;

    // This processor's patch faces, with their points scaled
    DynamicList<point> localPoints;
    DynamicList<face> localFaces;
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
            face g(f);
            forAll(g, i)
            {
                g[i] += offset;
            }
            localFaces.append(g);
        }
    }

    List<pointField> patchPoints(Pstream::nProcs());
    List<faceList> patchFaces(Pstream::nProcs());
    patchPoints[Pstream::myProcNo()] = localPoints;
    patchFaces[Pstream::myProcNo()] = localFaces;
    Pstream::gatherList(patchPoints);
    Pstream::scatterList(patchPoints);
    Pstream::gatherList(patchFaces);
    Pstream::scatterList(patchFaces);

    tmp<scalarField> tdist(new scalarField(points0.size(), GREAT));
    scalarField& dist = tdist.ref();
    forAll(points0, pointi)
    {
        const point p(cmptMultiply(s, points0[pointi]));
        forAll(patchFaces, proci)
        {
            for (const face& f : patchFaces[proci])
            {
                dist[pointi] = min
                (
                    dist[pointi],
                    f.nearestPoint(p, patchPoints[proci]).distance()
                );
            }
        }
    }
    return tdist;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Global Functions  * * * * * * * * * * * * * //

Foam::vector Foam::bodyMorphing::readDistanceScale(const dictionary& dict)
{
    const vector s(dict.lookupOrDefault<vector>("distanceScale", vector::one));
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
        tdist = scaledDistance(pMesh(), patchSet, points0, distanceScale);
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
