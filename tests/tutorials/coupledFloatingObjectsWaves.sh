#!/bin/bash
#------------------------------------------------------------------------------
# Smoke test of tutorials/coupledFloatingObjectsWaves: the two cubes of
# coupledFloatingObjects, tied by the linearSpring connector FMU, floating in
# regular Stokes II waves (H = 0.05 m, T = 1.5 s) in a 3D tank, at the
# default mesh (9000 cells) to 4.5 s: the ramp (1.5 s) and two wave periods
# at the cubes (about 3 minutes of CPU time). 4.5 s is a multiple of the
# write interval, 0.75 s, which the adjustable time step hits exactly. Checks:
#  - the solver reaches 4.5 s;
#  - the connector writes one row per time step with A.F = -B.F; the spring
#    obeys its law, tension = 100 N/m * (length - 0.2 m), and its length
#    equals the distance between the attachment points (0.1 0 0.17) on A and
#    (-0.1 0 0.17) on B as moved by the bodies' logged motion (floating
#    joints: the centres of mass move too);
#  - the waves reach the cubes and move them: each cube heaves with the wave
#    period, over a range of at least a third of the wave height;
#  - the plots are written.
# Needs platforms/<WM_OPTIONS>/lib/libfoamFmiBridge.so and
# build/fmus/linearSpring.fmu. Exits non-zero on the first failure.
#------------------------------------------------------------------------------
. "$(dirname "$0")/tutorialTestFunctions"
. "$(dirname "$0")/connectorTestFunctions"

endTime=4.5
stiffness=100
restLength=0.2
wavePeriod=1.5
waveHeight=0.05
attachmentA="0.1 0 0.17"
attachmentB="-0.1 0 0.17"

requireBridge linearSpring "the spring FMU (build it: cmake --build build)"

makeWorkDir
case=$workDir/coupledFloatingObjectsWaves
runTutorial coupledFloatingObjectsWaves "$case" -end-time $endTime
checkRanToEnd "$case" $endTime


# --- The spring --------------------------------------------------------------
checkConnectorRows "$case" spring balanced
dat=$(connectorFile "$case" spring)

# The law in every row. Tolerance: 1e-9 of the tension (the file has 12
# significant digits) plus k times the rounding of the written length
# (1e-11 m).
awk -v L="$(columnOf "$dat" length)" -v F="$(columnOf "$dat" tension)" \
    -v k=$stiffness -v L0=$restLength '
function abs(x) { return x < 0 ? -x : x }
/^#/ { next }
{
    e = abs($F - k*($L - L0))
    if (e > 1e-9*abs($F) + k*1e-11) { printf("t = %s: tension %.12g N, k (length - L0) = %.12g N\n", $1, $F, k*($L - L0)) > "/dev/stderr"; exit 1 }
    if ($F < minT) minT = $F
    if ($F > maxT) maxT = $F
}
END { printf("tension = k (length - L0) in every row; tension from %.3g to %.3g N\n", minT, maxT) }' \
    "$dat" > "$workDir/check.out" || fail "$dat: the spring law"
pass "spring: $(cat "$workDir/check.out")"

# Length against the bodies' logged motion: the connector is evaluated at
# the state the last outer corrector solves for, the log has the state the
# step ends with; they differ by a small part of one step's motion, so the
# tolerance is a tenth of the largest change of length in one step.
attachmentDistance \
    "$case/postProcessing/rigidBodyMotion/floatingObject1.dat" \
    "$case/postProcessing/rigidBodyMotion/floatingObject2.dat" \
    "$attachmentA" "$attachmentB" > "$workDir/distance.dat" \
    || fail "attachment points from the body motion"
checkLengthAgainstMotion "$workDir/distance.dat" "$dat" > "$workDir/check.out" \
    || fail "$dat: length against the body motion"
pass "spring: $(cat "$workDir/check.out")"


# --- The cubes follow the waves ----------------------------------------------
summary=$case/plots/waveResponse.dat
requireFile "$summary" "summary of waveResponse"
value()
{
    sed -n "s/^$1 //p" "$summary"
}

# Heave period: the mean interval between the up-crossings of the heave from
# the end of the ramp (1.5 s) to 4.5 s (plots/waveResponse.dat). The waves
# force the cubes at T = 1.5 s; left to themselves they heave at their own
# period, 0.64 s without added mass and somewhat longer with it, and noise
# or a numerical instability would oscillate faster still. The free heave
# that the waves' arrival starts decays over these periods and shifts the
# crossings: 10 % of T allows that and still tells T from the cubes' own
# period.
for body in floatingObject1 floatingObject2
do
    period=$(value "$body.heavePeriod")
    intervals=$(value "$body.heaveUpcrossingIntervals")
    [ -n "$period" ] || fail "$summary: no $body.heavePeriod"
    awk -v n="$intervals" -v p="$period" -v T=$wavePeriod \
        'BEGIN { exit !(n >= 1 && p > 0.9*T && p < 1.1*T) }' \
        || fail "$body heaves with period $period s over $intervals" \
            "up-crossing intervals, not the wave period $wavePeriod s +- 10 %"
    pass "$body heaves with period $period s ($intervals intervals," \
        "wave period $wavePeriod s +- 10 %)"
done

# Heave over the last wave period (from the logged motion): a cube of 0.2 m
# in waves 14 times longer follows the surface, its heave amplitude near the
# wave amplitude H/2 = 0.025 m (the coarse mesh damps the waves by some per
# cent before they reach the cubes). A range of H/3 (amplitude H/6) is far
# below that, and far above what a cube the waves do not reach, or one held
# back by a broken coupling, would do.
for body in floatingObject1 floatingObject2
do
    range=$(awk -v t0="$(awk -v t=$endTime -v T=$wavePeriod 'BEGIN { print t - T }')" '
        /^#/ || $1 < t0 - 1e-9 { next }
        { if (n++ == 0 || $4 < lo) lo = $4; if (n == 1 || $4 > hi) hi = $4 }
        END { printf("%.4g\n", n ? hi - lo : 0) }' \
        "$case/postProcessing/rigidBodyMotion/$body.dat")
    awk -v r="$range" -v H=$waveHeight 'BEGIN { exit !(r > H/3) }' \
        || fail "$body heaves over a range of $range m in the last period:" \
            "not above H/3 = $(awk -v H=$waveHeight 'BEGIN { print H/3 }') m"
    pass "$body heaves over a range of $range m in the last period" \
        "(wave height $waveHeight m)"
done

checkPlots "$case" waveResponse rotation displacement connector_spring
