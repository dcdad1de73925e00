// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
/*---------------------------------------------------------------------------*\
Application
    sixDoFSim

Description
    Integrates bodies moved by OpenFOAM's sixDoFRigidBodyMotion with no
    fluid: each body under gravity and its restraints (built-in ones and
    fmuConnector ones) only, as rigidBodySim does for rigidBodyMotion.

    The bodies are the entries of 'bodies' in constant/sixDoFBodies, each a
    sixDoFRigidBodyMotion dictionary (mass, momentOfInertia, centreOfMass,
    solver, restraints, ...) named by its keyword, as the patch name names
    a body of the sixDoFRigidBodyDisplacement condition; 'g' is gravity
    (default none). Time control comes from system/controlDict. The bodies
    are solved one after the other in their order in the file, each
    nIter times per time step (-nIter, default 1) in rounds, as PIMPLE
    outer correctors move the patches of a CFD run.

    At every write time the bodies' dictionaries with their current state
    are written to <time>/uniform/sixDoFBodies, as the point-patch condition
    writes its motion into the field file; a run that starts from a time
    with that file continues from it. A run that starts from a time written
    by an earlier run needs it, complete: a missing or cut short file is a
    FatalIOError naming the previous complete time. It is written to a
    temporary name and renamed, so a kill never leaves half of it.

    Output: postProcessing/sixDoFSim/<startTime>/bodies.dat with, per time
    step and per body, the centre of rotation, centre of mass, velocity
    (of the centre of rotation), angular velocity and orientation tensor
    (global frame, row by row).

Usage
    sixDoFSim [-nIter <n>] [-copyDicts] [-case <dir>]

    -copyDicts constructs each motion from a copy of its dictionary, as a
    sixDoFRigidBodyMotion solver of dynamicMeshDict does (its coefficients
    are a copy with no parent): a restraint cannot reach the case's time
    through its dictionary then, and the fmuConnector restraint loads its
    FMU at the first evaluation.
\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "sixDoFRigidBodyMotion.H"
#include "restartFiles.H"
#include "bodySim.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- The bodies' file: <startTime>/uniform/sixDoFBodies when it exists (a
//  restart), constant/sixDoFBodies otherwise. A run restarted from a time
//  written by an earlier run must find it there, complete
//  (restartFiles::require)
IOobject bodiesIO(const Time& runTime)
{
    restartFiles::require
    (
        runTime,
        runTime.timeName(),
        fileName("uniform")/"sixDoFBodies",
        wordList({"bodies"}),
        "the bodies' state"
    );

    IOobject restart
    (
        bodySim::uniformIO(runTime, "sixDoFBodies", IOobject::MUST_READ)
    );
    if (restart.typeHeaderOk<IOdictionary>(true))
    {
        return restart;
    }
    return bodySim::constantIO(runTime, "sixDoFBodies");
}


void writeHeader(Ostream& os, const wordList& names)
{
    os  << "# Time";
    for (const word& name : names)
    {
        bodySim::writeBodyHeader(os, name, {"r", "c", "v", "omega"});
    }
    os  << nl;
}


void writeRow
(
    Ostream& os,
    const scalar t,
    const PtrList<sixDoFRigidBodyMotion>& motions
)
{
    os  << t;
    for (const sixDoFRigidBodyMotion& m : motions)
    {
        bodySim::writeBodyRow
        (
            os,
            {m.centreOfRotation(), m.centreOfMass(), m.v(), m.omega()},
            m.orientation()
        );
    }
    os  << nl;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Integrate sixDoFRigidBodyMotion bodies without fluid"
    );
    argList::noParallel();
    argList::addBoolOption
    (
        "copyDicts",
        "Construct each motion from a copy of its dictionary, as a"
        " sixDoFRigidBodyMotion solver does: restraints cannot reach the"
        " case's time through it"
    );
    bodySim::addNIterOption();

    #include "setRootCase.H"
    #include "createTime.H"
    #include "setNIter.H"

    // Kept for the whole run: the restraints find the case's time through
    // the file their dictionaries belong to
    const IOdictionary bodiesDict(bodiesIO(runTime));
    Info<< "Bodies from " << bodiesDict.objectPath() << nl << endl;

    const vector g(bodiesDict.lookupOrDefault<vector>("g", Zero));
    const dictionary& bodies = bodiesDict.subDict("bodies");

    wordList names;
    PtrList<sixDoFRigidBodyMotion> motions;
    for (const entry& e : bodies)
    {
        if (e.isDict())
        {
            names.append(e.keyword());
            if (args.found("copyDicts"))
            {
                const dictionary copy(e.dict());
                motions.append
                (
                    new sixDoFRigidBodyMotion(copy, copy, runTime)
                );
            }
            else
            {
                motions.append
                (
                    new sixDoFRigidBodyMotion(e.dict(), e.dict(), runTime)
                );
            }
        }
    }

    Info<< motions.size() << " bodies " << names << ", " << nIter
        << " solve(s) per time step" << nl << endl;

    autoPtr<rowFile> outPtr(bodySim::newBodiesTable(runTime, "sixDoFSim"));
    rowFile& out = *outPtr;
    bodySim::appendRows
    (
        out,
        "the header and " + bodySim::rowOf(runTime.value()),
        [&](Ostream& os)
        {
            writeHeader(os, names);
            writeRow(os, runTime.value(), motions);
        }
    );

    while (runTime.run())
    {
        ++runTime;

        for (sixDoFRigidBodyMotion& m : motions)
        {
            m.newTime();
        }
        for (label iter = 0; iter < nIter; ++iter)
        {
            for (sixDoFRigidBodyMotion& m : motions)
            {
                m.update
                (
                    iter == 0,
                    m.mass()*g,
                    m.mass()*(m.momentArm() ^ g),
                    runTime.deltaTValue(),
                    runTime.deltaT0Value()
                );
            }
        }

        // The step is complete: its row reaches the file now, so that a run
        // ended by an error, a crash or a kill keeps it
        bodySim::appendRows
        (
            out,
            bodySim::rowOf(runTime.value()),
            [&](Ostream& os) { writeRow(os, runTime.value(), motions); }
        );

        // OpenFOAM's uniform/time first: a time directory that has it is
        // known to be written by a run, and a restart from it checks that
        // the state below is there and complete
        runTime.write();
        if (runTime.writeTime())
        {
            IOdictionary state
            (
                bodySim::uniformIO(runTime, "sixDoFBodies"),
                bodiesDict
            );
            dictionary& stateBodies = state.subDict("bodies");
            forAll(names, i)
            {
                dictionary& b = stateBodies.subDict(names[i]);
                for
                (
                    const word key
                  : {
                        "centreOfRotation", "orientation", "velocity",
                        "acceleration", "angularMomentum", "torque"
                    }
                )
                {
                    b.remove(key);
                }
                motions[i].state().write(b);
            }
            restartFiles::write(state, "the bodies' state");
        }
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
