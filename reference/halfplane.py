"""The linearised half-plane plot (Barquins 1988; Chaudhury et al. 1996), the baseline jkrcyl.fit is compared with.

Barquins' load (7.4) with the contact half-width a_h [m], A = beta*/(2 pi), 1/R* = 1/R_D - 1/R, R_D = R - Delta:

    P = a_h^2/(2 A R*) R_D/R - sqrt(4 a_h w/A)   <=>   P/sqrt(a_h) = a_h^(3/2) R_D/(2 A R* R) - sqrt(4 w/A),

a straight line in (a_h^(3/2), P/sqrt(a_h)): its slope gives A (the modulus), its intercept -sqrt(4 w/A) gives w.
Used by tests/test_fit.py and benchmarks/bench_fit.py only (ordinary least squares on the measured points).
"""
import numpy as np


def linearised_plot(width, P, R, Delta, A=None):
    """(w [J/m^2], A [1/Pa]) from the straight-line fit; A given: only the intercept is fitted (slope known).

    width: measured contact widths 2 a_h [m]; P: loads [N/m]; R, Delta: hole radius and clearance [m]."""
    a_h = np.asarray(width, dtype=float) / 2
    x, y = a_h ** 1.5, np.asarray(P, dtype=float) / np.sqrt(a_h)
    R_D = R - Delta
    k = R_D / (2 * R * (1 / R_D - 1 / R) ** -1)        # slope = k / A
    if A is None:
        slope, intercept = np.polyfit(x, y, 1)
        A = k / slope
    else:
        intercept = float(np.mean(y - x * k / A))
    return intercept ** 2 * A / 4, A
