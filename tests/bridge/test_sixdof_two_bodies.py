"""Two sixDoF bodies tied by one linearSpring FMU, run by sixDoFSim.

Each body has its own sixDoFRigidBodyMotion, as each cube of
tutorials/uncoupledFloatingObjectsSixDoF has its own point-patch
condition; the connector is one restraint of the same name in both, and
both share one FMU instance. The bodies are solved one after the other:
the first evaluation of a solve round uses body 1's current kinematics and
body 2's from its latest solve, and body 2 applies the opposite loads of
that same evaluation.

1. Every solve of every outer corrector applies equal and opposite forces
   (from the restraints' report lines), and there are two per round.
2. The total momentum is conserved to round-off (equal and opposite loads,
   equal time steps).
3. The relative motion follows the analytic two-mass oscillator
   x(t) = L0 + (x0 - L0) cos(w t), w = sqrt(k (m1 + m2) / (m1 m2)); body 2's
   lag of one solve makes the error first order in dt with one solve per
   step, and the outer correctors reduce it.
4. Misconfigurations stop the run with a message: an unknown entry, a
   restraint in the motion of a body it does not name, a connector missing
   from one body's motion, two restraints of one name that differ (also
   two connectors to the world of one name in two bodies), a
   two-body connector in motions built from copies of their dictionaries
   (sixDoFRigidBodyMotion solvers).
"""
import math
import re
import sys

from foamfmi.sixdofcase import SixDoFCase, fmu_path, sixdof_body, vec

K, L0, M1, M2, X0 = 50.0, 0.5, 2.0, 3.0, 0.6
W = math.sqrt(K * (M1 + M2) / (M1 * M2))


def spring(extra=""):
    return f"""            spring
            {{
                sixDoFRigidBodyMotionRestraint fmuConnector;
                fmu "{fmu_path('linearSpring')}";
                body cube1;
                bodyB cube2;
                report on;{extra}
                parameters {{ stiffness {K}; damping 0; restLength {L0}; A.p (0 0 0); B.p (0 0 0); }}
            }}
"""


def bodies(solver="symplectic", spring1=None, spring2=None):
    """cube1 at the origin, cube2 at (X0 0 0), at rest, the spring stretched;
    the start accelerations are the spring's (the sixDoF solvers start from
    the state's acceleration)."""
    f = K * (X0 - L0)
    b1 = sixdof_body(M1, 0.1, (0, 0, 0), solver, spring() if spring1 is None else spring1)
    b2 = sixdof_body(M2, 0.1, (X0, 0, 0), solver, spring() if spring2 is None else spring2)
    b1 += f"        acceleration {vec((f / M1, 0, 0))};\n"
    b2 += f"        acceleration {vec((-f / M2, 0, 0))};\n"
    return {"cube1": b1, "cube2": b2}


def report_forces(log):
    """[(body, force vector)] of every restraint report line, in order."""
    out = []
    for m in re.finditer(r"Restraint spring: t = \S+ .*?force on (\w+) \(([^)]*)\)", log):
        out.append((m.group(1), [float(x) for x in m.group(2).split()]))
    return out


def run_case(solver, n_iter, dt, end=2.0):
    case = SixDoFCase(f"sixdofTwo.{solver}.{n_iter}", bodies(solver), end, dt)
    log = case.run(n_iter=n_iter)
    return case, log


def check_solves(failures):
    for solver in ("symplectic", "Newmark", "CrankNicolson"):
        for n_iter in (1, 3):
            case, log = run_case(solver, n_iter, 0.001)
            b = case.bodies()
            steps = len(b["Time"]) - 1
            forces = report_forces(log)
            pairs = [forces[i:i + 2] for i in range(0, len(forces), 2)]
            # One report per body and solve: 2 per round, n_iter rounds per step
            ok_count = len(forces) == 2 * n_iter * steps
            # Equal and opposite, exactly: both are the same evaluation's
            # (linearSpring's B.F is -A.F); a second evaluation with body 2's
            # new kinematics would differ by far more than round-off
            worst = max(
                max(abs(fa + fb) for fa, fb in zip(p[0][1], p[1][1])) for p in pairs
            )
            ok_pairs = all(p[0][0] == "cube1" and p[1][0] == "cube2" for p in pairs)
            ok = ok_count and ok_pairs and worst == 0.0
            failures += not ok
            print(f"{'PASS' if ok else 'FAIL'} {solver} nIter {n_iter}: {len(forces)} loads for "
                  f"{steps} steps, largest |F1 + F2| {worst:.3e} N")
            # Momentum: the loads cancel, so m1 v1 + m2 v2 stays 0; its
            # round-off is ~1e-16 of the momenta (~0.4 kg m/s) per step:
            # 1e-12 over 2000 steps
            p = max(abs(M1 * v1 + M2 * v2) for v1, v2 in zip(b["cube1.v.x"], b["cube2.v.x"]))
            scale = max(abs(M1 * v1) for v1 in b["cube1.v.x"])
            ok = p <= 1e-12 * scale and scale > 0.1
            failures += not ok
            print(f"{'PASS' if ok else 'FAIL'} {solver} nIter {n_iter}: total momentum at most "
                  f"{p:.3e} kg m/s (momenta {scale:.3f})")
            case.cleanup()
    return failures


