#!/bin/bash
#------------------------------------------------------------------------------
# Smoke test of tutorials/hingedFloatingObjects: the two floating cubes free
# to translate and rotate (floating joints), joined by the hinge connector
# FMU (fmuConnector restraint, libfoamFmiBridge) along y through
# (0 0.5 0.6), the rigid-body motion solved by implicitNewmark
# (libimplicitRigidBodySolvers), coarse mesh (mesh factor 0.5, 20 x 10 x 15
# cells), 0.3 s. Checks:
#  - the run reaches the end time; each cube stays inside the tank and
#    moves;
#  - implicitNewmark converged in every solve: no warning in the log, and
#    its statistics line is there;
#  - the hinge writes one row per time step with A.F = -B.F;
#  - the hinge holds: its gap stays below 0.4 mm and its misalignment below
#    4 mrad in every row, while its angle changes by more than 0.5 deg. The
#    bounds are load/stiffness for loads the hinge cannot exceed here: it
#    carries at most the weight of a cube, 39 N (the cubes float, and the
#    wave's loads on a cube are smaller), which opens the hinge by
#    39 N/1e5 N/m = 0.39 mm, and at most that weight's moment about a
#    cube's centre across the axis, 39 N x 0.1 m, which tilts the axes by
#    3.9 N.m/1e3 N.m/rad = 3.9 mrad. In the smoke run both stay far below
#    (about 25 um and 0.25 mrad);
#  - the two bodies' relative motion, from their logged motion independently
#    of the FMU, is a rotation about the hinge line: the hinge points
#    (0.2 0 0.17) on A and (-0.2 0 0.17) on B stay within 0.4 mm of each
#    other, the relative rotation R_A^T R_B turns about y (its part across y
#    below 4 mrad), and its angle about y is the FMU's hinge angle (within
#    1 % of the largest angle plus 0.1 mrad: the FMU sees the state of the
#    last outer corrector, the log the state the step ends with);
#  - the plots are written.
# Needs platforms/<WM_OPTIONS>/lib/libfoamFmiBridge.so,
# libimplicitRigidBodySolvers.so and build/fmus/hinge.fmu. Exits non-zero on
# the first failure.
#------------------------------------------------------------------------------
. "$(dirname "$0")/tutorialTestFunctions"
. "$(dirname "$0")/connectorTestFunctions"

endTime=0.3
gapBound=4e-4
misalignmentBound=4e-3
hingeA="0.2 0 0.17"
hingeB="-0.2 0 0.17"

requireFile "$FOAM_USER_LIBBIN/libfoamFmiBridge.so" \
    "the bridge library (build it: ./Allwmake)"
requireFile "$FOAM_USER_LIBBIN/libimplicitRigidBodySolvers.so" \
    "the implicit rigid-body solver library (build it: ./Allwmake)"
requireFile "$FOAMFMI_FMU_DIR/hinge.fmu" "the hinge FMU (build it: ./Allwmake)"

makeWorkDir

hinged=$workDir/hingedFloatingObjects
runTutorial hingedFloatingObjects "$hinged" -mesh-factor 0.5 -end-time $endTime

checkRanToEnd "$hinged" $endTime
checkFreeBodies "$hinged" floatingObject1 floatingObject2

checkImplicitNewmark "$hinged"


# --- The hinge's output ------------------------------------------------------
checkConnectorRows "$hinged" hinge balanced

dat=$(connectorFile "$hinged" hinge) || exit 1
cols=$(columnsOf "$dat" gap misalignment angle) || exit 1
awk -v cols="$cols" -v gapBound=$gapBound -v misBound=$misalignmentBound '
function bad(msg) { print msg > "/dev/stderr"; failed = 1; exit 1 }
BEGIN { split(cols, k, " "); deg = 45/atan2(1, 1) }
/^#/ { next }
{
    gap = $(k[1]); mis = $(k[2]); phi = $(k[3])
    if (gap > gapBound) bad(sprintf("t = %s: gap %.3g m above %g m", $1, gap, gapBound))
    if (mis > misBound) bad(sprintf("t = %s: misalignment %.3g rad above %g rad", $1, mis, misBound))
    if (gap > maxGap) maxGap = gap
    if (mis > maxMis) maxMis = mis
    if (n++ == 0) { lo = phi; hi = phi }
    if (phi < lo) lo = phi
    if (phi > hi) hi = phi
}
END {
    if (failed) exit 1
    if ((hi - lo)*deg < 0.5) bad(sprintf("the hinge angle changes by %.3g deg only", (hi - lo)*deg))
    printf("gap <= %.3g m, misalignment <= %.3g rad, angle from %.3g to %.3g deg\n", maxGap, maxMis, lo*deg, hi*deg)
}' "$dat" > "$workDir/check.out" || fail "$dat: see above"
pass "hinge holds: $(cat "$workDir/check.out")"


