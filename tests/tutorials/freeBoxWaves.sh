#!/bin/bash
#------------------------------------------------------------------------------
# Smoke test of tutorials/freeBoxWaves: the free box of Ren et al. (2015)
# (12 kg, 0.3 m x 0.2 m, free in surge, heave and pitch) in a 2D flume,
# the added-mass coupling, in the larger of the experiment's waves
# (H = 0.10 m, T = 1.2 s, ramped up over 4 s), on a mesh coarser than the
# default (mesh factor 0.5: dx = 0.04 m, dz = 0.02 m, 2920 cells, 31 s of
# CPU; the default's 11796 cells take about 75 s of CPU per simulated
# second) to 3 s: the still start and the first waves at the box. Checks:
#  - the solver reaches 3 s; the added-mass coupling ran (its estimates of
#    the box's added masses are in the log: heave 23 kg, twice the box's
#    12 kg);
#  - the motion file has one row of finite numbers per time step;
#  - the box floats at rest before the first disturbance from the
#    generator reaches it (t < 0.8 s; measured: the surge leaves 0.2 mm
#    after 0.9 s): its centre of mass within 1 mm of its start in x and z
#    and its pitch within 0.1 deg (measured 0.3 mm, the first settling of
#    the interface, and 0.011 deg). 12 kg on 0.12 m^2 of waterplane: a box
#    1 % too heavy sinks 1 mm, so that start fails;
#  - the box moves with the waves: over the last period (2-3 s) its heave
#    ranges over more than 5 mm and its pitch over more than 0.3 deg, and
#    the elevation at the gauge x = 1 m over more than 10 mm (measured 14.6
#    mm, 1.0 deg and 35 mm), beyond what the start at rest allows;
#  - the mesh morphs the long way (Allrun -morphing long, the default at
#    H = 0.10 m): at 3 s the bed's points are where blockMesh put them and
#    those beside the gauge at x = 1 m, 0.85 m ahead of the box, have moved
#    with it (more than 0.1 mm; measured 3.1 mm, 0 with the short morphing);
#  - boxResponse keeps the run (plots/run.dat, series.dat with the motion
#    every T/32) and says that a run this short has no window to compare.
# Needs platforms/<WM_OPTIONS>/lib/libfoamFmiRigidBodyCoupling.so and
# interFoamAliasSafe. Exits non-zero on the first failure.
#------------------------------------------------------------------------------
. "$(dirname "$0")/tutorialTestFunctions"

endTime=3
restTime=0.8
restBound=0.001
restPitch=0.1
minWave=0.01
minHeave=0.005
minPitch=0.3

requireFile "$FOAM_USER_LIBBIN/libfoamFmiRigidBodyCoupling.so" \
    "libfoamFmiRigidBodyCoupling.so (build it: ./Allwmake)"

makeWorkDir
case=$workDir/freeBoxWaves
runTutorial freeBoxWaves "$case" -height 0.10 -mesh-factor 0.5 -end-time $endTime
checkRanToEnd "$case" $endTime
log=$(solverLog "$case")
n=$(grep -c "^    added mass of box: rotation" "$log")
[ "$n" -gt 0 ] || fail "$log: no added-mass estimate of the box (report on)"
pass "the added-mass coupling ran: $n estimates, first: $(grep -m 1 "^    added mass of box" "$log" | sed 's/^ *//')"

/usr/bin/python3 - "$case" $restTime $restBound $restPitch $minWave $minHeave $minPitch \
    > "$workDir/check.out" <<'PYTHON' || fail "see above"
import sys

import numpy as np

from foamfmi import dictionary, postprocessing

case = sys.argv[1]
rest_time, rest_bound, rest_pitch, min_wave, min_heave, min_pitch = map(float, sys.argv[2:8])
period = 1.2
log = postprocessing.solver_log(case + "/log." + postprocessing.case_solver(case))
m = np.array(postprocessing.read_table(case + "/postProcessing/rigidBodyMotion/box.dat"))
if len(m) != log["timeSteps"]:
    sys.exit("box.dat: %d rows for %d time steps" % (len(m), log["timeSteps"]))
