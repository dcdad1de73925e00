// foam-fmi-bridge: connector FMUs for OpenFOAM's rigid-body dynamics.
// Free software under the GNU General Public License version 3 or later
// (see LICENSE at the project's top).
/*---------------------------------------------------------------------------*\
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

    An fmuConnector with isolation process runs its FMU in a process of
    its own: a model with the same connector twice, once with isolation
    none and once with isolation process, gives the cost of the isolation
    side by side (bench/restraintCost/run.py). Its parts are timed with
    the FMU in this process all the same.

    For an fmuConnector the first evaluation of a step is also split into
    its parts, each timed on its own in the same rounds: the evaluation
    (inputs set, FMU stepped, outputs read), the state save
    (fmi2GetFMUstate into the state saved before) and the row of outputs
    (fmuConnectorOutput::record); and, within the evaluation, the switch of
    the solver's floating-point traps to masked and back
    (fmuImport::MaskFpTraps, once around the FMU calls).

    The times are the solver thread's, what a solver waits for. An
    fmuConnector's rows are formatted and written by the process's writer
    thread (fmuConnectorRows): so that the comparison stays honest, the
    CPU time of every thread per new step and per row, with the rows of
    the round written, is printed beside them, and the CPU time of the
    solver's thread alone per new step (its wait less the time another
    thread had its core).

Usage
    restraintCost [-evaluations <n>] [-rounds <n>] [-case <dir>]
\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "Time.H"
#include "IOdictionary.H"
#include "rigidBodyMotion.H"
#include "rigidBodyRestraint.H"
#include "fmuConnector.H"
#include "fmuConnectorOutput.H"
#include "fmuConnectorRows.H"
#include "fmuImport/fmuImport.hpp"
#include "bodySim.H"

#include <chrono>
#include <ctime>

using namespace Foam;

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

namespace
{

//- CPU seconds of the clock: every thread of the process, or this thread
scalar cpuSeconds(const clockid_t clock)
{
    timespec t;
    ::clock_gettime(clock, &t);
    return t.tv_sec + 1e-9*t.tv_nsec;
}

scalar processCpu()
{
    return cpuSeconds(CLOCK_PROCESS_CPUTIME_ID);
}


//- Seconds per call of f, for n calls, on the calling thread (the solver's
//  wait); with cpu, also the CPU seconds per call of every thread, with
//  the rows the calls left to the writer thread written (the whole cost),
//  and with threadCpu those of the calling thread alone
template<class Call>
scalar timeCalls
(
    const label n,
    const Call& f,
    scalar* cpu = nullptr,
    scalar* threadCpu = nullptr
)
{
    fmuConnectorRows::drainAll();
    const scalar cpuStart = processCpu();
    const scalar threadStart = cpuSeconds(CLOCK_THREAD_CPUTIME_ID);
    const auto start = std::chrono::steady_clock::now();
    for (label i = 0; i < n; ++i)
    {
        f(i);
    }
    const auto end = std::chrono::steady_clock::now();
    if (threadCpu)
    {
        *threadCpu = (cpuSeconds(CLOCK_THREAD_CPUTIME_ID) - threadStart)/n;
    }
    fmuConnectorRows::drainAll();
    if (cpu)
    {
        *cpu = (processCpu() - cpuStart)/n;
    }

    return std::chrono::duration<scalar>(end - start).count()/n;
}


//- Seconds per evaluation of the restraint, for nEval evaluations: a new
//  time step (the time and its index advanced) every evaluation, or one
//  time step evaluated repeatedly; cpu as timeCalls
scalar timeEvaluations
(
    Time& runTime,
    const RBD::restraint& restraint,
    RBD::rigidBodyModelState& state,
    scalarField& tau,
    Field<spatialVector>& fx,
    const label nEval,
    const bool newStepEach,
    scalar* cpu = nullptr,
    scalar* threadCpu = nullptr
)
{
    return timeCalls
    (
        nEval,
        [&](label)
        {
            if (newStepEach)
            {
                state.t() += state.deltaT();
                runTime.setTime(state.t(), runTime.timeIndex() + 1);
            }
            restraint.restrain(tau, fx, state);
        },
        cpu,
        threadCpu
    );
}


//- The restraint's FMU and parameters, the FMU run in this process with
//  no time limit
fmuConnectorCore::restraintEntries coreEntries(const dictionary& dict)
{
    fmuConnectorCore::restraintEntries entries;
    entries.fmu = dict.get<fileName>("fmu");
    entries.parameters = dict.subOrEmptyDict("parameters");
    return entries;
}


//- The parts of an fmuConnector's new-step evaluation, each on its own
class fmuConnectorParts
{
    fmuConnectorCore fmu_;
    fmuConnectorOutput output_;
    fmuImport::Fmu rawFmu_;
    fmuImport::Instance rawInstance_;
    fmuImport::Instance::State state_;
    scalar t_;
    label timeIndex_;
    label rowIndex_;

public:

    fmuConnectorParts
    (
        const word& name,
        const dictionary& dict,
        const Time& runTime
    )
    :
        fmu_(runTime, name, dict, coreEntries(dict), 0),
        output_("cost." + name, runTime, fmu_, "restraintCost " + name),
        rawFmu_(fmu_.file()),
        rawInstance_(rawFmu_, name),
        t_(0),
        timeIndex_(0),
        rowIndex_(0)
    {
        // Defaults of the raw instance: the state's size does not depend on
        // the parameters
        rawInstance_.setupExperiment(0);
        rawInstance_.enterInitializationMode();
        rawInstance_.exitInitializationMode();
    }

    //- Seconds per evaluation of a new step without the state save and the
    //  output row (an FMU evaluation that saves its state, minus the save)
    scalar evaluation(const label n, const scalar deltaT)
    {
        const fmuConnectorCore::kinematics A{vector(0.1, 0, 0.2), tensor::I, Zero, Zero};
        const fmuConnectorCore::kinematics B(fmuConnectorCore::kinematics::world());
        const scalar total = timeCalls
        (
            n,
            [&](label)
            {
                t_ += deltaT;
                fmu_.evaluate(++timeIndex_, t_, deltaT, A, B);
            }
        );
        return total - stateSave(n);
    }

    //- Seconds per save of the FMU state, as within an evaluation: into
    //  the state saved before, with the floating-point traps masked once
    //  around it (the evaluation's cost)
    scalar stateSave(const label n)
    {
        const fmuImport::MaskFpTraps masked;
        return timeCalls(n, [&](label) { rawInstance_.getState(state_); });
    }

    //- Seconds per switch of the floating-point traps to masked and back,
    //  as an evaluation makes it once around its FMU calls
    scalar trapMask(const label n)
    {
        return timeCalls(n, [](label) { const fmuImport::MaskFpTraps masked; });
    }

    //- Seconds per row of outputs on this thread, and the CPU seconds
    //  per row of every thread (the writer's formatting and writing). In
    //  chunks the ring holds, each begun with every row written: the
    //  solver's part when the writer keeps up, as in a run whose steps take
    //  longer than a row's formatting (in a loop of rows alone it cannot)
    scalar output(const label n, scalar& cpu)
    {
        const label chunk = 1000;
        scalar solver = 0;
        const scalar cpuStart = processCpu();
        for (label done = 0; done < n; done += chunk)
        {
            solver += chunk*timeCalls
            (
                chunk,
                [&](label) { ++rowIndex_; output_.record(rowIndex_, rowIndex_); }
            );
        }
        fmuConnectorRows::drainAll();
        cpu = (processCpu() - cpuStart)/n;
        return solver/n;
    }
};

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
        bodySim::constantIO(runTime, "dynamicMeshDict")
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

    // The parts of each fmuConnector's evaluation
    PtrList<fmuConnectorParts> parts(restraints.size());
    forAll(restraints, i)
    {
        if (isA<RBD::restraints::fmuConnector>(restraints[i]))
        {
            parts.set
            (
                i,
                new fmuConnectorParts
                (
                    names[i],
                    restraintsDict.subDict(names[i]),
                    runTime
                )
            );
        }
    }
    scalarList evaluation(restraints.size(), GREAT);
    scalarList stateSave(restraints.size(), GREAT);
    scalarList output(restraints.size(), GREAT);
    scalarList newStepCpu(restraints.size(), GREAT);
    scalarList newStepThreadCpu(restraints.size(), GREAT);
    scalarList outputCpu(restraints.size(), GREAT);
    scalarList trapMask(restraints.size(), GREAT);

    for (label round = 0; round < nRounds; ++round)
    {
        forAll(restraints, i)
        {
            scalar cpu = 0;
            scalar threadCpu = 0;
            newStep[i] = min
            (
                newStep[i],
                timeEvaluations
                (
                    runTime, restraints[i], state, tau, fx, nEval, true,
                    &cpu, &threadCpu
                )
            );
            newStepCpu[i] = min(newStepCpu[i], cpu);
            newStepThreadCpu[i] = min(newStepThreadCpu[i], threadCpu);
            repeated[i] = min
            (
                repeated[i],
                timeEvaluations(runTime, restraints[i], state, tau, fx, nEval, false)
            );
            if (parts.set(i))
            {
                evaluation[i] =
                    min(evaluation[i], parts[i].evaluation(nEval, 1e-3));
                stateSave[i] = min(stateSave[i], parts[i].stateSave(nEval));
                output[i] = min(output[i], parts[i].output(nEval, cpu));
                outputCpu[i] = min(outputCpu[i], cpu);
                trapMask[i] = min(trapMask[i], parts[i].trapMask(nEval));
            }
        }
    }

    // Parts not timed (built-in restraints) are printed as 0. The times
    // are the solver thread's; the cpu columns count every thread
    Info<< "restraint  type  new-step-ns  repeated-ns"
        << "  evaluation-ns  state-save-ns  output-ns"
        << "  new-step-cpu-ns  output-cpu-ns  new-step-thread-cpu-ns"
        << "  trap-mask-ns" << nl;
    forAll(restraints, i)
    {
        const bool split = parts.set(i);
        Info<< names[i] << ' ' << restraints[i].type() << ' '
            << 1e9*newStep[i] << ' ' << 1e9*repeated[i] << ' '
            << (split ? 1e9*evaluation[i] : 0) << ' '
            << (split ? 1e9*stateSave[i] : 0) << ' '
            << (split ? 1e9*output[i] : 0) << ' '
            << 1e9*newStepCpu[i] << ' '
            << (split ? 1e9*outputCpu[i] : 0) << ' '
            << 1e9*newStepThreadCpu[i] << ' '
            << (split ? 1e9*trapMask[i] : 0) << nl;
    }
    Info<< endl;

    return 0;
}


// ************************************************************************* //
