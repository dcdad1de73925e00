#!/bin/bash
#------------------------------------------------------------------------------
# Smoke test of tutorials/coupledFloatingObjectsSixDoF: the two floating
# cubes moved by sixDoFRigidBodyDisplacement patches, tied by the
# linearSpring connector FMU through the sixDoF fmuConnector restraint (one
# restraint in each patch's motion, one shared FMU instance), coarse mesh
# (mesh factor 0.5), 0.3 s. It also runs tutorials/coupledFloatingObjects,
# the same spring in rigidBodyMotion, and checks:
#  - both runs reach the end time; each cube rotates about its fixed centre
#    of mass and stays inside the tank;
#  - the connector writes one finite row per time step with A.F = -B.F;
#  - in every solve of every outer corrector the two cubes' restraints
#    apply equal and opposite forces (the log's report lines, two per solve
#    round: the second body applies the loads of the first one's
#    evaluation), exactly;
#  - the cubes' rotations and the spring's tension follow the rigidBodyMotion
#    case over the first 0.2 s. The two differ in how the mesh follows the
#    bodies (as the uncoupled cases do, within 5 % of the peak rotation,
#    tests/tutorials/uncoupledFloatingObjectsSixDoF.sh) and in the coupling
#    (rigidBodyMotion solves both cubes at once; here body 2 sees body 1's
#    kinematics of its latest solve). Tolerance: 10 % of the peak plus
#    0.05 deg, and 15 % of the peak tension plus 0.01 N; a spring applied to
#    one cube only, on the wrong side or with the attachment points in the
#    wrong frame changes them by far more;
#  - the plots are written.
#------------------------------------------------------------------------------
# shellcheck disable=SC2154  # the case folders, set by runCubePair
. "$(dirname "$0")/tutorialTestFunctions"
. "$(dirname "$0")/connectorTestFunctions"

endTime=0.3

requireBridge linearSpring "the spring FMU (build it: cmake --build build)"

makeWorkDir

runCubePair $endTime rigidBody=coupledFloatingObjects sixDoF=coupledFloatingObjectsSixDoF

checkConnectorRows "$sixDoF" spring balanced


# --- Equal and opposite in every outer corrector ------------------------------
log=$(solverLog "$sixDoF")
nSteps=$(grep -c '^Time = ' "$log")
nOuter=$(sed -n 's/^ *nOuterCorrectors *\([0-9]*\);.*/\1/p' "$sixDoF/system/fvSolution")
grep 'Restraint spring: t = ' "$log" \
  | sed 's/.*t = \([^ ]*\) .*force on \([^ ]*\) (\([^)]*\)).*/\1 \2 \3/' \
  | awk -v expected=$((2*nSteps*nOuter)) '
    function bad(msg) { print msg > "/dev/stderr"; failed = 1; exit 1 }
    function abs(x) { return x < 0 ? -x : x }
    NR % 2 == 1 {
        if ($2 != "floatingObject1") bad("line " NR ": first load of a solve round on " $2)
        t = $1; f1 = $3; f2 = $4; f3 = $5; next
    }
    {
        if ($2 != "floatingObject2" || $1 != t) bad("line " NR ": second load of a solve round on " $2 " at t = " $1)
        # The same evaluation: the printed forces are the same numbers
        # with opposite signs
        e = abs(f1 + $3) + abs(f2 + $4) + abs(f3 + $5)
        if (e != 0) bad(sprintf("t = %s: forces %g %g %g and %g %g %g", t, f1, f2, f3, $3, $4, $5))
        if (abs(f1) > maxF) maxF = abs(f1)
    }
    END {
        if (failed) exit 1
        if (NR != expected) bad(NR " loads for " expected " (2 per solve, " expected/2 " solves)")
        if (maxF < 1e-3) bad("the spring does not pull: largest force " maxF " N")
        printf("%d loads, two per solve, equal and opposite (largest |F_x| %.3g N)\n", NR, maxF)
    }' > "$workDir/check.out" || fail "$log: loads of the two cubes' restraints"
pass "$(cat "$workDir/check.out")"


# --- Against the rigidBodyMotion case ----------------------------------------
for body in floatingObject1 floatingObject2
do
    compareSeries "$rigidBody/postProcessing/rigidBodyMotion/$body.dat" \
        "$sixDoF/postProcessing/rigidBodyMotion/$body.dat" "6 7 8" 0.1 0.05 \
        "$body rotation, sixDoF against rigidBodyMotion, coupled" 0.2
done
dat=postProcessing/fmuConnectors/0/spring.dat
compareSeries "$rigidBody/$dat" "$sixDoF/$dat" "$(columnOf "$sixDoF/$dat" tension)" \
    0.15 0.01 "spring tension, sixDoF against rigidBodyMotion" 0.2


# --- Plots -------------------------------------------------------------------
checkPlots "$sixDoF" rotation displacement connector_spring snapshots
