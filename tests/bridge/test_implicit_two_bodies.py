"""The implicitNewmark rigid-body solver on two free bodies joined by the
spring FMU, no gravity, no damping.

- Stiff, at a CFD-like time step (k dt^2/mu = 100, mu the reduced mass),
  centres joined along x, the bodies on Pxyz + Rs joints (Rs: a
  unit-quaternion joint) and spinning, body1 about x, body2 about z; the
  spring exerts no moment. The run must stay stable, keep the total linear
  momentum at zero, conserve the energy (translation, rotation and the
  spring's potentialEnergy output; the trapezoidal rule conserves it
  exactly for a linear spring) and turn each body as OpenFOAM's symplectic solver does, with 1 and 3 solves per step; OpenFOAM's Newmark with 3 solves
  diverges on the same model.
- Soft, centres joined along x: the error of the separation against the
  analytic solution falls at second order in dt.
"""
import math
import sys

from foamfmi.bridgecase import check, check_order, rigid_body_model, spring_fmu, vec
from foamfmi.implicitcase import ImplicitCase, run_bodies, solver_entry

M1, M2, L0, STRETCH, INERTIA = 2.0, 3.0, 1.0, 0.1, 0.1
MU = M1 * M2 / (M1 + M2)
DT = 0.01


def body(name, mass, origin):
    return (
        f"    {name}\n    {{\n        type rigidBody;\n        parent root;\n"
        f"        mass {mass};\n        centreOfMass (0 0 0);\n"
        f"        inertia ({INERTIA} 0 0 {INERTIA} 0 {INERTIA});\n"
        f"        transform (1 0 0 0 1 0 0 0 1) {vec(origin)};\n"
        f"        joint {{ type composite; joints ({{ type Pxyz; }} {{ type Rs; }}); }}\n"
        f"    }}\n"
    )


SPIN1, SPIN2 = 0.2, 0.3  # rad/s, body1 about x, body2 about z


def model(solver, k, pA, pB, spin=False):
    x2 = L0 + STRETCH + pA[0] - pB[0]
    # DoF: body1 Pxyz, Rs (body-frame angular velocity), body2 Pxyz, Rs
    qdot = f"qDot (0 0 0 {SPIN1} 0 0 0 0 0 0 0 {SPIN2});" if spin else ""
    bodies = body("body1", M1, (0, 0, 0)) + body("body2", M2, (x2, pA[1] - pB[1], pA[2] - pB[2]))
    spring = spring_fmu("spring", "body1", pB, pA, k, 0, L0, body_b="body2")
    return rigid_body_model(bodies, spring, solver, extra=f"    {qdot}\n")


def run(solver, k, pA, pB, dt, end_time, n_iter=1, spin=False):
    """Bodies and connector outputs, or (None, log) if the run stopped."""
    case = ImplicitCase("implicitTwoBodies", model(solver, k, pA, pB, spin), end_time, dt)
    try:
        log = case.run(n_iter=n_iter)
    except AssertionError as error:
        case.cleanup()
        return None, str(error)
    b, c = case.bodies(), case.connector("spring")
    case.cleanup()
    return b, c


def energy(b, c, i):
    """Kinetic energy at row i of bodies.dat plus the spring's potential
    energy at the same time (connector row i - 1: it has no initial row)."""
    e = 0.0
    for name, m in (("body1", M1), ("body2", M2)):
        v = [b[f"{name}.v.{x}"][i] for x in "xyz"]
        w = [b[f"{name}.omega.{x}"][i] for x in "xyz"]
        e += 0.5 * m * sum(x * x for x in v) + 0.5 * INERTIA * sum(x * x for x in w)
    return e + c["potentialEnergy"][i - 1]


