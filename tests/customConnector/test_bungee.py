"""A connector from outside the project runs in the installed bridge.

The example examples/customConnector (bungee.c, modelDescription.xml,
Makefile) is built on its own in a temporary copy, checked with
fmusim check, and loaded by rigidBodySim through libfoamFmiBridge.so as
./Allwmake installed it. A 2 kg body hangs from the world on the bungee,
attached at its centre of mass straight below the anchor, so it moves
along z only and the law gives, with stretch e = -z - L0:

    m z'' = -m g + T,   T = k1 e + k3 e^3 for e > 0, 0 when slack

- equilibrium: at stretch e* with k1 e* + k3 e*^3 = m g the body stays;
- taut (k3 = 0): z = z_eq - a cos(w t), w = sqrt(k1/m), period 2 pi/w;
- slack then taut (k3 = 0): free fall z0 - g t^2/2 until the line is
  taut, then the harmonic motion above, then free flight back to z0: the
  exact piecewise motion, periodic;
- nonlinear (k3 > 0): kinetic + gravity + the FMU's potentialEnergy is
  conserved.

The sha256 of libfoamFmiBridge.so and rigidBodySim are taken before and
after: the OpenFOAM side must be the same files throughout.
"""
import math
import os
import shutil
import sys

import customfmu
from foamfmi.bridgecase import Case, foam_file, rigid_body, vec

M, G = 2.0, 9.81
ANCHOR = (0.0, 0.0, 0.0)


def model(fmu, k1, k3, rest_length, z0, solver):
    return f"""
    solver {{ type {solver}; }}
    g (0 0 {-G});
    bodies
    {{
{rigid_body("weight", M, 0.1, (0, 0, z0), "floating")}
    }}
    restraints
    {{
        bungee
        {{
            type fmuConnector;
            body weight;
            fmu "{fmu}";
            parameters
            {{
                stiffness {k1};
                cubicStiffness {k3};
                restLength {rest_length};
                A.p {vec((0, 0, 0))};
                B.p {vec(ANCHOR)};
            }}
        }}
    }}
"""


def bounce_exact(t, k1, rest_length, slack):
    """z(t) of the body dropped from rest with the line slack by `slack`
    (k3 = 0): free fall, harmonic motion while taut, free flight up."""
    w = math.sqrt(k1 / M)
    delta = M * G / k1                       # static stretch, m
    z_catch = -rest_length                   # the line becomes taut here
    z_eq = z_catch - delta
    t1 = math.sqrt(2 * slack / G)            # fall to the catch, s
    v1 = -G * t1                             # velocity there, m/s
    phi = math.atan2(v1 / w, delta)          # y = A cos(w tau - phi)
    amplitude = math.hypot(delta, v1 / w)
    tau2 = (2 * math.pi + 2 * phi) / w       # time taut
    period = 2 * t1 + tau2
    s = math.fmod(t, period)
    if s <= t1:
        return z_catch + slack - 0.5 * G * s * s, period
    if s <= t1 + tau2:
        return z_eq + amplitude * math.cos(w * (s - t1) - phi), period
    u = s - t1 - tau2                        # rising from the catch at -v1
    return z_catch - v1 * u - 0.5 * G * u * u, period


def run(fmu, name, k1, k3, rest_length, z0, end_time, delta_t, solver="symplectic", n_iter=1):
    """rigidBodySim from rest at z0, with the initial acceleration in the
    start state: OpenFOAM's rigid-body state starts with zero acceleration
    unless 0/uniform/rigidBodyMotionState gives one, and both solvers use
    the previous acceleration in their first step."""
    case = Case(f"bungee.{name}", model(fmu, k1, k3, rest_length, z0, solver), end_time, delta_t)
    e = -z0 - rest_length
    tension = k1 * e + k3 * e ** 3 if e > 0 else 0.0
    os.makedirs(os.path.join(case.dir, "0", "uniform"))
    with open(os.path.join(case.dir, "0", "uniform", "rigidBodyMotionState"), "w") as f:
        f.write(foam_file("rigidBodyMotionState", (
            "q 6 (0 0 0 0 0 0);\nqDot 6 (0 0 0 0 0 0);\n"
            f"qDdot 6 (0 0 {-G + tension / M!r} 0 0 0);\nt 0;\ndeltaT {delta_t};\n"
        )))
    case.run(n_iter=n_iter)
    return case