if not np.all(np.isfinite(m)):
    sys.exit("box.dat: a value that is not finite")
t, surge, heave, pitch = m[:, 0], m[:, 1] - 2.0, m[:, 3] - 0.4, m[:, 6]
rest = t < rest_time
worst = max(np.abs(surge[rest]).max(), np.abs(heave[rest]).max())
if worst > rest_bound or np.abs(pitch[rest]).max() > rest_pitch:
    sys.exit("before t = %g s the box moved by %.3g m (at most %g) and %.3g deg (at most %g)"
             % (rest_time, worst, rest_bound, np.abs(pitch[rest]).max(), rest_pitch))
last = t > t[-1] - period
heave_range = np.ptp(heave[last])
pitch_range = np.ptp(pitch[last])
if heave_range < min_heave or pitch_range < min_pitch:
    sys.exit("over the last period heave ranged over %.3g m (at least %g) and pitch over "
             "%.3g deg (at least %g)" % (heave_range, min_heave, pitch_range, min_pitch))
times, eta = postprocessing.read_gauges(case, 0.4)
times = np.array(times)
x1 = min(eta, key=lambda x: abs(x - 1.0))
e = np.array(eta[x1])
wave_range = np.ptp(e[times > times[-1] - period])
if wave_range < min_wave:
    sys.exit("the gauge at x = %g m: the elevation ranged over %.3g m in the last period "
             "(at least %g)" % (x1, wave_range, min_wave))

# The long morphing (the default at H = 0.10 m): the bed's points where
# blockMesh put them, to the digits written; those beside the gauge at
# x = 1 m, 0.85 m ahead of the box, moved with it
p0 = np.array(dictionary.read_points(case + "/constant/polyMesh/points"))
p1 = np.array(dictionary.read_points(case + "/%g/polyMesh/points" % t[-1]))
if p0.shape != p1.shape or len(p0) == 0:
    sys.exit("polyMesh/points: %s points at the start, %s at %g s" % (p0.shape, p1.shape, t[-1]))
moved = np.abs(p1 - p0).max(axis=1)
bed = p0[:, 2] == 0.0
near_gauge = np.abs(p0[:, 0] - 1.0) < 0.05
if moved[bed].max() != 0.0 or moved[near_gauge].max() < 1e-4:
    sys.exit("the long morphing: the bed's points moved by up to %.3g m (none may), those "
             "beside x = 1 m by %.3g m (at least 1e-4)" % (moved[bed].max(), moved[near_gauge].max()))
print("at rest before %g s within %.2g m and %.2g deg; over the last period heave %.3g m, "
      "pitch %.3g deg, surge %.3g m, the wave at x = %.3g m %.3g m (ranges); the mesh beside "
      "the gauge moved by %.2g m, the bed's points by 0; %d steps, %.0f s"
      % (rest_time, worst, np.abs(pitch[rest]).max(), heave_range, pitch_range,
         np.ptp(surge[last]), x1, wave_range, moved[near_gauge].max(), log["timeSteps"],
         log["executionTime"]))
PYTHON
pass "$(cat "$workDir/check.out")"

for f in run.dat series.dat
do
    requireFile "$case/plots/$f" "boxResponse's $f"
done
grep -q "^# Time surge heave pitch eta.1 eta.3$" "$case/plots/series.dat" \
    || fail "$case/plots/series.dat: not boxResponse's columns"
grep -q "no comparison: the run ends at" "$case/log.Allrun" \
    || fail "$case/log.Allrun: boxResponse did not say that the run is too short to compare"
pass "boxResponse kept the run: $(grep -vc '^#' "$case/plots/series.dat") samples"

#------------------------------------------------------------------------------
