"""A body on the spring FMU tied to the world moves exactly as the same body
on OpenFOAM's built-in linearSpring restraint.

Two identical bodies share one model (bodies do not interact in
rigidBodyDynamics): 'builtin' hangs from a linearSpring, 'fmu' from the
linearSpring FMU with the same anchor, attachment point, stiffness, damping
and rest length. The attachment point is off the centre of mass and the
joint is 'floating' (6 DoF), so the FMU's moments and the bridge's
conversion to moments about the global origin are exercised. Run for each
rigid-body solver and for 1 and 3 solves per time step (PIMPLE outer
correctors): the FMU is rolled back within a time step, so its trajectory
must match the built-in one in every combination.
"""
import sys

from foamfmi.bridgecase import Case, linear_spring, rigid_body, rigid_body_model, spring_fmu, summary

ANCHOR = (0.3, 0.2, 1.2)
ATTACHMENT = (0.1, 0.0, 0.05)  # body frame, from the centre of mass
K, C, L0 = 50.0, 0.5, 0.5


def model(solver):
    bodies = rigid_body("builtin", 2, 0.1, (0, 0, 0), "floating") + rigid_body(
        "fmu", 2, 0.1, (0, 0, 0), "floating"
    )
    spring = (ANCHOR, ATTACHMENT, K, C, L0)
    return rigid_body_model(
        bodies,
        linear_spring("builtinSpring", "builtin", *spring) + spring_fmu("fmuSpring", "fmu", *spring),
        solver, g=(0, 0, -9.81))


def main():
    failures = checks = 0
    for solver in ("symplectic", "Newmark", "CrankNicolson"):
        for n_iter in (1, 3):
            case = Case(f"springWorld.{solver}.{n_iter}", model(solver), 2.0, 0.001)
            case.run(n_iter=n_iter)
            b = case.bodies()
            amplitude = max(abs(z) for z in b["builtin.c.z"])
            worst = 0.0
            for q in ("c.x", "c.y", "c.z", "v.x", "v.z", "omega.y", "R.xz"):
                worst = max(
                    worst,
                    max(abs(x - y) for x, y in zip(b["builtin." + q], b["fmu." + q])),
                )
            # The FMU evaluates the same formula as linearSpring in another
            # order of operations; round-off of ~1e-16 per evaluation grows
            # at most linearly over 2000 steps of a stable oscillator, so
            # 1e-10 of the motion's amplitude is far above round-off and far
            # below any real difference (a one-step lag would be ~1e-3).
            ok = worst <= 1e-10 * amplitude
            checks += 2
            failures += not ok
            print(f"{'PASS' if ok else 'FAIL'} {solver} nIter {n_iter}: "
                  f"max difference {worst:.3e} (amplitude {amplitude:.3f})")
            # The connector's outputs are written once per time step
            out = case.connector("fmuSpring")
            if len(out["Time"]) != len(b["Time"]) - 1:
                failures += 1
                print(f"FAIL {solver} nIter {n_iter}: {len(out['Time'])} output rows "
                      f"for {len(b['Time']) - 1} time steps")
            case.cleanup()
    return summary(checks, failures)


if __name__ == "__main__":
    sys.exit(main())
