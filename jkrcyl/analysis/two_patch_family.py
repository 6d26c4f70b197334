"""The two-patch family of a problem, reached through its edge law: the law names its family
(jkrcyl.model.edge.Edge.two_patch_family), :data:`REGISTRY` maps the name to the class, and every analysis
(jkrcyl.equilibria.two_patch, Contact.two_patch, solve's 'two-patch' branch) asks :func:`family`.

A family has ``branches(n)`` (tuple of jkrcyl.results.TwoPatchCurve), ``state(eps, eps_top, guess)``
(jkrcyl.results.TwoPatchState), ``states_at(key, target)`` (the states where P_star, delta_over_Delta or
delta_work_over_Delta equals target), ``flags(state)`` ((stable_load, stable_grip, stable_grip_work)) and
``potential(state)`` (the total potential in the kernel scale, units 4 pi Delta^2/beta*).
"""
from __future__ import annotations

import functools

from ..model import two_patch as _two
from ..model.problem import Problem
from . import tracing as _tr
from . import cohesive_two_patch as _cohesive


class JKRTwoPatch:
    """JKR's two-patch family: jkrcyl.analysis.tracing (branches, states at a load) and jkrcyl.model.two_patch
    (a state at a half-angle, the second variation)."""

    def __init__(self, pb: Problem):
        self.pb = _two.require_two_patch(pb)

    def branches(self, n=None) -> tuple:
        return _tr.branches(self.pb, n)

    def state(self, eps=None, eps_top=None, guess=None):
        return _two.solve(self.pb, eps_top=eps_top, eps=eps, guess=guess)

    def states_at(self, key: str, target: float) -> list:
        return _tr.states_at(self.pb, key, target) if _tr.onset_angles(self.pb) else []

    def flags(self, s):
        return _two.stability(self.pb, s.eps, s.eps_top, s.delta_over_Delta, lin=s._lin)

    def potential(self, s) -> float:
        return self.pb.scale * s.energy - 2 * self.pb.m ** 2 * (s.eps + s.eps_top)


#: the two-patch families by the name a law gives (Edge.two_patch_family): each a callable of the problem
REGISTRY = {"JKRTwoPatch": JKRTwoPatch, "CohesiveTwoPatch": _cohesive.of}


@functools.lru_cache(maxsize=32)
def family(pb: Problem, what: str = "two-patch states are", param: str = ""):
    """The two-patch family of the problem's edge law (cached per problem); ValueError naming the law's parameter
    where its two-patch branches are not modelled, theta where vartheta = inf."""
    pb.require("two-patch-branches", what, param)
    name = pb.edge.two_patch_family
    if name not in REGISTRY:        # a law of one's own that models two patches without saying by which family
        raise ValueError(f"{pb.edge.param}: the {pb.edge.name} law models two patches but names the two-patch "
                         f"family {name!r}, not one of {sorted(REGISTRY)} (jkrcyl.analysis.two_patch_family)")
    return REGISTRY[name](pb)
