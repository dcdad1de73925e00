#!/bin/bash
#------------------------------------------------------------------------------
# Smoke test of tutorials/hingedPontoonsWaves: five pontoons in a 2D flume
# joined by four hinges (hinge.fmu) and moored at both ends by catenary
# lines (catenary.fmu), every connector an fmuConnector restraint, the
# motion solved by implicitNewmark under the added-mass coupling, in regular
# waves (H = 0.05 m, T = 1.5 s), at the default mesh to 3 s: the ramp, the
# waves' arrival at the chain (1.4 s) and their first period along it (about
# a minute of CPU time). 3 s is a multiple of the write interval, 1.5 s,
# which the adjustable time step hits exactly. Checks:
#  - the solver reaches 3 s; implicitNewmark converged in every solve (no
#    warning in the log, its statistics line is there);
#  - every connector writes one row of finite numbers per time step; each
#    hinge's loads are equal and opposite (A.F = -B.F);
#  - the hinges hold: the hinge points (0.325 0 0) on A and (-0.325 0 0) on
#    B, as moved by the bodies' logged motion, stay within 0.2 mm of each
#    other. The bound is load/stiffness for loads a hinge cannot exceed
#    here: the waves' load on a pontoon, rho g (H/2) l = 123 N per metre, and
#    the lines' pull, 14 N, open a hinge of 1e6 N/m by 0.14 mm; the smoke run
#    stays far below (measured in the README). A hinge 100 times softer, or
#    a hinge applied to the wrong points, fails;
#  - the moments balance about the shared hinge point M (the middle of the
#    hinge points): A.M - (M - r_A) x A.F = -(B.M - (M - r_B) x B.F), and
#    that moment is the hinge's only one, its damper's torque about y
#    (ptoTorque), with nothing about x or z. r_A, r_B and M come from the
#    logged motion, the end state of the step; the connector was evaluated
#    at the state of the last evaluation, which differs from it by a small
#    part of one step's motion: the tolerance is |A.F| times the largest
#    one-step motion of a centre of mass in the run (plus 1e-9 N m);
#  - the chain bends: some hinge turns by more than 0.2 deg (so the checks
#    above are not made on a rigid chain);
#  - the pontoons float at their draught: before the waves reach the chain
#    (t < 1.4 s) every centre of mass stays within 3 mm of the still-water
#    level, where the hydrostatics of constant/dynamicMeshDict put it (50 kg
#    on 0.5 m^2 of waterplane, the end pontoons lighter by their line's
#    pull: a pontoon 5 % too heavy sinks 5 mm), and with the waves within
#    H = 0.05 m of it (pontoons 0.5 m long in waves 2.8 m long follow the
#    surface, +-H/2);
#  - the lines' tensions are those of an elastic catenary with touchdown
#    (1.5 m, 10 N/m, EA = 1e5 N, no friction) between the fairlead the line
#    was evaluated at and its anchor, solved independently of the FMU
#    (foamfmi.catenary): H, V and the fairlead tension within 1e-6 N + 1e-6 of the
#    tension (the FMU's Newton method stops at 1e-10 of the span, the files
#    have 16 digits); that fairlead is the one of the logged motion within a
#    tenth of the largest one-step motion of a fairlead (plus 1e-9 m); a
#    line weight 1 % off fails;
#  - the summary and the plots are written.
# Needs platforms/<WM_OPTIONS>/lib/libfoamFmiBridge.so,
# libimplicitRigidBodySolvers.so, libfoamFmiRigidBodyCoupling.so and
# build/fmus/hinge.fmu, catenary.fmu. Exits non-zero on the first failure.
#------------------------------------------------------------------------------
. "$(dirname "$0")/tutorialTestFunctions"
. "$(dirname "$0")/connectorTestFunctions"

