/*---------------------------------------------------------------------------*\
  foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics
-------------------------------------------------------------------------------
License
    This file is part of foam-fmi-bridge, free software under the GNU General
    Public License version 3 or later (see LICENSE at the project's top).

Application
    restraintCost

Description
    Benchmark: the cost of one evaluation of each restraint of a rigid-body
    model, side by side in one run. The model is the rigidBodyMotionCoeffs
    dictionary of constant/dynamicMeshDict. Each restraint is constructed on
    its own and evaluated in rounds that alternate between the restraints,
    so that both see the same machine load; the fastest round counts.

    Two kinds of evaluation are timed: the first of a time step (an FMU
    connector saves its state and steps) and a repeated one within the same
    step (it restores its state and steps again), as PIMPLE outer correctors
    cause.

Usage
    restraintCost [-evaluations <n>] [-rounds <n>] [-case <dir>]

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "rigidBodyMotion.H"
#include "rigidBodyRestraint.H"

#include <chrono>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- Seconds per evaluation of the restraint, for nEval evaluations: a new
//  time step every evaluation, or one time step evaluated repeatedly
scalar timeEvaluations
(
    const RBD::restraint& restraint,
    RBD::rigidBodyModelState& state,
    scalarField& tau,
    Field<spatialVector>& fx,
    const label nEval,
    const bool newStepEach
)
{
    const auto start = std::chrono::steady_clock::now();
    for (label i = 0; i < nEval; ++i)
    {
        if (newStepEach)
        {
            state.t() += state.deltaT();
        }
        restraint.restrain(tau, fx, state);
    }
    const auto end = std::chrono::steady_clock::now();

    return std::chrono::duration<scalar>(end - start).count()/nEval;
}

} // End anonymous namespace


int main(int argc, char *argv[])
{
    argList::addNote("Cost of one evaluation of each restraint of a model");
    argList::noParallel();
    argList::addOption("evaluations", "n", "Evaluations per round (10000)");
    argList::addOption("rounds", "n", "Rounds per restraint (5)");

    #include "setRootCase.H"
    #include "createTime.H"

    const label nEval = args.getOrDefault<label>("evaluations", 10000);
    const label nRounds = args.getOrDefault<label>("rounds", 5);

    const IOdictionary dynamicMeshDict
    (
        IOobject
        (
            "dynamicMeshDict",
            runTime.constant(),
            runTime,
            IOobject::MUST_READ,
            IOobject::NO_WRITE,
            false
        )
    );
    const dictionary& dict = dynamicMeshDict.subDict("rigidBodyMotionCoeffs");
    RBD::rigidBodyMotion motion(runTime, dict);

    RBD::rigidBodyModelState state(motion.state());
    state.deltaT() = 1e-3;
    scalarField tau(motion.nDoF(), Zero);
    Field<spatialVector> fx(motion.nBodies(), Zero);

    // Each restraint on its own, constructed from the model's dictionary
    const dictionary& restraintsDict = dict.subDict("restraints");
    PtrList<RBD::restraint> restraints(restraintsDict.size());
    wordList names(restraintsDict.size());
    label ri = 0;
    for (const entry& e : restraintsDict)
    {
        names[ri] = e.keyword();
        restraints.set
        (
            ri,
            RBD::restraint::New(names[ri], e.dict(), motion).ptr()
        );
        ++ri;
    }

    scalarList newStep(restraints.size(), GREAT);
    scalarList repeated(restraints.size(), GREAT);

    for (label round = 0; round < nRounds; ++round)
    {
        forAll(restraints, i)
        {
            newStep[i] = min
            (
                newStep[i],
                timeEvaluations(restraints[i], state, tau, fx, nEval, true)
            );
            repeated[i] = min
            (
                repeated[i],
                timeEvaluations(restraints[i], state, tau, fx, nEval, false)
            );
        }
    }

    Info<< "restraint  type  new-step-ns  repeated-ns" << nl;
    forAll(restraints, i)
    {
        Info<< names[i] << ' ' << restraints[i].type() << ' '
            << 1e9*newStep[i] << ' ' << 1e9*repeated[i] << nl;
    }
    Info<< endl;

    return 0;
}


// ************************************************************************* //
