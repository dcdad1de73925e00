#!/bin/bash
#------------------------------------------------------------------------------
# Smoke test of tutorials/sharedMooringWaves: two pontoons in a 2D flume,
# each moored on its outer side to the bed by a dynamic line and joined by a
# shared dynamic line (mooringLine.fmu: one restraint acting on both
# pontoons), the motion solved by Newmark under the added-mass coupling, in
# regular waves (H = 0.05 m, T = 1.5 s), at the case's defaults: the
# default mesh to 3 s, the ramp and the waves' arrival at both pontoons.
# Checks:
#  - the solver reaches 3 s;
#  - every line writes one row of finite numbers per time step, and its
#    tensions at both ends are positive (a line cannot push);
#  - the start at rest: the lines start in their static equilibrium, which
#    leaves every attachment at 45 degrees with the same horizontal tension,
#    and each pontoon is lighter by its lines' pull (constant/
#    dynamicMeshDict): before the waves reach the pontoons (t < 1.0 s; the
#    front, at the group velocity 1.40 m/s, reaches x = 2.0 m at 1.43 s)
#    every centre of mass stays within 1.5 mm of its start in x and z and
#    every pitch within 0.2 deg (measured 0.63 mm and 0.048 deg). The lines'
#    pull is 19.4 N a pontoon: left on a pontoon of 50 kg it would sink it
#    by 4 mm (heave stiffness 4905 N/m), so that start fails;
#  - at rest the fairlead tensions are the statics' 13.70 N within 1 N (the
#    end segments, EA/l = 67-104 kN/m, ring with the pontoons' first motions
#    of 0.1 mm: measured 0.46 N), and the shared line's tensions at its two
#    ends are equal within 0.06 N, its weight per metre times twice the
#    1.5 mm that each end may move (measured 0.0013 N); over the whole run
#    they differ by less than its weight, w L = 19.38 N (a hanging line's
#    ends differ by w times their height difference, plus the inertia and
#    drag of its nodes; measured 0.375 N);
#  - the shared line is attached to both pontoons: its first shape point
#    (A end) and its last (B end) are the attachment points (0.1 0 -0.1) on
#    pontoon1 and (-0.1 0 -0.1) on pontoon2 as moved by the bodies' logged
#    motion, within a tenth of the largest one-step motion of an attachment
#    point (the restraint is evaluated at Newmark's predicted state) plus
#    1e-6 m (measured 1.4e-6 m against 1.6e-4 m); a line with its ends
#    swapped, or on one body, fails;
#  - both pontoons move with the waves: over the last period (1.5-3 s; the
#    front reaches pontoon2 at 2.2 s) heave ranges above 5 mm and surge
#    ranges above 10 mm, beyond what the start at rest allows (measured
#    29 and 11 mm of heave, 28 and 27 mm of surge);
#  - the summary has the amplitudes and the plots are written.
# Needs platforms/<WM_OPTIONS>/lib/libfoamFmiBridge.so,
# libfoamFmiRigidBodyCoupling.so and build/fmus/mooringLine.fmu. Exits
# non-zero on the first failure.
#------------------------------------------------------------------------------
. "$(dirname "$0")/tutorialTestFunctions"
. "$(dirname "$0")/connectorTestFunctions"

endTime=3
restTime=1.0
restBound=0.0015
restPitchBound=0.2
restTensionBound=1.0
sharedRestBound=0.06
restTension=13.7039
sharedWeight=19.380
minHeave=0.005
minSurge=0.01
period=1.5

for lib in foamFmiBridge foamFmiRigidBodyCoupling
do
    requireFile "$FOAM_USER_LIBBIN/lib$lib.so" "lib$lib.so (build it: ./Allwmake)"
done
requireFile "$FOAMFMI_FMU_DIR/mooringLine.fmu" "the mooringLine FMU (build it: ./Allwmake)"

makeWorkDir
case=$workDir/sharedMooringWaves
runTutorial sharedMooringWaves "$case"
checkRanToEnd "$case" $endTime

for name in line1 sharedLine line2
do
    checkConnectorRows "$case" $name
done

/usr/bin/python3 - "$case" $restTime $restBound $restPitchBound $restTensionBound $restTension \
    $sharedRestBound $sharedWeight $minHeave $minSurge $period $endTime > "$workDir/check.out" <<'PYTHON' \
    || fail "see above (the runs are kept in $workDir)"
import math
import os
import sys

from foamfmi import postprocessing

case = sys.argv[1]
(rest_time, rest_bound, rest_pitch, rest_tension_bound, rest_tension, shared_rest_bound,
 shared_weight, min_heave, min_surge, period, end_time) = (float(v) for v in sys.argv[2:13])
motion_dir = os.path.join(case, "postProcessing", "rigidBodyMotion")
conn_dir = os.path.join(case, "postProcessing", "fmuConnectors", "0")
start = {"pontoon1": (2.25, 0.5), "pontoon2": (3.3, 0.5)}
report = []


def fail(message):
    sys.exit("FAIL: " + message)


def rotate_y(deg, p):
    """p turned by deg about y (the pontoons' only rotation)."""
    a = math.radians(deg)
    return [p[0] * math.cos(a) + p[2] * math.sin(a), p[1], -p[0] * math.sin(a) + p[2] * math.cos(a)]