endTime=3
waveArrival=1.4
restBound=0.003
waveHeight=0.05
gapBound=2e-4
minHingeTurn=0.2
hingeA="0.325 0 0"
hingeB="-0.325 0 0"
# The lines of constant/dynamicMeshDict: unstretched length, submerged
# weight, axial stiffness; name:body:fairlead (body frame):anchor (global)
lineLength=1.5
lineWeight=10
lineEA=1e5
lines="line1:pontoon1:-0.1,0,-0.1:0.7643976,0.5,0 line2:pontoon5:0.1,0,-0.1:6.3356024,0.5,0"

for lib in foamFmiBridge implicitRigidBodySolvers foamFmiRigidBodyCoupling
do
    requireFile "$FOAM_USER_LIBBIN/lib$lib.so" "lib$lib.so (build it: ./Allwmake)"
done
for fmu in hinge catenary
do
    requireFile "$FOAMFMI_FMU_DIR/$fmu.fmu" "the $fmu FMU (build it: ./Allwmake)"
done

makeWorkDir
case=$workDir/hingedPontoonsWaves
runTutorial hingedPontoonsWaves "$case" -end-time $endTime
checkRanToEnd "$case" $endTime
motion=$case/postProcessing/rigidBodyMotion

checkImplicitNewmark "$case"


