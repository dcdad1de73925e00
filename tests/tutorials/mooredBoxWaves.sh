#!/bin/bash
#------------------------------------------------------------------------------
# Smoke test of tutorials/mooredBoxWaves: the moored box of Wu et al. (2018)
# (0.2 m x 0.2 m x 0.132 m, 3.148 kg) on four quasi-static catenary lines
# (catenary.fmu, fmuConnector restraints, implicitNewmark) in Stokes II
# waves (H = 0.04 m, T = 2 s), on a mesh coarser than the default (mesh
# factor 0.375, 3108 cells, time step T/112) to 10 s, a multiple of the
# write interval (2 s), which the adjustable time step hits exactly: the
# ramp (2 s), the waves' arrival at the box (3.7 s) and 3 periods (about
# 2 minutes of CPU time; the default mesh takes 4.5). Checks:
#  - the solver reaches 10 s; implicitNewmark converged in every solve;
#  - hydrostatics and line pretension: before the waves reach the box
#    (t <= 1.2 s) it floats at the draught where buoyancy carries its weight
#    and the lines' vertical pull, solved independently
#    (tutorials/mooredBoxWaves/mooringStatics: elastic catenary with
#    touchdown), and does not drift or tilt;
#  - every row of every line: the fairlead tension is that of the
#    independent elastic catenary for the fairlead position the line logged
#    (shape point 1) and its anchor;
#  - the box responds at the wave period: its heave's up-crossings from 4 s
#    (after the waves' arrival) are T apart within 10 %, over a range above
#    H/3;
#  - raoAnalysis writes its summary and the plots are written;
#  - each line is written as VTK at every write time with the points and
#    tensions of its output rows (checkLineOutputs.py);
#  - the dynamic lines in the waves (-lines dynamic, 6 s: the waves reach
#    the lines at 3.7 s): the water velocity fmuConnectorFlow gives each
#    line at the last write time is OpenFOAM's own probe of U at the line's
#    points, and the water there moves.
# Needs platforms/<WM_OPTIONS>/lib/libfoamFmiBridge.so,
# libimplicitRigidBodySolvers.so and build/fmus/catenary.fmu,
# mooringLine.fmu. Exits non-zero on the first failure.
#------------------------------------------------------------------------------
. "$(dirname "$0")/tutorialTestFunctions"
. "$(dirname "$0")/connectorTestFunctions"

endTime=10
wavePeriod=2
waveHeight=0.04
restEnd=1.2
statics=$FOAMFMI_DIR/tutorials/mooredBoxWaves/mooringStatics

requireFile "$FOAM_USER_LIBBIN/libfoamFmiBridge.so" \
    "the bridge library (build it: ./Allwmake)"
requireFile "$FOAM_USER_LIBBIN/libimplicitRigidBodySolvers.so" \
    "the implicit rigid-body solver library (build it: ./Allwmake)"
requireFile "$FOAMFMI_FMU_DIR/catenary.fmu" \
    "the catenary FMU (build it: cmake --build build)"

makeWorkDir
case=$workDir/mooredBoxWaves
runTutorial mooredBoxWaves "$case" -mesh-factor 0.375 -end-time $endTime
checkRanToEnd "$case" $endTime
checkImplicitNewmark "$case"
motion=$case/postProcessing/rigidBodyMotion/floatingObject.dat
requireFile "$motion" "the box's motion"


# --- At rest before the waves arrive -----------------------------------------
# The analytic rest position: centre of mass at z = 0.48037 m, 83.23 mm
# draught (78.84 mm from the mass alone, 4.39 mm from the lines' pull).
# The mean height over t <= 1.2 s (the waves' first disturbance reaches the
# box at about 1.5 s) must be within 1 mm of it: the flow's start (the
# pressure builds up in the first steps) sets the box heaving by about
# 2.3 mm at its own period (about 0.8 s), which the mean over 1.5 of its
# periods leaves within 0.5 mm; a box that missed the lines' pull would sit
# 4.4 mm higher. No heave away from it beyond 4 mm (twice that start-up
# amplitude), no sway or surge beyond 1 mm, no tilt beyond 0.1 deg.
zRest=$(python3 "$statics" -json | python3 -c 'import json, sys; print(json.load(sys.stdin)["centreOfMassZ"])') \
    || fail "$statics failed"
awk -v t1=$restEnd -v z0="$zRest" '
function abs(x) { return x < 0 ? -x : x }
/^#/ || $1 > t1 { next }
{
    n++; s += $4
    if (abs($4 - z0) > dz) dz = abs($4 - z0)
    h = sqrt($2^2 + $3^2); if (h > dh) dh = h
    if ($5 > da) da = $5
}
END {
    if (n < 20) { print "only " n " steps before t = " t1 " s" > "/dev/stderr"; exit 1 }
    m = s/n
    printf("mean centre of mass z = %.5f m over %d steps to %g s (analytic %.5f m, %+.2f mm); largest |dz| %.2f mm, horizontal %.3f mm, tilt %.3f deg\n", m, n, t1, z0, 1000*(m - z0), 1000*dz, 1000*dh, da)
    exit !(abs(m - z0) < 1e-3 && dz < 4e-3 && dh < 1e-3 && da < 0.1)
}' "$motion" > "$workDir/check.out" \
    || fail "the box is not at rest at its draught before the waves: $(cat "$workDir/check.out")"
pass "at rest: $(cat "$workDir/check.out")"


