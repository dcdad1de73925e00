"""The mooring lines of the bridge's moored-body cases
(tests/bridge/test_catenary_world.py, bench/mooringSystems): a chain of
submerged weight W per metre, as catenary.fmu (quasi-static) and
mooringLine.fmu (lumped mass) restraints, and the constant push and the
damper that hold a moored body off its neutral place and settle it
(OpenFOAM's externalForce and linearDamper).
"""
import math

from foamfmi.bridgecase import restraint

L, EA, W, DEPTH = 100.0, 5e7, 700.0, 40.0       # m, N, N/m (submerged), m
DIAMETER, RHO, G = 0.1, 1025.0, 9.81            # m, kg/m^3, m/s^2
MU = W / G + RHO * math.pi * DIAMETER ** 2 / 4  # kg/m, dry mass for weight W
AXIAL_DAMPING = 2e5                             # N s, mooringLine's


def catenary_parameters(length=L, seabed_contact=1, **more):
    """catenary.fmu's parameters of a line of length (m); more: further
    ones (seabedFriction, ...)."""
    return {"unstretchedLength": length, "EA": EA, "weight": W,
            "seabedContact": seabed_contact, **more}


def lumped_parameters(segments, length=L, seabed_contact=1):
    """mooringLine.fmu's parameters of the same line in segments."""
    return {"unstretchedLength": length, "EA": EA, "axialDamping": AXIAL_DAMPING,
            "massPerLength": MU, "diameter": DIAMETER, "waterDensity": RHO, "gravity": G,
            "seabedContact": seabed_contact, "segments": segments}


def push_and_damper(push, damper, body, force, coeff):
    """OpenFOAM's externalForce restraint push, force (N) along +x at the
    body's frame origin, and its linearDamper damper of coefficient coeff
    (N s/m)."""
    return (restraint(push, {"type": "externalForce", "body": body, "location": "(0 0 0)",
                             "force": f"constant ({force} 0 0)"})
            + restraint(damper, {"type": "linearDamper", "body": body, "coeff": coeff}))
