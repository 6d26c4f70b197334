"""Forward problems: every equilibrium at a given load P [N/m] or approach [m].

``solve`` searches the branches of an explicit registry, :data:`BRANCH_SOLVERS`, each entry a function
``(problem, units, key, target, control) -> [Equilibrium]``:

* ``sub-critical``, ``super-critical``: the single bottom patch of sections 4-6 (a below or above a_crit);
* ``sub-critical-top``, ``super-critical-top``: the same patch at the top of the hole, the mirror image
  phi -> phi + pi: P -> -P, delta -> -2 Delta - delta (either approach);
* ``two-patch``: contact at the bottom and the top at once (jkrcyl.analysis.tracing), present when a single patch
  can close the gap at phi = pi (the confined regime, :func:`confined`);
* ``full-contact``: the pin bonded all round (no edge; stable where the bond holds, jkrcyl.model.full_contact
  .holds), confined regime only (any finite vartheta for a law without two patches, the cohesive one);
* ``separated``: the free pin (no contact, P = 0), for a given approach -2 Delta < delta < 0 only (within
  -2 Delta + h0 < delta < -h0 for a cohesive law of range h0);
* ``contactless``, ``contactless-top``: cohesive law only -- the pin without contact held by its zone at the
  bottom (top) of the hole (jkrcyl.model.cohesive), a saddle under load, stable under grip where the zone's
  opening grows with it.

With a cohesive (Maugis-Dugdale) edge law the single-patch branches (sub- and super-critical, contactless) are
the solver's (jkrcyl.model.cohesive), full contact is JKR's bonded pin where the tension stays below sigma0, and
the two-patch states are those of its traced branches (jkrcyl.analysis.cohesive_two_patch, alpha* = 0), found
when the user names the branch (Contact.solve(..., branches=['two-patch'])); a search of every branch leaves them
out, the walker landing on them only where the top closes (jkrcyl.analysis.landing.land, from the onset h(pi) = 0)
(a law without two-patch branches: a ValueError when asked by name).

Stability is that of the control (jkrcyl.units.CONTROLS): fixed load for P, fixed paper's approach for
delta ('grip'), fixed work-conjugate approach for delta_work ('grip-work').  Signs as in section 6: P and delta
are positive downward (pushing the pin into the bottom of the hole).
"""
from __future__ import annotations

import math
import warnings
from typing import Callable, Dict, List

import numpy as np

from ..model import full_contact as _full
from ..model import stability as _stab
from ..model.problem import Problem
from ..model.single_patch import solver
from ..notices import BranchLimitWarning
from ..results import Equilibrium, Point
from ..units import CONTROLS, Units
from . import branches as _br
from . import tracing as _tr
from .two_patch_family import family as _family


def _state(pb, un, branch, control, side, a, eps, P_star, dn, h, flags, U, a_top=0.0, eps_top=0.0, K=None,
           extra=None, total=None) -> Equilibrium:
    """U: the elastic energy in the kernel scale (units 4 pi Delta^2/beta*); the state's total potential is
    U - 2 m^2 (eps + eps_top) there (the work of adhesion over the contact length 2 R (eps + eps_top)), or
    ``total`` when the single-patch solver gives it (jkrcyl.model.patch.SinglePatch.potential)."""
    dw = dn + pb.work_shift * pb.scale * P_star
    energy = un.energy_scale * (U - 2 * pb.m ** 2 * (eps + eps_top) if total is None else total)
    return Equilibrium(branch=branch, control=control, a=a, eps=eps, contact_width=2 * un.R * (eps + eps_top),
                       P=un.physical("load", P_star), delta=un.physical("grip", dn),
                       delta_work=un.physical("grip-work", dw), h_pi=h * un.Delta,
                       K=un.K_edge if K is None else K, P_star=P_star, delta_over_Delta=dn,
                       delta_work_over_Delta=dw, feasible=bool(flags[0]), stable_load=bool(flags[1]),
                       stable_grip=bool(flags[2]), stable_grip_work=bool(flags[3]), side=side, a_top=a_top,
                       eps_top=eps_top, energy=energy, extra=extra or {})


def single_patch_states(pb: Problem, un: Units, regime: str, a, control: str, side="bottom") -> List[Equilibrium]:
    """Equilibria of one single-patch branch at contact parameters a (mirrored when side == 'top': the elastic
    energy is the same, [(1 + delta/Delta) P* - B*]/2 being invariant under the mirror)."""
    a = _br.on_branch(pb, regime, np.atleast_1d(np.asarray(a, dtype=float))) if np.size(a) else np.zeros(0)
    if a.size == 0:
        return []
    sv = solver(pb)
    s = sv.states(a)
    flags = _stab.single_patch_flags(s, pb.work_shift)
    total, eps, feasible = sv.potential(s), s.contact, s.gap_open
    sgn, name = (-1.0, regime + "-top") if side == "top" else (1.0, regime)
    out = []
    for i in range(a.size):
        P, d = sgn * float(s.p[i]) / pb.scale, float(s.dn[i])
        d = -2.0 - d if side == "top" else d
        fl = (feasible[i], flags["load"][i], flags["grip"][i], flags["grip-work"][i])
        extra = {} if s.c is None else {"c": float(s.c[i]), "c_top": float(s.c_top[i])}
        out.append(_state(pb, un, name, control, side, float(a[i]), float(eps[i]), P, d, float(s.h[i]), fl,
                          float(s.energy[i]), extra=extra, total=float(total[i])))
    return out


