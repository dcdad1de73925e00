"""The schemes' own recurrences on the linear test problems, for the
theoretical stability limits the measurements are compared with.

x'' = -W2 x - C x' with W2 = k/m (spring) or C = c/m (damper), written as
the solvers do it (OpenFOAM v1912 source, rigidBodySolvers/*/*.C, and
docs/fmusim.md); the restraint is evaluated where each solver evaluates it.
State (x, v, a): a is the stored acceleration, zero at the start as in
OpenFOAM.
"""
import math

GAMMA, BETA = 0.5, 0.25  # OpenFOAM Newmark defaults


def step(scheme, n_iter, w2, c, h, x, v, a):
    if scheme == "symplectic":       # velocity Verlet, loads after the drift
        vh = v + 0.5 * h * a
        x1 = x + h * vh
        a1 = -w2 * x1 - c * vh
        return x1, vh + 0.5 * h * a1, a1
    if scheme == "Newmark":          # loads at the previous iterate
        xi, vi = x, v
        for _ in range(n_iter):
            ai = -w2 * xi - c * vi
            vi = v + h * (GAMMA * ai + (1 - GAMMA) * a)
            xi = x + h * v + h * h * (BETA * ai + (0.5 - BETA) * a)
        return xi, vi, ai
    if scheme == "explicit":         # fmusim: symplectic Euler
        a0 = -w2 * x - c * v
        v1 = v + h * a0
        return x + h * v1, v1, a0
    if scheme in ("implicitNewmark", "implicit"):  # trapezoidal, solved exactly
        # a1 = -w2 (x + h v + h^2/4 (a + a1)) - c (v + h/2 (a + a1))
        rhs = -w2 * (x + h * v + 0.25 * h * h * a) - c * (v + 0.5 * h * a)
        a1 = rhs / (1 + 0.25 * w2 * h * h + 0.5 * c * h)
        return x + h * v + 0.25 * h * h * (a + a1), v + 0.5 * h * (a + a1), a1
    raise ValueError(scheme)


def spectral_radius(scheme, n_iter, w2, c, h):
    """Largest |eigenvalue| of the one-step map on (x, v, a), from the norm
    of its 2^40-th power (repeated squaring, renormalised)."""
    cols = [step(scheme, n_iter, w2, c, h, *e) for e in ((1, 0, 0), (0, 1, 0), (0, 0, 1))]
    m = [[cols[j][i] for j in range(3)] for i in range(3)]
    log_scale = 0.0
    for k in range(40):
        m = [[sum(m[i][l] * m[l][j] for l in range(3)) for j in range(3)] for i in range(3)]
        n = max(abs(x) for row in m for x in row)
        if n == 0 or not math.isfinite(n):
            return 0.0 if n == 0 else float("inf")
        m = [[x / n for x in row] for row in m]
        log_scale = 2 * log_scale + math.log(n)
    return math.exp(log_scale / 2**40)


def window_growth(scheme, n_iter, w2, c, h, steps, x0=1.0, v0=0.0):
    """Largest |x| (spring) or |v| (damper, x0 = 0) over `steps` steps,
    relative to the initial one."""
    x, v, a = x0, v0, 0.0
    big = 0.0
    for _ in range(steps):
        x, v, a = step(scheme, n_iter, w2, c, h, x, v, a)
        big = max(big, abs(x) / x0 if x0 else abs(v) / v0)
        if not math.isfinite(big) or big > 1e30:
            return float("inf")
    return big


def limit(stable, low=1e-6, high=1e8, rel=1e-3):
    """The largest value of a parameter in [low, high] for which
    stable(value) holds, assuming one boundary; high if stable there."""
    if stable(high):
        return high
    if not stable(low):
        return 0.0
    while high / low > 1 + rel:
        mid = math.sqrt(low * high)
        low, high = (mid, high) if stable(mid) else (low, mid)
    return low
