"""Restarts of the sixDoF connector tutorial in interFoam, serial and
parallel, as tests/tutorials/restart.py does for the rigidBodyMotion ones.

coupledFloatingObjectsSixDoF (the spring between two
sixDoFRigidBodyDisplacement patches, one FMU shared by their restraints)
runs on the coarse mesh to T = 0.2 s, writing at 0.1 s in binary with 17
digits; a copy restarted from 0.1 s (startFrom latestTime) runs to T. The
point-patch condition writes each body's motion, with its restraints, into
pointDisplacement; the connector's state goes to uniform/fmuConnectors.
Checked for every run:

- the restart runs to T and restores the connector's FMU state, once;
- the connector writes one row per time step after the restart, at the
  uninterrupted run's times;
- the bodies' state at T (orientation and angular velocity of the last
  report of each body in the solver log) stays within OpenFOAM's own
  restart floor, measured on uncoupledFloatingObjectsSixDoF (no connector),
  times 10 for the coupled dynamics, and at most 2 %: v1912's interFoam does
  not restart exactly (docs/restarts.md), the connector does
  (tests/bridge/test_sixdof_spring_world.py, bit for bit).
"""
import os
import re
import sys

from foamfmi import postprocessing
from restart import check_scenes

SCENES = {
    "uncoupledFloatingObjectsSixDoF": ([], []),
    "coupledFloatingObjectsSixDoF": (["spring"], []),
    "coupledFloatingObjectsSixDoF -parallel": (["spring"], ["-parallel"]),
}


def body_state(full, restarted, parallel):
    """Orientation and angular velocity of the last report of each of the
    two bodies (the motions report in patch order every solve), in the
    uninterrupted and the restarted run's logs."""
    def state(log):
        with open(log) as f:
            text = f.read()
        orientations = re.findall(r"Orientation: \(([^)]*)\)", text)[-2:]
        omegas = re.findall(r"Angular velocity: \(([^)]*)\)", text)[-2:]
        return [float(x) for block in orientations + omegas for x in block.split()]

    return (state(os.path.join(full, "log." + postprocessing.case_solver(full))),
            state(os.path.join(restarted, "log.restart")))


def main():
    return check_scenes(SCENES, body_state, "tutorialRestartSixDoF.")


if __name__ == "__main__":
    sys.exit(main())
