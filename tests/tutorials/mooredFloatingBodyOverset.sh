#!/bin/bash
#------------------------------------------------------------------------------
# Smoke test of tutorials/mooredFloatingBodyOverset: a floating cube on an
# overset mesh (overInterDyMFoamAliasSafe, sixDoFRigidBodyMotion solver),
# moored by two quasi-static catenary lines (catenary.fmu in two fmuConnector
# restraints), released 0.2 m from its mooring equilibrium x = 0, coarse mesh
# (mesh factor 0.5), 1 s. Checks:
#  - the run reaches the end time; the motion file has one finite row per
#    time step; the cube stays in its plane (y = 0, rotation about y only:
#    the constraints of the 2D case);
#  - each line writes one row of finite numbers per time step, and the
#    fairlead it was evaluated at (its shape's first point) is the cube's
#    fairlead as moved by the logged motion at the start of that step
#    (sixDoFRigidBodyMotion's Newmark solver evaluates restraints at the
#    state the step starts from), within 1e-7 m: the motion file's 10
#    significant digits; evaluated one step late it would be off by the
#    cube's motion in a step, 1e-5 to 1e-3 m once it moves;
#  - each line's horizontal tension H, vertical tension V at the fairlead
#    and fairlead tension are those of an elastic catenary with touchdown
#    (1.6 m, 2 N/m, EA = 5000 N, no friction) between that fairlead and its
#    anchor (the anchor as the case gives it), solved here independently
#    (nested bisection, below), within 1e-6 N + 1e-6 of the tension: the
#    FMU's Newton method stops at 1e-10 of the span, which moves H by 1e-8 N
#    where the line is stiffest (dH/dx = 100 N/m near lift-off); the file
#    has 16 significant digits (measured: 2e-14 N). A weight 1 % off fails;
#  - the lines pull the cube back: while it is on the side x > 0 the lines'
#    net horizontal force on it points to -x in every step, and by the end it
#    has moved towards the equilibrium by more than 0.04 m (measured 0.084 m
#    at 1 s; half of that fails a restoring force halved, and a cube the
#    lines do not reach stays where it was released);
#  - the plots are written.
# Needs platforms/<WM_OPTIONS>/bin/overInterDyMFoamAliasSafe,
# platforms/<WM_OPTIONS>/lib/libfoamFmiBridge.so and build/fmus/catenary.fmu.
# Exits non-zero on the first failure.
#------------------------------------------------------------------------------
. "$(dirname "$0")/tutorialTestFunctions"
. "$(dirname "$0")/connectorTestFunctions"

tutorial=mooredFloatingBodyOverset
endTime=1
minMoved=0.04
# The lines of constant/dynamicMeshDict: unstretched length, submerged
# weight, axial stiffness; name:fairlead (body frame):anchor (global)
lineLength=1.6
lineWeight=2
lineEA=5000
lines="line1:0.1,0,-0.03:1.4,0,0 line2:-0.1,0,-0.03:-1.4,0,0"

solver=$(caseSolverOf "$FOAMFMI_DIR/tutorials/$tutorial")
command -v "$solver" > /dev/null || fail "the overset solver $solver not found (build it: ./Allwmake)"
requireFile "$FOAM_USER_LIBBIN/libfoamFmiBridge.so" \
    "the bridge library (build it: ./Allwmake)"
requireFile "$FOAMFMI_FMU_DIR/catenary.fmu" \
    "the catenary FMU (build it: ./Allwmake)"

# Where the cube starts (constant/bodyStart)
x0=$(sed -n 's/^x0[ \t][ \t]*\([^;]*\);.*/\1/p' \
    "$FOAMFMI_DIR/tutorials/$tutorial/constant/bodyStart")
[ -n "$x0" ] || fail "no x0 in tutorials/$tutorial/constant/bodyStart"

makeWorkDir

moored=$workDir/$tutorial
runTutorial "$tutorial" "$moored" -mesh-factor 0.5 -end-time $endTime

checkRanToEnd "$moored" $endTime
bodyDat=$moored/postProcessing/rigidBodyMotion/floatingObject.dat
requireFile "$bodyDat" "motion of floatingObject"
nSteps=$(grep -c '^Time = ' "$(solverLog "$moored")")


