#!/bin/bash
#------------------------------------------------------------------------------
# Smoke test of tutorials/coupledFloatingObjects: two floating cubes tied by
# the linearSpring connector FMU (fmuConnector restraint, libfoamFmiBridge),
# coarse mesh (mesh factor 0.5, 20 x 10 x 15 cells), 0.3 s. Runs the coupled
# case in serial and on 2 processors and the uncoupled case for comparison,
# then checks:
#  - every run reaches its end time; each cube rotates about its fixed centre
#    of mass and stays inside the tank;
#  - the connector writes one row per time step with A.F = -B.F, and zero
#    total moment about the origin (a central force between the attachments);
#  - the spring obeys its law: tension = 100 N/m * (length - 0.2 m), and its
#    length equals the distance between the attachment points (0.1 0 0.17)
#    on A and (-0.1 0 0.17) on B as moved by the bodies' logged motion;
#  - the spring limits the motion: each cube's largest pitch angle (rotation
#    about y, the axis normal to the plane of the wave and of the spring) is
#    at least 10 % smaller than in the uncoupled case over the same 0.3 s,
#    and the distance between the attachment points changes at least 25 %
#    less;
#  - the parallel run matches the serial one (tolerance below);
#  - the plots are written.
# Needs platforms/<WM_OPTIONS>/lib/libfoamFmiBridge.so and
# build/fmus/linearSpring.fmu. Exits non-zero on the first failure.
#------------------------------------------------------------------------------
. "$(dirname "$0")/tutorialTestFunctions"
. "$(dirname "$0")/connectorTestFunctions"

endTime=0.3
stiffness=100
restLength=0.2
attachmentA="0.1 0 0.17"
attachmentB="-0.1 0 0.17"

requireBridge linearSpring "the spring FMU (build it: cmake --build build)"

makeWorkDir

serial=$workDir/serial/coupledFloatingObjects
uncoupled=$workDir/serial/uncoupledFloatingObjects
parallel=$workDir/parallel/coupledFloatingObjects

runTutorial uncoupledFloatingObjects "$uncoupled" -mesh-factor 0.5 \
    -end-time $endTime -no-plot
runTutorial coupledFloatingObjects "$serial" -mesh-factor 0.5 \
    -end-time $endTime
runTutorial coupledFloatingObjects "$parallel" -mesh-factor 0.5 \
    -end-time $endTime -parallel -no-plot

checkRuns $endTime "$cubeBodies" "$uncoupled" "$serial" "$parallel"


# --- The connector's output --------------------------------------------------

