#!/bin/bash
#------------------------------------------------------------------------------
# Lines longer than the CFD domain: tutorials/mooredBoxWaves with dynamic
# lines (mooringLine.fmu) in a tank 2 m long instead of 6 m (Allrun
# -tank-length 2), so that the anchors (x = +-1.385 m) are 0.385 m beyond
# the tank's ends and about a third of each line's shape points lies
# outside the mesh; fmuConnectorFlow takes the inlet's Stokes II wave there
# (incidentWave inlet; blendWidth 0.2). The lines also take the water's
# acceleration the function object samples (acceleration true; and the
# lines' flowInertia 2, set in this copy of the case). Mesh factor 0.375
# to 2 s (the ramp's end, a write time): about 50 s of CPU time. Checks:
#  - the solver reaches 2 s;
#  - each line is written as VTK at every write time with the points and
#    tensions of its output rows (checkLineOutputs.py);
#  - every shape point beyond the tank, at every step, has the velocity of
#    the textbook second-order Stokes wave there and then, to 1e-9 of
#    H omega/2; at 2 s the points in the 0.2 m hand-over have the blend of
#    the wave and OpenFOAM's own probe of U, those further inside the probe
#    (checkIncidentWave.py, whose head gives the tolerances' reasons);
#  - the acceleration beyond the tank is the wave's time derivative, and
#    in mid-water it agrees with the centred difference of the sampled
#    velocities, better than the step before's would (not a step late);
#  - the velocities and accelerations written at 2 s restore a run
#    restarted from there (three steps), and a state file whose
#    accelerations were lost stops the restart with an error naming them.
# Needs platforms/<WM_OPTIONS>/lib/libfoamFmiBridge.so,
# libimplicitRigidBodySolvers.so and build/fmus/mooringLine.fmu. Exits
# non-zero on the first failure.
#------------------------------------------------------------------------------
. "$(dirname "$0")/tutorialTestFunctions"

requireFile "$FOAM_USER_LIBBIN/libfoamFmiBridge.so" \
    "the bridge library (build it: ./Allwmake)"
requireFile "$FOAM_USER_LIBBIN/libimplicitRigidBodySolvers.so" \
    "the implicit rigid-body solver library (build it: ./Allwmake)"
requireFile "$FOAMFMI_FMU_DIR/mooringLine.fmu" \
    "the mooringLine FMU (build it: cmake --build build)"

makeWorkDir
case=$workDir/mooredBoxWavesShortTank
cp -r "$FOAMFMI_DIR/tutorials/mooredBoxWaves" "$case" || fail "cannot copy mooredBoxWaves"
"$case/Allclean" > /dev/null 2>&1 || fail "mooredBoxWaves: Allclean failed"
sed -i 's/^    segments .*;$/&\n    flowInertia         2;/' "$case/constant/mooringLines.dynamic"
sed -i 's/^    connectors .*;$/&\n    acceleration true;/' "$case/system/lineFlow.dynamic"
grep -q '^    flowInertia         2;' "$case/constant/mooringLines.dynamic" \
    && grep -q '^    acceleration true;' "$case/system/lineFlow.dynamic" \
    || fail "cannot set flowInertia 2 and acceleration true in the case"
echo "Running mooredBoxWaves -tank-length 2 in $case"
"$case/Allrun" -mesh-factor 0.375 -end-time 2 -lines dynamic -tank-length 2 \
    -no-plot > "$case/log.Allrun" 2>&1 \
    || { tail -n 25 "$case/log.Allrun" 1>&2; fail "mooredBoxWaves: Allrun failed (see $case/log.Allrun)"; }
checkRanToEnd "$case" 2
grep -q '^ *incidentWave inlet;' "$case/system/lineFlow" \
    || fail "Allrun -tank-length 2 did not set incidentWave in system/lineFlow"

python3 "$(dirname "$0")/checkIncidentWave.py" "$case" line1 line2 line3 line4 \
    --flow lineFlow --solver "$(caseSolverOf "$case")" --blend 0.2 --depth 0.5 \
    --bounds -1 1 -0.5 0.5 --acceleration > "$workDir/check.out" 2>&1 \
    || { cat "$workDir/check.out" 1>&2; fail "the lines beyond the tank: see above"; }
while read -r line; do pass "$line"; done < "$workDir/check.out"


# --- A restart from 2 s ------------------------------------------------------
state=$case/2/uniform/fmuConnectorFlow/lineFlow
requireFile "$state" "the water's velocity and acceleration written at 2 s"
grep -q '^acceleration' "$state" || fail "$state: no acceleration dictionary"
solver=$(caseSolverOf "$case")
sed -i 's/^endTime .*;/endTime         2.05;/; s/^startFrom .*;/startFrom       latestTime;/' \
    "$case/system/controlDict" "$case/system/runSettings"
cp "$state" "$workDir/lineFlow.written"
# without the accelerations: refused, naming them
sed -i '/^acceleration/,$d' "$state"
(cd "$case" && "$solver" > log.restartLost 2>&1) \
    && fail "a restart whose state file lost the accelerations ran (see $case/log.restartLost)"
grep -q 'acceleration' "$case/log.restartLost" \
    && grep -q 'FOAM FATAL IO ERROR' "$case/log.restartLost" \
    || fail "a restart without the accelerations failed without naming them: $(tail -n 5 "$case/log.restartLost")"
pass "a state file without the accelerations stops the restart with an error naming them"
cp "$workDir/lineFlow.written" "$state"
# (the refused run began the files of 2 s; OpenFOAM would number the next)
rm -rf "$case"/postProcessing/*/2
(cd "$case" && "$solver" > log.restart 2>&1) \
    || { tail -n 20 "$case/log.restart" 1>&2; fail "the restart from 2 s failed"; }
grep -q 'water velocity at the lines restored from' "$case/log.restart" \
    || fail "the restart did not restore the lines' water velocity and acceleration"
rows=$(grep -vc '^#' "$case/postProcessing/lineFlow/2/line1.dat")
[ "$rows" -ge 2 ] || fail "the restart wrote $rows rows of line1's flow"
pass "restarted from 2 s with the velocities and accelerations written then: $rows steps to 2.05 s"
