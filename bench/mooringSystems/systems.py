"""Mooring systems for rigidBodySim: floating bodies held by anchored lines
and by shared lines between neighbouring bodies, each line a
mooringLine.fmu (lumped mass) or catenary.fmu (quasi-static) restraint; the
statics they must come to rest at, computed here without the FMUs.

A body moves in surge and sway only (joint Px then Py, the restoring in
heave and the rotations are the water's, which rigidBodySim does not
have). A constant push along +x (a steady current or wind, OpenFOAM's
externalForce) holds it off its neutral place, OpenFOAM's linearDamper
(critical for its own lines' stiffness) settles it. All fairleads are at
z = 0, 40 m above a flat seabed.

Anchored line: the elastic catenary with seabed contact
(foamfmi.catenary). Shared line: suspended between two fairleads at the
same height, H from span = 2 (H/w) asinh(w L / (2 H)) + H L/EA; it pulls
both bodies towards each other with H and carries w L / 2 at each end.
"""
import math

import numpy as np

from foamfmi import catenary
from foamfmi.bridgecase import fmu_restraint, rigid_body, rigid_body_model
# The anchored lines: those of tests/bridge/test_catenary_world.py
from foamfmi.mooringcase import (DEPTH, EA, G, L, W, catenary_parameters, lumped_parameters,
                                 push_and_damper)

SEGMENTS = 20
SPAN = 85.0                     # m, anchor to fairlead (horizontal): H ~ 1.6e4 N
SHARED_L = 55.0                 # m, shared line between fairleads 50 m apart
MASS = 1e3                      # kg, each body
RADIUS = 5.0                    # m, fairleads from the body's centre
SPACING = 60.0                  # m, between neighbouring bodies' centres
PUSH = 5e3                      # N along +x on every body


class System:
    """Bodies (neutral centres), anchored lines (body, fairlead offset,
    anchor) and shared lines (body A, offset, body B, offset)."""

    def __init__(self, name, centres, sway=1.0):
        self.name = name
        self.sway = sway  # m, every body's start offset in sway
        self.centres = [np.array(c, dtype=float) for c in centres]  # (x, y), m
        self.anchored = []
        self.shared = []

    def anchor(self, body, angle):
        """A line from the body's fairlead at angle (rad) to its anchor SPAN
        further out."""
        e = np.array([math.cos(angle), math.sin(angle)])
        self.anchored.append((body, RADIUS * e, self.centres[body] + (RADIUS + SPAN) * e))

    def share(self, a, b):
        """A line between the facing fairleads of bodies a and b."""
        e = self.centres[b] - self.centres[a]
        e /= np.linalg.norm(e)
        self.shared.append((a, RADIUS * e, b, -RADIUS * e))

    @property
    def n_lines(self):
        return len(self.anchored) + len(self.shared)

    # Statics ---------------------------------------------------------------

    def forces(self, x):
        """Horizontal force (N) on each body, its centre moved by x[i] from
        the neutral one (rows x, y)."""
        f = np.zeros((len(self.centres), 2))
        f[:, 0] += PUSH
        for body, offset, anchor in self.anchored:
            p = self.centres[body] + x[body] + offset
            d = anchor - p
            h, _ = catenary.tensions(np.linalg.norm(d), DEPTH, L, W, EA)
            f[body] += h * d / np.linalg.norm(d)
        for a, off_a, b, off_b in self.shared:
            d = (self.centres[b] + x[b] + off_b) - (self.centres[a] + x[a] + off_a)
            h = shared_tension(np.linalg.norm(d))
            f[a] += h * d / np.linalg.norm(d)
            f[b] -= h * d / np.linalg.norm(d)
        return f

    def statics(self):
        """Offsets (m) at rest and the stiffness matrix there (N/m), by
        Newton with a central-difference Jacobian."""
        n = 2 * len(self.centres)
        x = np.zeros(n)
        for _ in range(50):
            r = self.forces(x.reshape(-1, 2)).ravel()
            k = self.stiffness(x)
            dx = np.linalg.solve(k, r)
            x += dx
            if np.max(np.abs(dx)) < 1e-9:
                return x.reshape(-1, 2), self.stiffness(x)
        raise RuntimeError(f"{self.name}: statics do not converge")

    def stiffness(self, x, e=1e-5):
        n = len(x)
        k = np.zeros((n, n))
        for j in range(n):
            xp, xm = x.copy(), x.copy()
            xp[j] += e
            xm[j] -= e
            k[:, j] = -(self.forces(xp.reshape(-1, 2)).ravel()
                        - self.forces(xm.reshape(-1, 2)).ravel()) / (2 * e)
        return k


def shared_tension(span):
    """Horizontal tension (N) of a shared line whose fairleads, at the same
    height, are span (m) apart: bisection on the suspended catenary."""
    lo, hi = 1e-3, 1e9
    for _ in range(200):
        h = math.sqrt(lo * hi)
        s = 2 * h / W * math.asinh(W * SHARED_L / (2 * h)) + h * SHARED_L / EA
        lo, hi = (h, hi) if s < span else (lo, h)
    return math.sqrt(lo * hi)


def array():
    """3 bodies in a row, 3 anchored lines each at 90, 210 and 330 degrees,
    a shared line between each pair of neighbours: 11 lines."""
    s = System("array", [(-SPACING, 0), (0, 0), (SPACING, 0)])
    for body in range(3):
        for degrees in (90, 210, 330):
            s.anchor(body, math.radians(degrees))
    s.share(0, 1)
    s.share(1, 2)
    return s


