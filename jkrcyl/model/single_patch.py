"""The single-patch solvers: one interface, two implementations, and the only place that knows whether a pair
has a closed form.

:func:`solver` returns, for a :class:`~jkrcyl.model.problem.Problem`, the :class:`ClosedForm` solver (the
paper's kernels, alpha* = 0) or the :class:`Collocation` solver (the bordered arc of numerics.one_arc, any
alpha*).  Both give, at contact parameters a = tan(eps/2) of one bottom patch at its edge condition, a
:class:`Slice` in the kernel scale (p = P beta*/(4 pi Delta), lengths over Delta):

    p, dn = delta/Delta (5.8), dw = delta_work/Delta (derive/green.py), h = h(pi)/Delta (5.10),
    their slopes along the equilibrium dp_da, ddn_da, ddw_da (analytic, or per point: never a difference
    across grid points, which can straddle a pole of the unit cases),
    p_k, dn_k: the fixed-arc derivatives dp/dk, d(delta/Delta)/dk with respect to the edge coefficient k of
    nu ~ -k/sqrt(eps - |phi|) (jkrcyl.model.stability turns them into the stability flags),

and the pole a_crit (the receding contact: adhesionless P -> inf), for every pair, rigid bodies included.
The edge law decides first: a Dugdale law gets :class:`Cohesive` (jkrcyl.model.cohesive: the Maugis-Dugdale
branches, a the branch parameter, the Slice carrying eps, the zone end c and the total potential).
"""
from __future__ import annotations

import functools

from ..materials import ALPHA_TOLERANCE
from .closed_form import ClosedForm, ClosedFormPhysical
from .cohesive import Cohesive
from .collocation import Collocation, CollocationPhysical
from .patch import FIELDS, SLOPE_OF, SinglePatch, Slice  # noqa: F401  (the interface's names)
from .problem import Dugdale, Problem


def closed_form(alpha_ratio: float) -> bool:
    """Whether the paper's closed forms hold: alpha* = 0 (|alpha*/beta*| <= ALPHA_TOLERANCE, section 2)."""
    return abs(alpha_ratio) <= ALPHA_TOLERANCE


@functools.lru_cache(maxsize=64)
def solver(problem: Problem) -> SinglePatch:
    """The single-patch solver of a problem (cached: a_crit and the branch tables are computed once): the
    Maugis-Dugdale branches for a Dugdale edge law (any pair), else the closed forms where alpha* = 0."""
    if isinstance(problem.edge, Dugdale):
        return Cohesive(problem)
    return ClosedForm(problem) if closed_form(problem.alpha_ratio) else Collocation(problem)


def resolution(materials):
    """(noise, a_max) of the single-patch solver of a material pair: the relative rounding of its states and the
    largest contact parameter it resolves (for callers that tune differences or tables to the solver)."""
    sv = solver(Problem.of_materials(materials))
    return sv.noise, sv.a_max


@functools.lru_cache(maxsize=64)
def physical(contact, method="auto"):
    """The dimensional single-patch solver of a jkrcyl.Contact (any clearance, Delta = 0 included): states,
    pressure and gap in physical units, closed form where alpha* = 0 (method 'auto'), the collocation solver
    always with method 'numeric'."""
    closed = method == "closed-form" or (method == "auto" and closed_form(contact.materials.alpha_ratio))
    return (ClosedFormPhysical if closed else CollocationPhysical)(contact)