motion = {b: postprocessing.read_table(os.path.join(motion_dir, b + ".dat")) for b in start}
for b, rows in motion.items():
    for r in rows:
        if abs(r[2] - 0.5) > 1e-9 or abs(r[5]) > 1e-9 or abs(r[7]) > 1e-9:
            fail("%s at t = %g: motion out of the x-z plane (y %g m, rotation %g %g deg)"
                 % (b, r[0], r[2], r[5], r[7]))
    at_rest = [r for r in rows if r[0] < rest_time]
    if not at_rest:
        fail("%s: no motion row before t = %g s" % (b, rest_time))
    dx = max(abs(r[1] - start[b][0]) for r in at_rest)
    dz = max(abs(r[3] - start[b][1]) for r in at_rest)
    pitch = max(abs(r[6]) for r in at_rest)
    if max(dx, dz) > rest_bound or pitch > rest_pitch:
        fail("%s: before the waves (t < %g s) it moved by %.3g m in x, %.3g m in z, %.3g deg"
             " (at most %g m, %g deg): not at rest at the start" % (b, rest_time, dx, dz, pitch,
                                                                   rest_bound, rest_pitch))
    last = [r for r in rows if r[0] >= end_time - period - 1e-9]
    heave = max(r[3] for r in last) - min(r[3] for r in last)
    surge = max(r[1] for r in last) - min(r[1] for r in last)
    if heave < min_heave or surge < min_surge:
        fail("%s: over the last period it heaved over %.3g m and surged over %.3g m (at least"
             " %g m and %g m): it does not move with the waves" % (b, heave, surge, min_heave, min_surge))
    report.append("%s: at rest before the waves within %.2g m (x), %.2g m (z), %.2g deg;"
                  " over the last period heave range %.3g m, surge range %.3g m"
                  % (b, dx, dz, pitch, heave, surge))

lines = {}
rest_worst = 0.0
for name in ("line1", "sharedLine", "line2"):
    header, rows = postprocessing.read_named_table(os.path.join(conn_dir, name + ".dat"))
    lines[name] = (header, rows)
    col = {n: header.index(n) for n in ("fairleadTension", "anchorTension")}
    lo = min(min(r[col["fairleadTension"]], r[col["anchorTension"]]) for r in rows)
    if not lo > 0:
        fail("%s: a tension of %g N: a line cannot push" % (name, lo))
    for r in rows:
        if r[0] < rest_time:
            rest_worst = max(rest_worst, abs(r[col["fairleadTension"]] - rest_tension))
        if r[0] < rest_time and abs(r[col["fairleadTension"]] - rest_tension) > rest_tension_bound:
            fail("%s at t = %g: fairlead tension %.6g N at rest, the statics' %g N (within %g N)"
                 % (name, r[0], r[col["fairleadTension"]], rest_tension, rest_tension_bound))

report.append("lines at rest: fairlead tensions within %.2g N of the statics' %g N (at most %g N)"
              % (rest_worst, rest_tension, rest_tension_bound))

header, rows = lines["sharedLine"]
col = {n: header.index(n) for n in ("fairleadTension", "anchorTension", "shape.x[1]", "shape.z[1]",
                                    "shape.x[11]", "shape.z[11]")}
rest_diff = max(abs(r[col["fairleadTension"]] - r[col["anchorTension"]]) for r in rows if r[0] < rest_time)
if rest_diff > shared_rest_bound:
    fail("sharedLine: at rest its end tensions differ by %.3g N (at most %g N)" % (rest_diff, shared_rest_bound))
run_diff = max(abs(r[col["fairleadTension"]] - r[col["anchorTension"]]) for r in rows)
if run_diff > shared_weight:
    fail("sharedLine: its end tensions differ by %.3g N, more than its weight %g N" % (run_diff, shared_weight))
report.append("sharedLine: end tensions equal within %.2g N at rest (at most %g N), within %.3g N"
              " over the run (its weight %g N)" % (rest_diff, shared_rest_bound, run_diff, shared_weight))

# The shared line's ends against the attachment points of the logged motion
ends = {"A": ("pontoon1", [0.1, 0.0, -0.1], "1"), "B": ("pontoon2", [-0.1, 0.0, -0.1], "11")}
if len(rows) != len(motion["pontoon1"]) or len(rows) != len(motion["pontoon2"]):
    fail("sharedLine: %d rows, the bodies %d and %d" % (len(rows), len(motion["pontoon1"]), len(motion["pontoon2"])))
for end, (body, p, k) in ends.items():
    logged = []
    for b in motion[body]:
        q = rotate_y(b[6], p)
        logged.append((b[1] + q[0], b[3] + q[2]))
    step = max(math.dist(logged[i], logged[i - 1]) for i in range(1, len(logged)))
    tol = 0.1 * step + 1e-6
    worst = 0.0
    for r, want in zip(rows, logged):
        got = (r[col["shape.x[" + k + "]"]], r[col["shape.z[" + k + "]"]])
        e = math.dist(got, want)
        if e > tol:
            fail("sharedLine at t = %g: its %s end at (%g %g), %s's attachment point at (%g %g)"
                 " (tolerance %.3g m)" % (r[0], end, got[0], got[1], body, want[0], want[1], tol))
        worst = max(worst, e)
    report.append("sharedLine: %s end on %s's attachment point within %.2g m (tolerance %.2g m)"
                  % (end, body, worst, tol))
print("\n".join(report))
PYTHON
while read -r line
do
    pass "$line"
done < "$workDir/check.out"

summary=$case/plots/pontoonResponse.dat
requireFile "$summary" "summary of pontoonResponse"
for key in pontoon1.heaveAmplitude pontoon2.surgeAmplitude sharedLine.tensionAmplitude \
    sharedLine.tensionBAmplitude line1.tensionAmplitude line2.meanTension
do
    grep -q "^$key " "$summary" || fail "$summary: no $key"
done
pass "summary: $(grep -c . "$summary") entries"
checkPlots "$case" pontoonMotion chainLoads rotation displacement

#------------------------------------------------------------------------------
