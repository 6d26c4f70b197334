"""The top bridge of the Maugis-Dugdale law as a branch of equilibria: ``curve(regime="top-bridge")``.

A zone at the top of the hole held by its own traction, beside the contact and its zone at the bottom (the model
core: jkrcyl.model.cohesive_bridge; the numerics: jkrcyl.numerics.cohesive_top_zone, and past the touch
jkrcyl.numerics.cohesive_contactless).  Its states are the barrier between one patch and two: unstable under every
control.  Reached through :func:`jkrcyl.equilibria.curve` and :meth:`jkrcyl.Contact.curve`.
"""
from __future__ import annotations

import functools
import math

import numpy as np

from .analysis import branches as _br
from .model import cohesive_bridge as _bridge
from .model.problem import Problem
from .model.single_patch import solver
from .results import Curve

TOP_BRIDGE = _bridge.TOP_BRIDGE
ALL_REGIMES = _br.REGIMES + (_br.ZONE_ONLY, TOP_BRIDGE)


def check_regime(regime) -> str:
    """The regime name, or ValueError naming regime with every branch a curve can be."""
    if regime not in ALL_REGIMES:
        raise ValueError(f"regime must be one of {', '.join(ALL_REGIMES)}, got {regime!r}")
    return regime


def curve(pb: Problem, a=None) -> Curve:
    """The top-bridge families of the problem as one :class:`jkrcyl.results.Curve` (normalised), as traced.

    Parameters
    ----------
    pb : jkrcyl.model.problem.Problem
        A problem with the Maugis-Dugdale edge (jkrcyl.laws.DugdaleEdge).
    a : None
        The states are those traced (c_top geometric from 1e-9 by 2 per point to the family's end; past a touch
        the bottom zone c by 0.95): a given parameter is refused.

    Returns
    -------
    jkrcyl.results.Curve
        regime 'top-bridge': a = j + c_top/pi (family j = 0, 1, ... in increasing junction contact), eps [rad] (0
        past the touch), the zone ends c, c_top [rad], P* (section 6), delta/Delta (5.8), delta_work/Delta,
        h(pi)/Delta (5.10), the slopes d/da per point, the stability flags under load, grip and grip-work (all
        False: saddles) and ``ends`` (how each family ends, in words).  dG/da: NaN (no Griffith edge).

    Raises
    ------
    ValueError
        Naming regime: JKR (no bridge: its top adheres at h(pi) = 0), or no junction h(pi) = h0 with a gap minimum
        at the top; naming a where one is given.
    """
    if a is not None:
        raise ValueError("a: the top bridge's states are those traced (a = j + c_top/pi); give no a")
    _bridge.require(pb)
    return _curve(pb)


@functools.lru_cache(maxsize=16)
def _curve(pb: Problem) -> Curve:
    t = _bridge.table(pb, solver(pb))
    k, nan = pb.scale, np.full(t["a"].shape, math.nan)
    return Curve(M=pb.M, theta=pb.theta, gb=pb.gb, regime=TOP_BRIDGE, a=t["a"], eps=t["eps"],
                 eps_star=t["eps"] / math.pi, P_star=t["p"] / k, delta_over_Delta=t["dn"], h_pi_over_Delta=t["h"],
                 feasible=t["feasible"], stable_load=t["stable_load"], stable_grip=t["stable_grip"],
                 stable_grip_work=t["stable_grip_work"], dP_star_da=t["dp_da"] / k, ddelta_da=t["ddn_da"],
                 delta_work_over_Delta=t["dw"], ddelta_work_da=t["ddw_da"], dG_da_P=nan, dG_da_delta=nan,
                 dG_da_delta_work=nan, alpha_ratio=pb.alpha_ratio, c=t["c"], c_top=t["c_top"],
                 ends=t["ends"])
