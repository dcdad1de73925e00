"""The fmuConnector restraint of sixDoFRigidBodyMotion: a body on the
linearSpring FMU tied to the fixed world, run by sixDoFSim (no fluid).

1. Against OpenFOAM's own sixDoF linearSpring restraint: two identical
   bodies in one case (sixDoF bodies do not interact), one on the built-in
   spring, one on the FMU with the same anchor, attachment point (off the
   centre of mass, so that the moment and the body frame of A.p are
   exercised), stiffness, damping and rest length; every solver, 1 and 3
   solves per time step (the FMU is rolled back between them).
2. Against the analytic oscillation: the body hangs on the FMU from its
   centre of mass, no gravity, no damping: z(t) = z_eq + (z0 - z_eq) cos(w t)
   with w = sqrt(k/m).
3. Restart: the run to 1 s, restarted from its write at 0.5 s, continues
   bit for bit (body and connector output), and a restart without the
   connector's state file stops with a message saying so.
4. A stiffness changed in the case's constant/sixDoFBodies before the
   restart: the restart reads the restraint from the copy the earlier run
   wrote (0.5/uniform/sixDoFBodies, as the point-patch condition reads
   <time>/pointDisplacement), so the change is reported with both values
   and the run goes on with the copy's; an unchanged case reports nothing.
   (Before, it was ignored without a word.)

1 and 3 also with sixDoFSim -copyDicts, which builds each motion from a
copy of its dictionary as a sixDoFRigidBodyMotion solver does: the
restraint then loads its FMU at the first evaluation, with the start time's
state file and output directory.
"""
import math
import os
import shutil
import subprocess
import sys

from foamfmi.sixdofcase import SixDoFCase, fmu_path, sixdof_body, vec

CENTRE = (0.0, 0.0, 0.6)
ANCHOR = (0.3, 0.2, 1.2)
ATTACHMENT = (0.1, 0.0, 0.05)  # from the centre of rotation, body frame
K, C, L0, M, J = 50.0, 0.5, 0.5, 2.0, 0.1


def fmu_spring(body, attachment=ATTACHMENT, anchor=ANCHOR, damping=C, extra=""):
    return f"""            spring_{body}
            {{
                sixDoFRigidBodyMotionRestraint fmuConnector;
                fmu "{fmu_path('linearSpring')}";
                body {body};{extra}
                parameters
                {{
                    stiffness {K}; damping {damping}; restLength {L0};
                    A.p {vec(attachment)}; B.p {vec(anchor)};
                }}
            }}
"""


def builtin_spring():
    point = [c + a for c, a in zip(CENTRE, ATTACHMENT)]
    return f"""            spring_builtin
            {{
                sixDoFRigidBodyMotionRestraint linearSpring;
                anchor {vec(ANCHOR)};
                refAttachmentPt {vec(point)};
                stiffness {K}; damping {C}; restLength {L0};
            }}
"""


def compare_builtin():
    failures = 0
    for solver, n_iter, copy in [(s, n, False) for s in ("symplectic", "Newmark", "CrankNicolson")
                                 for n in (1, 3)] + [("Newmark", 3, True)]:
        if True:
            case = SixDoFCase(
                f"sixdofWorld.{solver}.{n_iter}",
                {
                    "builtin": sixdof_body(M, J, CENTRE, solver, builtin_spring()),
                    "fmu": sixdof_body(M, J, CENTRE, solver, fmu_spring("fmu")),
                },
                2.0, 0.001, g=(0, 0, -9.81),
            )
            case.run(n_iter=n_iter, args=["-copyDicts"] if copy else [])
            b = case.bodies()
            amplitude = max(abs(z - CENTRE[2]) for z in b["builtin.c.z"])
            worst = 0.0
            for q in ("c.x", "c.y", "c.z", "v.x", "v.z", "omega.x", "omega.y", "R.xz"):
                worst = max(worst, max(abs(x - y) for x, y in zip(b["builtin." + q], b["fmu." + q])))
            # The FMU evaluates linearSpring's law in another order of
            # operations (moment as M = (R p) x F, not via the attachment
            # point); round-off of ~1e-16 per evaluation grows at most
            # linearly over 2000 steps of a stable oscillator: 1e-10 of the
            # amplitude is far above that and far below a one-step lag
            # (~1e-3) or a wrong frame for A.p (~1e-2)
            ok = worst <= 1e-10 * amplitude and amplitude > 0.01
            failures += not ok
            print(f"{'PASS' if ok else 'FAIL'} builtin linearSpring, {solver}, nIter {n_iter}"
                  f"{', -copyDicts' if copy else ''}: "
                  f"max difference {worst:.3e} (amplitude {amplitude:.3f})")
            rows = case.connector("spring_fmu")["Time"]
            if len(rows) != len(b["Time"]) - 1:
                failures += 1
                print(f"FAIL {solver} nIter {n_iter}: {len(rows)} output rows for "
                      f"{len(b['Time']) - 1} time steps")
            case.cleanup()
    return failures


