#!/bin/bash
#------------------------------------------------------------------------------
# tutorials/mooredSectionWaves' scheme switches, -ddt, -momentum-ddt and
# -momentum-scheme, on the flume alone (-empty-flume, the generator 2.5 m
# before the section's position, to 0.1 s: the mesh, the waves' start and
# the solver's first steps), -coupling stock and -phase-advection
# isoAdvector. Checks:
#  - a value that is not a scheme is refused before anything is run, the
#    message naming the switch and the value;
#  - the schemes given are those the case's system/fvSchemes holds
#    (foamDictionary reads them through its #includeIfPresent), and the
#    solver runs to the end time with them (Allrun saying that a run
#    ending before the window measures no wave);
#  - a scheme OpenFOAM does not have stops the solver with its own error
#    naming it (the solver reads the momentum's scheme from the file
#    Allrun writes), and Allrun with it, saying so;
#  - -coupling stock runs the section under OpenFOAM's own rigidBodyMotion
#    (the solver selects it, with the case's bodies and restraints, and
#    steps to 0.02 s);
#  - -phase-advection isoAdvector runs the section, on its moving mesh, by
#    interIsoFoamAliasSafe (the case's controlDict names it through
#    system/application), with the isoAdvector settings in the case's
#    system/fvSolution, to 0.02 s;
#  - raoSweep hands the flume's switches to Allrun whole (a scheme of
#    several words, with a semicolon), in a folder named by them, and
#    stops, keeping nothing, when Allrun refuses one;
#  - heaveDecay refuses a variant it cannot name before running any.
# Needs the project's OpenFOAM environment (etc/bashrc). Exits non-zero on
# the first failure.
#------------------------------------------------------------------------------
. "$(dirname "$0")/tutorialTestFunctions"

endTime=0.1
flume="-empty-flume -period 0.802 -generator-distance 2.5 -end-time $endTime"
ddt="CrankNicolson 0.9"
momentumDdt="CrankNicolson 0.7"
momentum="Gauss linearUpwindV grad(U)"

makeWorkDir
case=$workDir/mooredSectionWaves
cp -r "$FOAMFMI_DIR/tutorials/mooredSectionWaves" "$case" || fail "cannot copy the case"
"$case/Allclean" > /dev/null 2>&1 || fail "Allclean failed"

# refuseSwitch SWITCH VALUE: Allrun stops before the mesh, naming both
refuseSwitch()
{
    if "$case/Allrun" $flume "$1" "$2" > "$case/log.refused" 2>&1
    then
        fail "Allrun $1 '$2' ran; expected a refusal"
    fi
    grep -q -- "$1: .*$2" "$case/log.refused" \
        || fail "Allrun $1 '$2': the message does not name the switch and the value: $(tail -n 1 "$case/log.refused")"
    [ ! -f "$case/log.blockMesh" ] || fail "Allrun $1 '$2': meshed before refusing"
    pass "Allrun $1 '$2' refused: $(tail -n 1 "$case/log.refused")"
}
refuseSwitch -momentum-scheme "linearUpwindV grad(U)"
refuseSwitch -momentum-scheme "Gauss linear; div(phi,alpha) Gauss upwind"
refuseSwitch -ddt "CrankNicolson 2"
refuseSwitch -momentum-ddt "CrankNicolson 0.9 0.5"
refuseSwitch -coupling "rigidBodyMotion"
refuseSwitch -phase-advection "isoadvector"

# refuseInSweep SWITCH VALUE FOLDER: raoSweep's Allrun refuses it in
# sweep/FOLDER, and raoSweep stops without keeping a run
refuseInSweep()
{
    if "$case/raoSweep" -mesh-factor 0.5 "$1" "$2" 0.802 > "$case/log.raoSweep" 2>&1
    then
        fail "raoSweep $1 '$2' ran; expected a refusal"
    fi
    grep -q -- "$1: .*$2" "$case/sweep/$3/log.Allrun" \
        || fail "raoSweep $1 '$2': sweep/$3/log.Allrun does not refuse it: $(tail -n 1 "$case/sweep/$3/log.Allrun" 2>&1)"
    grep -q "period 0.802 s failed" "$case/log.raoSweep" \
        || fail "raoSweep $1 '$2' did not stop on the refusal: $(tail -n 1 "$case/log.raoSweep")"
    [ ! -d "$case/results/$3" ] || fail "raoSweep $1 '$2': kept results/$3"
    pass "raoSweep $1 '$2' reached Allrun in sweep/$3, refused: $(tail -n 1 "$case/sweep/$3/log.Allrun")"
}
refuseInSweep -ddt "CrankNicolson 2" F0.5_H0.024_T0.802_ddtCrankNicolson2
refuseInSweep -momentum-scheme "Gauss linear; div(phi,alpha) Gauss upwind" \
    "F0.5_H0.024_T0.802_divlinear;divphi,alphaGaussupwind"

# refuseInDecay VARIANT MESSAGE: heaveDecay stops before any run, saying so
refuseInDecay()
{
    if "$case/heaveDecay" '' "$1" > "$case/log.heaveDecay" 2>&1
    then
        fail "heaveDecay '$1' ran; expected a refusal"
    fi
    grep -q -- "$2" "$case/log.heaveDecay" \
        || fail "heaveDecay '$1': not refused with '$2': $(tail -n 1 "$case/log.heaveDecay")"
    [ ! -d "$case/sweep/heaveDecay" ] || fail "heaveDecay '$1': ran a variant before refusing"
    pass "heaveDecay '$1' refused: $(tail -n 1 "$case/log.heaveDecay")"
}
refuseInDecay "-ddt Euler -momentum-ddt" "-momentum-ddt needs a value"
refuseInDecay "-guide-friction 0.5" "-guide-friction: not a flume switch"