# --- The pontoons float at their draught -------------------------------------
for i in 1 2 3 4 5
do
    dat=$motion/pontoon$i.dat
    requireFile "$dat" "motion of pontoon$i"
    awk -v tWave=$waveArrival -v restBound=$restBound -v H=$waveHeight '
    function bad(msg) { print msg > "/dev/stderr"; failed = 1; exit 1 }
    function abs(x) { return x < 0 ? -x : x }
    /^#/ { next }
    {
        for (i = 1; i <= NF; i++)
            if ($i !~ /^[-+]?[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$/) bad("t = " $1 ": not a finite number: " $i)
        h = abs($4 - 0.5)
        if ($1 < tWave && h > restBound) bad(sprintf("t = %s: before the waves, the centre of mass is %.3g m from the still-water level (at most %g m)", $1, h, restBound))
        if (h > H) bad(sprintf("t = %s: the centre of mass is %.3g m from the still-water level (at most H = %g m)", $1, h, H))
        if ($1 < tWave && h > maxRest) maxRest = h
        if (h > maxH) maxH = h
    }
    END {
        if (failed) exit 1
        printf("within %.3g m of its floating position before the waves, %.3g m with them\n", maxRest, maxH)
    }' "$dat" > "$workDir/check.out" || fail "$dat: see above"
    pass "pontoon$i: $(cat "$workDir/check.out")"
done


# --- The hinges ----------------------------------------------------------------
turned=0
for i in 1 2 3 4
do
    name=hinge$i
    checkConnectorRows "$case" $name balanced
    dat=$(connectorFile "$case" $name) || exit 1
    cols=$(columnsOf "$dat" 'A.F[1]' 'A.F[2]' 'A.F[3]' 'A.M[1]' 'A.M[2]' 'A.M[3]' \
        'B.F[1]' 'B.F[2]' 'B.F[3]' 'B.M[1]' 'B.M[2]' 'B.M[3]' ptoTorque angle) || exit 1
    awk -v cols="$cols" -v pa="$hingeA" -v pb="$hingeB" -v gapBound=$gapBound \
        "$rotateAwk$hingeRowsAwk"'
    function bad(msg) { print msg > "/dev/stderr"; failed = 1; exit 1 }
    function abs(x) { return x < 0 ? -x : x }
    # m = L - (P - r) x F, components 1..3 of arrays
    function about(L, P, r, F, m,    d1, d2, d3)
    {
        d1 = P[1] - r[1]; d2 = P[2] - r[2]; d3 = P[3] - r[3]
        m[1] = L[1] - (d2*F[3] - d3*F[2])
        m[2] = L[2] - (d3*F[1] - d1*F[3])
        m[3] = L[3] - (d1*F[2] - d2*F[1])
    }
    BEGIN { deg = atan2(1, 1)/45; split(cols, k, " "); split(pa, pA, " "); split(pb, pB, " ") }
    {
        hingeRow()
        for (j = 1; j <= 3; j++)
        {
            rA[j] = A[n, j + 1]; rB[j] = B[n, j + 1]
            FA[j] = $(k[j]); MA[j] = $(k[j + 3]); FB[j] = $(k[j + 6]); MB[j] = $(k[j + 9])
        }
        tau = $(k[13]); phi = $(k[14])
        rotate(A[n, 6], A[n, 7], A[n, 8], pA, qA)
        rotate(B[n, 6], B[n, 7], B[n, 8], pB, qB)
        gap = 0
        for (j = 1; j <= 3; j++)
        {
            P[j] = rA[j] + qA[j]; Q[j] = rB[j] + qB[j]; M[j] = 0.5*(P[j] + Q[j])
            gap += (P[j] - Q[j])^2
        }
        gap = sqrt(gap)
        if (gap > gapBound) bad(sprintf("t = %s: the hinge points are %.3g m apart (at most %g m)", $1, gap, gapBound))
        if (gap > maxGap) maxGap = gap
        # Largest one-step motion of either centre of mass so far
        if (n > 1)
        {
            s = sqrt((rA[1] - rA0[1])^2 + (rA[3] - rA0[3])^2); if (s > step) step = s
            s = sqrt((rB[1] - rB0[1])^2 + (rB[3] - rB0[3])^2); if (s > step) step = s
        }
        for (j = 1; j <= 3; j++) { rA0[j] = rA[j]; rB0[j] = rB[j] }
        # Moments about the shared point M, kept for the end (the tolerance
        # needs the whole run step)
        about(MA, M, rA, FA, mA); about(MB, M, rB, FB, mB)
        F[n] = sqrt(FA[1]^2 + FA[2]^2 + FA[3]^2)
        sum[n] = sqrt((mA[1] + mB[1])^2 + (mA[2] + mB[2])^2 + (mA[3] + mB[3])^2)
        torque[n] = abs(mA[2] - tau); across[n] = sqrt(mA[1]^2 + mA[3]^2)
        t[n] = $1
        if (abs(tau) > maxTau) maxTau = abs(tau)
        if (n == 1 || phi < lo) lo = phi
        if (n == 1 || phi > hi) hi = phi
    }
    END {
        if (failed) exit 1
        hingeRowsEnd()
        for (j = 1; j <= n; j++)
        {
            tol = F[j]*step + 1e-9
            e = sum[j]; if (torque[j] > e) e = torque[j]; if (across[j] > e) e = across[j]
            if (e > tol) bad(sprintf("t = %s: about the hinge point: A.M + B.M off by %.3g N m, A.M about y - ptoTorque %.3g N m, A.M across y %.3g N m (tolerance %.3g N m)", t[j], sum[j], torque[j], across[j], tol))
            if (tol > 0 && e/tol > worst) worst = e/tol
        }
        printf("hinge points within %.3g m (at most %g m); about the hinge point A.M = -B.M = the damper torque (up to %.3g N m), within %.2g of the tolerance |F| x %.3g m; angle from %.3g to %.3g deg\n", maxGap, gapBound, maxTau, worst, step, lo/deg, hi/deg)
        print (hi - lo)/deg > "/dev/stderr"
    }' "$motion/pontoon$i.dat" "$motion/pontoon$((i + 1)).dat" "$dat" \
        > "$workDir/check.out" 2> "$workDir/turn.out" \
        || { cat "$workDir/turn.out" 1>&2; fail "$dat: see above"; }
    pass "$name: $(cat "$workDir/check.out")"
    awk -v d="$(tail -n 1 "$workDir/turn.out")" -v m=$minHingeTurn 'BEGIN { exit !(d > m) }' \
        && turned=1
done
[ "$turned" -eq 1 ] || fail "no hinge turned by more than $minHingeTurn deg: the chain did not bend"
pass "the chain bends: a hinge turned by more than $minHingeTurn deg"


# --- The lines: an independent catenary at the fairlead they were evaluated at
for spec in $lines
do
    IFS=: read -r name body fairlead anchor <<< "$spec"
    checkConnectorRows "$case" "$name"
    dat=$(connectorFile "$case" "$name") || exit 1
    python3 - "$motion/$body.dat" "$dat" "$fairlead" "$anchor" \
        $lineLength $lineWeight $lineEA > "$workDir/check.out" <<'PYTHON' \
        || fail "$dat: see above"
import math
import sys

from foamfmi import catenary, postprocessing

body_file, line_file, fairlead, anchor = sys.argv[1:5]
L, w, EA = (float(v) for v in sys.argv[5:8])
p = [float(v) for v in fairlead.split(",")]
q = [float(v) for v in anchor.split(",")]


def rotate(rv_deg, v):
    """v turned by the rotation vector rv (degrees), Rodrigues."""
    r = [math.radians(c) for c in rv_deg]
    th = math.sqrt(sum(c * c for c in r))
    if th < 1e-300:
        return list(v)
    k = [c / th for c in r]
    c, s = math.cos(th), math.sin(th)
    d = sum(k[i] * v[i] for i in range(3))
    x = [k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0]]
    return [v[i] * c + x[i] * s + k[i] * d * (1 - c) for i in range(3)]


