#!/bin/bash
#------------------------------------------------------------------------------
# Smoke test of tutorials/mooredSectionWaves: the ship section of Sundsdal et
# al. (2025) held in sway by two springs (linearSpring.fmu) with the rig's
# sway and heave dampers (linearDamper.fmu), free in sway, heave and roll, in regular
# waves (H = 0.024 m, T = 1.158 s) in a 2D flume, at the default mesh to
# 4 periods (4.632 s, a write time) with a ramp of one period instead of the
# experiment's five (-ramp-periods 1) and the generator 3 m before the
# section instead of the experiment's 7 (-generator-distance 3): the ramp,
# the waves' travel to the section and its first periods there. Checks:
#  - the solver reaches the end time; implicitNewmark converged in every
#    solve (no warning, its statistics line is there);
#  - every connector writes one row of finite numbers per time step;
#  - the springs: tension = k (L - L0) with the parameters of
#    constant/dynamicMeshDict (k = 29.86 N/m, L0 = 4.665104 m, no damping:
#    the rig's is in the dampers) from the FMU's own length, within 1e-9 N + 1e-9
#    of the tension (the same arithmetic; the files have 16 digits), and the
#    length against the distance from the logged centre of mass (the
#    attachment point) to the anchor, within a tenth of the largest
#    one-step change of length (the motion is logged at the end of the step,
#    the connector evaluated within it; 6 digits); a stiffness 1 % off, or an
#    anchor or attachment point 1 mm off, fails;
#  - the sway and heave dampers: tension = c dL/dt (c = 8.70 N s/m)
#    likewise, and their lengths against the logged motion;
#  - the section floats at its draught: the still water's pressure settles
#    in the first steps and sets it heaving at its natural period (1.17 s)
#    by 3.2 mm (measured); before the waves reach it (t < 1.5 s: the front
#    of the ramped wave, at its phase speed, 1.8 m/s, needs 1.6 s to the
#    section) its centre of mass oscillates within 5 mm about a mean, over
#    t = 0.3-1.5 s (one period of that oscillation), within 1.5 mm of
#    where the mesh put it (z = 0.906 m: the mass is the water displaced at
#    the draft of 0.2 m; a mass 0.75 % off shifts it by 1.5 mm; measured
#    0.07 mm); it sways less than 2 mm and rolls less than 0.05 deg
#    (measured 0.6 mm, 0.014 deg: the section and the springs are
#    symmetric, the flume is not: 3 m before it, 3.5 wavelengths behind);
#  - the waves move it: its heave over the last period exceeds a/2 (a long
#    wave, 5.2 beams, lifts a section with its heave resonance at 1.17 s
#    by more than a; a/2 leaves room for the first periods' build-up);
#  - the wave at the gauge WP_4 (1.5 m before the section) over the last
#    period is within 25 % of the target height (the coarse default mesh
#    has 4 cells per wave height; the README has the measured height);
#  - the plots and the summary are written.
# Needs platforms/<WM_OPTIONS>/lib/libfoamFmiBridge.so,
# libimplicitRigidBodySolvers.so, libfoamFmiRigidBodyCoupling.so and
# build/fmus/linearSpring.fmu, linearDamper.fmu. Exits non-zero on the first
# failure.
#------------------------------------------------------------------------------
. "$(dirname "$0")/tutorialTestFunctions"
. "$(dirname "$0")/connectorTestFunctions"

endTime=4.632
period=1.158
waveHeight=0.024
restTime=1.5
settleTime=0.3
z0=0.906
springStiffness=29.86
springRestLength=4.665104
springDamping=0
damperDamping=8.70
# name:anchor (global; attached at the centre of mass)
springs="springWeather:-5,0.293,0.906 springLee:5,0.293,0.906"
dampers="swayDamper:5,0.293,0.906 heaveDamper:0,0.293,5.906"

for lib in foamFmiBridge implicitRigidBodySolvers foamFmiRigidBodyCoupling
do
    requireFile "$FOAM_USER_LIBBIN/lib$lib.so" "lib$lib.so (build it: ./Allwmake)"
done
for fmu in linearSpring linearDamper
do
    requireFile "$FOAMFMI_FMU_DIR/$fmu.fmu" "the $fmu FMU (build it: ./Allwmake)"
done

makeWorkDir
case=$workDir/mooredSectionWaves
runTutorial mooredSectionWaves "$case" -end-time $endTime -ramp-periods 1 -generator-distance 3
checkRanToEnd "$case" $endTime
checkImplicitNewmark "$case"
motion=$case/postProcessing/rigidBodyMotion/section.dat
requireFile "$motion" "motion of the section"