def stationary_points(pb: Problem, un: Units, control: str, regime: str, n=None) -> List[Point]:
    """Every state of a branch where the held quantity of ``control`` is stationary (folds: 'min' or 'max'),
    sorted by a (jkrcyl.analysis.branches.stationary_roots; n: a root grid of n points instead of the table)."""
    found = _br.stationary_roots(pb, control, regime, n)
    if not found:
        return []
    a = [r for r, _ in found]
    c = _br.values_at(pb, regime, a)
    return [Point.of(s, kind=kind, M=pb.M, theta=pb.theta, gb=pb.gb, alpha_ratio=pb.alpha_ratio,
                     eps_star=float(c.eps_star[i]), h_pi_over_Delta=float(c.h_pi_over_Delta[i]))
            for i, (s, (_, kind)) in enumerate(zip(single_patch_states(pb, un, regime, a, control), found))]


def _single(regime: str, side: str = "bottom"):
    def solver(pb: Problem, un: Units, key: str, target: float, control: str) -> List[Equilibrium]:
        if not _br.solver(pb).has(regime):
            return []
        if side == "top":                        # mirror: P* -> -P*, either approach -> -2 - itself
            target = -target if key == "P_star" else -2.0 - target
        field = CONTROLS[control].field
        t = target * (pb.scale if CONTROLS[control].is_load else 1.0)    # normalised -> kernel scale
        _warn_past_table(pb, un, regime, field, t, side)
        return single_patch_states(pb, un, regime, [r for r, _ in _br.roots(pb, regime, field, t)], control, side)
    solver.__doc__ = f"{regime} single patch at the {side} of the hole."
    return solver


def _warn_past_table(pb, un, regime, field, target, side):
    """BranchLimitWarning where the target lies beyond the held quantity's range on a branch's table, on the side
    of the table's last value, and the table stops short of the branch's end there (the solver's extent, e.g. the
    cohesive law's traced load cap); the closed forms' tables reach a_crit, where the load is unbounded."""
    values = _br.table_values(pb, regime, field)[1]
    if not values.size:
        return
    last = values[-1]
    beyond = (target > values.max() and last >= values.max()) or (target < values.min() and last <= values.min())
    if beyond and solver(pb).stops_short(regime):
        what, unit = ("P", un.per_kernel("load")) if field == "p" else ("the approach", un.Delta)
        sgn = -1.0 if side == "top" else 1.0
        end = sgn * last * unit
        warnings.warn(f"{what}: the {regime}{'-top' if side == 'top' else ''} branch of the {pb.edge.name} law is "
                      f"traced up to {what} = {end:.6g} (the solver's table: {solver(pb).stops_short(regime)}); "
                      "states beyond were not searched", BranchLimitWarning, stacklevel=5)


def confined(pb: Problem) -> bool:
    """True when some single-patch state closes the gap at phi = pi (h(pi) = 0 of (5.10)): two-patch states
    exist (M > 0).  False where two patches are not modelled (the cohesive law)."""
    return pb.models("two-patch") and bool(_tr.onset_angles(pb))


def two_patch_state(pb: Problem, un: Units, s, control) -> Equilibrium:
    """A jkrcyl.results.TwoPatchState as an Equilibrium (stability and total potential from the law's two-patch
    family: JKR's second variation, the cohesive law's zone-end-held energy)."""
    fam = _family(pb)
    return _state(pb, un, "two-patch", control, "both", s.a, s.eps, s.P_star, s.delta_over_Delta, 0.0,
                  (s.feasible, *fam.flags(s)), pb.scale * s.energy, a_top=s.a_top, eps_top=s.eps_top,
                  extra={"gap_min_over_Delta": s.gap_min, "G_bot": s.G_bot, "G_top": s.G_top},
                  total=fam.potential(s))


def _two_patch_solver(pb: Problem, un: Units, key: str, target: float, control: str) -> List[Equilibrium]:
    """The registry's two-patch branch, searched by the walker too: a law whose two patches it lands on (JKR)."""
    return two_patch_states(pb, un, key, target, control) if pb.models("two-patch") else []