checkSpring()
{
    local caseDir="$1" dat nSteps cols
    dat="$caseDir/postProcessing/fmuConnectors/0/spring.dat"
    requireFile "$dat" "connector output"
    nSteps=$(grep -c '^Time = ' "$(solverLog "$caseDir")")

    cols=$(columnsOf "$dat" 'A.F[1]' 'A.F[2]' 'A.F[3]' 'A.M[1]' 'A.M[2]' \
        'A.M[3]' 'B.F[1]' 'B.F[2]' 'B.F[3]' 'B.M[1]' 'B.M[2]' 'B.M[3]' \
        length tension) || exit 1

    # Rows: one per time step, finite, A.F = -B.F, moments balance about the
    # origin with the reference points (the fixed centres of mass), and the
    # spring law. Tolerances: 1e-9 relative to the loads (the file has 12
    # significant digits; the bridge adds B's loads as the FMU returns them);
    # for the law also k times the rounding of the written length (1e-11 m).
    awk -v cols="$cols" -v nSteps="$nSteps" -v k="$stiffness" -v L0="$restLength" "$momentAwk"'
    BEGIN { split(cols, c, " ") }
    /^#/ { next }
    {
        n++
        for (i = 1; i <= NF; i++)
            if ($i !~ /^[-+]?[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$/) bad("t = " $1 ": not a finite number: " $i)
        if (n > 1 && $1 <= tPrev) bad("t = " $1 " after t = " tPrev ": not one row per time step")
        tPrev = $1
        # Total moment about the global origin (balanceMoment), A.F = -B.F
        balanceMoment(c)
        for (i = 1; i <= 3; i++)
        {
            e = abs(FA[i] + FB[i])
            if (e > 1e-9*scale + 1e-14) bad(sprintf("t = %s: A.F[%d] = %.12g but B.F[%d] = %.12g", $1, i, FA[i], i, FB[i]))
            if (e > worstF) worstF = e
        }
        L = $(c[13]); T = $(c[14])
        e = abs(T - k*(L - L0))
        if (e > 1e-9*abs(T) + k*1e-11) bad(sprintf("t = %s: tension %.12g N, k (length - L0) = %.12g N", $1, T, k*(L - L0)))
        if (abs(T) > maxT) maxT = abs(T)
    }
    END {
        if (failed) exit 1
        if (n != nSteps) bad(n " rows for " nSteps " time steps")
        if (maxT < 1e-3) bad("the spring is slack all the time: largest tension " maxT " N")
        printf("%d rows, |A.F + B.F| <= %.2g N, |total moment| <= %.2g N.m, largest tension %.3g N\n", n, worstF, worstM, maxT)
    }' "$dat" > "$workDir/check.out" || fail "$dat: see above"
    pass "${caseDir#$workDir/} spring: $(cat "$workDir/check.out")"

    # Length against the bodies' logged motion. The connector is evaluated
    # inside the rigid-body solve, at the state the last outer corrector
    # solves for; the logged state is the one it ends with. They differ by a
    # small part of one step's motion, so the tolerance is a tenth of the
    # largest change of length in one step (1e-6 m at the 0.3 s smoke run).
    attachmentDistances "$attachmentA" "$attachmentB" "$caseDir"
    checkLengthAgainstMotion "$caseDir/attachmentDistance.dat" "$dat" > "$workDir/check.out" \
        || fail "$dat: length against the body motion"
    pass "${caseDir#$workDir/} spring: $(cat "$workDir/check.out")"
}

checkSpring "$serial"
checkSpring "$parallel"


# --- The spring limits the motion --------------------------------------------
# Each cube's largest pitch at least 10 % smaller than without the spring;
# the distance between the attachment points changes at least 25 % less
# than the distance between the same points without it (about half as much
# in the smoke run; the serial run's distances are written by checkSpring)
attachmentDistances "$attachmentA" "$attachmentB" "$uncoupled"
checkSmallerMotion "$serial" "$uncoupled" spring 10 25 $restLength


# --- Parallel against serial -------------------------------------------------
# The decomposition changes only how the linear solvers converge (GAMG
# agglomeration and smoothing per processor, sums in another order); the
# discretisation is the same, and so is the time-step sequence up to
# round-off. Differences stay near the solver tolerances: about 1e-5 of the
# peak values in 0.4 s runs. The tolerance, 1 % of each quantity's peak over
# the run (plus 1e-4 deg or 1e-6 N), leaves room for their growth over the
# run, and still fails for any parallel error in the coupling: a load applied
# on every rank, or a body's force not summed over the processors, changes
# the motion by tens of percent.
for body in floatingObject1 floatingObject2
do
    compareSeries "$serial/postProcessing/rigidBodyMotion/$body.dat" \
        "$parallel/postProcessing/rigidBodyMotion/$body.dat" "6 7 8" 0.01 1e-4 \
        "$body rotation, parallel against serial"
done
dat=postProcessing/fmuConnectors/0/spring.dat
compareSeries "$serial/$dat" "$parallel/$dat" \
    "$(columnOf "$serial/$dat" 'A.F[1]') $(columnOf "$serial/$dat" 'A.F[2]') $(columnOf "$serial/$dat" 'A.F[3]')" \
    0.01 1e-6 "spring force on A, parallel against serial"


# --- Plots -------------------------------------------------------------------
checkPlots "$serial" rotation displacement connector_spring snapshots
