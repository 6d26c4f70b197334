"""The receding contact a_crit (section 4): the one meaning of the name in jkrcyl."""
import math
from typing import Optional

from .model.problem import Problem
from .model.single_patch import solver


def a_crit(theta: float, gb: Optional[float] = None, alpha_ratio: float = 0.0) -> float:
    """The receding contact a_crit = tan(eps_crit/2) of a material pair: the contact parameter where the
    adhesionless load is infinite (the pole of (4.4)), the boundary of the sub- and super-critical branches.

    Parameters
    ----------
    theta : float
        vartheta (section 4), >= 1/2, or inf (rigid cradle).
    gb : float, optional
        (1/G_I)/beta* in [0, 1]; needed only where alpha* != 0 (the closed form does not depend on it).
    alpha_ratio : float, optional
        alpha*/beta* in (-1, 1); 0 (default): the paper's root of 2 vartheta - log(1 + a^2) - 2 a^4 = 0.

    Returns
    -------
    float
        a_crit; inf for a rigid cradle at alpha* = 0 (section 7.2).  ``Contact.a_crit`` is this for its pair.

    Raises
    ------
    ValueError
        Naming theta, gb or alpha_ratio outside their ranges (gb missing where alpha* != 0).

    Examples
    --------
    >>> round(a_crit(1.0), 4)          # section 4: eps_crit = 2 atan(a_crit) = 84.8 deg at vartheta = 1
    0.9136
    >>> a = a_crit(1.0)
    >>> abs(2 * 1.0 - math.log(1 + a * a) - 2 * a ** 4) < 1e-12                 # the root of the closed form
    True
    >>> a_crit(math.inf)                # rigid cradle (section 7.2)
    inf
    """
    sv = solver(Problem(0.0, theta, 0.0 if gb is None else gb, alpha_ratio))
    if gb is None and sv.pole_needs_gb:
        raise ValueError(f"gb must be given where alpha* != 0 (the pole depends on (1/G_I)/beta*), got alpha_ratio = "
                         f"{alpha_ratio!r}")
    return sv.a_crit
