#!/bin/bash
#------------------------------------------------------------------------------
# Smoke test of tutorials/mooredFloatingObject: a floating cube free to
# translate and rotate (floating joint), moored to the tank floor by four
# quasi-static catenary lines (catenary.fmu in four fmuConnector
# restraints), the rigid-body motion solved by implicitNewmark, coarse mesh
# (mesh factor 0.5, 20 x 10 x 15 cells), 0.3 s. With the argument
# mooredFloatingObjectDynamic, the same checks on that tutorial (the lines
# as dynamic lumped-mass lines, mooringLine.fmu), except the two that hold
# for a quasi-static line only (marked *). Checks:
#  - the run reaches the end time; the cube stays inside the tank and moves;
#    implicitNewmark converged in every solve (no warning in the log);
#  - each line writes one row of finite numbers per time step; its fairlead
#    and anchor tensions are positive in every row, and (*) the fairlead
#    tension is the magnitude of the force on the cube (the dynamic line's
#    force also carries the fairlead half-segment's weight and inertia);
#  - (*) the lines start with the tension of the elastic catenary of the
#    case: 1.1 m, 1 N/m, from a fairlead at a corner of the cube's bottom
#    face (0.4 m above the floor) to an anchor 0.919 m away horizontally,
#    solved here independently (inextensible catenary with touchdown, by
#    bisection; the stretch, 1.4e-4, is below the tolerance of 1 %); the
#    dynamic line's first tension follows the cube's first motion through
#    its stiff end segment (tutorials/README.md), so it is only printed;
#  - each line's length output is the distance between its fairlead, as
#    moved by the cube's logged motion, and its anchor (within a tenth of
#    the largest change of length in one step);
#  - the moorings hold the cube: its centre of mass stays within the
#    anchors' footprint (-0.95..0.95, 0.05..0.95), less than 0.08 m from
#    where it started horizontally (the offset at which a line would lift
#    completely off the floor), and every line keeps part of its length on
#    the floor;
#  - each line is written as VTK at every write time, with the points and
#    tensions of its output rows; (dynamic lines) the water velocity the
#    lines are given (function object fmuConnectorFlow) is U at the lines'
#    points, as OpenFOAM's probes find it (checkLineOutputs.py);
#  - the plots are written.
# Needs platforms/<WM_OPTIONS>/lib/libfoamFmiBridge.so,
# libimplicitRigidBodySolvers.so and build/fmus/catenary.fmu (mooringLine.fmu).
# Exits non-zero on the first failure.
#------------------------------------------------------------------------------
. "$(dirname "$0")/tutorialTestFunctions"
. "$(dirname "$0")/connectorTestFunctions"

tutorial=${1:-mooredFloatingObject}
case "$tutorial" in
mooredFloatingObject) fmu=catenary; quasiStatic=1 ;;
mooredFloatingObjectDynamic) fmu=mooringLine; quasiStatic=0 ;;
*) echo "usage: $0 [mooredFloatingObject|mooredFloatingObjectDynamic]" 1>&2; exit 2 ;;
esac
testName=$tutorial

endTime=0.3
lineLength=1.1
lineWeight=1
fairleadHeight=0.4
# line:fairlead (body frame):anchor (global)
lines="line1:0.1,0.1,-0.03:0.95,0.95,0 line2:-0.1,0.1,-0.03:-0.95,0.95,0
line3:-0.1,-0.1,-0.03:-0.95,0.05,0 line4:0.1,-0.1,-0.03:0.95,0.05,0"

requireFile "$FOAM_USER_LIBBIN/libfoamFmiBridge.so" \
    "the bridge library (build it: ./Allwmake)"
requireFile "$FOAM_USER_LIBBIN/libimplicitRigidBodySolvers.so" \
    "the implicit rigid-body solver library (build it: ./Allwmake)"
requireFile "$FOAMFMI_FMU_DIR/$fmu.fmu" \
    "the $fmu FMU (build it: ./Allwmake)"

makeWorkDir

moored=$workDir/$tutorial
runTutorial "$tutorial" "$moored" -mesh-factor 0.5 -end-time $endTime

checkRanToEnd "$moored" $endTime
checkFreeBodies "$moored" floatingObject
bodyDat=$moored/postProcessing/rigidBodyMotion/floatingObject.dat

checkImplicitNewmark "$moored"


