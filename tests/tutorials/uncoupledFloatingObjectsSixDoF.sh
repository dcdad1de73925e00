#!/bin/bash
#------------------------------------------------------------------------------
# Smoke test of tutorials/uncoupledFloatingObjectsSixDoF: the two free
# floating cubes moved by sixDoFRigidBodyDisplacement patches (point
# constraint at the centre of mass) and a displacementLaplacian mesh motion,
# coarse mesh (mesh factor 0.5, 20 x 10 x 15 cells), 0.3 s. Checks that the
# case runs to its end time, that each cube rotates about its fixed centre of
# mass and stays inside the tank, and that the plots are written.
#
# It also runs tutorials/uncoupledFloatingObjects (rigidBodyMotion, spherical
# joints) and compares the rotations of the cubes over the first 0.2 s, while
# the first wave passes: the two are independent implementations of the same
# rigid-body motion and differ only in how the mesh follows the bodies, which
# changes the flow near them a little. They agree to within about 5 % of the
# peak rotation there; the tolerance is 10 % of it plus 0.05 deg. A sign or
# transpose error in either body frame, or forces on the wrong body, breaks
# the agreement at once.
#------------------------------------------------------------------------------
# shellcheck disable=SC2154  # the case folders, set by runCubePair
. "$(dirname "$0")/tutorialTestFunctions"

endTime=0.3
makeWorkDir

runCubePair $endTime rigidBody=uncoupledFloatingObjects sixDoF=uncoupledFloatingObjectsSixDoF

for body in floatingObject1 floatingObject2
do
    compareSeries "$rigidBody/postProcessing/rigidBodyMotion/$body.dat" \
        "$sixDoF/postProcessing/rigidBodyMotion/$body.dat" "6 7 8" 0.1 0.05 \
        "$body rotation, sixDoFRigidBodyDisplacement against rigidBodyMotion" \
        0.2
done

checkPlots "$sixDoF" rotation displacement snapshots
