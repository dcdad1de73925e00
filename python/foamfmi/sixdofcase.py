"""Build and run sixDoFRigidBodyMotion cases with no fluid through sixDoFSim.

Like bridgecase.Case, but the model is constant/sixDoFBodies: 'bodies', one
sixDoFRigidBodyMotion dictionary per body (named by its keyword, as a patch
names a body of the sixDoFRigidBodyDisplacement condition), and 'g'.
"""
import functools
import os

from foamfmi import bridgecase
from foamfmi.bridgecase import Case, foam_file, fmu_path, vec  # noqa: F401

# An fmuConnector restraint in a body's restraints (bridgecase.fmu_restraint)
fmu_restraint = functools.partial(bridgecase.fmu_restraint, indent=12,
                                  type_key="sixDoFRigidBodyMotionRestraint")


def sixdof_body(mass, inertia, centre, solver="symplectic", restraints=""):
    """A body at rest at centre, orientation identity, diagonal inertia."""
    return (
        f"        mass {mass};\n"
        f"        momentOfInertia ({inertia} {inertia} {inertia});\n"
        f"        centreOfMass {vec(centre)};\n"
        f"        solver {{ type {solver}; }}\n"
        f"        restraints\n        {{\n{restraints}        }}\n"
    )


class SixDoFCase(Case):
    """A temporary sixDoFSim case; bodies is {name: body dictionary text}."""

    def __init__(self, name, bodies, end_time, delta_t, write_interval=None, g=(0, 0, 0)):
        super().__init__(name, "", end_time, delta_t, write_interval)
        os.remove(os.path.join(self.dir, "constant", "dynamicMeshDict"))
        self.write_bodies(bodies, g)

    def write_bodies(self, bodies, g=(0, 0, 0)):
        text = f"g {vec(g)};\nbodies\n{{\n"
        for body, dictionary in bodies.items():
            text += f"    {body}\n    {{\n{dictionary}    }}\n"
        text += "}\n"
        with open(os.path.join(self.dir, "constant", "sixDoFBodies"), "w") as f:
            f.write(foam_file("sixDoFBodies", text))

    def run(self, n_iter=1, expect_failure=False, args=()):
        """Run sixDoFSim with args; return its log (stdout and stderr)."""
        return self.run_application(
            ["sixDoFSim", "-case", self.dir, "-nIter", str(n_iter), *args], expect_failure)

    def bodies(self, start="0"):
        return self.table("postProcessing", "sixDoFSim", start, "bodies.dat")