# Tension at rest of the case's lines: inextensible catenary with touchdown,
# horizontal span x, height z of the fairlead above the anchor. With
# a = H/w the suspended length is s = sqrt(z^2 + 2 z a) and
# x = L - s + a asinh(s/a); bisection on a (x grows with a).
restTension=$(awk -v L=$lineLength -v w=$lineWeight -v z=$fairleadHeight '
function asinh(u) { return log(u + sqrt(u*u + 1)) }
function span(a,    s) { s = sqrt(z*z + 2*z*a); return L - s + a*asinh(s/a) }
BEGIN {
    x = sqrt(0.85^2 + 0.35^2)
    lo = 1e-6; hi = 100
    for (i = 0; i < 200; i++) { m = 0.5*(lo + hi); if (span(m) < x) lo = m; else hi = m }
    a = 0.5*(lo + hi); s = sqrt(z*z + 2*z*a)
    printf("%.10g\n", sqrt((w*a)^2 + (w*s)^2))
}')


# --- Each line ---------------------------------------------------------------
for spec in $lines
do
    mooringLineRows "$moored" "$spec"
    cols=$(columnsOf "$dat" 'A.F[1]' 'A.F[2]' 'A.F[3]' fairleadTension anchorTension \
        groundedLength length) || exit 1

    awk -v cols="$cols" -v T0="$restTension" -v quasiStatic="$quasiStatic" \
        -v pa="$fairlead" -v anchor="$anchor" "$rotateAwk"'
    function bad(msg) { print msg > "/dev/stderr"; failed = 1; exit 1 }
    function abs(x) { return x < 0 ? -x : x }
    BEGIN { deg = atan2(1, 1)/45; split(cols, k, " "); split(pa, p, " "); split(anchor, q, " ") }
    FNR == 1 { f++ }
    /^#/ { next }
    f == 1 {
        nB++; tB[nB] = $1
        rotate($6, $7, $8, p, r)
        D[nB] = sqrt(($2 + r[1] - q[1])^2 + ($3 + r[2] - q[2])^2 + ($4 + r[3] - q[3])^2)
        next
    }
    {
        n++
        if (n > nB || abs(tB[n] - $1) > 1e-5*(abs($1) + 1e-3)) bad("row " n ": different times in the body and line files")
        F = sqrt($(k[1])^2 + $(k[2])^2 + $(k[3])^2)
        Tf = $(k[4]); Ta = $(k[5]); g = $(k[6]); L[n] = $(k[7])
        if (!(Tf > 0) || !(Ta > 0)) bad(sprintf("t = %s: fairlead tension %.6g N, anchor tension %.6g N: not positive", $1, Tf, Ta))
        if (quasiStatic && abs(F - Tf) > 1e-9*Tf) bad(sprintf("t = %s: |A.F| = %.12g N, fairlead tension %.12g N", $1, F, Tf))
        if (!(g > 0)) bad(sprintf("t = %s: no part of the line on the floor (grounded length %.6g m)", $1, g))
        if (n == 1) T1 = Tf
        if (n == 1 || Tf < minT) minT = Tf
        if (Tf > maxT) maxT = Tf
        if (n == 1 || g < minG) minG = g
        e = abs(L[n] - D[n])
        if (e > worst) { worst = e; tWorst = $1 }
        if (n > 1 && abs(L[n] - L[n - 1]) > maxStep) maxStep = abs(L[n] - L[n - 1])
    }
    END {
        if (failed) exit 1
        if (n != nB) bad(n " line rows, " nB " body rows")
        if (quasiStatic && abs(T1 - T0) > 0.01*T0) bad(sprintf("first fairlead tension %.6g N, the catenary at rest %.6g N", T1, T0))
        if (worst > 0.1*maxStep) bad(sprintf("length differs from the distance fairlead-anchor by %.3g m at t = %s (tolerance %.3g m)", worst, tWorst, 0.1*maxStep))
        printf("fairlead tension %.4g N at the start (catenary %.4g N), %.4g to %.4g N, anchor tension > 0, %slength = fairlead-anchor distance within %.2g m, at least %.3g m on the floor\n", T1, T0, minT, maxT, quasiStatic ? "|A.F| = fairlead tension, " : "", worst, minG)
    }' "$bodyDat" "$dat" > "$workDir/check.out" || fail "$dat: see above"
    pass "$lineName: $(cat "$workDir/check.out")"
done


# --- The moorings hold the cube ----------------------------------------------
awk '
function bad(msg) { print msg > "/dev/stderr"; failed = 1; exit 1 }
/^#/ { next }
{
    if (n++ == 0) { x0 = $2; y0 = $3 }
    if ($2 <= -0.95 || $2 >= 0.95 || $3 <= 0.05 || $3 >= 0.95)
        bad("t = " $1 ": centre of mass (" $2 " " $3 ") outside the anchors footprint")
    d = sqrt(($2 - x0)^2 + ($3 - y0)^2)
    if (d > 0.08) bad(sprintf("t = %s: centre of mass %.3g m from where it started", $1, d))
    if (d > maxD) maxD = d
}
END {
    if (failed) exit 1
    printf("centre of mass inside the anchors footprint, at most %.3g m from where it started horizontally\n", maxD)
}' "$bodyDat" > "$workDir/check.out" || fail "$bodyDat: see above"
pass "moorings hold: $(cat "$workDir/check.out")"


# --- Lines as VTK; the water velocity at the dynamic lines -------------------
flowArgs=""
[ "$quasiStatic" = 1 ] || flowArgs="--flow lineFlow --solver $(caseSolverOf "$moored")"
# shellcheck disable=SC2086
python3 "$(dirname "$0")/checkLineOutputs.py" "$moored" line1 line2 line3 \
    line4 $flowArgs > "$workDir/check.out" 2>&1 \
    || { cat "$workDir/check.out" 1>&2; fail "line outputs: see above"; }
while read -r line; do pass "$line"; done < "$workDir/check.out"


# --- Plots -------------------------------------------------------------------
checkPlots "$moored" rotation displacement connector_line1 connector_line2 \
    connector_line3 connector_line4 lineTensions snapshots

#------------------------------------------------------------------------------
