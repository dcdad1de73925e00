// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
/*---------------------------------------------------------------------------*\
    The point check, constraints, state writing and reading follow OpenFOAM
    v1912's rigidBodyMeshMotion and sixDoFRigidBodyMotionSolver (GPL v3,
    OpenCFD Ltd. and the OpenFOAM Foundation).
\*---------------------------------------------------------------------------*/

#include "addedMassMotionSolver.H"
#include "fvMesh.H"
#include "pointConstraints.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::addedMassMotionSolver::addedMassMotionSolver
(
    const polyMesh& mesh,
    const IOdictionary& dict,
    const word& type,
    const word& stateName,
    const string& stateDescription
)
:
    displacementMotionSolver(mesh, dict, type),
    stateName_(stateName),
    stateDescription_(stateDescription),
    coupling_(type, refCast<const fvMesh>(mesh))
{
    // Written at every write time, whichever mesh constructed the solver:
    // v2312's dynamicMotionSolverListFvMesh (and so dynamicOversetFvMesh)
    // hands a dynamicMeshDict without "solvers" to its one motion solver
    // as NO_WRITE, and the motion state would never reach uniform/
    #if OPENFOAM >= 2206
    writeOpt(IOobject::AUTO_WRITE);
    #else
    writeOpt() = IOobject::AUTO_WRITE;
    #endif
}


// * * * * * * * * * * * * * Protected Member Functions * * * * * * * * * * * //

Foam::IOobject Foam::addedMassMotionSolver::stateIO() const
{
    return IOobject
    (
        stateName_,
        mesh().time().timeName(),
        "uniform",
        mesh(),
        IOobject::READ_IF_PRESENT,
        IOobject::NO_WRITE,
        false
    );
}


const Foam::dictionary& Foam::addedMassMotionSolver::restartCoeffs
(
    const wordList& stateEntries,
    const string& what
) const
{
    return addedMassCoupling::checkedRestart
    (
        mesh().time(),
        coeffDict(),
        fileName("uniform")/stateName_,
        stateEntries,
        what
    );
}


Foam::dictionary Foam::addedMassMotionSolver::initialState() const
{
    if (stateIO().typeHeaderOk<IOdictionary>(true))
    {
        return IOdictionary(stateIO());
    }

    return coeffDict();
}


void Foam::addedMassMotionSolver::readCouplingState(const label nBodies)
{
    if (stateIO().typeHeaderOk<IOdictionary>(true))
    {
        coupling_.readState(IOdictionary(stateIO()), nBodies);
    }
}


void Foam::addedMassMotionSolver::checkPoints() const
{
    if (mesh().nPoints() != points0().size())
    {
        FatalErrorInFunction
            << "The number of points in the mesh seems to have changed." << endl
            << "In constant/polyMesh there are " << points0().size()
            << " points; in the current mesh there are " << mesh().nPoints()
            << " points." << exit(FatalError);
    }
}


void Foam::addedMassMotionSolver::constrainDisplacement()
{
    pointConstraints::New
    (
        pointDisplacement_.mesh()
    ).constrainDisplacement(pointDisplacement_);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::pointField> Foam::addedMassMotionSolver::curPoints() const
{
    tmp<pointField> newPoints
    (
        points0() + pointDisplacement_.primitiveField()
    );

    if (moveAllCells())
    {
        return newPoints;
    }

    tmp<pointField> tzonePoints(new pointField(mesh().points()));
    UIndirectList<point>(tzonePoints.ref(), pointIDs()) =
        pointField(newPoints(), pointIDs());

    return tzonePoints;
}


#if OPENFOAM >= 2006
bool Foam::addedMassMotionSolver::writeObject
(
    IOstreamOption streamOpt,
    const bool valid
) const
#else
bool Foam::addedMassMotionSolver::writeObject
(
    IOstream::streamFormat fmt,
    IOstream::versionNumber ver,
    IOstream::compressionType cmp,
    const bool valid
) const
#endif
{
    dictionary state;
    writeMotionState(state);
    coupling_.writeStateFile(stateName_, state, stateDescription_);

    return true;
}


bool Foam::addedMassMotionSolver::read()
{
    if (displacementMotionSolver::read())
    {
        readMotion();
        readCoupling();

        return true;
    }

    return false;
}


// ************************************************************************* //