def equilibrium(fmu, check):
    k1, k3, rest_length = 50.0, 400.0, 1.0
    e = M * G / k1
    for _ in range(50):                      # Newton on k1 e + k3 e^3 = m g
        e -= (k1 * e + k3 * e ** 3 - M * G) / (k1 + 3 * k3 * e * e)
    z_eq = -(rest_length + e)
    case = run(fmu, "equilibrium", k1, k3, rest_length, z_eq, 1.0, 0.001)
    b, out = case.bodies(), case.connector("bungee")
    drift = max(abs(z - z_eq) for z in b["weight.c.z"])
    tension = max(abs(t - M * G) for t in out["tension"])
    # Forces balance to round-off (~1e-15 of m g): the body moves by
    # round-off over stiffness, ~1e-16 m; 1e-9 m and 1e-9 m g catch any
    # error in the cubic term (k3 e^3 = 14 N here).
    check(drift < 1e-9 and tension < 1e-9 * M * G, "nonlinear equilibrium",
          f"stretch {e:.6f} m, |z - z_eq| <= {drift:.1e} m, |tension - m g| <= {tension:.1e} N")
    case.cleanup()


def taut_oscillation(fmu, check):
    k1, rest_length, a = 50.0, 1.0, 0.2      # a < m g/k1 = 0.39 m: never slack
    w = math.sqrt(k1 / M)
    z_eq = -(rest_length + M * G / k1)
    for solver, n_iter in (("symplectic", 1), ("Newmark", 3)):
        case = run(fmu, f"taut.{solver}", k1, 0.0, rest_length, z_eq - a, 4.0, 0.001, solver, n_iter)
        b = case.bodies()
        t, z, vz = b["Time"], b["weight.c.z"], b["weight.v.z"]
        error = max(abs(zi - (z_eq - a * math.cos(w * ti))) for ti, zi in zip(t, z))
        # The schemes lag the phase by (w h)^2/24 (symplectic, velocity
        # Verlet) and (w h)^2/12 (Newmark converged by 3 solves: the
        # trapezoidal rule) per radian: over w t = 20 rad, 4e-6 m and 8e-6 m
        # for a = 0.2 m. 5e-5 m is 1/4000 of the amplitude: a one-step lag
        # of the loads (w h a = 1e-3 m) or a wrong stiffness fails it.
        check(error < 5e-5, f"taut oscillation, {solver} nIter {n_iter}",
              f"max |z - (z_eq - a cos wt)| = {error:.2e} m (amplitude {a} m)")
        # Period from the upward zero crossings of v.z, linearly interpolated
        ups = [t[i] - vz[i] * (t[i + 1] - t[i]) / (vz[i + 1] - vz[i])
               for i in range(len(t) - 1) if vz[i] < 0 <= vz[i + 1]]
        period = (ups[-1] - ups[0]) / (len(ups) - 1)
        expected = 2 * math.pi * math.sqrt(M / k1)
        # Same phase errors, at most (w h)^2/12 = 2e-6 relative;
        # interpolating the crossings adds less than 1e-6: 1e-5 catches a
        # stiffness wrong by 0.002 %.
        check(abs(period / expected - 1) < 1e-5, f"taut period, {solver} nIter {n_iter}",
              f"{period:.6f} s, 2 pi sqrt(m/k) = {expected:.6f} s, {len(ups) - 1} periods")
        case.cleanup()


def slack_and_taut(fmu, check):
    k1, rest_length, slack = 50.0, 1.0, 0.2
    z0 = -rest_length + slack
    errors = {}
    for delta_t in (0.002, 0.001):
        case = run(fmu, f"bounce.{delta_t}", k1, 0.0, rest_length, z0, 2.8, delta_t)
        b, out = case.bodies(), case.connector("bungee")
        t, z = b["Time"], b["weight.c.z"]
        exact = [bounce_exact(ti, k1, rest_length, slack)[0] for ti in t]
        errors[delta_t] = max(abs(zi - ze) for zi, ze in zip(z, exact))
        if delta_t == 0.001:
            t1 = math.sqrt(2 * slack / G)
            fall = [(ti, zi, T) for ti, zi, T in zip(out["Time"], z[1:], out["tension"]) if ti < t1 - delta_t]
            fall_error = max(abs(zi - (z0 - 0.5 * G * ti * ti)) for ti, zi, _ in fall)
            # Newmark integrates a constant acceleration exactly: the free
            # fall matches z0 - g t^2/2 to round-off (1e-12 m); the FMU
            # must report exactly no tension while slack.
            slack_tension = max(abs(T) for _, _, T in fall)
            check(fall_error < 1e-12 and slack_tension == 0, "slack phase is free fall",
                  f"{len(fall)} steps, max |z - (z0 - g t^2/2)| = {fall_error:.1e} m, "
                  f"max |tension| {slack_tension:g} N")
            period = bounce_exact(0, k1, rest_length, slack)[1]
            lowest = min(z)
            delta = M * G / k1
            w = math.sqrt(k1 / M)
            expected_lowest = -rest_length - delta - math.hypot(delta, G * t1 / w)
            # The lowest sample misses the exact minimum by at most
            # w^2 A (h/2)^2 / 2 = 1.7e-6 m; with the phase error, 2e-5 m.
            check(abs(lowest - expected_lowest) < 2e-5, "lowest point",
                  f"{lowest:.6f} m, analytic {expected_lowest:.6f} m (bounce period {period:.4f} s)")
        case.cleanup()
    fine, coarse = errors[0.001], errors[0.002]
    # The force is continuous but its slope jumps where the line becomes
    # taut or slack, so the time integration stays second order (error
    # ratio ~4 for half the step); a fault in the law or a step lag would
    # give an error that does not shrink with the step.
    check(fine < 1e-4 and coarse / fine > 3, "bounce against the exact piecewise motion",
          f"max |z - z_exact| over two bounces: {coarse:.2e} m (h = 2 ms), {fine:.2e} m (h = 1 ms), "
          f"ratio {coarse / fine:.2f}")


