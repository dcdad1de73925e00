#!/bin/bash
#------------------------------------------------------------------------------
# The FMI 3.0 FMUs in a CFD tutorial: tutorials/coupledFloatingObjects (two
# floating cubes joined by linearSpring.fmu, interFoamAliasSafe) run to
# 0.3 s twice, once with the spring's FMI 2.0 FMU and once with its FMI 3.0
# FMU (FOAMFMI_FMU_DIR pointed at build/fmus/fmi3, so that Allrun copies
# the 3.0 archive under the same name). Checks: both reach the end time and
# write the same connector outputs (postProcessing/fmuConnectors; the
# header's FMU path names each run's case folder) and the same bodies'
# motion in the solver log, byte for byte: the 3.0 FMU is the
# 2.0 FMU's law behind arrays, the same doubles in the same order, and the
# flow sees the same loads at every step.
# Needs ./Allwmake (interFoamAliasSafe, the bridge library, both FMUs).
# Exits non-zero on the first failure.
#------------------------------------------------------------------------------
. "$(dirname "$0")/tutorialTestFunctions"

endTime=0.3
requireFile "$FOAM_USER_LIBBIN/libfoamFmiBridge.so" "the bridge library (build it: ./Allwmake)"
requireFile "$FOAMFMI_FMU_DIR/linearSpring.fmu" "the spring's FMI 2.0 FMU (./Allwmake)"
requireFile "$FOAMFMI_FMU_DIR/fmi3/linearSpring.fmu" "the spring's FMI 3.0 FMU (./Allwmake)"

makeWorkDir
runTutorial coupledFloatingObjects "$workDir/fmi2" -end-time $endTime
FOAMFMI_FMU_DIR="$FOAMFMI_FMU_DIR/fmi3" \
    runTutorial coupledFloatingObjects "$workDir/fmi3" -end-time $endTime
for v in fmi2 fmi3
do
    checkRanToEnd "$workDir/$v" $endTime
done
unzip -p "$workDir/fmi3/constant/fmu/linearSpring.fmu" modelDescription.xml \
    | grep -q 'fmiVersion="3.0"' \
    || fail "the second run's constant/fmu/linearSpring.fmu is not the FMI 3.0 FMU"
pass "both runs reach $endTime s; the second one's spring is the FMI 3.0 FMU"

# The connectors' outputs: every file, every byte
n=0
for f in "$workDir"/fmi2/postProcessing/fmuConnectors/*/*.dat
do
    g="$workDir/fmi3/${f#"$workDir"/fmi2/}"
    requireFile "$g" "the FMI 3.0 run's ${f#"$workDir"/fmi2/}"
    # (the header names the FMU by its path, in each run's own case folder)
    cmp -s <(sed "1s|$workDir/fmi2/|CASE/|" "$f") <(sed "1s|$workDir/fmi3/|CASE/|" "$g") \
        || fail "${f#"$workDir"/fmi2/} differs between the FMI 2.0 and 3.0 runs"
    n=$((n + 1))
done
[ "$n" -gt 0 ] || fail "no connector output in $workDir/fmi2/postProcessing/fmuConnectors"
pass "$n connector output file(s) byte for byte"

# The bodies' motion as the solver reported it, every step
log2=$(solverLog "$workDir/fmi2")
log3=$(solverLog "$workDir/fmi3")
motion()
{
    awk '/^Rigid-body motion of the/ { n = 5 } n-- > 0' "$1"
}
[ -n "$(motion "$log2")" ] || fail "no body reports in $log2"
cmp -s <(motion "$log2") <(motion "$log3") \
    || fail "the bodies' motion differs between the FMI 2.0 and 3.0 runs ($log2, $log3)"
pass "the bodies' motion in $(grep -c '^Time = ' "$log2") time steps, byte for byte"
echo "tests passed: tutorials.fmi3SameAnswers"
