// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).

#include "implicitNewmarkState.H"
#include "implicitNewmark.H"
#include "Time.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace RBD
{
namespace rigidBodySolvers
{
    defineTypeNameAndDebug(implicitNewmarkState, 0);
}
}
}


// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The entries of the file
const Foam::wordList entries
({
    "tSolve", "aBar", "converged", "stepFailed", "nFailedSteps",
    "jacobianDeltaT", "jacobianSize", "jacobian", "pivots"
});

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::RBD::rigidBodySolvers::implicitNewmarkState::implicitNewmarkState
(
    const Time& runTime,
    implicitNewmark& solver,
    const bool fresh
)
:
    restartFiles::stateFile
    (
        IOobject
        (
            "implicitNewmark",
            runTime.timeName(),
            "uniform",
            runTime,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        )
    ),
    solver_(solver)
{
    if (!Pstream::master())
    {
        return;
    }

    if (fresh)
    {
        if (restartFiles::restarted(runTime, instance()))
        {
            Info<< "Rigid-body solver implicitNewmark: restart fresh: its"
                << " memory (Newton matrix, algorithmic acceleration) starts"
                << " anew, " << objectPath() << " is not read" << endl;
        }
        return;
    }

    restartFiles::require
    (
        runTime,
        instance(),
        local()/name(),
        entries,
        "the state of the rigid-body solver implicitNewmark",
        " (or, if the run that wrote it used another rigid-body solver, set"
        " 'restart fresh;' in the solver dictionary: implicitNewmark then"
        " starts its memory anew, and the restarted run is not bit for bit"
        " the uninterrupted one)"
    );

    if (isFile(objectPath()))
    {
        readData(readStream(typeName));
        close();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

bool Foam::RBD::rigidBodySolvers::implicitNewmarkState::readData(Istream& is)
{
    const dictionary dict(is);

    implicitNewmark& s = solver_;
    s.tSolve_ = dict.get<scalar>("tSolve");
    s.aBar_ = dict.get<scalarField>("aBar");
    s.converged_ = dict.get<bool>("converged");
    s.stepFailed_ = dict.get<bool>("stepFailed");
    s.nFailedSteps_ = dict.get<label>("nFailedSteps");
    s.jacobianDeltaT_ = dict.get<scalar>("jacobianDeltaT");

    const label n = dict.get<label>("jacobianSize");
    const scalarList jacobian(dict.get<scalarList>("jacobian"));
    s.pivots_ = dict.get<labelList>("pivots");
    if (jacobian.size() != n*n || s.pivots_.size() != n)
    {
        FatalIOErrorInFunction(dict)
            << "the Newton matrix of size " << n << " needs " << n*n
            << " entries and " << n << " pivots, the file has "
            << jacobian.size() << " and " << s.pivots_.size()
            << exit(FatalIOError);
    }
    s.jacobian_ = scalarSquareMatrix(n);
    forAll(jacobian, k)
    {
        s.jacobian_(k/n, k%n) = jacobian[k];
    }

    return true;
}


bool Foam::RBD::rigidBodySolvers::implicitNewmarkState::writeData
(
    Ostream& os
) const
{
    const implicitNewmark& s = solver_;
    const label n = s.jacobian_.m();
    scalarList jacobian(n*n);
    forAll(jacobian, k)
    {
        jacobian[k] = s.jacobian_(k/n, k%n);
    }

    // Every digit: a restart continues bit for bit
    const label precision = os.precision(17);
    os.writeEntry("tSolve", s.tSolve_);
    os.writeEntry("aBar", s.aBar_);
    os.writeEntry("converged", s.converged_);
    os.writeEntry("stepFailed", s.stepFailed_);
    os.writeEntry("nFailedSteps", s.nFailedSteps_);
    os.writeEntry("jacobianDeltaT", s.jacobianDeltaT_);
    os.writeEntry("jacobianSize", n);
    os.writeEntry("jacobian", jacobian);
    os.writeEntry("pivots", s.pivots_);
    os.precision(precision);

    return os.good();
}


// ************************************************************************* //