# --- The cube: finite, one row per step, in its plane -------------------------
awk -v nSteps="$nSteps" '
function bad(msg) { print msg > "/dev/stderr"; failed = 1; exit 1 }
function abs(x) { return x < 0 ? -x : x }
/^#/ { next }
{
    n++
    if (NF != 17) bad("row " n " has " NF " columns, expected 17")
    for (i = 1; i <= NF; i++)
        if ($i !~ /^[-+]?[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$/) bad("t = " $1 ": not a finite number: " $i)
    # y and the rotations about x and z stay zero (plane and axis
    # constraints); the file has 10 significant digits
    if (abs($3) > 1e-9 || abs($6) > 1e-6 || abs($8) > 1e-6)
        bad(sprintf("t = %s: out of the x-z plane: y = %g m, rotation (%g %g %g) deg", $1, $3, $6, $7, $8))
    if (abs($7) > maxPitch) maxPitch = abs($7)
}
END {
    if (failed) exit 1
    if (n != nSteps) bad(n " rows for " nSteps " time steps in the log")
    printf("%d steps, in the x-z plane, largest pitch %.3g deg\n", n, maxPitch)
}' "$bodyDat" > "$workDir/check.out" || fail "$bodyDat: see above"
pass "cube: $(cat "$workDir/check.out")"


# --- Each line: where it was evaluated, and its tensions -----------------------
# Elastic catenary with touchdown and without friction (the law of
# connectors/catenary/README.md), horizontal span x and height z of the
# fairlead above the anchor: with a = V/H,
#   touchdown (V < wL):  x = L - V/w + (H/w) asinh(a) + H L/EA
#                        z = (H/w)(sqrt(1 + a^2) - 1) + V^2/(2 EA w)
#   suspended (V >= wL): b = (V - wL)/H,
#                        x = (H/w)(asinh(a) - asinh(b)) + H L/EA
#                        z = (H/w)(sqrt(1 + a^2) - sqrt(1 + b^2)) + (V L - w L^2/2)/EA
# For a given H, z grows with V: V by bisection on z; then x grows with H:
# H by bisection on x. H = 0 is the line hanging straight down onto the
# floor (x <= L - V/w, z = V/w + V^2/(2 EA w)).
catenaryAwk='
function asinh(u) { return u < 0 ? -log(-u + sqrt(u*u + 1)) : log(u + sqrt(u*u + 1)) }
function zOf(H, V,    a, b)
{
    if (H <= 0) return V/w + V*V/(2*EA*w)
    a = V/H
    if (V < w*L) return (H/w)*(sqrt(1 + a*a) - 1) + V*V/(2*EA*w)
    b = (V - w*L)/H
    return (H/w)*(sqrt(1 + a*a) - sqrt(1 + b*b)) + (V*L - w*L*L/2)/EA
}
function xOf(H, V,    a, b)
{
    if (H <= 0) return L - V/w
    a = V/H
    if (V < w*L) return L - V/w + (H/w)*asinh(a) + H*L/EA
    b = (V - w*L)/H
    return (H/w)*(asinh(a) - asinh(b)) + H*L/EA
}
function vFor(H, z,    lo, hi, m, i)
{
    lo = 0; hi = w*L + 1e4
    for (i = 0; i < 200; i++) { m = 0.5*(lo + hi); if (zOf(H, m) < z) lo = m; else hi = m }
    return 0.5*(lo + hi)
}
# sets cH, cV for span x, height z
function catenary(x, z,    lo, hi, m, i)
{
    if (xOf(0, vFor(0, z)) >= x) { cH = 0; cV = vFor(0, z); return }
    lo = 0; hi = 1e4
    for (i = 0; i < 200; i++) { m = 0.5*(lo + hi); if (xOf(m, vFor(m, z)) < x) lo = m; else hi = m }
    cH = 0.5*(lo + hi); cV = vFor(cH, z)
}
'

for spec in $lines
do
    mooringLineRows "$moored" "$spec"
    cols=$(columnsOf "$dat" 'A.F[1]' H V fairleadTension 'shape.x[1]' 'shape.y[1]' 'shape.z[1]') || exit 1

    awk -v cols="$cols" -v pa="$fairlead" -v anchor="$anchor" -v x0="$x0" \
        -v L=$lineLength -v w=$lineWeight -v EA=$lineEA \
        "$rotateAwk$catenaryAwk"'
    function bad(msg) { print msg > "/dev/stderr"; failed = 1; exit 1 }
    function abs(x) { return x < 0 ? -x : x }
    BEGIN {
        deg = atan2(1, 1)/45; split(cols, k, " "); split(pa, p, " "); split(anchor, q, " ")
        # the fairlead at the start: the cube released unrotated with its
        # centre of mass at (x0 0 0.43) (constant/dynamicMeshDict)
        P[0, 1] = x0 + p[1]; P[0, 2] = p[2]; P[0, 3] = 0.43 + p[3]
    }
    FNR == 1 { f++ }
    /^#/ { next }
    f == 1 {
        # the fairlead at the end of each step, from the motion file
        nB++
        rotate($6, $7, $8, p, r)
        P[nB, 1] = $2 + r[1]; P[nB, 2] = $3 + r[2]; P[nB, 3] = $4 + r[3]
        next
    }
    {
        n++
        Px = $(k[5]); Py = $(k[6]); Pz = $(k[7])
        # evaluated at the state the step starts from: the previous row
        e = sqrt((Px - P[n - 1, 1])^2 + (Py - P[n - 1, 2])^2 + (Pz - P[n - 1, 3])^2)
        if (e > 1e-7) bad(sprintf("t = %s: evaluated with the fairlead at (%.9g %.9g %.9g), the motion file has (%.9g %.9g %.9g) at the start of the step", $1, Px, Py, Pz, P[n - 1, 1], P[n - 1, 2], P[n - 1, 3]))
        if (e > maxE) maxE = e
        x = sqrt((Px - q[1])^2 + (Py - q[2])^2); z = Pz - q[3]
        catenary(x, z)
        T = sqrt(cH*cH + cV*cV)
        tol = 1e-6 + 1e-6*T
        if (abs($(k[2]) - cH) > tol || abs($(k[3]) - cV) > tol || abs($(k[4]) - T) > tol)
            bad(sprintf("t = %s: span %.6g m, height %.6g m: H %.8g, V %.8g, tension %.8g N; the catenary %.8g, %.8g, %.8g N", $1, x, z, $(k[2]), $(k[3]), $(k[4]), cH, cV, T))
        d = abs($(k[4]) - T); if (d > maxD) maxD = d
        if (n == 1 || T < minT) minT = T
        if (T > maxT) maxT = T
        if (n == 1 || x < minX) minX = x
        if (x > maxX) maxX = x
    }
    END {
        if (failed) exit 1
        if (n != nB) bad(n " line rows, " nB " body rows")
        printf("evaluated at the logged fairlead (within %.2g m); spans %.4g-%.4g m, fairlead tensions %.4g-%.4g N, the catenary within %.2g N\n", maxE, minX, maxX, minT, maxT, maxD)
    }' "$bodyDat" "$dat" > "$workDir/check.out" || fail "$dat: see above"
    pass "$lineName: $(cat "$workDir/check.out")"
done


# --- The lines pull the cube back ----------------------------------------------
dat1=$(connectorFile "$moored" line1) || exit 1
dat2=$(connectorFile "$moored" line2) || exit 1
c1=$(columnOf "$dat1" 'A.F[1]')
c2=$(columnOf "$dat2" 'A.F[1]')
paste <(awk '!/^#/' "$bodyDat") <(awk -v c="$c1" '!/^#/ { print $c }' "$dat1") \
    <(awk -v c="$c2" '!/^#/ { print $c }' "$dat2") \
  | awk -v minMoved=$minMoved '
function bad(msg) { print msg > "/dev/stderr"; failed = 1; exit 1 }
{
    n++
    # the force of row n acts from the state the step starts from: the
    # previous row (the first row is within 1e-6 m of the release)
    if (n == 1) { x0 = $2; x = $2 }
    xStart = x
    F = $18 + $19
    if (xStart > 0.01 && !(F < 0)) bad(sprintf("t = %s: cube at x = %.4g m, net horizontal force of the lines %.4g N", $1, xStart, F))
    if (n == 1) F0 = F
    x = $2
}
END {
    if (failed) exit 1
    moved = x0 - x
    if (!(moved > minMoved)) bad(sprintf("the cube moved from x = %.4g m to %.4g m: less than %s m towards the equilibrium x = 0", x0, x, minMoved))
    printf("net horizontal force %.4g N at the start, towards x = 0 while x > 0.01 m; the cube moved from x = %.4g m to %.4g m (more than %s m)\n", F0, x0, x, minMoved)
}' > "$workDir/check.out" || fail "$bodyDat: see above"
pass "lines pull back: $(cat "$workDir/check.out")"


# --- Summary and plots -----------------------------------------------------------
requireFile "$moored/plots/summary.dat" "summary"
grep -q '^finished yes' "$moored/plots/summary.dat" \
    || fail "$moored/plots/summary.dat: the summary does not say the run finished"
pass "summary: $(grep '^maxExcursion' "$moored/plots/summary.dat")"
checkPlots "$moored" rotation displacement connector_line1 connector_line2 \
    lineTensions

#------------------------------------------------------------------------------
