"""The rigidBodyMotion fmuConnector feeds the mass properties a connector
declares (A.m, A.c[1..3], A.J[1..3,1..3], and B's): massEcho.fmu (built
here from massEcho/massEcho.c) returns no load and echoes them as outputs.

The model: 'hull' (2 kg, centre of mass (0.1 0 0) in its frame, inertia
diag(0.1 0.2 0.3) about it) with 'lid' (1 kg, centre of mass at its frame
origin, inertia diag(0.01 0.01 0.01)) merged into it 0.2 m up, and 'buoy'
(3 kg, centre of mass (0 0.05 0)). What moves is the merged body, so the
connector on hull (to buoy) sees the merged mass, centre of mass and
inertia in the hull's frame, and buoy's as B; a connector from buoy to the
world leaves B's mass inputs at their start values.
"""
import os
import sys

from foamfmi.bridgecase import Case, entries, fmu_restraint, rigid_body_model, summary, vec

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "massEcho"))
import build  # noqa: E402


def body(mass, centre, inertia, origin, **links):
    """A rigidBody: mass, centre of mass and inertia about it (body frame),
    frame origin, and its parent and joint or the body it is merged with."""
    return {"type": "rigidBody", **links, "mass": mass, "centreOfMass": centre,
            "inertia": inertia, "transform": f"(1 0 0 0 1 0 0 0 1) {vec(origin)}"}


def model(fmu):
    floating = {"parent": "root", "joint": {"type": "floating"}}
    bodies = {
        "hull": body(2, (0.1, 0, 0), "(0.1 0 0 0.2 0 0.3)", (0, 0, 0), **floating),
        "lid": body(1, (0, 0, 0), "(0.01 0 0 0.01 0 0.01)", (0, 0, 0.2), mergeWith="hull"),
        "buoy": body(3, (0, 0.05, 0), "(0.4 0 0 0.4 0 0.4)", (1, 0, 0), **floating),
    }
    return rigid_body_model(entries(bodies, 8), fmu_restraint("echo", fmu, "hull", None, "buoy")
                            + fmu_restraint("echoWorld", fmu, "buoy", None), "Newmark", g=None)


def merged():
    """Mass, centre of mass and inertia about it of hull + lid, hull frame."""
    parts = [(2.0, (0.1, 0.0, 0.0), (0.1, 0.2, 0.3)), (1.0, (0.0, 0.0, 0.2), (0.01, 0.01, 0.01))]
    m = sum(p[0] for p in parts)
    c = [sum(p[0] * p[1][i] for p in parts) / m for i in range(3)]
    J = [[0.0] * 3 for _ in range(3)]
    for mi, ci, Ii in parts:
        d = [ci[k] - c[k] for k in range(3)]
        dd = sum(x * x for x in d)
        for i in range(3):
            for j in range(3):
                J[i][j] += (Ii[i] if i == j else 0) + mi * ((dd if i == j else 0) - d[i] * d[j])
    return m, c, J


def expected(prefix, m, c, J):
    v = {f"{prefix}.m": m}
    for i in range(3):
        v[f"{prefix}.c[{i + 1}]"] = c[i]
        for j in range(3):
            v[f"{prefix}.J[{i + 1},{j + 1}]"] = J[i][j]
    return v


def main():
    with build.built() as fmu:
        case = Case("massProperties", model(fmu), 0.01, 0.001)
        case.run(n_iter=2)
    m, c, J = merged()
    # The merged inertia is a sum of a few products of the inputs:
    # round-off 1e-15; 1e-14 leaves room and fails on any wrong term
    rows = {name: {k: v[-1] for k, v in case.connector(name).items()} for name in ("echo", "echoWorld")}
    failures = build.check_echo("echo", rows["echo"], {
        **expected("A", m, c, J),
        **expected("B", 3.0, (0, 0.05, 0), [[0.4, 0, 0], [0, 0.4, 0], [0, 0, 0.4]])}, 1e-14)
    # B, the world, keeps its start values: mass 1, the rest 0
    failures += build.check_echo("echoWorld", rows["echoWorld"], {
        **expected("A", 3.0, (0, 0.05, 0), [[0.4, 0, 0], [0, 0.4, 0], [0, 0, 0.4]]),
        **expected("B", 1.0, (0, 0, 0), [[0] * 3] * 3)}, 1e-14)
    case.cleanup()
    return summary(2, failures)


if __name__ == "__main__":
    sys.exit(main())
