// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "fmuConnectorFlow.H"
#include "fmuConnectorCore.H"
#include "interpolation.H"
#include "volFields.H"
#include "surfaceFields.H"
#include "fvcReconstruct.H"
#include "fvcSnGrad.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::List<Foam::labelList>
Foam::functionObjects::fmuConnectorFlow::findCells
(
    const List<pointField>& points
) const
{
    List<labelList> cells(points.size());
    forAll(points, i)
    {
        cells[i].setSize(points[i].size());
        forAll(points[i], k)
        {
            cells[i][k] = mesh_.findCell(points[i][k]);
        }
    }
    return cells;
}


Foam::List<Foam::vectorField>
Foam::functionObjects::fmuConnectorFlow::sample
(
    const List<pointField>& points,
    const List<labelList>& cells,
    const volVectorField& field,
    vector (incidentWave::*wave)(const point&, scalar) const
) const
{
    // Each processor samples the points in its cells; a point on a
    // processor boundary may be found by two, whose values are averaged
    autoPtr<interpolation<vector>> interp
    (
        interpolation<vector>::New(scheme_, field)
    );
    List<vectorField> sums(points.size());
    List<scalarField> counts(points.size());
    forAll(points, i)
    {
        sums[i].setSize(points[i].size(), Zero);
        counts[i].setSize(points[i].size(), Zero);
        forAll(points[i], k)
        {
            const label celli = cells[i][k];
            if (celli >= 0)
            {
                sums[i][k] = interp->interpolate(points[i][k], celli);
                counts[i][k] = 1;
            }
        }
    }
    Pstream::listCombineGather(sums, plusEqOp<vectorField>());
    Pstream::listCombineGather(counts, plusEqOp<scalarField>());

    List<vectorField> values(points.size());
    if (Pstream::master())
    {
        const scalar t = time_.value();
        forAll(points, i)
        {
            values[i] = sums[i]/max(counts[i], scalar(1));
            forAll(points[i], k)
            {
                // The wave's share beyond the mesh and in the hand-over
                const scalar w = wave_ ? waveWeight(points[i][k]) : 0;
                if (w > 0)
                {
                    values[i][k] =
                        w*(wave_().*wave)(points[i][k], t)
                      + (1 - w)*values[i][k];
                }
            }
        }
    }
    return values;
}


Foam::FixedList<Foam::List<Foam::vectorField>, 2>
Foam::functionObjects::fmuConnectorFlow::sampleFlow
(
    const List<pointField>& points
) const
{
    // The cell of each point, found once for both fields
    const List<labelList> cells(findCells(points));
    FixedList<List<vectorField>, 2> flows;
    flows[0] = sample
    (
        points, cells, lookupObject<volVectorField>(UName_), &incidentWave::U
    );
    if (acceleration_)
    {
        flows[1] = sample
        (
            points, cells, waterAcceleration()(), &incidentWave::acceleration
        );
    }
    return flows;
}


Foam::tmp<Foam::volVectorField>
Foam::functionObjects::fmuConnectorFlow::waterAcceleration() const
{
    wordList missing;
    for (const word field : {"p_rgh", "rho"})
    {
        if (!foundObject<volScalarField>(field))
        {
            missing.append(field);
        }
    }
    if (!foundObject<surfaceScalarField>("ghf"))
    {
        missing.append("ghf");
    }
    if (missing.size())
    {
        FatalErrorInFunction
            << "function object " << name() << ": acceleration needs the"
            << " fields p_rgh, rho and ghf of a volume-of-fluid solver"
            << " (interFoam and its relatives); this solver has no "
            << missing << exit(FatalError);
    }
    const volScalarField& p_rgh = lookupObject<volScalarField>("p_rgh");
    const volScalarField& rho = lookupObject<volScalarField>("rho");
    const surfaceScalarField& ghf = lookupObject<surfaceScalarField>("ghf");

    // The force per volume of the solver's momentum equation but for the
    // viscous, convective and surface-tension terms, over the density
    tmp<volVectorField> ta
    (
        fvc::reconstruct
        (
            (-ghf*fvc::snGrad(rho) - fvc::snGrad(p_rgh))*mesh_.magSf()
        )/rho
    );
    ta.ref().rename("waterAcceleration");
    return ta;
}


Foam::scalar Foam::functionObjects::fmuConnectorFlow::waveWeight
(
    const point& p
) const
{
    // The distance inside the bounds, across gravity
    scalar d = GREAT;
    for (direction c = 0; c < vector::nComponents; ++c)
    {
        if (horizontal_[c])
        {
            d = min(d, min(p[c] - bounds_.min()[c], bounds_.max()[c] - p[c]));
        }
    }
    if (d <= 0)
    {
        return 1;
    }
    if (d >= blendWidth_)
    {
        return 0;
    }
    return 0.5*(1 + cos(constant::mathematical::pi*d/blendWidth_));
}


void Foam::functionObjects::fmuConnectorFlow::setFlow
(
    const label i,
    const FixedList<List<vectorField>, 2>& flows
) const
{
    fmuConnectorCore& core = *fmuConnectorCore::find(time_, connectors_[i]);
    core.setFlow(flows[0][i]);
    if (acceleration_)
    {
        core.setAcceleration(flows[1][i]);
    }
}


// ************************************************************************* //
