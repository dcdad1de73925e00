// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
/*---------------------------------------------------------------------------*\
Application
    rigidBodySim

Description
    Integrates a rigidBodyMotion model with no fluid: the bodies move under
    gravity and their restraints (built-in ones and fmuConnector ones) only.
    The model is the rigidBodyMotionCoeffs dictionary of
    constant/dynamicMeshDict, so the rigid-body part of a CFD case can be run
    on its own, or any dictionary given with -dict. Time control (startTime,
    endTime, deltaT, writeControl) comes from system/controlDict as usual.

    Each time step calls the model's solve nIter times (-nIter, default 1),
    as the PIMPLE outer correctors of a CFD run do. At every write time the
    rigid-body state is written to <time>/uniform/rigidBodyMotionState (the
    file a CFD run restarts from), so a run restarts from any written time.

    Output: postProcessing/rigidBodySim/<startTime>/bodies.dat with, per
    time step and per body, the centre of mass, its velocity, the angular
    velocity and the orientation tensor (global frame, row by row), each
    row written when its time step is complete.

    A run that starts from a time written by an earlier run needs that
    time's rigid-body state, complete: a missing or cut short state file
    is a FatalIOError naming the previous complete time. The state file is
    written to a temporary name and renamed, so a kill never leaves half of
    it.

Usage
    rigidBodySim [-dict <file>] [-nIter <n>] [-case <dir>]
\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "rigidBodyMotion.H"
#include "rigidBody.H"
#include "restartFiles.H"
#include "bodySim.H"

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- The model dictionary: -dict <file>, or rigidBodyMotionCoeffs of
//  constant/dynamicMeshDict
dictionary modelDict(const argList& args, const Time& runTime)
{
    if (args.found("dict"))
    {
        const fileName file(args.get<fileName>("dict"));
        IOobject io
        (
            file.name(),
            file.path(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        );
        return IOdictionary(io);
    }

    const IOdictionary dynamicMeshDict
    (
        bodySim::constantIO(runTime, "dynamicMeshDict")
    );
    return dynamicMeshDict.subDict("rigidBodyMotionCoeffs");
}


//- The rigid-body state written at the start time, if there is one: a
//  run restarted from a time written by an earlier run must find it there,
//  complete (restartFiles::require)
autoPtr<IOdictionary> startState(const Time& runTime)
{
    restartFiles::require
    (
        runTime,
        runTime.timeName(),
        fileName("uniform")/"rigidBodyMotionState",
        wordList({"q", "qDot", "qDdot", "t", "deltaT"}),
        "the rigid-body state"
    );

    IOobject io
    (
        bodySim::uniformIO(runTime, "rigidBodyMotionState", IOobject::MUST_READ)
    );

    if (io.typeHeaderOk<IOdictionary>(true))
    {
        return autoPtr<IOdictionary>(new IOdictionary(io));
    }
    return nullptr;
}


void writeHeader(Ostream& os, const RBD::rigidBodyMotion& motion)
{
    os  << "# Time";
    for (label bodyID = 1; bodyID < motion.nBodies(); ++bodyID)
    {
        bodySim::writeBodyHeader(os, motion.name(bodyID), {"c", "v", "omega"});
    }
    os  << nl;
}


void writeRow(Ostream& os, const scalar t, const RBD::rigidBodyMotion& motion)
{
    os  << t;
    for (label bodyID = 1; bodyID < motion.nBodies(); ++bodyID)
    {
        // Centre of mass, body frame, and the body's transform
        const vector c = motion.bodies()[bodyID].c();
        const spatialTransform X0(motion.X0(bodyID));
        const spatialVector vc(motion.v(bodyID, c));

        const vector centre = X0.E().T() & c;
        bodySim::writeBodyRow
        (
            os,
            {centre + X0.r(), vc.l(), vc.w()},
            X0.E().T()
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
        "Integrate a rigidBodyMotion model without fluid"
    );
    argList::noParallel();
    argList::addOption
    (
        "dict",
        "file",
        "Model dictionary (default: rigidBodyMotionCoeffs of"
        " constant/dynamicMeshDict)"
    );
    bodySim::addNIterOption();

    #include "setRootCase.H"
    #include "createTime.H"
    #include "setNIter.H"

    const dictionary dict(modelDict(args, runTime));
    const autoPtr<IOdictionary> state(startState(runTime));

    RBD::rigidBodyMotion motion
    (
        runTime,
        dict,
        state.valid() ? static_cast<const dictionary&>(*state) : dict
    );

    Info<< "Model with " << motion.nBodies() - 1 << " bodies, "
        << motion.nDoF() << " degrees of freedom, " << nIter
        << " solve(s) per time step" << nl << endl;

    autoPtr<rowFile> bodiesPtr
    (
        bodySim::newBodiesTable(runTime, "rigidBodySim")
    );
    rowFile& bodies = *bodiesPtr;
    bodySim::appendRows
    (
        bodies,
        "the header and " + bodySim::rowOf(runTime.value()),
        [&](Ostream& os)
        {
            writeHeader(os, motion);
            writeRow(os, runTime.value(), motion);
        }
    );

    // No fluid: no joint forces and no external body forces
    const scalarField tau(motion.nDoF(), Zero);
    const Field<spatialVector> fx(motion.nBodies(), Zero);

    while (runTime.run())
    {
        ++runTime;

        motion.newTime();
        for (label iter = 0; iter < nIter; ++iter)
        {
            motion.solve(runTime.value(), runTime.deltaTValue(), tau, fx);
        }

        // The step is complete: its row reaches the file now, so that a run
        // ended by an error, a crash or a kill keeps it
        bodySim::appendRows
        (
            bodies,
            bodySim::rowOf(runTime.value()),
            [&](Ostream& os) { writeRow(os, runTime.value(), motion); }
        );

        // OpenFOAM's uniform/time first: a time directory that has it is
        // known to be written by a run, and a restart from it checks that
        // the state below is there and complete
        runTime.write();
        if (runTime.writeTime())
        {
            IOdictionary stateDict
            (
                bodySim::uniformIO(runTime, "rigidBodyMotionState")
            );
            motion.state().write(stateDict);
            restartFiles::write(stateDict, "the rigid-body state");
        }

        if (motion.report())
        {
            for (label bodyID = 1; bodyID < motion.nBodies(); ++bodyID)
            {
                motion.status(bodyID);
            }
        }
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