# --- Relative motion of the bodies: a rotation about the hinge line ---------
awk -v pa="$hingeA" -v pb="$hingeB" -v angleCol="$(columnOf "$dat" angle)" \
    -v gapBound=$gapBound -v misBound=$misalignmentBound "$rotateAwk$hingeRowsAwk"'
function bad(msg) { print msg > "/dev/stderr"; failed = 1; exit 1 }
function abs(x) { return x < 0 ? -x : x }
BEGIN { deg = atan2(1, 1)/45; split(pa, pA, " "); split(pb, pB, " ") }
{
    hingeRow()
    # Hinge points from the body motion
    rotate(A[n, 6], A[n, 7], A[n, 8], pA, qA)
    rotate(B[n, 6], B[n, 7], B[n, 8], pB, qB)
    d = sqrt((A[n, 2] + qA[1] - B[n, 2] - qB[1])^2 + (A[n, 3] + qA[2] - B[n, 3] - qB[2])^2 + (A[n, 4] + qA[3] - B[n, 4] - qB[3])^2)
    if (d > gapBound) bad(sprintf("t = %s: hinge points %.3g m apart", $1, d))
    if (d > maxD) maxD = d
    # Relative rotation R = R_A^T R_B, column by column
    for (j = 1; j <= 3; j++)
    {
        e[1] = (j == 1); e[2] = (j == 2); e[3] = (j == 3)
        rotate(B[n, 6], B[n, 7], B[n, 8], e, u)
        rotate(-A[n, 6], -A[n, 7], -A[n, 8], u, v)
        for (i = 1; i <= 3; i++) R[i, j] = v[i]
    }
    sx = 0.5*(R[3, 2] - R[2, 3]); sy = 0.5*(R[1, 3] - R[3, 1]); sz = 0.5*(R[2, 1] - R[1, 2])
    s = sqrt(sx*sx + sy*sy + sz*sz)
    th = atan2(s, 0.5*(R[1, 1] + R[2, 2] + R[3, 3] - 1))
    fac = (s > 1e-300) ? th/s : 1
    across = fac*sqrt(sx*sx + sz*sz)
    about = fac*sy
    if (across > misBound) bad(sprintf("t = %s: relative rotation %.3g rad across the hinge axis", $1, across))
    if (across > maxAcross) maxAcross = across
    phi[n] = $angleCol; rel[n] = about
    if (abs(phi[n]) > maxPhi) maxPhi = abs(phi[n])
}
END {
    if (failed) exit 1
    hingeRowsEnd()
    for (i = 1; i <= n; i++)
        if (abs(phi[i] - rel[i]) > worst) { worst = abs(phi[i] - rel[i]); tWorst = i }
    tol = 0.01*maxPhi + 1e-4
    if (worst > tol) bad(sprintf("relative rotation about y %.6g rad, hinge angle %.6g rad (row %d, tolerance %.3g rad)", rel[tWorst], phi[tWorst], tWorst, tol))
    printf("hinge points within %.3g m, relative rotation across the axis <= %.3g rad, about the axis = hinge angle within %.3g rad (tolerance %.3g rad)\n", maxD, maxAcross, worst, tol)
}' "$hinged/postProcessing/rigidBodyMotion/floatingObject1.dat" \
   "$hinged/postProcessing/rigidBodyMotion/floatingObject2.dat" "$dat" \
    > "$workDir/check.out" || fail "relative motion of the bodies: see above"
pass "relative motion: $(cat "$workDir/check.out")"


# --- Plots -------------------------------------------------------------------
checkPlots "$hinged" rotation displacement connector_hinge snapshots

#------------------------------------------------------------------------------