def two_patch_states(pb: Problem, un: Units, key: str, target: float, control: str) -> List[Equilibrium]:
    """The states of the law's traced two-patch branches (any law with 'two-patch-branches'): the two-patch branch
    of a solve that names it (:func:`solve_normalised` with by_name)."""
    if not pb.models("two-patch-branches") or pb.M <= 0:
        return []
    try:
        states = _family(pb).states_at(key, target)
    except ValueError as why:          # the law's two-patch family refuses this problem (e.g. a small lambda)
        warnings.warn(f"two-patch states not searched: {why}", BranchLimitWarning, stacklevel=4)
        return []
    return [two_patch_state(pb, un, s, control) for s in states]


def full_contact_state(pb: Problem, un: Units, key: str, target: float, control: str):
    """The bonded pin (eps + eps_top = pi) at P*, delta/Delta or delta_work/Delta = target; None when the
    approach fixes no load."""
    try:
        fc = (_full.at_work(pb, target) if key == "delta_work_over_Delta"
              else _full.state(pb, **{key: target}))
    except ValueError:
        return None
    holds = _full.holds(pb, fc)
    return _state(pb, un, "full-contact", control, "both", math.inf, math.pi, fc.P_star, fc.delta_over_Delta, 0.0,
                  (holds,) * 4, pb.scale * fc.energy, a_top=math.inf, K=0.0,
                  extra={"tension_everywhere": fc.tension_everywhere})


def _full_contact_solver(pb: Problem, un: Units, key: str, target: float, control: str) -> List[Equilibrium]:
    # a law with two patches reaches full contact through them (the confined regime); one without (the cohesive
    # law) from its contact branches' ends and at first touch: the bonded pin (a rigid cradle: a compressible pin)
    if not (confined(pb) if pb.models("two-patch") else pb.models("full-contact")):
        return []
    s = full_contact_state(pb, un, key, target, control)
    return [] if s is None else [s]


def separated_state(pb: Problem, un: Units, delta_over_Delta: float, control: str) -> Equilibrium:
    """The free pin at approach delta (no contact, P = 0): stable under grip, neutral under load; its energy the
    solver's (a cohesive pin floating in a range all round: its zone's, else 0)."""
    return _state(pb, un, "separated", control, "none", 0.0, 0.0, 0.0, delta_over_Delta, 2 + delta_over_Delta,
                  (True, False, True, True), 0.0, K=0.0, total=solver(pb).free_potential(delta_over_Delta))


def _separated_solver(pb: Problem, un: Units, key: str, target: float, control: str) -> List[Equilibrium]:
    lo, hi = solver(pb).free_range()                     # (-2, 0), or within the cohesive range's reach
    if key == "P_star" or not lo < target < hi:          # P = 0: delta_work = delta
        return []
    return [separated_state(pb, un, target, control)]


BranchSolver = Callable[[Problem, Units, str, float, str], List[Equilibrium]]

#: The branches searched by :func:`solve`, in this order.
BRANCH_SOLVERS: Dict[str, BranchSolver] = {
    "sub-critical": _single("sub-critical"),
    "super-critical": _single("super-critical"),
    "sub-critical-top": _single("sub-critical", "top"),
    "super-critical-top": _single("super-critical", "top"),
    "contactless": _single("contactless"),
    "contactless-top": _single("contactless", "top"),
    "two-patch": _two_patch_solver,
    "full-contact": _full_contact_solver,
    "separated": _separated_solver,
}


def check_branches(branches, pb: Problem = None) -> list:
    """The branch names to search (None: all); naming two-patch or full-contact for an edge law that does not
    model them (the cohesive law) is a ValueError."""
    if branches is None:
        return list(BRANCH_SOLVERS)
    if isinstance(branches, str) or not hasattr(branches, "__iter__"):
        raise ValueError(f"branches must be a list of branch names ({', '.join(BRANCH_SOLVERS)}), got {branches!r}")
    names = list(branches)
    for b in names:
        if not isinstance(b, str) or b not in BRANCH_SOLVERS:
            raise ValueError(f"branches: unknown branch {b!r} (choose from {', '.join(BRANCH_SOLVERS)})")
    for prefix, family in (("two-patch", "two-patch-branches"), ("full-contact", "full-contact"),
                           ("super-critical", "super-critical")):
        if pb is not None and any(b.startswith(prefix) for b in names):
            pb.require(family, f"the {prefix} branch is")
    return names


def solve_normalised(pb: Problem, un: Units, control: str, target: float, branches=None,
                     by_name: bool = False) -> List[Equilibrium]:
    """Every equilibrium with the held quantity of ``control`` at the normalised target (P*, delta/Delta or
    delta_work/Delta), sorted by contact size then branch order.  by_name: the user named the branches (a law
    whose two-patch branches are traced but not landed on, the cohesive one, answers 'two-patch' only then)."""
    key = CONTROLS[control].normalised
    out = []
    for name in check_branches(branches):
        solver_of = two_patch_states if (by_name and name == "two-patch") else BRANCH_SOLVERS[name]
        out += solver_of(pb, un, key, target, control)
    order = {n: i for i, n in enumerate(BRANCH_SOLVERS)}
    return sorted(out, key=lambda s: (s.size, order[s.branch]))
