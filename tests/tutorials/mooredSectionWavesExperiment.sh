#!/bin/bash
#------------------------------------------------------------------------------
# Test of tutorials/mooredSectionWaves/experimentRao, the measured RAOs of
# the 2D ship section in the flume (Sundsdal et al., scenario B; the data's
# extract in experiment/data, written by experiment/extractData):
#  - run again on the extract (-no-plot, into a scratch file), it reproduces
#    the committed experiment/measured.dat: the same header, rows and
#    columns, every value within 1e-9 relative (the same arithmetic on the
#    same data), and the committed measured series (experiment/series)
#    byte for byte;
#  - extractData on a clone-like tree (plain CSV files with more columns, as
#    the data repository has them, made from the extract of two cases)
#    writes an extract whose files decompress to those columns verbatim, and
#    experimentRao reads the plain CSV files and the new extract alike;
#  - the measured table is physically sound (each check states its reason
#    and tolerance below).
# Needs python3 and Debian's python3-numpy (/usr/bin/python3), git and xz
# (xz-utils); no OpenFOAM. Exits non-zero on the first failure.
#------------------------------------------------------------------------------
. "$(dirname "$0")/tutorialTestFunctions"

tutorial="$FOAMFMI_DIR/tutorials/mooredSectionWaves"
data="$tutorial/experiment/data"
committed="$tutorial/experiment/measured.dat"

requireFile "$data/SOURCE" "the data's origin (experiment/data/SOURCE)"
requireFile "$committed" "the committed measured table"

makeWorkDir
"$tutorial/experimentRao" -no-plot -data "$data" -output "$workDir/measured.dat" \
    > "$workDir/log.experimentRao" 2>&1 \
    || { cat "$workDir/log.experimentRao" 1>&2; fail "experimentRao failed"; }
pass "experimentRao ran on $data"

