#!/bin/bash
#------------------------------------------------------------------------------
# Smoke test of tutorials/uncoupledFloatingObjects: two floating cubes free of
# each other, rigidBodyMotion with spherical joints, coarse mesh (mesh factor
# 0.5, 20 x 10 x 15 cells), 0.3 s. Checks that the case runs to its end time,
# that each cube rotates about its fixed centre of mass and stays inside the
# tank, and that the plots are written. Exits non-zero on the first failure.
#------------------------------------------------------------------------------
. "$(dirname "$0")/tutorialTestFunctions"

endTime=0.3
makeWorkDir

case=$workDir/uncoupledFloatingObjects
runTutorial uncoupledFloatingObjects "$case" -mesh-factor 0.5 -end-time $endTime

checkRanToEnd "$case" $endTime
# shellcheck disable=SC2086
checkBodies "$case" $cubeBodies

checkPlots "$case" rotation displacement snapshots
