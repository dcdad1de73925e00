"""A block launched along a guide of the world decelerates under the
coulombFriction FMU and stops where Coulomb friction stops it.

The block of a wave-flume rig's guide: m = 5 kg, launched at v0 = 0.2 m/s,
F_c = 0.4 N, v_s = 1 mm/s. Coulomb friction stops it after
t_s = m v0/F_c = 2.5 s at d = m v0^2/(2 F_c) = 0.25 m; the regularised law
slides (m/(2 F_c)) [v0 sqrt(v0^2 + v_s^2) + v_s^2 asinh(v0/v_s)], 1.6e-4
further (connectors/coulombFriction/README.md).

Two bodies share the model: 'guided' slides on a prismatic x joint (Px)
with the friction along the FMU's guide B.axis = x; 'free' is a floating
body (6 DoF) launched along (0.6, 0.8, 0) with friction in every direction
(B.axis = 0), its contact point at its centre of mass, so that it slides
the same distance along its launch direction and never turns. Run for each
rigid-body solver, 1 and 3 solves per time step (PIMPLE outer correctors:
the FMU rolled back within a step), no flow. Measured (h = 1 ms): the
distance 0.2500406 m (symplectic, 3 solves: the regularised law's own) to
0.2501406 m (a step's lag), v = v_s at 2.4940 s (the law's exact 2.4933 s).
"""
import math
import sys

from foamfmi.bridgecase import Case, fmu_path, rigid_body, summary

M, V0, FC, VS = 5.0, 0.2, 0.4, 1e-3
DIRECTION = (0.6, 0.8, 0.0)
DT, END = 0.001, 3.5


def friction(name, body, axis):
    return f"""
        {name}
        {{
            type fmuConnector;
            body {body};
            fmu "{fmu_path('coulombFriction')}";
            parameters
            {{
                frictionForce {FC};
                regularisationVelocity {VS};
                B.axis ({axis});
                A.p (0 0 0);
                B.p (0 0 0);
            }}
        }}
"""


def model(solver):
    bodies = rigid_body("guided", M, 0.1, (0, 0, 0), "Px") + rigid_body(
        "free", M, 0.1, (0, 1, 0), "floating")
    # qDot: Px (1), then floating = Pxyz (3) and Rs (3)
    qdot = f"{V0} {V0 * DIRECTION[0]} {V0 * DIRECTION[1]} 0 0 0 0"
    return f"""
    solver {{ type {solver}; }}
    g (0 0 0);
    qDot ({qdot});
    bodies
    {{
{bodies}
    }}
    restraints
    {{
{friction("guideFriction", "guided", "1 0 0")}
{friction("freeFriction", "free", "0 0 0")}
    }}
"""


def main():
    d = M * V0 ** 2 / (2 * FC)
    exact = M / (2 * FC) * (V0 * math.hypot(V0, VS) + VS ** 2 * math.asinh(V0 / VS))
    tau = M * VS / FC  # time constant of the creep near rest
    failures = checks = 0

    def check(ok, text):
        nonlocal failures, checks
        checks += 1
        failures += not ok
        print(f"{'PASS' if ok else 'FAIL'} {text}")

    for solver in ("symplectic", "Newmark", "CrankNicolson"):
        for n_iter in (1, 3):
            case = Case(f"frictionWorld.{solver}.{n_iter}", model(solver), END, DT)
            case.run(n_iter=n_iter)
            b = case.bodies()
            t = b["Time"]
            guided = b["guided.c.x"][-1]
            free = math.hypot(b["free.c.x"][-1], b["free.c.y"][-1] - 1.0)
            # The solvers take the friction of the step's start or end
            # state (or average them): at most a step's lag of the
            # velocity, h v0/2 = 1e-4 m, 4e-4 of d, beside the law's own
            # 1.6e-4: 1e-3 of d.
            for name, x in (("guided", guided), ("free", free)):
                check(abs(x - exact) <= 1e-3 * d,
                      f"{solver} nIter {n_iter} {name}: distance {x:.7f} m, "
                      f"regularised {exact:.7f} m, Coulomb {d:.4f} m")
            # Free: straight along its launch direction, no rotation
            # (force at the centre of mass, opposite the velocity).
            sideways = abs(b["free.c.x"][-1] * DIRECTION[1]
                           - (b["free.c.y"][-1] - 1.0) * DIRECTION[0])
            turn = max(abs(w) for q in ("omega.x", "omega.y", "omega.z")
                       for w in b["free." + q])
            check(sideways <= 1e-9 * d and turn <= 1e-12,
                  f"{solver} nIter {n_iter} free: {sideways:.1e} m off its line, "
                  f"largest angular velocity {turn:.1e} rad/s")
            # Stopping time: the velocity reaches v_s within the creep
            # time tau (and a step) of Coulomb's t_s = 2.5 s.
            v = b["guided.v.x"]
            stop = next(t[i] for i in range(len(v)) if v[i] <= VS)
            check(abs(stop - M * V0 / FC) <= tau + DT,
                  f"{solver} nIter {n_iter}: v <= v_s at {stop:.4f} s, "
                  f"Coulomb stops at {M * V0 / FC:.4f} s (tau {tau:.4f} s)")
            # The connector's output: friction along the guide, -F_c while
            # sliding fast (v >= 0.1 m/s: F_c/sqrt(1 + (v_s/v)^2) within
            # 5e-5 of F_c)
            out = case.connector("guideFriction")
            sliding = [f for f, u in zip(out["friction"], out["slidingVelocity"])
                       if u >= 0.1]
            check(len(sliding) > 0 and all(abs(f + FC) <= 5e-5 * FC for f in sliding),
                  f"{solver} nIter {n_iter}: friction output -F_c while sliding "
                  f"({len(sliding)} rows)")
            case.cleanup()
    return summary(checks, failures)


if __name__ == "__main__":
    sys.exit(main())