def compare_analytic():
    failures = 0
    anchor = (0.0, 0.0, 1.2)
    z_eq = anchor[2] - L0
    w = math.sqrt(K / M)
    a0 = K * (anchor[2] - CENTRE[2] - L0) / M
    for dt in (0.001, 0.0005):
        # The sixDoF solvers start from the acceleration of the state
        # (zero by default); the consistent one makes symplectic second order
        body = sixdof_body(M, J, CENTRE, "symplectic", fmu_spring("fmu", (0, 0, 0), anchor, 0.0))
        body += f"        acceleration (0 0 {a0!r});\n"
        case = SixDoFCase(f"sixdofAnalytic.{dt}", {"fmu": body}, 2.0, dt)
        case.run(n_iter=2)
        b = case.bodies()
        worst = max(
            abs(z - (z_eq + (CENTRE[2] - z_eq) * math.cos(w * t)))
            for t, z in zip(b["Time"], b["fmu.c.z"])
        )
        # Stoermer-Verlet's phase error is w^3 dt^2 t / 24 per unit
        # amplitude, 1.0e-5 at dt = 1 ms and t = 2 s on the 0.1 m
        # amplitude: 1.1e-6 m; half of it at dt/2 would be a quarter. The
        # bound is 2x that estimate; a one-step lag of the FMU's input
        # would be ~w dt amplitude = 5e-4 m
        bound = 2 * w**3 * dt**2 * 2.0 / 24 * abs(CENTRE[2] - z_eq)
        ok = worst <= bound
        failures += not ok
        print(f"{'PASS' if ok else 'FAIL'} analytic oscillation, dt {dt}: max |z - z_exact| "
              f"{worst:.3e} m (bound {bound:.3e} m)")
        case.cleanup()
    return failures


def compare_restart(args=()):
    failures = 0
    bodies = {"fmu": sixdof_body(M, J, CENTRE, "Newmark", fmu_spring("fmu"))}
    full = SixDoFCase("sixdofRestart.full", bodies, 1.0, 0.005, write_interval=0.5, g=(0, 0, -9.81))
    full.run(n_iter=2, args=args)

    for keep_state in (True, False):
        case = SixDoFCase("sixdofRestart.half", bodies, 1.0, 0.005, write_interval=0.5, g=(0, 0, -9.81))
        shutil.copytree(os.path.join(full.dir, "0.5"), os.path.join(case.dir, "0.5"))
        if not keep_state:
            os.remove(os.path.join(case.dir, "0.5", "uniform", "fmuConnectors", "spring_fmu"))
        case.set_time(0.5, 1.0, 0.005, 0.5)
        result = subprocess.run(["sixDoFSim", "-case", case.dir, "-nIter", "2", *args],
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if keep_state:
            a, b = full.bodies(), case.bodies("0.5") if result.returncode == 0 else {"Time": []}
            # The step ending at 0.5 s (the sum of the steps, not exactly 0.5)
            i0 = min(range(len(a["Time"])), key=lambda i: abs(a["Time"][i] - 0.5))
            # Bit for bit: the bodies' state is written with 17 digits and
            # the FMU's state exactly, and both continue the same time line
            same = result.returncode == 0 and all(
                a[q][i0:] == b[q] for q in a if q != "Time"
            ) and len(b["Time"]) == len(a["Time"]) - i0
            fa, fb = full.connector("spring_fmu"), (case.connector("spring_fmu", "0.5") if same else {})
            j0 = min(range(len(fa["Time"])), key=lambda i: abs(fa["Time"][i] - 0.5)) + 1 if same else 0
            # Every output bit for bit; the Time column is OpenFOAM's, which
            # restarts from the directory's name (0.5, not the uninterrupted
            # run's 0.5000000000000003, docs/restarts.md): within 1e-12 s
            same = same and all(fa[q][j0:] == fb[q] for q in fa if q != "Time")
            same = same and max(abs(x - y) for x, y in zip(fa["Time"][j0:], fb["Time"])) < 1e-12
            # The connector took its state from the written file
            same = same and "FMU state restored at t = 0.5" in result.stdout
            failures += not same
            print(f"{'PASS' if same else 'FAIL'} restart from 0.5 s continues bit for bit "
                  f"{' '.join(args)} (exit code {result.returncode})")
        else:
            ok = result.returncode != 0 and "is missing" in result.stdout and "restart fresh" in result.stdout
            # The message names the start time's directory
            ok = ok and "starts from t = 0.5," in result.stdout
            failures += not ok
            print(f"{'PASS' if ok else 'FAIL'} restart without the connector's state is fatal "
                  f"{' '.join(args)} (exit code {result.returncode})")
        case.cleanup()
    full.cleanup()
    return failures


def changed_parameters():
    failures = 0
    bodies = {"fmu": sixdof_body(M, J, CENTRE, "Newmark", fmu_spring("fmu"))}
    full = SixDoFCase("sixdofChanged.full", bodies, 1.0, 0.005, write_interval=0.5, g=(0, 0, -9.81))
    full.run()
    stiffer = {"fmu": sixdof_body(M, J, CENTRE, "Newmark", fmu_spring("fmu").replace(
        f"stiffness {K};", "stiffness 80;"))}
    for name, case_bodies in (("changed", stiffer), ("unchanged", bodies)):
        case = SixDoFCase("sixdofChanged." + name, case_bodies, 1.0, 0.005, write_interval=0.5,
                          g=(0, 0, -9.81))
        shutil.copytree(os.path.join(full.dir, "0.5"), os.path.join(case.dir, "0.5"))
        case.set_time(0.5, 1.0, 0.005, 0.5)
        log = case.run()
        reported = "restraint spring_fmu: the run restarts from" in log
        if name == "changed":
            ok = reported and "parameters.stiffness: 80 in the case's dictionary, 50 in the restored copy" in log
        else:
            ok = not reported
        failures += not ok
        print(f"{'PASS' if ok else 'FAIL'} restart, stiffness {name} in constant/sixDoFBodies: "
              f"{'reported' if reported else 'not reported'}" + ("" if ok else "\n" + log[-2500:]))
        case.cleanup()
    full.cleanup()
    return failures


def main():
    failures = compare_builtin() + compare_analytic() + compare_restart() + changed_parameters()
    failures += compare_restart(["-copyDicts"])
    print("all passed" if not failures else f"{failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