# --- The connectors ------------------------------------------------------------
# checkConnector NAME ANCHOR STIFFNESS RESTLENGTH DAMPING
checkConnector()
{
    local name="$1" anchor="$2" k="$3" L0="$4" c="$5" dat
    checkConnectorRows "$case" "$name"
    dat=$(connectorFile "$case" "$name") || exit 1
    awk -v k="$k" -v L0="$L0" -v c="$c" -v anchor="$anchor" \
        -v lc="$(columnOf "$dat" length)" -v rc="$(columnOf "$dat" lengthRate)" \
        -v tc="$(columnOf "$dat" tension)" '
    function bad(msg) { print msg > "/dev/stderr"; failed = 1; exit 1 }
    function abs(x) { return x < 0 ? -x : x }
    BEGIN { split(anchor, p, ",") }
    FNR == 1 { f++ }
    /^#/ { next }
    f == 1 { nB++; tB[nB] = $1; D[nB] = sqrt(($2 - p[1])^2 + ($3 - p[2])^2 + ($4 - p[3])^2); next }
    {
        n++
        if (abs($1 - tB[n]) > 1e-5*(abs($1) + 1e-3)) bad("row " n ": connector time " $1 ", body time " tB[n])
        T = k*($lc - L0) + c*$rc
        e = abs($tc - T)
        if (e > 1e-9*abs(T) + 1e-9) bad(sprintf("t = %s: tension %.12g N, the law gives %.12g N", $1, $tc, T))
        L[n] = $lc
        e = abs(D[n] - L[n])
        if (e > worst) { worst = e; tWorst = $1 }
        if (n > 1 && abs(L[n] - L[n - 1]) > maxStep) maxStep = abs(L[n] - L[n - 1])
        if (abs($tc) > maxT) maxT = abs($tc)
    }
    END {
        if (failed) exit 1
        if (n != nB) bad(n " connector rows, " nB " body rows")
        if (worst > 0.1*maxStep + 1e-9) bad(sprintf("length differs from the distance centre of mass - anchor by %.3g m at t = %s (tolerance %.3g m)", worst, tWorst, 0.1*maxStep))
        printf("tension = the law within 1e-9; length = centre of mass to anchor within %.2g m (tolerance %.2g m); largest tension %.4g N\n", worst, 0.1*maxStep + 1e-9, maxT)
    }' "$motion" "$dat" > "$workDir/check.out" || fail "$name: see above"
    pass "$name: $(cat "$workDir/check.out")"
}

for spec in $springs
do
    checkConnector "${spec%%:*}" "${spec#*:}" $springStiffness $springRestLength $springDamping
done
for spec in $dampers
do
    checkConnector "${spec%%:*}" "${spec#*:}" 0 0 $damperDamping
done


# --- At rest before the waves, moving with them -------------------------------
awk -v tRest=$restTime -v tSettle=$settleTime -v z0=$z0 \
    -v a=$(awk -v H=$waveHeight 'BEGIN { print H/2 }') \
    -v tLast=$(awk -v t=$endTime -v T=$period 'BEGIN { print t - T }') '
function bad(msg) { print msg > "/dev/stderr"; failed = 1; exit 1 }
function abs(x) { return x < 0 ? -x : x }
/^#/ { next }
{
    if (n++ == 0) x0 = $2
    if ($1 < tRest)
    {
        if (abs($4 - z0) > 5e-3) bad(sprintf("t = %s: before the waves the centre of mass is at z = %.6g m, %.3g m from %g", $1, $4, $4 - z0, z0))
        if (abs($2 - x0) > 2e-3) bad(sprintf("t = %s: before the waves the section swayed by %.3g m", $1, $2 - x0))
        if (abs($7) > 0.05) bad(sprintf("t = %s: before the waves the section rolled by %.3g deg", $1, $7))
        if (abs($4 - z0) > restZ) restZ = abs($4 - z0)
        if (abs($7) > restRoll) restRoll = abs($7)
        # time-weighted mean over the settling oscillation
        if ($1 >= tSettle && nRest++) { sumZ += 0.5*($4 + zPrev)*($1 - tPrev); sumT += $1 - tPrev }
        zPrev = $4; tPrev = $1
    }
    if ($1 >= tLast) { if (!nLast++ || $4 > zMax) zMax = $4; if (nLast == 1 || $4 < zMin) zMin = $4 }
}
END {
    if (failed) exit 1
    meanZ = sumZ/sumT - z0
    if (abs(meanZ) > 1.5e-3) bad(sprintf("before the waves the centre of mass oscillates about %.3g m from z = %g (at most 1.5 mm)", meanZ, z0))
    heave = (zMax - zMin)/2
    if (heave < a/2) bad(sprintf("heave amplitude over the last period %.3g m, below a/2 = %.3g m", heave, a/2))
    printf("before the waves about %.2g mm from its draught, within %.2g mm, roll below %.2g deg; heave amplitude over the last period %.3g mm (a = %g mm)\n", 1e3*meanZ, 1e3*restZ, restRoll, 1e3*heave, 1e3*a)
}' "$motion" > "$workDir/check.out" || fail "the section's motion: see above"
pass "section: $(cat "$workDir/check.out")"


# --- The wave at the gauge WP_4 -------------------------------------------------
series=$case/plots/series.dat
requireFile "$series" "the run's series (sectionResponse)"
awk -v H=$waveHeight -v tLast=$(awk -v t=$endTime -v T=$period 'BEGIN { print t - T }') \
    -v c="$(columnOf "$series" eta.WP4)" '
/^#/ { next }
$1 >= tLast { if (!n++ || $c > hi) hi = $c; if (n == 1 || $c < lo) lo = $c }
END {
    h = hi - lo
    if (h < 0.75*H || h > 1.25*H) { printf("wave height at WP_4 over the last period %.4g m, target %g m (+-25 %%)\n", h, H) > "/dev/stderr"; exit 1 }
    printf("WP_4: wave height over the last period %.4g m (target %g m)\n", h, H)
}' "$series" > "$workDir/check.out" || fail "the wave: see above"
pass "$(cat "$workDir/check.out")"

checkPlots "$case" rotation displacement
echo "tests passed: mooredSectionWaves"
