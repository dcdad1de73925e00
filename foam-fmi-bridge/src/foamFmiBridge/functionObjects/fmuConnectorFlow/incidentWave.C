// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "incidentWave.H"
#include "waveModel.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

// What gives a Stokes wave model's velocity at a point is protected in
// OpenFOAM's classes (the model computes it for its patch's faces only):
// the velocity of its wave theory (StokesI::UfBase, virtual: StokesII and
// StokesV give theirs), the ramp, the wave's parameters and the patch's
// frame. A class derived from StokesI may name them; the pointers to
// members it forms are pointers to members of the base classes, which
// apply to the patch's model. The class itself is never made.
struct stokesMembers
:
    public waveModels::StokesI
{
    using waveModel::Rgl_;
    using waveModel::Rlg_;
    using waveModel::zMin0_;
    using waveModel::waterDepthRef_;
    using waveModel::timeCoeff;
    using waveModels::regularWaveModel::waveHeight_;
    using waveModels::regularWaveModel::waveAngle_;
    using waveModels::regularWaveModel::wavePeriod_;
    using waveModels::regularWaveModel::waveLength_;
    using waveModels::regularWaveModel::wavePhase_;
    using waveModels::StokesI::UfBase;
};


const waveModels::StokesI& stokesModel
(
    const fvMesh& mesh,
    const dictionary& dict,
    const word& entry,
    const word& patchName
)
{
    const label patchi = mesh.boundaryMesh().findPatchID(patchName);
    if (patchi < 0)
    {
        FatalIOErrorInFunction(dict)
            << "entry " << entry << " names patch " << patchName
            << ", which is not a patch of the mesh; expected the patch"
            << " whose entry in constant/waveProperties generates the waves"
            << " (the patches: " << mesh.boundaryMesh().names() << ")"
            << exit(FatalIOError);
    }

    // The model the patch's boundary conditions find, made now if they
    // have not made it yet
    const waveModel& model =
        waveModel::lookupOrCreate
        (
            mesh.boundaryMesh()[patchi],
            mesh,
            waveModel::dictName
        )();

    const auto* stokes = dynamic_cast<const waveModels::StokesI*>(&model);
    if (!stokes)
    {
        FatalIOErrorInFunction(dict)
            << "entry " << entry << " names patch " << patchName
            << ", whose waveModel in constant/waveProperties is "
            << model.type() << "; expected a regular Stokes wave (StokesI,"
            << " StokesII or StokesV), whose velocity is known everywhere"
            << exit(FatalIOError);
    }
    return *stokes;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::incidentWave::incidentWave
(
    const fvMesh& mesh,
    const dictionary& dict,
    const word& entry
)
:
    patchName_(dict.get<word>(entry)),
    model_(stokesModel(mesh, dict, entry, patchName_))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::vector Foam::incidentWave::U(const point& p, const scalar t) const
{
    using m = stokesMembers;
    const waveModels::StokesI& w = model_;

    // In the patch's frame (x along the waves generated, z up, about the
    // global origin), the height from the patch's lowest point, as the
    // model takes its faces' (waveModel::setPaddlePropeties)
    const vector local(w.*(&m::Rgl_) & p);
    const scalar depth = w.*(&m::waterDepthRef_);
    const scalar z = min(max(local.z() - w.*(&m::zMin0_), scalar(0)), depth);

    // The wave's numbers as the model's setVelocity computes them
    const scalar omega = constant::mathematical::twoPi/(w.*(&m::wavePeriod_));
    const scalar k = constant::mathematical::twoPi/(w.*(&m::waveLength_));
    const scalar angle = w.*(&m::waveAngle_);

    const vector Ulocal =
        (w.*(&m::UfBase))
        (
            w.*(&m::waveHeight_),
            depth,
            k*cos(angle),
            local.x(),
            k*sin(angle),
            local.y(),
            omega,
            t,
            w.*(&m::wavePhase_),
            z
        );

    return (w.*(&m::timeCoeff))(t)*(w.*(&m::Rlg_) & Ulocal);
}


Foam::vector Foam::incidentWave::acceleration
(
    const point& p,
    const scalar t
) const
{
    const scalar dt = 1e-4*(model_.*(&stokesMembers::wavePeriod_));
    return (U(p, t + dt) - U(p, t - dt))/(2*dt);
}


Foam::vector Foam::incidentWave::up() const
{
    using m = stokesMembers;
    // The frame's z axis (against gravity): the third row of the tensor
    // made of the frame's axes (waveModel::initialiseGeometry)
    return (model_.*(&m::Rlg_)).z();
}


Foam::string Foam::incidentWave::describe() const
{
    return string(model_.type()) + " wave of patch " + patchName_;
}


// ************************************************************************* //