# The measured series of every scenario B run (experiment/series, the
# overlays' data): the same files, byte for byte (the same arithmetic)
nSeries=0
for f in "$tutorial"/experiment/series/*.dat
do
    cmp -s "$f" "$workDir/series/$(basename "$f")" \
        || fail "experimentRao: series/$(basename "$f") differs from the committed $f"
    nSeries=$((nSeries + 1))
done
[ "$nSeries" -eq "$(ls "$workDir"/series/*.dat | wc -l)" ] && [ "$nSeries" -eq 13 ] \
    || fail "experimentRao: $nSeries committed series, $(ls "$workDir"/series/*.dat | wc -l) written (13 runs expected)"
pass "experimentRao: the 13 runs' measured series as committed"

# A clone-like tree of two cases (PP 6 H 1 and PP 14 H 2): the extract's
# columns decompressed, with a column of the data repository's files that
# the extract leaves out (WP_1) and, in 1PPH, the leading index column
clone="$workDir/clone"
mkdir -p "$clone/data/3PPH" "$clone/data/1PPH" "$clone/docs"
cp "$data/LICENSE" "$clone/LICENSE"
cp "$data/README-3PPH.md" "$clone/data/3PPH/README.md"
cp "$data/README-1PPH.md" "$clone/data/1PPH/README.md"
cp "$data/experimental_setup.md" "$clone/docs/experimental_setup.md"
for f in "$data"/3PPH/306*.csv.xz "$data"/3PPH/3142*.csv.xz
do
    xz -dc "$f" | awk -F, -v OFS=, '{ print $0, (NR == 1 ? "WP_1 [m]" : NR * 1e-6) }' \
        > "$clone/data/3PPH/$(basename "$f" .xz)"
done
for f in "$data"/1PPH/106*.csv.xz "$data"/1PPH/1142*.csv.xz
do
    xz -dc "$f" | awk -F, -v OFS=, '{ print (NR == 1 ? "" : NR - 2), $1, "0.5", $2, $3 }' \
        | sed '1s/,0.5,/,WP_1 [m],/' > "$clone/data/1PPH/$(basename "$f" .xz)"
done
git -C "$clone" init -q && git -C "$clone" add -A \
    && git -C "$clone" -c user.name=test -c user.email=test@localhost commit -qm data \
    || fail "cannot make the clone-like git tree $clone"
"$tutorial/experiment/extractData" -output "$workDir/extract" "$clone" \
    > "$workDir/log.extractData" 2>&1 \
    || { cat "$workDir/log.extractData" 1>&2; fail "extractData failed"; }
for f in "$data"/3PPH/306*.csv.xz "$data"/3PPH/3142*.csv.xz \
         "$data"/1PPH/106*.csv.xz "$data"/1PPH/1142*.csv.xz
do
    sub=$(basename "$(dirname "$f")")
    cmp -s <(xz -dc "$f") <(xz -dc "$workDir/extract/$sub/$(basename "$f")") \
        || fail "extractData: $sub/$(basename "$f") differs from the committed extract's columns"
done
[ "$(find "$workDir/extract" -name '*.csv.xz' | wc -l)" -eq 7 ] \
    || fail "extractData: expected the 7 files of the two cases in $workDir/extract"
grep -q "^Commit: $(git -C "$clone" rev-parse HEAD)\$" "$workDir/extract/SOURCE" \
    || fail "extractData: $workDir/extract/SOURCE does not name the clone's commit"
pass "extractData: the two cases' 7 files, their columns verbatim, the commit in SOURCE"

# experimentRao on the plain CSV files and on the new extract: the same rows
# as the committed table's for these two cases
cp "$workDir/extract/SOURCE" "$clone/data/SOURCE"
for input in "$clone/data" "$workDir/extract"
do
    "$tutorial/experimentRao" -no-plot -data "$input" -output "$workDir/two.dat" \
        > "$workDir/log.two" 2>&1 \
        || { cat "$workDir/log.two" 1>&2; fail "experimentRao failed on $input"; }
    cmp -s <(grep -v '^#' "$workDir/two.dat") \
           <(grep -v '^#' "$committed" | awk '($1 == 6 && $2 == 1) || ($1 == 14 && $2 == 2)') \
        || fail "experimentRao on $input: the rows of PP 6 H 1 and PP 14 H 2 differ from $committed"
done
pass "experimentRao on plain CSV files and on a new extract: the committed rows"

python3 - "$committed" "$workDir/measured.dat" > "$workDir/check.log" 2>&1 <<'PYTHON'
import math
import sys


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def ok(message):
    print("ok: " + message)


def read(path):
    """Header comments, column names (the last comment line) and rows."""
    comments, rows = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                comments.append(line.rstrip("\n"))
            elif line.strip():
                rows.append([float(v) for v in line.split()])
    if not comments or not rows:
        fail("%s: expected a commented header and rows" % path)
    names = comments[-1][1:].split()
    for i, r in enumerate(rows):
        if len(r) != len(names):
            fail("%s: row %d has %d values for %d columns" % (path, i + 1, len(r), len(names)))
    return comments, names, [dict(zip(names, r)) for r in rows]


committed, scratch = sys.argv[1], sys.argv[2]
c_head, c_names, c_rows = read(committed)
s_head, s_names, s_rows = read(scratch)

# --- Reproduction of the committed table -----------------------------------
if c_head != s_head:
    diff = [(a, b) for a, b in zip(c_head, s_head) if a != b]
    fail("the header differs from %s (%d against %d lines; first difference: %r against %r)"
         % (committed, len(c_head), len(s_head), *(diff[0] if diff else ("", ""))))
if len(c_rows) != len(s_rows):
    fail("%d rows, the committed table has %d" % (len(s_rows), len(c_rows)))
worst = 0.0
for i, (c, s) in enumerate(zip(c_rows, s_rows)):
    for name in c_names:
        d = abs(c[name] - s[name])
        scale = max(abs(c[name]), abs(s[name]))
        # 1e-9 relative: the same arithmetic on the same data, written with
        # 10 significant digits
        if d > 1e-9 * scale:
            fail("row %d (PP %d H %d) %s: %.10g, committed %.10g"
                 % (i + 1, c["PP"], c["H"], name, s[name], c[name]))
        if scale > 0:
            worst = max(worst, d / scale)
ok("reproduces %s: %d rows x %d columns, largest relative difference %.1e"
   % (committed, len(c_rows), len(c_names), worst))

rows = c_rows
by_T = sorted(rows, key=lambda r: r["T"])
RHO, G, H_WATER, LENGTH = 1000.0, 9.81, 1.0, 0.586     # kg/m3, m/s2, m, m
T_HEAVE, T_ROLL, T_SWAY = 1.17, 1.26, 7.50             # decay tests [s]

# --- The calibrated waves have the prescribed height ------------------------
# The flap's transfer function was calibrated iteratively to the prescribed
# H (docs); 5 % allows for the gauges' accuracy and the decay of the wave
# along the flume (WP_4 is 1.5 m before the section's position).
for r in rows:
    if abs(r["a"] / r["aNominal"] - 1) > 0.05:
        fail("PP %d H %d: calibrated amplitude %.5f m, prescribed H/2 = %.3f m (more than 5 %%)"
             % (r["PP"], r["H"], r["a"], r["aNominal"]))
ok("calibrated amplitudes within 5 %% of H/2: a/(H/2) = %s"
   % ", ".join("%.3f" % (r["a"] / r["aNominal"]) for r in by_T))

# --- Heave at the longest period ---------------------------------------------
# The longest period, 1.516 s, is only 1.3 times the heave natural period
# 1.17 s: the section follows the long wave (RAO 1 as T -> infinity) and the
# resonance amplifies it. A one-degree-of-freedom heave with the long-wave
# excitation: 1/(1 - (T_heave/T)^2) = 2.47 without damping is the upper
# bound, and the RAO stays above 1 for any damping ratio below 0.59 (far
# above a floating section's).
longest = by_T[-1]
upper = 1 / (1 - (T_HEAVE / longest["T"]) ** 2)
if not 1.0 <= longest["raoHeave"] <= upper:
    fail("heave RAO %.3f at the longest period T = %.3f s, expected between 1 and %.2f"
         % (longest["raoHeave"], longest["T"], upper))
ok("heave RAO %.3f at the longest period T = %.3f s: between 1 (the long wave) and %.2f "
   "(undamped amplification)" % (longest["raoHeave"], longest["T"], upper))

# --- Heave in the shortest waves ---------------------------------------------
# At T = 0.634 s (lambda = 0.63 m) the wave's pressure at the keel (draft
# 0.2 m) is e^(-k d) of that at the surface, the beam (0.64 lambda) averages
# it further, and well above the natural frequency the response is below
# the static one: the heave RAO is below e^(-k d).
shortest = by_T[0]
bound = math.exp(-shortest["k"] * 0.2)
if not shortest["raoHeave"] < bound:
    fail("heave RAO %.3f at T = %.3f s, expected below e^(-k d) = %.3f"
         % (shortest["raoHeave"], shortest["T"], bound))
ok("heave RAO %.3f at the shortest period T = %.3f s, below e^(-k d) = %.3f"
   % (shortest["raoHeave"], shortest["T"], bound))

# --- Resonances ----------------------------------------------------------------
# The largest heave and roll RAOs are at the tested periods near the decay
# tests' natural periods; 0.1 s allows for the coupling of sway, heave and
# roll, which moves the peaks of the coupled response, and for the spacing
# of the tested periods (0.03-0.05 s there).
for key, tn, what in (("raoHeave", T_HEAVE, "heave"), ("raoRoll", T_ROLL, "roll")):
    peak = max(rows, key=lambda r: r[key])
    if abs(peak["T"] - tn) > 0.1:
        fail("largest %s RAO %.3f at T = %.3f s, more than 0.1 s from the natural period %.2f s"
             % (what, peak[key], peak["T"], tn))
    ok("largest %s RAO %.3f at T = %.3f s, within 0.1 s of the natural period %.2f s"
       % (what, peak[key], peak["T"], tn))

# --- The springs ---------------------------------------------------------------
# Each spring (30 N/m; the two together 59.2-60.9 N/m in the static tests)
# joins the flume to the sway carriage, so its tension changes by 30 N/m
# times the sway, the starboard spring's against the port side's. The
# ring gauges' accuracy is not given: 0.2 % of their calibrated range
# (0-68 N), 0.14 N, the accuracy quoted for the lab's calibrated force
# transducer; the camera's sway is known to a pixel, 0.9 mm, 0.027 N of
# spring force. Tensions against 30 N/m x sway: 0.14 + 0.027 N; the two
# gauges against each other: 0.14 N x sqrt(2).
GAUGE, PIXEL, K_SPRING = 0.2e-2 * 68.0, 0.9e-3, 30.0
tol_sway, tol_pair = GAUGE + K_SPRING * PIXEL, GAUGE * math.sqrt(2)
worst_sway = worst_pair = 0.0
for r in rows:
    spring = K_SPRING * r["swayAmp"]
    for side in ("tensionSBAmp", "tensionPSAmp"):
        d = abs(r[side] - spring)
        worst_sway = max(worst_sway, d)
        if d > tol_sway:
            fail("PP %d H %d: %s %.3f N against 30 N/m x sway %.3f N (tolerance %.3f N)"
                 % (r["PP"], r["H"], side, r[side], spring, tol_sway))
    d = abs(r["tensionSBAmp"] - r["tensionPSAmp"])
    worst_pair = max(worst_pair, d)
    if d > tol_pair:
        fail("PP %d H %d: spring tension amplitudes %.3f and %.3f N (tolerance %.3f N)"
             % (r["PP"], r["H"], r["tensionSBAmp"], r["tensionPSAmp"], tol_pair))
ok("spring tension amplitudes: against 30 N/m x sway within %.3f N (tolerance %.3f N), "
   "against each other within %.3f N (tolerance %.3f N)"
   % (worst_sway, tol_sway, worst_pair, tol_pair))

# --- Wave drift ------------------------------------------------------------------
# Where the window spans at least the sway natural period (7.5 s), so that
# the slow sway oscillation started by the waves' front averages out: the
# mean sway offset is downwave (the mean drift force on a body in regular
# waves pushes along them), it stretches the starboard spring and relaxes
# the port side's, and the drift force (the lowest measured stiffness,
# 59.2 N/m, times the offset) is at most that of total reflection,
# rho g a^2 L / 2 (1 + 2 k h / sinh 2 k h).
checked = []
for r in rows:
    if r["windowPeriods"] * r["T"] < T_SWAY:
        continue
    kh = r["k"] * H_WATER
    total = 0.5 * RHO * G * r["a"] ** 2 * LENGTH * (1 + 2 * kh / math.sinh(2 * kh))
    force = 59.2 * r["swayMean"]
    if not (r["swayMean"] > 0 and r["tensionSBMean"] > 0 > r["tensionPSMean"]):
        fail("PP %d H %d: mean sway %.2f mm, mean tensions %.3f (starboard) and %.3f N "
             "(port side), expected a downwave offset stretching the starboard spring"
             % (r["PP"], r["H"], 1e3 * r["swayMean"], r["tensionSBMean"], r["tensionPSMean"]))
    if force > total:
        fail("PP %d H %d: drift force %.3f N above total reflection's %.3f N"
             % (r["PP"], r["H"], force, total))
    checked.append("T = %.3f s H%d %.2f mm (%.2f of total reflection)"
                   % (r["T"], r["H"], 1e3 * r["swayMean"], force / total))
if not checked:
    fail("no case with a window of at least %.1f s" % T_SWAY)
ok("wave drift downwave and below total reflection's: " + "; ".join(checked))
PYTHON
status=$?
sed -n 's/^ok: /ok   ['"$testName"']: /p' "$workDir/check.log"
[ "$status" -eq 0 ] || { grep -v '^ok: ' "$workDir/check.log" 1>&2; fail "the checks above"; }