runTutorial mooredSectionWaves "$case" $flume -ddt "$ddt" -momentum-ddt "$momentumDdt" \
    -momentum-scheme "$momentum"
# (the flume alone's time step is not cut to end at the end time)
grep -q '^End' "$(solverLog "$case")" || fail "the solver did not finish ($(solverLog "$case"))"
pass "the solver ran to t = $(sed -n 's/^Time = //p' "$(solverLog "$case")" | tail -n 1) s"
grep -q "before the window .*no wave measured" "$case/log.Allrun" \
    || fail "Allrun did not say that a run ending before the window measures no wave"
read -r _ ddtRead < <(foamDictionary -case "$case" -entry ddtSchemes/default \
    "$case/system/fvSchemes" 2>/dev/null | tr -d ';')
[ "$ddtRead" = "$ddt" ] || fail "ddtSchemes/default is '$ddtRead', expected '$ddt'"
read -r _ momentumDdtRead < <(foamDictionary -case "$case" -entry 'ddtSchemes/ddt(rho,U)' \
    "$case/system/fvSchemes" 2>/dev/null | tr -d ';')
[ "$momentumDdtRead" = "$momentumDdt" ] \
    || fail "ddtSchemes/ddt(rho,U) is '$momentumDdtRead', expected '$momentumDdt'"
read -r _ momentumRead < <(foamDictionary -case "$case" -entry 'divSchemes/div(rhoPhi,U)' \
    "$case/system/fvSchemes" 2>/dev/null | tr -d ';')
[ "$momentumRead" = "$momentum" ] \
    || fail "divSchemes/div(rhoPhi,U) is '$momentumRead', expected '$momentum'"
pass "the case's schemes: ddt $ddtRead, ddt(rho,U) $momentumDdtRead, div(rhoPhi,U) $momentumRead"

# A scheme OpenFOAM does not have: the solver's own error names it
"$case/Allclean" > /dev/null 2>&1 || fail "Allclean failed"
if "$case/Allrun" $flume -momentum-scheme "Gauss noSuchScheme" > "$case/log.Allrun" 2>&1
then
    fail "Allrun -momentum-scheme 'Gauss noSuchScheme' ran to the end"
fi
log=$(solverLog "$case")
grep -q "noSuchScheme" "$log" \
    || fail "the solver did not stop on the unknown scheme ($log: $(tail -n 3 "$log"))"
grep -q "stopped at t = .*see log" "$case/log.Allrun" \
    || fail "Allrun did not say that the solver stopped ($(tail -n 1 "$case/log.Allrun"))"
pass "an unknown momentum scheme stops the solver: $(grep -m 1 -i "unknown" "$log"); Allrun: $(tail -n 1 "$case/log.Allrun")"

# OpenFOAM's own coupling for the section (-coupling stock): the solver
# selects rigidBodyMotion, reads the case's restraints and steps
stock=$workDir/stock
runTutorial mooredSectionWaves "$stock" -period 0.802 -generator-distance 2.5 \
    -end-time 0.02 -no-plot -coupling stock
log=$(solverLog "$stock")
grep -q "Selecting motion solver: rigidBodyMotion" "$log" \
    || fail "-coupling stock: the solver did not select rigidBodyMotion ($log)"
grep -q "Selecting motion solver: addedMassRigidBodyMotion" "$log" \
    && fail "-coupling stock: the added-mass coupling was selected too ($log)"
grep -q "springWeather" "$log" || fail "-coupling stock: no restraint springWeather in $log"
grep -q '^End' "$log" || fail "-coupling stock: the solver did not finish ($log)"
pass "-coupling stock: rigidBodyMotion with the case's restraints ran to t = $(sed -n 's/^Time = //p' "$log" | tail -n 1) s"

# The phase fraction by isoAdvector (-phase-advection isoAdvector): the
# solver the case's controlDict then names runs the section's moving mesh
iso=$workDir/isoAdvector
runTutorial mooredSectionWaves "$iso" -period 0.802 -generator-distance 2.5 \
    -end-time 0.02 -no-plot -phase-advection isoAdvector
read -r _ application < <(foamDictionary -case "$iso" -entry application \
    "$iso/system/controlDict" 2>/dev/null | tr -d ';')
[ "$application" = interIsoFoamAliasSafe ] \
    || fail "-phase-advection isoAdvector: controlDict's application is '$application'"
read -r _ isoFaceTol < <(foamDictionary -case "$iso" -entry 'solvers/alpha.water.*/isoFaceTol' \
    "$iso/system/fvSolution" 2>/dev/null | tr -d ';')
[ "$isoFaceTol" = 1e-10 ] \
    || fail "-phase-advection isoAdvector: fvSolution's isoFaceTol is '$isoFaceTol'"
log=$(solverLog "$iso")
[ "${log##*/}" = log.interIsoFoamAliasSafe ] \
    || fail "-phase-advection isoAdvector: the solver's log is $log"
grep -q "isoAdvection: time consumption" "$log" \
    || fail "-phase-advection isoAdvector: the solver did not advect by isoAdvector ($log)"
grep -q '^End' "$log" || fail "-phase-advection isoAdvector: the solver did not finish ($log)"
pass "-phase-advection isoAdvector: interIsoFoamAliasSafe (isoFaceTol $isoFaceTol) ran the" \
    "section to t = $(sed -n 's/^Time = //p' "$log" | tail -n 1) s"
