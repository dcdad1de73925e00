"""Numerical and validation uncertainty of a CFD result.

Grid convergence: the procedure of Celik, Ghia, Roache, Freitas, Coleman
and Raad (Procedure for estimation and reporting of uncertainty due to
discretization in CFD applications, J. Fluids Eng. 130, 078001, 2008):
three solutions phi_1 (fine), phi_2, phi_3 (coarse) on grids of
representative cell sizes h_1 < h_2 < h_3 (cells and time step refined
together), the apparent order p from their differences by fixed-point
iteration, Richardson's extrapolation phi_ext, the approximate and the
extrapolated relative errors and the fine-grid convergence index
GCI = 1.25 e_a/(r_21^p - 1).

Validation: ASME V&V 20-2009: the comparison error E = S - D against the
validation uncertainty u_val = sqrt(u_num^2 + u_input^2 + u_D^2), each a
standard uncertainty. The numerical one from an expanded estimate U_num:
u_num = U_num/1.15, the standard's conversion of a GCI with the factor of
safety 1.25 (an interval taken to hold the exact solution with about 95 %
confidence; its error distribution is not Gaussian, so the divisor is not
2). The same divisor is used for three times the range (Eca and Hoekstra
2014, factor of safety 3), which is also meant as a 95 % interval. The
input one from one-at-a-time sensitivities: u_input = sqrt(sum (s_i
u_i)^2), s_i the change of the result per unit of input i, u_i that
input's standard uncertainty.
"""

import collections
import math

# Celik et al. (2008): the factor of safety of the GCI from three grids
SAFETY_FACTOR = 1.25

GridConvergence = collections.namedtuple(
    "GridConvergence", "p extrapolated approximate_error extrapolated_error gci oscillatory")
GridConvergence.__doc__ = """p: apparent order; extrapolated: phi_ext^21;
approximate_error: |(phi_1 - phi_2)/phi_1|; extrapolated_error:
|(phi_ext - phi_1)/phi_ext|; gci: the fine grid's convergence index (a
fraction of phi_1); oscillatory: the differences change sign (Celik et
al.: oscillatory convergence, p and the extrapolation are then taken with
|eps32/eps21| and should be read with care)."""


class ConvergenceError(ValueError):
    """Three solutions from which no apparent order follows."""


def grid_convergence(phi, h):
    """The Celik et al. (2008) procedure for phi = (phi_1, phi_2, phi_3)
    on cells of size h = (h_1, h_2, h_3), fine to coarse (h_1 < h_2 <
    h_3)."""
    phi1, phi2, phi3 = phi
    h1, h2, h3 = h
    if not h1 < h2 < h3:
        raise ConvergenceError("cell sizes %g, %g, %g: not fine to coarse" % (h1, h2, h3))
    r21, r32 = h2 / h1, h3 / h2
    eps21, eps32 = phi2 - phi1, phi3 - phi2
    if eps21 == 0 or eps32 == 0:
        raise ConvergenceError("solutions %g, %g, %g: two are equal, no order follows"
                               % (phi1, phi2, phi3))
    ratio = eps32 / eps21
    s = math.copysign(1.0, ratio)
    # Fixed-point iteration of p = |ln|eps32/eps21| + q(p)|/ln r21,
    # q(p) = ln((r21^p - s)/(r32^p - s))
    p = abs(math.log(abs(ratio))) / math.log(r21)
    for _ in range(200):
        q = math.log((r21 ** p - s) / (r32 ** p - s))
        p_next = abs(math.log(abs(ratio)) + q) / math.log(r21)
        if abs(p_next - p) < 1e-12:
            p = p_next
            break
        p = p_next
    else:
        raise ConvergenceError("apparent order not converged for %g, %g, %g" % (phi1, phi2, phi3))
    if r21 ** p == 1:
        raise ConvergenceError("solutions %g, %g, %g: apparent order 0, no extrapolation"
                               % (phi1, phi2, phi3))
    extrapolated = (r21 ** p * phi1 - phi2) / (r21 ** p - 1)
    e_a = abs((phi1 - phi2) / phi1)
    e_ext = abs((extrapolated - phi1) / extrapolated)
    gci = SAFETY_FACTOR * e_a / (r21 ** p - 1)
    return GridConvergence(p, extrapolated, e_a, e_ext, gci, ratio < 0)


# ASME V&V 20-2009: u_num = GCI/1.15 for a GCI with the factor of safety
# 1.25 (an expanded uncertainty of about 95 % coverage)
NUMERICAL_COVERAGE = 1.15


def standard_numerical_uncertainty(expanded):
    """u_num of an expanded numerical uncertainty U_num (a GCI, or three
    times the range: numerical_uncertainty), ASME V&V 20-2009:
    U_num/1.15."""
    return expanded / NUMERICAL_COVERAGE


def uniform_standard_uncertainty(low, high):
    """The standard uncertainty of an input known only to lie in [low,
    high], every value in it equally likely (GUM 4.3.7): the half-range
    over sqrt(3)."""
    return 0.5 * abs(high - low) / math.sqrt(3.0)


def input_uncertainty(contributions):
    """ASME V&V 20: u_input = sqrt(sum c_i^2) of the inputs'
    contributions c_i = s_i u_i (independent inputs, first order)."""
    return math.sqrt(sum(c * c for c in contributions))


def validation(simulation, data, u_num, u_input, u_data):
    """ASME V&V 20: the comparison error E = S - D and the validation
    uncertainty u_val = sqrt(u_num^2 + u_input^2 + u_D^2) (standard
    uncertainties, the units of S and D). Returns (E, u_val)."""
    return simulation - data, math.sqrt(u_num ** 2 + u_input ** 2 + u_data ** 2)


# The apparent orders for which the GCI is taken (below: the three
# solutions are not in the asymptotic range)
ORDER_RANGE = (0.5, 3.0)


def numerical_uncertainty(phi, h):
    """Expanded numerical uncertainty U of the finest solution phi_1 (the
    units of phi) and how it was found: Celik et al.'s GCI x |phi_1| when
    the three solutions converge monotonically with an apparent order in
    ORDER_RANGE; otherwise (oscillating, or an order outside it: not in
    the asymptotic range) three times the solutions' range, the estimate
    Eca and Hoekstra (J. Comput. Phys. 262, 2014) give for such data.
    Returns (U, GridConvergence or None, "GCI" or "3 x range")."""
    data_range = max(phi) - min(phi)
    try:
        g = grid_convergence(phi, h)
    except ConvergenceError:
        return 3 * data_range, None, "3 x range"
    if g.oscillatory or not ORDER_RANGE[0] <= g.p <= ORDER_RANGE[1]:
        return 3 * data_range, g, "3 x range"
    return g.gci * abs(phi[0]), g, "GCI"
