"""Checks of the water velocity fmuConnectorFlow gives the points of lines
that leave the CFD mesh (its entries incidentWave and blendWidth).

Usage: checkIncidentWave.py CASE LINE... --flow NAME --solver APP
           --blend B --depth D --bounds X0 X1 Y0 Y1

CASE is a run whose constant/waveProperties generates second-order Stokes
waves (waveModel StokesII) at the patch inlet, in still water D m deep
over a flat bed at z = 0, in a mesh that spans X0..X1 and Y0..Y1
horizontally, and whose function object NAME (fmuConnectorFlow) names
that patch in incidentWave and B (m) in blendWidth. For each LINE:

  - at every time step, every shape point beyond the mesh's horizontal
    bounds (x and y here: the mesh is a box) has the velocity of the
    textbook second-order Stokes wave (Dean and Dalrymple, the expressions
    of OpenFOAM's StokesII: the first-order term with cosh k(z)/sinh kh
    and the second with 3/4 (H^2/4) omega k cosh 2kz/sinh^4 kh), at that
    point and time, ramped linearly over rampTime, of wave number k from
    the linear dispersion relation (foamfmi.waves, Newton's method, not
    OpenFOAM's fixed-point iteration), phase k x - omega t + 3 pi/2
    (OpenFOAM's default wavePhase), the height held between the bed and
    the still-water level. Tolerance 1e-9 of H omega/2 (the file holds 13
    significant digits; the wave number of the two solves agrees to
    rounding): a point taken at the wrong place, time or frame, or a wave
    of another theory, is off by a fraction of the wave's velocity;
  - at the last written time, every point inside the bounds by more than
    B has U interpolated by OpenFOAM's own probes (checkLineOutputs'
    check), and every point inside by d < BLEND has w U_wave + (1 - w)
    U_probe, w = (1 + cos(pi d/BLEND))/2 (tolerance 1e-8 of the largest
    speed: U read back from the 12-digit time directory), w = (1 + cos(pi
    d/B))/2;
  - over all the lines, at least one point beyond the bounds moves with
    the wave (speed above H omega/20) and one point lies in the hand-over.

With --acceleration (the function object's `acceleration true;`, the
rows holding Ax/Ay/Az[k] after the velocities):
  - beyond the bounds, at every step, the wave's acceleration: the time
    derivative of the same ramped wave, differentiated here analytically
    (the bridge takes a central difference over 1e-4 T: within 1e-7 of
    it); tolerance 1e-6 of H omega^2/2; rows within 1e-3 s of the ramp's
    end, where the ramped wave has no derivative, left out;
  - inside, at the points in mid-water (0.25 < z < 0.4 m: above the two
    coarse bed cells, whose interpolation to the no-slip bed damps the
    sampled velocity but not the pressure, below the box's bottom at
    0.417 m), every step after 0.5 s: the acceleration the pressure and
    gravity give (the bridge's) against the centred difference of the
    sampled velocities of the steps before and after, (U(t+) - U(t-))/
    (t+ - t-): within 3 % of the largest acceleration there (measured
    1.1-1.7 % on v1912, 1.4-2.2 % on v2312: the difference's O(h^2)
    error, the convective term, about k a U / a = 2 %, and the points'
    motion), and within half of what the acceleration of the step before
    would give (measured 0.30-0.37 of it): an acceleration a step late,
    as the change of the sampled velocities over the previous step is,
    fails.
Prints what it found; exits non-zero at the first failure.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import checkLineOutputs as lines  # noqa: E402
from foamfmi import cli, foamdict, waves  # noqa: E402


def fail(msg):
    sys.exit(f"checkIncidentWave: {msg}")


def stokes2_terms(wave, point, t):
    """The unramped second-order Stokes wave's velocity (u, w) and its
    time derivative (du/dt, dw/dt) at point, time t; the ramp c(t) and
    its slope."""
    H, T, ramp, depth, phase = wave
    omega = 2 * math.pi / T
    k = waves.wave_number(omega, depth)
    theta = k * point[0] - omega * t + phase
    z = min(max(point[2], 0.0), depth)
    s = math.sinh(k * depth)
    first = H / 2 * omega / s
    second = 0.75 * H * H / 4 * omega * k / s ** 4
    ch, sh = math.cosh(k * z), math.sinh(k * z)
    ch2, sh2 = math.cosh(2 * k * z), math.sinh(2 * k * z)
    u = first * math.cos(theta) * ch + second * ch2 * math.cos(2 * theta)
    w = first * math.sin(theta) * sh + second * sh2 * math.sin(2 * theta)
    dudt = omega * (first * math.sin(theta) * ch + 2 * second * ch2 * math.sin(2 * theta))
    dwdt = -omega * (first * math.cos(theta) * sh + 2 * second * sh2 * math.cos(2 * theta))
    c = min(max(t / ramp, 0.0), 1.0)
    dc = 1.0 / ramp if t < ramp else 0.0
    return (u, w), (dudt, dwdt), c, dc


def stokes2(wave, point, t):
    """Velocity (u, v, w) of the ramped second-order Stokes wave at point,
    time t."""
    (u, w), _, c, _ = stokes2_terms(wave, point, t)
    return (c * u, 0.0, c * w)


def stokes2_acceleration(wave, point, t):
    """Time derivative of stokes2 at point, time t (not at t = rampTime)."""
    (u, w), (dudt, dwdt), c, dc = stokes2_terms(wave, point, t)
    return (c * dudt + dc * u, 0.0, c * dwdt + dc * w)


def check_acceleration(wave, line, rows_c, col, rows_f, n, low, high):
    """The acceleration columns of a line's flow rows (see the head);
    (point-steps beyond, worst error there, mid-water error / largest,
    the same with the step before's acceleration / largest)."""
    H, T, ramp = wave[0], wave[1], wave[2]
    scale = H / 2 * (2 * math.pi / T) ** 2
    beyond, worst = 0, 0.0
    mid, lagged, largest = 0.0, 0.0, 0.0
    for j, (rc, rf) in enumerate(zip(rows_c, rows_f)):
        t = rc[0]
        for k in range(n):
            p = [rc[col[f"shape.{a}[{k + 1}]"]] for a in "xyz"]
            a = rf[1 + 3 * n + 3 * k:4 + 3 * n + 3 * k]
            if inside_distance(p, low, high) <= 0:
                if abs(t - ramp) < 1e-3:
                    continue
                expected = stokes2_acceleration(wave, p, t)
                e = max(abs(x - y) for x, y in zip(a, expected))
                worst = max(worst, e)
                beyond += 1
                if e > 1e-6 * scale:
                    fail(f"{line} at t = {t}, point {k + 1} at {p}: acceleration {a}, "
                         f"the wave's {expected}")
            elif 0.25 < p[2] < 0.4 and t > 0.5 and 0 < j < len(rows_f) - 1:
                before, after = rows_f[j - 1], rows_f[j + 1]
                du = [(after[1 + 3 * k + i] - before[1 + 3 * k + i]) / (after[0] - before[0])
                      for i in range(3)]
                a_before = before[1 + 3 * n + 3 * k:4 + 3 * n + 3 * k]
                mid = max(mid, max(abs(x - y) for x, y in zip(a, du)))
                lagged = max(lagged, max(abs(x - y) for x, y in zip(a_before, du)))
                largest = max(largest, max(map(abs, a)))
    if largest == 0:
        fail(f"{line}: no point in mid-water (0.25 < z < 0.4 m) after 0.5 s")
    if mid > 0.03 * largest or mid > 0.5 * lagged:
        fail(f"{line}: in mid-water the acceleration is {mid:.3g} m/s2 from the centred "
             f"difference of the velocities (largest acceleration {largest:.3g} m/s2; "
             f"the step before's is {lagged:.3g} from it)")
    return beyond, worst, mid / largest, lagged / largest


def inside_distance(point, low, high):
    """Distance inside the bounds across x and y (negative beyond them)."""
    return min(min(point[i] - low[i], high[i] - point[i]) for i in (0, 1))


def main(argv):
    p = cli.parser("checkIncidentWave.py", __doc__)
    p.add_argument("case", metavar="CASE")
    p.add_argument("lines", nargs="+", metavar="LINE")
    p.add_argument("--flow", required=True, metavar="NAME")
    p.add_argument("--solver", required=True, metavar="APP")
    p.add_argument("--blend", required=True, type=float, metavar="B")
    p.add_argument("--depth", required=True, type=float, metavar="D")
    p.add_argument("--bounds", required=True, type=float, nargs=4, metavar=("X0", "X1", "Y0", "Y1"))
    p.add_argument("--acceleration", action="store_true", help="the rows hold accelerations too")
    args = p.parse_args(argv)
    case, flow, solver, blend, names = args.case, args.flow, args.solver, args.blend, args.lines
    inlet = foamdict.parse(os.path.join(case, "constant", "waveProperties"), case)["inlet"]
    if foamdict.word(inlet["waveModel"]) != "StokesII":
        fail("the inlet's waveModel is not StokesII")
    H, T, ramp = waves.read_wave_properties(case)
    phase = float(foamdict.word(inlet["wavePhase"])) if "wavePhase" in inlet else 1.5 * math.pi
    low, high = (args.bounds[0], args.bounds[2]), (args.bounds[1], args.bounds[3])
    wave = (H, T, ramp, args.depth, phase)
    scale = H * math.pi / T
    times = lines.write_times(case)
    moving, blended, beyond = 0, 0, 0
    worst = 0.0
    for line in names:
        names_c, rows_c = lines.read_table(os.path.join(case, "postProcessing", "fmuConnectors", "0",
                                                        line + ".dat"))
        _, rows_f = lines.read_table(os.path.join(case, "postProcessing", flow, "0", line + ".dat"))
        col = {n: i for i, n in enumerate(names_c)}
        n = sum(1 for name in names_c if name.startswith("shape.x["))
        if len(rows_f) != len(rows_c):
            fail(f"{line}: {len(rows_f)} flow rows, {len(rows_c)} connector rows")
        for rc, rf in zip(rows_c, rows_f):
            if abs(rc[0] - rf[0]) > 1e-9 * max(1.0, rc[0]):
                fail(f"{line}: flow row at t = {rf[0]}, connector row at {rc[0]}")
            for k in range(1, n + 1):
                p = [rc[col[f"shape.{a}[{k}]"]] for a in "xyz"]
                if inside_distance(p, low, high) > 0:
                    continue
                beyond += 1
                expected = stokes2(wave, p, rc[0])
                got = rf[1 + 3 * (k - 1):4 + 3 * (k - 1)]
                e = max(abs(a - b) for a, b in zip(got, expected))
                worst = max(worst, e)
                if e > 1e-9 * scale:
                    fail(f"{line} at t = {rc[0]}, point {k} at {p}: U {got}, the wave's {expected}")
                if math.sqrt(sum(c * c for c in expected)) > scale / 10:
                    moving += 1
        if args.acceleration:
            if len(rows_f[0]) != 1 + 6 * n:
                fail(f"{line}: flow rows of {len(rows_f[0])} values, expected the time, then "
                     f"the velocity and the acceleration at {n} points")
            b, w, m, lag = check_acceleration(wave, line, rows_c, col, rows_f, n, low, high)
            print(f"{line}: acceleration at {b} point-steps beyond the tank = the wave's within "
                  f"{w:.2g} m/s2; in mid-water within {100 * m:.2g} % of the largest from the "
                  f"centred difference of the velocities (the step before's: {100 * lag:.2g} %)")
        rows, points = lines.check_vtk(case, line, times)
        t_name = times[-1][1]
        row = min(rows_f, key=lambda r: abs(r[0] - float(t_name)))
        probed = lines.probe(case, solver, t_name, points)
        speed = max(math.sqrt(sum(c * c for c in u)) for u in probed if max(map(abs, u)) < 1e299)
        for k, (p, u) in enumerate(zip(points, probed), start=1):
            d = inside_distance(p, low, high)
            if d <= 0 or max(map(abs, u)) > 1e299:
                continue  # beyond (checked above), or on the mesh's boundary
            got = row[1 + 3 * (k - 1):4 + 3 * (k - 1)]
            if d < blend:
                w = 0.5 * (1 + math.cos(math.pi * d / blend))
                wu = stokes2(wave, p, float(t_name))
                expected = [w * a + (1 - w) * b for a, b in zip(wu, u)]
                blended += 1
            else:
                expected = u
            e = max(abs(a - b) for a, b in zip(got, expected))
            if e > 1e-8 * speed + 1e-12:
                fail(f"{line} at t = {t_name}, point {k} at {p} ({d:.3g} m inside): U {got}, "
                     f"expected {expected}")
    if not moving:
        fail(f"no point beyond the mesh moves with the wave ({beyond} points beyond it)")
    if not blended:
        fail(f"no point within {blend} m inside the mesh's bounds at t = {times[-1][1]}")
    print(f"{beyond} point-steps beyond the mesh's horizontal bounds: the Stokes II wave "
          f"within {worst:.2g} m/s ({moving} moving faster than H omega/20)")
    print(f"at t = {times[-1][1]}: {blended} points in the {blend} m hand-over = the blend of the "
          f"wave and OpenFOAM's probes of U, the points further inside = the probes")


if __name__ == "__main__":
    main(sys.argv[1:])