def check_analytic(failures):
    errors = {}
    for n_iter in (1, 3):
        for dt in (0.001, 0.0005):
            case, _ = run_case("symplectic", n_iter, dt)
            b = case.bodies()
            errors[n_iter, dt] = max(
                abs((x2 - x1) - (L0 + (X0 - L0) * math.cos(W * t)))
                for t, x1, x2 in zip(b["Time"], b["cube1.c.x"], b["cube2.c.x"])
            )
            case.cleanup()
    amplitude = X0 - L0
    for (n_iter, dt), e in sorted(errors.items()):
        print(f"     nIter {n_iter} dt {dt}: max |x - x_exact| {e:.3e} m")
    # One solve per step: body 2's position in the spring force lags one
    # step, which feeds the oscillation energy at a relative rate of order
    # w^2 dt: the error is of order w^2 dt t amplitude (8.3e-3 m at 1 ms and
    # 2 s), bounded here by half that. First order: halving dt halves it
    # (ratio 1.6 to 2.4)
    e1, e2 = errors[1, 0.001], errors[1, 0.0005]
    bound = 0.5 * W**2 * 0.001 * 2.0 * amplitude
    ok = e1 <= bound and 1.6 <= e1 / e2 <= 2.4
    failures += not ok
    print(f"{'PASS' if ok else 'FAIL'} analytic, 1 solve per step: error {e1:.3e} m "
          f"(bound {bound:.3e}), first order (ratio {e1 / e2:.2f})")
    # Three outer correctors iterate the lag away to the coupled scheme's
    # own second-order error: at least 10x smaller than with one
    e3 = errors[3, 0.001]
    ok = e3 <= e1 / 10
    failures += not ok
    print(f"{'PASS' if ok else 'FAIL'} analytic, 3 solves per step: error {e3:.3e} m, "
          f"{e1 / e3:.0f}x smaller than with 1")
    return failures


def check_errors(failures):
    cases = {
        "unknown entry": (bodies(spring1=spring("\n                stifness 3;"),
                                 spring2=spring("\n                stifness 3;")),
                          ["unknown entry 'stifness'", "sixDoFRigidBodyMotionRestraint", "bodyB"]),
        "restraint in another body's motion": (
            {**bodies(), "cube3": sixdof_body(1, 0.1, (0, 1, 0), restraints=spring())},
            ["connects cube1 and cube2 but is in the motion of cube3"]),
        "restraint missing in body 2's motion": (bodies(spring2=""),
                                                 ["did not evaluate it", "cube2"]),
        "restraints differ": (bodies(spring2=spring().replace("stiffness 50.0", "stiffness 40.0")),
                              ["must be the same connector"]),
    }
    # Two connectors to the world of one name, one per body: they would
    # share the state file and the output, and are refused
    world = lambda b: spring().replace("bodyB cube2;", "").replace("body cube1;", f"body {b};")
    cases["two world connectors of one name"] = (
        bodies(spring1=world("cube1"), spring2=world("cube2")),
        ["must be the same connector", "give separate connectors separate names"])
    # A motion built from a copy of its dictionary (a sixDoFRigidBodyMotion
    # solver) cannot share a connector between two bodies
    cases["two bodies in motions built from copies"] = (
        bodies(), ["needs each body moved by its own sixDoFRigidBodyDisplacement"], ["-copyDicts"])
    for name, (model, needles, *args) in cases.items():
        case = SixDoFCase("sixdofTwo.error", model, 0.01, 0.001)
        log = case.run(expect_failure=True, args=args[0] if args else [])
        ok = all(n in log for n in needles)
        failures += not ok
        print(f"{'PASS' if ok else 'FAIL'} {name} is fatal with a message naming it")
        if not ok:
            print(log[-1500:])
        case.cleanup()
    return failures


def main():
    failures = check_solves(0)
    failures = check_analytic(failures)
    failures = check_errors(failures)
    print("all passed" if not failures else f"{failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
