// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
/*---------------------------------------------------------------------------*\
Description
    The added-mass coupling's state in the time directories: the added
    mass in use written with the bodies' state, read back at a restart,
    and the check that a restart's state file is complete.
\*---------------------------------------------------------------------------*/

#include "addedMassCoupling.H"
#include "restartFiles.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::addedMassCoupling::readState
(
    const dictionary& state,
    const label nBodies
)
{
    const word key
    (
        state.found("addedMassBody", keyType::LITERAL)
      ? "addedMassBody"
      : "addedMass"
    );

    scalarSquareMatrix M;
    if (!state.readIfPresent(key, M))
    {
        return;
    }

    if (M.m() != 6*nBodies)
    {
        FatalIOErrorInFunction(state)
            << solverType_ << ": the state's added-mass matrix '"
            << key << "' has " << M.m() << " rows, "
            << 6*nBodies << " expected (6 for each of the "
            << nBodies << " bodies with patches): the state was"
            << " written for other bodies" << exit(FatalIOError);
    }

    if (key == "addedMassBody")
    {
        Mbody_ = M;
    }
    else
    {
        M_ = M;
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const Foam::dictionary& Foam::addedMassCoupling::checkedRestart
(
    const Time& runTime,
    const dictionary& coeffs,
    const fileName& stateFile,
    const wordList& stateEntries,
    const string& what
)
{
    if (!restartFiles::restarted(runTime, runTime.timeName()))
    {
        return coeffs;
    }

    // The coupling's entries are checked later (read)
    wordList entries(stateEntries);
    if
    (
        !coeffs.getOrDefault<bool>("test", false)
     && (
            !coeffs.isDict("coupling")
         || coeffs.subDict("coupling").getOrDefault<Switch>("addedMass", true)
        )
    )
    {
        entries.append("addedMass");
    }

    restartFiles::require
    (
        runTime,
        runTime.timeName(),
        stateFile,
        entries,
        what
    );

    return coeffs;
}


void Foam::addedMassCoupling::writeState(dictionary& state) const
{
    // The added mass in use (global axes) and the last estimate in the
    // bodies' axes, from which a restart between two estimates goes on
    if (addedMass_ && M_.m())
    {
        state.add("addedMass", M_);
    }
    if (addedMass_ && Mbody_.m())
    {
        state.add("addedMassBody", Mbody_);
    }
}


void Foam::addedMassCoupling::writeStateFile
(
    const word& name,
    const dictionary& motionState,
    const string& what
) const
{
    IOdictionary dict
    (
        IOobject
        (
            name,
            mesh_.time().timeName(),
            "uniform",
            mesh_,
            IOobject::NO_READ,
            IOobject::NO_WRITE,
            false
        )
    );

    dict.merge(motionState);
    writeState(dict);

    // ASCII, to a temporary file renamed over the state file: a kill
    // leaves the old file or the new one, never half of it
    restartFiles::write(dict, "the " + what);
}


void Foam::addedMassCoupling::writeState(Ostream& os) const
{
    dictionary state;
    writeState(state);
    for (const entry& e : state)
    {
        e.write(os);
    }
}


// ************************************************************************* //
