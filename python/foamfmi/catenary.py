"""An elastic catenary with seabed contact and no seabed friction
(Jonkman's closed form, the textbook solution), written independently of
connectors/catenary: the reference the tests check the catenary FMU's
tensions against.

A line of unstretched length L (m), submerged weight w (N/m) and axial
stiffness EA (N) from an anchor on the seabed to a fairlead x (horizontal)
and z (above) from it; H and V are the horizontal and vertical tension at
the fairlead (N).
"""

import math


def fairlead_position(H, V, L, w, EA):
    """Span x and height z of the fairlead over the anchor for the fairlead
    tension components H, V: part of the line on the seabed when V < w L,
    else all of it suspended."""
    if V < w * L:
        lb = L - V / w  # on the seabed
        xs = lb + H / w * math.asinh(V / H) + H * L / EA
        zs = H / w * (math.sqrt(1 + (V / H) ** 2) - 1) + V * V / (2 * EA * w)
    else:
        va = V - w * L
        xs = H / w * (math.asinh(V / H) - math.asinh(va / H)) + H * L / EA
        zs = (H / w * (math.sqrt(1 + (V / H) ** 2) - math.sqrt(1 + (va / H) ** 2))
              + (V * L - 0.5 * w * L * L) / EA)
    return xs, zs


def _residual(H, V, x, z, L, w, EA):
    xs, zs = fairlead_position(H, V, L, w, EA)
    return xs - x, zs - z


def tensions(x, z, L, w, EA):
    """Horizontal and vertical fairlead tension (N) of a line whose fairlead
    is x (horizontal) and z (above) from its anchor on the seabed. Newton on
    the two closure equations (finite-difference Jacobian) to 1e-13 m."""
    H, V = max(0.1 * w * L, 1e-3), 0.5 * w * L
    for _ in range(200):
        r = _residual(H, V, x, z, L, w, EA)
        if max(abs(r[0]), abs(r[1])) < 1e-13:
            return H, V
        e = 1e-7 * max(H, V, 1e-6)
        rh = _residual(H + e, V, x, z, L, w, EA)
        rv = _residual(H, V + e, x, z, L, w, EA)
        a, b = (rh[0] - r[0]) / e, (rv[0] - r[0]) / e
        c, d = (rh[1] - r[1]) / e, (rv[1] - r[1]) / e
        det = a * d - b * c
        dH = (-r[0] * d + r[1] * b) / det
        dV = (-a * r[1] + c * r[0]) / det
        step = 1.0
        while H + step * dH <= 0:
            step *= 0.5
        H, V = H + step * dH, V + step * dV
    raise RuntimeError("catenary: no convergence for x = %g, z = %g" % (x, z))


def line_tension(fairlead, anchor, L, w, EA):
    """Fairlead tension (N), H and V of a line from the point fairlead to
    the anchor (global coordinates, z up, the anchor on the seabed)."""
    x = math.hypot(fairlead[0] - anchor[0], fairlead[1] - anchor[1])
    H, V = tensions(x, fairlead[2] - anchor[2], L, w, EA)
    return math.hypot(H, V), H, V