def main():
    failures = 0

    # Stiff spring between the centres, spinning bodies
    k = 100 * MU / DT**2
    omega = math.sqrt(k / MU)
    pA = pB = (0.0, 0.0, 0.0)
    e0 = 0.5 * k * STRETCH**2 + 0.5 * INERTIA * (SPIN1**2 + SPIN2**2)
    for n_iter in (1, 3):
        b, c = run(solver_entry("implicitNewmark"), k, pA, pB, DT, 200 * DT, n_iter, True)
        if b is None:
            failures += check(f"stiff, nIter {n_iter}: runs", False, c[-2000:])
            continue
        # Momentum: equal and opposite loads and a residual of 1e-10 of the
        # accelerations per solve: 1e-8 of m |v|max over 200 steps is
        # round-off and Newton tolerance, far below any real imbalance.
        vmax = max(abs(v) for n in ("body1", "body2") for x in "xyz" for v in b[f"{n}.v.{x}"])
        p = max(
            abs(M1 * b[f"body1.v.{x}"][i] + M2 * b[f"body2.v.{x}"][i])
            for x in "xyz" for i in range(len(b["Time"]))
        )
        failures += check(f"stiff, nIter {n_iter}: momentum", p <= 1e-8 * M2 * vmax,
                          f"max |p| = {p:.1e} kg m/s, m |v|max = {M2 * vmax:.2e}")
        # Energy: conserved exactly by the trapezoidal rule for a linear
        # spring, and the free spins are untouched; what is left is the
        # Newton tolerance (1e-10 of the accelerations per solve) and
        # round-off: 1e-8 of E0 over 200 steps.
        de = max(abs(energy(b, c, i) - e0) for i in range(1, len(b["Time"]))) / e0
        failures += check(f"stiff, nIter {n_iter}: energy conserved", de < 1e-8,
                          f"max |E - E0|/E0 = {de:.2e} over "
                          f"{200 * DT * omega / 2 / math.pi:.0f} periods")
        # Orientation: with no moment the spin is integrated as OpenFOAM's
        # own solvers integrate it (q - q0 = dt omega, rotated in by
        # correctQuaternionJoints); symplectic on the same model must give
        # the same orientations to round-off (1e-9 over 200 steps).
        ref, _ = run(solver_entry("symplectic"), 0.0, pA, pB, DT, 200 * DT, 1, True)
        worst = max(
            abs(x - y)
            for name in ("body1", "body2")
            for comp in ("xx", "xy", "xz", "yx", "yy", "yz", "zx", "zy", "zz")
            for x, y in zip(b[f"{name}.R.{comp}"], ref[f"{name}.R.{comp}"])
        )
        turned = math.acos(max(-1.0, min(1.0, b["body1.R.yy"][-1])))
        failures += check(f"stiff, nIter {n_iter}: quaternion joints as in OpenFOAM",
                          worst < 1e-9, f"max |R - R_symplectic| = {worst:.1e}, body1 turned"
                          f" {turned:.3f} rad")

    # OpenFOAM's Newmark, 3 solves per step, on the same model
    b, c = run(solver_entry("Newmark"), k, pA, pB, DT, 200 * DT, 3, True)
    if b is None:
        failures += check("built-in Newmark x3 diverges", True, "the run stopped")
    else:
        de = max(abs(energy(b, c, i) - e0) for i in range(1, len(b["Time"]))) / e0
        failures += check("built-in Newmark x3 diverges", de > 10, f"max |E - E0|/E0 = {de:.2e}")

    # Soft spring between the centres: separation against the analytic
    # solution s(t) = STRETCH cos(omega t), at 25, 50, 100 steps per period
    k = 50.0
    omega = math.sqrt(k / MU)
    period = 2 * math.pi / omega
    errors = []
    for n in (25, 50, 100):
        b, c = run(solver_entry("implicitNewmark"), k, (0, 0, 0), (0, 0, 0),
                   period / n, 5 * period)
        if b is None:
            failures += check(f"soft, {n} steps per period", False, c[-2000:])
            break
        errors.append(max(
            abs(x2 - x1 - L0 - STRETCH * math.cos(omega * t))
            for t, x1, x2 in zip(b["Time"], b["body1.c.x"], b["body2.c.x"])
        ))
    if len(errors) == 3:
        # The trapezoidal rule's phase error, (omega dt)^2/12 per period,
        # dominates: order 2 to within the O(dt^4) terms at 25 steps.
        failures += check_order("soft: second order", errors, 1.9, 2.1, unit=" m")

    print(f"{'all' if not failures else failures} {'passed' if not failures else 'failed'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