# --- Line tensions against an independent catenary ---------------------------
# Every row of every line: the fairlead tension against the elastic
# catenary with touchdown of foamfmi.catenary (Jonkman's closed form, Newton
# to 1e-13 m; length, EA and submerged weight of the case's
# constant/mooringLines) for the fairlead the line logged (shape.x/y/z[1])
# and its anchor (shape.x/y/z[11]). Both solve the same equations; the tolerance, 1e-6 of the
# tension, is far above their convergence and the 17 digits written, and
# far below any change of the law (seabed friction, the stretch: EA = 29 N
# stretches the line by 1.9 %).
for n in 1 2 3 4
do
    dat=$(connectorFile "$case" line$n)
    python3 - "$dat" "$case/constant/mooringLines" > "$workDir/check.out" <<'PYTHON' || fail "$dat: $(cat "$workDir/check.out")"
import sys
from foamfmi import catenary, dictionary, postprocessing
path = sys.argv[1]
# The line of the case (constant/mooringLines, lineParameters)
par = {key: dictionary.read_scalar(sys.argv[2], key)
       for key in ("unstretchedLength", "EA", "weight")}
names, rows = postprocessing.read_named_table(path)
if not rows:
    sys.exit("no rows")
c = {k: names.index(k) for k in ("shape.x[1]", "shape.y[1]", "shape.z[1]",
                                 "shape.x[11]", "shape.y[11]", "shape.z[11]",
                                 "fairleadTension")}
worst = (0.0, 0.0, 0.0)
for r in rows:
    fairlead = (r[c["shape.x[1]"]], r[c["shape.y[1]"]], r[c["shape.z[1]"]])
    anchor = (r[c["shape.x[11]"]], r[c["shape.y[11]"]], r[c["shape.z[11]"]])
    expected = catenary.line_tension(fairlead, anchor, par["unstretchedLength"],
                                     par["weight"], par["EA"])[0]
    err = abs(r[c["fairleadTension"]] - expected) / expected
    if err > worst[0]:
        worst = (err, r[0], expected)
    if err > 1e-6:
        print("t = %g s: fairlead tension %.9g N, catenary %.9g N" % (r[0], r[c["fairleadTension"]], expected))
        sys.exit(1)
t = [r[c["fairleadTension"]] for r in rows]
print("%d rows, fairlead tension %.3f-%.3f N, largest relative difference %.1e (t = %g s)"
      % (len(rows), min(t), max(t), worst[0], worst[1]))
PYTHON
    pass "line$n: $(cat "$workDir/check.out")"
done


# --- The response has the wave period ----------------------------------------
# Heave up-crossings of its mean from 4 s (the wave front reaches the box
# at 3.7 s): the waves force the box at T = 2 s; left to itself it heaves at
# about 0.8 s and sways at the lines' period, several seconds. 10 % of T
# tells T from both and allows the start-up transient that shifts the
# crossings. Range above H/3 in the last period: a box that follows a wave
# 20 times its length heaves by about the wave height.
awk -v t0=4 -v T=$wavePeriod -v H=$waveHeight -v tEnd=$endTime '
/^#/ || $1 < t0 { next }
{ n++; t[n] = $1; z[n] = $4; s += $4 }
END {
    m = s/n
    for (i = 2; i <= n; i++)
        if (z[i-1] < m && z[i] >= m) { c[++k] = t[i-1] + (m - z[i-1])/(z[i] - z[i-1])*(t[i] - t[i-1]) }
    for (i = 1; i <= n; i++)
        if (t[i] >= tEnd - T) { if (!lo || z[i] < zl) zl = z[i]; if (!lo || z[i] > zh) zh = z[i]; lo = 1 }
    if (k < 2) { print "fewer than two up-crossings after " t0 " s"; exit 1 }
    p = (c[k] - c[1])/(k - 1)
    printf("heave period %.3f s (%d intervals from %g s, wave period %g s), range %.3f m in the last period\n", p, k - 1, t0, T, zh - zl)
    exit !(p > 0.9*T && p < 1.1*T && zh - zl > H/3)
}' "$motion" > "$workDir/check.out" \
    || fail "the box does not respond at the wave period: $(cat "$workDir/check.out")"
pass "$(cat "$workDir/check.out")"

requireFile "$case/plots/rao.dat" "summary of raoAnalysis"
checkPlots "$case" rao rotation displacement


# --- The lines as VTK; the dynamic lines in the waves --------------------------
python3 "$(dirname "$0")/checkLineOutputs.py" "$case" line1 line2 line3 line4 \
    > "$workDir/check.out" 2>&1 \
    || { cat "$workDir/check.out" 1>&2; fail "line outputs: see above"; }
while read -r line; do pass "catenary $line"; done < "$workDir/check.out"

requireFile "$FOAMFMI_FMU_DIR/mooringLine.fmu" \
    "the mooringLine FMU (build it: cmake --build build)"
dynamic=$workDir/mooredBoxWavesDynamic
runTutorial mooredBoxWaves "$dynamic" -mesh-factor 0.375 -end-time 6 \
    -lines dynamic -no-plot
checkRanToEnd "$dynamic" 6
python3 "$(dirname "$0")/checkLineOutputs.py" "$dynamic" line1 line2 line3 \
    line4 --flow lineFlow --solver "$(caseSolverOf "$dynamic")" > "$workDir/check.out" 2>&1 \
    || { cat "$workDir/check.out" 1>&2; fail "dynamic line outputs: see above"; }
while read -r line; do pass "dynamic $line"; done < "$workDir/check.out"