def scaling(n):
    """n anchored lines: one line (upstream of the push) on one body, or
    10 lines evenly around each of n/10 bodies, 1000 m apart."""
    if n == 1:
        s = System("1 line", [(0, 0)], sway=0.0)  # a single line hardly holds sway
        s.anchor(0, math.pi)
        return s
    bodies = n // 10
    s = System(f"{n} lines", [(0, 1000.0 * i) for i in range(bodies)])
    for body in range(bodies):
        for k in range(10):
            s.anchor(body, math.pi + 2 * math.pi * k / 10)
    return s


# The case ----------------------------------------------------------------

def body_entry(i, centre, start):
    return rigid_body(f"body{i}", MASS, "1e4", (*(centre + start), 0),
                      "composite; joints ({ type Px; } { type Py; })")


def line_entry(name, fmu, a, p_a, b, p_b, anchored):
    """A restraint for one line; p_b is the anchor (global) when b is None."""
    length = L if anchored else SHARED_L
    if fmu.endswith("catenary.fmu"):
        law = catenary_parameters(length, int(anchored))
    else:
        law = lumped_parameters(SEGMENTS if anchored else int(SEGMENTS * SHARED_L // L),
                                length, int(anchored))
    return fmu_restraint(name, fmu, f"body{a}", {**law, "A.p": p_a, "B.p": p_b},
                         None if b is None else f"body{b}")


def model(system, fmu, damping, start, lines=True):
    """The rigidBodyMotionCoeffs of the system: fmu the path of the lines'
    FMU, damping (N s/m) and start offset (m, x and y) per body; without
    lines, the bodies, push and dampers only."""
    bodies = "".join(body_entry(i, c, start[i]) for i, c in enumerate(system.centres))
    restraints = "".join(push_and_damper(f"push{i}", f"damper{i}", f"body{i}", PUSH, damping[i])
                         for i in range(len(system.centres)))
    if lines:
        for j, (body, offset, anchor) in enumerate(system.anchored):
            restraints += line_entry(f"line{j}", fmu, body, (*offset, 0),
                                     None, (*anchor, -DEPTH), True)
        for j, (a, off_a, b, off_b) in enumerate(system.shared):
            restraints += line_entry(f"shared{j}", fmu, a, (*off_a, 0), b, (*off_b, 0), False)
    return rigid_body_model(bodies, restraints, "Newmark", g=(0, 0, -G))


def damping(system, k):
    """Critical damping of each body on its own diagonal stiffness."""
    return [2 * math.sqrt(k[2 * i, 2 * i] * MASS) for i in range(len(system.centres))]


def start_offsets(system):
    """Every body starts at its neutral place moved in sway by the system's
    sway (the push moves it in surge)."""
    return [np.array([0.0, system.sway]) for _ in system.centres]


def check(system, case, x_eq, k, fmu_name):
    """Failures (a list of sentences) of a finished run. The catenary's
    bodies at rest at the statics within 1 mm at the end; the lumped
    lines' nodes keep vibrating (about 1 % of the tension, their drag damps
    them slowly), so there the means over the last quarter of the run,
    within the discretisation (0.5 % of the line tension over the
    stiffness, as tests/bridge/test_catenary_world.py) plus 1 mm, their
    mean speed within 5 mm/s (catenary: the last speed within 1 mm/s). Each
    shared line's horizontal loads on its two bodies equal and opposite
    (1e-6 of its tension, mooringLine 1 %), its tension the statics' (1e-4,
    mooringLine 2 %)."""
    failures = []
    dynamic = fmu_name == "mooringLine"
    b = case.bodies()
    rows = len(b["Time"]) // 4 if dynamic else 1

    def final(column):
        return float(np.mean(column[-rows:]))

    tension = catenary.tensions(SPAN, DEPTH, L, W, EA)[0]
    got = []
    for i, centre in enumerate(system.centres):
        k_i = min(k[2 * i, 2 * i], k[2 * i + 1, 2 * i + 1])
        allowed = 1e-3 + (0.005 * tension / k_i if dynamic else 0.0)
        got.append(np.array([final(b[f"body{i}.c.x"]), final(b[f"body{i}.c.y"])]) - centre)
        error = np.max(np.abs(got[i] - x_eq[i]))
        speed = math.hypot(final(b[f"body{i}.v.x"]), final(b[f"body{i}.v.y"]))
        if error > allowed or speed > (5e-3 if dynamic else 1e-3):
            failures.append(
                f"{system.name}, {fmu_name}: body{i} at {got[i]}, statics {x_eq[i]} (error "
                f"{error:.2e} m, allowed {allowed:.2e} m), speed {speed:.2e} m/s")
    for j, (a, off_a, bb, off_b) in enumerate(system.shared):
        c = case.connector(f"shared{j}")
        fa = np.array([final(c["A.F[1]"]), final(c["A.F[2]"])])
        fb = np.array([final(c["B.F[1]"]), final(c["B.F[2]"])])
        h = np.linalg.norm(fa)
        expected = shared_tension(np.linalg.norm(
            (system.centres[bb] + x_eq[bb] + off_b) - (system.centres[a] + x_eq[a] + off_a)))
        if np.linalg.norm(fa + fb) > (1e-2 if dynamic else 1e-6) * h \
                or abs(h - expected) > (2e-2 if dynamic else 1e-4) * expected:
            failures.append(f"{system.name}, {fmu_name}: shared{j}'s horizontal loads {fa} and "
                            f"{fb}, statics {expected:.1f} N, equal and opposite")
    return failures