body = postprocessing.read_table(body_file)
header, rows = postprocessing.read_named_table(line_file)
col = {n: header.index(n) for n in ("H", "V", "fairleadTension", "shape.x[1]", "shape.y[1]", "shape.z[1]")}
if len(rows) != len(body):
    sys.exit("%d line rows, %d body rows" % (len(rows), len(body)))
logged = []
for b in body:
    r = rotate(b[5:8], p)
    logged.append([b[1 + i] + r[i] for i in range(3)])
step = max(math.dist(logged[i], logged[i - 1]) for i in range(1, len(logged)))
worst_t = worst_p = 0.0
tensions = []
for i, row in enumerate(rows):
    P = [row[col["shape.x[1]"]], row[col["shape.y[1]"]], row[col["shape.z[1]"]]]
    e = math.dist(P, logged[i])
    if e > 0.1 * step + 1e-9:
        sys.exit("t = %s: evaluated with the fairlead at %s, the logged motion has %s"
                 " (tolerance %.3g m)" % (row[0], P, logged[i], 0.1 * step + 1e-9))
    worst_p = max(worst_p, e)
    x = math.hypot(P[0] - q[0], P[1] - q[1])
    z = P[2] - q[2]
    H, V = catenary.tensions(x, z, L, w, EA)
    T = math.hypot(H, V)
    tol = 1e-6 + 1e-6 * T
    got = (row[col["H"]], row[col["V"]], row[col["fairleadTension"]])
    d = max(abs(got[0] - H), abs(got[1] - V), abs(got[2] - T))
    if d > tol:
        sys.exit("t = %s: span %.6g m, height %.6g m: H %.8g, V %.8g, tension %.8g N;"
                 " the catenary %.8g, %.8g, %.8g N" % (row[0], x, z, *got, H, V, T))
    worst_t = max(worst_t, d)
    tensions.append(T)
print("evaluated at the logged fairlead (within %.2g m, tolerance %.2g m); fairlead tensions"
      " %.4g-%.4g N, the catenary within %.2g N" % (worst_p, 0.1 * step + 1e-9,
                                                   min(tensions), max(tensions), worst_t))
PYTHON
    pass "$name: $(cat "$workDir/check.out")"
done


# --- Summary and plots -----------------------------------------------------------
requireFile "$case/plots/pontoonResponse.dat" "summary of pontoonResponse"
grep -q '^hinge1.maxAbsMoment ' "$case/plots/pontoonResponse.dat" \
    || fail "$case/plots/pontoonResponse.dat: no hinge moments"
pass "summary: $(grep -c . "$case/plots/pontoonResponse.dat") entries"
checkPlots "$case" pontoonMotion chainLoads rotation displacement lineTensions \
    connector_hinge1 connector_line1

#------------------------------------------------------------------------------
