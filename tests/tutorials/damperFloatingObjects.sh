#!/bin/bash
#------------------------------------------------------------------------------
# Smoke test of tutorials/damperFloatingObjects: the two floating cubes joined
# by the linearDamper connector FMU (fmuConnector restraint,
# libfoamFmiBridge), coarse mesh (mesh factor 0.5, 20 x 10 x 15 cells),
# 0.3 s. Runs the case and tutorials/uncoupledFloatingObjects over the same
# interval, then checks:
#  - both runs reach the end time; each cube rotates about its fixed centre
#    of mass and stays inside the tank;
#  - the damper writes one row per time step with A.F = -B.F and zero total
#    moment about the origin (a force along the line between the
#    attachment points);
#  - it obeys its law: tension = c lengthRate and dissipatedPower =
#    c lengthRate^2 >= 0 in every row (c = 10 N s/m), with a dissipated
#    energy above 1 mJ over the run, so it does act; its length equals the
#    distance between the attachment points (0.1 0 0.17) on A and
#    (-0.1 0 0.17) on B as moved by the bodies' logged motion;
#  - it damps the motion: each cube's largest pitch angle (rotation about y)
#    is at least 20 % smaller than in the uncoupled case over the same 0.3 s
#    (about 45 % smaller in the smoke run), and the distance between the
#    attachment points changes at least 20 % less;
#  - the plots are written.
# Needs platforms/<WM_OPTIONS>/lib/libfoamFmiBridge.so and
# build/fmus/linearDamper.fmu. Exits non-zero on the first failure.
#------------------------------------------------------------------------------
# shellcheck disable=SC2154  # the case folders, set by runCubePair
. "$(dirname "$0")/tutorialTestFunctions"
. "$(dirname "$0")/connectorTestFunctions"

endTime=0.3
damping=10
attachmentA="0.1 0 0.17"
attachmentB="-0.1 0 0.17"
restLength=0.2

requireBridge linearDamper "the damper FMU (build it: ./Allwmake)"

makeWorkDir

runCubePair $endTime uncoupled=uncoupledFloatingObjects damped=damperFloatingObjects


# --- The damper's output -----------------------------------------------------
checkConnectorRows "$damped" damper balanced

dat=$(connectorFile "$damped" damper) || exit 1
cols=$(columnsOf "$dat" 'A.F[1]' 'A.F[2]' 'A.F[3]' 'A.M[1]' 'A.M[2]' 'A.M[3]' \
    'B.F[1]' 'B.F[2]' 'B.F[3]' 'B.M[1]' 'B.M[2]' 'B.M[3]' \
    lengthRate tension dissipatedPower) || exit 1

# Total moment about the origin with the reference points (the fixed centres
# of mass), and the law. Tolerances: 1e-9 relative to the loads, and for the
# law c times the rounding of the written rate (12 significant digits).
awk -v cols="$cols" -v c="$damping" "$momentAwk"'
BEGIN { split(cols, k, " ") }
/^#/ { next }
{
    balanceMoment(k)
    rate = $(k[13]); T = $(k[14]); P = $(k[15])
    if (P < 0) bad(sprintf("t = %s: dissipatedPower %.12g W < 0", $1, P))
    if (abs(T - c*rate) > 1e-9*abs(T) + c*1e-12*(abs(rate) + 1e-3))
        bad(sprintf("t = %s: tension %.12g N, c lengthRate = %.12g N", $1, T, c*rate))
    if (abs(P - c*rate*rate) > 1e-9*P + 1e-15)
        bad(sprintf("t = %s: dissipatedPower %.12g W, c lengthRate^2 = %.12g W", $1, P, c*rate*rate))
    if (n++ > 0) E += 0.5*(P + PPrev)*($1 - tPrev)
    PPrev = P; tPrev = $1
    if (abs(T) > maxT) maxT = abs(T)
}
END {
    if (failed) exit 1
    if (E < 1e-3) bad(sprintf("the damper dissipates only %.3g J over the run", E))
    printf("|total moment| <= %.2g N.m; tension = c lengthRate, dissipatedPower = c lengthRate^2 >= 0 in %d rows; largest tension %.3g N, dissipated energy %.4g J\n", worstM, n, maxT, E)
}' "$dat" > "$workDir/check.out" || fail "$dat: see above"
pass "damper: $(cat "$workDir/check.out")"


# The damper's length against the bodies' logged motion. The connector is
# evaluated at the state the last outer corrector solves for; the logged
# state is the one the step ends with. They differ by a small part of one
# step's motion: the tolerance is a tenth of the largest change of length in
# one step.
attachmentDistances "$attachmentA" "$attachmentB" "$uncoupled" "$damped"
checkLengthAgainstMotion "$damped/attachmentDistance.dat" "$dat" > "$workDir/check.out" \
    || fail "$dat: length against the body motion"
pass "damper: $(cat "$workDir/check.out")"


# --- The damper reduces the motion -------------------------------------------
checkSmallerMotion "$damped" "$uncoupled" damper 20 20 $restLength


# --- Plots -------------------------------------------------------------------
checkPlots "$damped" rotation displacement connector_damper snapshots

#------------------------------------------------------------------------------