def energy(fmu, check):
    k1, k3, rest_length, slack = 50.0, 400.0, 1.0, 0.2
    z0 = -rest_length + slack
    case = run(fmu, "energy", k1, k3, rest_length, z0, 3.0, 0.001)
    b, out = case.bodies(), case.connector("bungee")
    energies = []
    for i, ti in enumerate(out["Time"]):
        j = i + 1                            # bodies.dat also has t = 0
        assert abs(b["Time"][j] - ti) < 1e-9, "bodies.dat and bungee.dat rows do not match"
        v2 = b["weight.v.x"][j] ** 2 + b["weight.v.y"][j] ** 2 + b["weight.v.z"][j] ** 2
        energies.append(0.5 * M * v2 + M * G * b["weight.c.z"][j] + out["potentialEnergy"][i])
    stored = max(out["potentialEnergy"])
    spread = max(energies) - min(energies)
    # The symplectic scheme's energy error is O(h^2) and bounded, also
    # with the cubic term and the kinks where the line goes taut or slack:
    # ~1.3e-5 of the largest stored energy at h = 1 ms. A potentialEnergy
    # output inconsistent with the force (k3 e^4/3 for k3 e^4/4) spreads
    # by ~10 % of it, a wrong cubic force likewise.
    check(spread < 1e-4 * stored, "nonlinear energy balance",
          f"kinetic + gravity + potentialEnergy varies by {spread:.2e} J; largest stored {stored:.3f} J")
    case.cleanup()


def main():
    check = customfmu.Checks()
    before = customfmu.openfoam_side()

    folder = customfmu.copy_example("good")
    fmu, make_output = customfmu.build(folder)
    check("warning" not in make_output, "builds on its own, -Wall -Wextra -pedantic clean",
          f"make in a copy of the three files; {fmu}")
    problems = customfmu.schema_errors(os.path.join(folder, "modelDescription.xml"))
    check(not problems, "modelDescription.xml against the FMI 2.0 XSD", problems or "valid")

    code, report = customfmu.fmusim_check(fmu)
    failed = [line for line in report.splitlines() if line.startswith("FAIL")]
    passed = {line.split()[1] for line in report.splitlines() if line.startswith("PASS")}
    needed = {"required-variables", "units", "state-get-set", "repeatable-step", "state-serialize",
              "non-finite-inputs", "equal-and-opposite-forces", "zero-total-moment"}
    check(code == 0 and not failed and needed <= passed, "fmusim check",
          f"exit {code}, {report.strip().splitlines()[-1]}; {failed or 'no FAIL'}; "
          f"missing PASS: {sorted(needed - passed) or 'none'}")

    equilibrium(fmu, check)
    taut_oscillation(fmu, check)
    slack_and_taut(fmu, check)
    energy(fmu, check)

    rebuilt = customfmu.compare_openfoam_side(before)
    check(not rebuilt, "OpenFOAM side untouched",
          rebuilt or "; ".join(f"{os.path.basename(p)} sha256 {d}" for p, d in before.items()))

    if os.environ.get("KEEP_CASES") != "1":
        shutil.rmtree(folder, ignore_errors=True)
    print(f"{check.passed} passed, {check.failed} failed")
    return 1 if check.failed else 0


if __name__ == "__main__":
    sys.exit(main())
