"""The single-patch solver of a problem: its edge law's (jkrcyl.model.edge.Edge.single_patch), cached.

A solver gives, at contact parameters a of one bottom patch at its edge condition, a
:class:`~jkrcyl.model.patch.Slice` in the kernel scale (p = P beta*/(4 pi Delta), lengths over Delta):

    p, dn = delta/Delta (5.8), dw = delta_work/Delta (derive/green.py), h = h(pi)/Delta (5.10),
    their slopes along the equilibrium dp_da, ddn_da, ddw_da (analytic, or per point: never a difference
    across grid points, which can straddle a pole of the unit cases),
    p_k, dn_k: the fixed-arc derivatives dp/dk, d(delta/Delta)/dk with respect to the edge coefficient k of
    nu ~ -k/sqrt(eps - |phi|) (jkrcyl.model.stability turns them into the stability flags),

and the pole a_crit (the receding contact: adhesionless P -> inf), for every pair, rigid bodies included.
JKR's Griffith edge (jkrcyl.laws.griffith) has the paper's closed forms where alpha* = 0 and the collocation of
the bordered arc otherwise; the Maugis-Dugdale law (jkrcyl.laws.dugdale) its traced branches.
"""
from __future__ import annotations

import functools

from .patch import FIELDS, SLOPE_OF, SinglePatch, Slice  # noqa: F401  (the interface's names)
from .problem import Problem


@functools.lru_cache(maxsize=64)
def solver(problem: Problem) -> SinglePatch:
    """The single-patch solver of a problem (cached: a_crit and the branch tables are computed once)."""
    return problem.edge.single_patch(problem)


def resolution(materials):
    """(noise, a_max) of the single-patch solver of a material pair: the relative rounding of its states and the
    largest contact parameter it resolves (for callers that tune differences or tables to the solver)."""
    sv = solver(Problem.of_materials(materials))
    return sv.noise, sv.a_max
