#!/bin/bash
#------------------------------------------------------------------------------
# Smoke test of tutorials/waveTank: the numerical wave tank at its defaults
# (mesh factor 0.5: 2400 cells, 5 per wave height, 47 per wavelength; 15 s,
# 10 wave periods; about 15 s on an idle core). Checks that the tank runs to
# its end time, that the analysis window starts after the waves reflected at
# the outlet came back to every gauge, that the free surface stays on the
# gauge lines, that the wave height at the gauge nearest the generator is
# near the target, that the reflection coefficient is low, and that the plots
# are written. Exits non-zero on the first failure.
#
# WAVETANK_TEST_OPTIONS adds Allrun switches, e.g. -reflecting-outlet (a wall
# instead of the absorber at the outlet) to see the reflection check fail.
#------------------------------------------------------------------------------
. "$(dirname "$0")/tutorialTestFunctions"

endTime=15
makeWorkDir

case=$workDir/waveTank
# shellcheck disable=SC2086
runTutorial waveTank "$case" -mesh-factor 0.5 -end-time $endTime \
    ${WAVETANK_TEST_OPTIONS:-}

checkRanToEnd "$case" $endTime

results="$case/plots/waveTank.dat"
requireFile "$results" "results of waveAnalysis"

# value KEY: the value of KEY in plots/waveTank.dat
value()
{
    local v
    v=$(awk -v k="$1" '$1 == k { print $2; exit }' "$results")
    [ -n "$v" ] || fail "no $1 in $results"
    echo "$v"
}

# The window must come after the reflected waves' return, or the reflection
# check would pass on waves that have not met the outlet yet
[ "$(value reflectionMeasured)" = 1 ] \
    || fail "the analysis window ($(value windowStart)-$(value windowEnd) s) starts" \
        "before the reflected waves return ($(value reflectionReturnTime) s)"
pass "window $(value windowStart)-$(value windowEnd) s, $(value windowPeriods) periods," \
    "after the reflected waves' return at $(value reflectionReturnTime) s"

# Reflection coefficient (two-probe method, gauges near x = 3.0 and 3.5 m)
# below 0.15. Measured 0.077 (0.077-0.082 over neighbouring pairs, 0.08-0.09
# on finer meshes): OpenFOAM's active absorption corrects the boundary
# velocity by shallow-water theory, exact only for kh -> 0; at kh = 1.11 it
# leaves about 8 %. With a wall at the outlet (Allrun -reflecting-outlet)
# K_R is 0.97 (0.97-1.02 over the pairs) and this check fails.
awk -v r="$(value reflectionCoefficient)" 'BEGIN { exit !(r >= 0 && r < 0.15) }' \
    || fail "reflection coefficient $(value reflectionCoefficient)" \
        "(x = $(value reflectionPairX1), $(value reflectionPairX2) m), allowed below 0.15"
pass "reflection coefficient $(value reflectionCoefficient) (x = $(value reflectionPairX1)," \
    "$(value reflectionPairX2) m; neighbouring pairs $(value reflectionCoefficientMin)-$(value reflectionCoefficientMax)), allowed below 0.15"

# Height at the gauge nearest the generator (x = 0.51 m) within 10 % of the
# target (0.05 m). Measured -3.8 %: on this coarse mesh (5 cells per wave
# height) numerical damping has taken about 2 % off the incident wave there
# (0.4 % at mesh factor 2), and the residual reflection (K_R about 0.08) adds
# a standing part that changes the local height by up to +-K_R with the
# gauge's position (-11 to +6 % between the gauges). With a wall at the
# outlet the local height is anywhere between 0 and twice the target (+81 %
# at this gauge).
awk -v e="$(value nearestGaugeHeightError)" 'BEGIN { exit !(e < 0.10 && e > -0.10) }' \
    || fail "height at x = $(value nearestGaugeX) m: $(value nearestGaugeHeight) m," \
        "relative error $(value nearestGaugeHeightError), allowed +-0.10"
pass "height at x = $(value nearestGaugeX) m: $(value nearestGaugeHeight) m" \
    "(target $(value waveHeight) m, relative error $(value nearestGaugeHeightError), allowed +-0.10)"

# The free surface must stay within the gauge lines (0.44-0.56 m), or the
# measured elevation would be clipped (checked after the height and the
# reflection, which are then wrong too: with a wall at the outlet the
# standing wave leaves the lines, and the reflection check says why)
[ "$(value gaugeSamplesOffLine)" = 0 ] \
    || fail "the free surface left the gauge lines in $(value gaugeSamplesOffLine) samples"
pass "free surface within the gauge lines"

for f in waveTank.dat gauges.dat reflection.dat elevation.dat
do
    requireFile "$case/plots/$f" "result file"
done
for png in elevation waveHeight
do
    f="$case/plots/$png.png"
    requireFile "$f" "plot"
    [ "$(head -c 4 "$f" | tail -c 3)" = PNG ] || fail "$f is not a PNG image"
done
pass "results: waveTank.dat, gauges.dat, reflection.dat, elevation.dat; plots: elevation.png, waveHeight.png"
