"""Helpers of the implicitNewmark tests: cases that load the solver's
library, runs that may diverge, and the single-body spring model.
"""
import math
import os

from foamfmi.bridgecase import (Case, linear_spring, rigid_body_model, solver_entry,  # noqa: F401
                                spring_fmu, vec)

LIBS = 'libs ("libfoamFmiBridge.so" "libimplicitRigidBodySolvers.so");'


class ImplicitCase(Case):
    """A rigidBodySim case that also loads libimplicitRigidBodySolvers."""

    def set_time(self, start_time, end_time, delta_t, write_interval):
        super().set_time(start_time, end_time, delta_t, write_interval)
        path = os.path.join(self.dir, "system", "controlDict")
        with open(path) as f:
            text = f.read()
        with open(path, "w") as f:
            f.write(text.replace('libs ("libfoamFmiBridge.so");', LIBS))


def run_bodies(name, model, end_time, delta_t, n_iter=1):
    """Run a case; return (bodies table, log), or (None, log) when
    rigidBodySim stops with an error (a floating-point exception of a run
    that diverged, or the solver's own FatalError)."""
    case = ImplicitCase(name, model, end_time, delta_t)
    try:
        log = case.run(n_iter=n_iter)
    except AssertionError as error:
        case.cleanup()
        return None, str(error)
    b = case.bodies()
    case.cleanup()
    return b, log


def slider(name, mass, origin=(0, 0, 0), joint="Pz"):
    """A body on a one-DoF joint, frame origin at its centre of mass."""
    return (
        f"    {name}\n    {{\n        type rigidBody;\n        parent root;\n"
        f"        mass {mass};\n        centreOfMass (0 0 0);\n"
        f"        inertia (0.1 0 0 0.1 0 0.1);\n"
        f"        transform (1 0 0 0 1 0 0 0 1) {vec(origin)};\n"
        f"        joint {{ type {joint}; }}\n    }}\n"
    )


# The single-body spring: a body of mass MASS on a prismatic z joint, hung
# from ANCHOR by a spring whose rest length puts the equilibrium at
# z = -X0, so the body starts at rest X0 above it: z(t) = -X0 + X0 cos(wt).
MASS, X0 = 1.0, 0.1
ANCHOR = (0.0, 0.0, -2.0)
REST_LENGTH = 2.0 - X0


def spring_model(solver, k, with_fmu=True):
    """Bodies 'builtin' (linearSpring) and 'fmu' (the linearSpring FMU),
    identical and independent, in one model."""
    bodies = slider("builtin", MASS) + (slider("fmu", MASS) if with_fmu else "")
    spring = (ANCHOR, (0, 0, 0), k, 0, REST_LENGTH)
    restraints = linear_spring("builtinSpring", "builtin", *spring)
    if with_fmu:
        restraints += spring_fmu("fmuSpring", "fmu", *spring)
    return rigid_body_model(bodies, restraints, solver)


def spring_errors(b, body, omega, dt):
    """Largest amplitude and phase errors of a body of the single-body
    spring, relative to X0, against the trapezoidal rule's exact discrete
    solution: amplitude X0 (omega^2 x^2 + v^2 is conserved exactly), phase
    advance 2 atan(omega dt / 2) per step (a period error of
    (omega dt)^2 / 12 to leading order)."""
    theta = 2 * math.atan(0.5 * omega * dt)
    amplitude = phase = 0.0
    for n, (z, v) in enumerate(zip(b[body + ".c.z"], b[body + ".v.z"])):
        x = z + X0
        amplitude = max(amplitude, abs(math.hypot(x, v / omega) - X0) / X0)
        phase = max(phase, abs(x - X0 * math.cos(n * theta)) / X0)
    return amplitude, phase


def growth(b, body):
    """Largest displacement from equilibrium over the initial one."""
    return max(abs(z + X0) for z in b[body + ".c.z"]) / X0
