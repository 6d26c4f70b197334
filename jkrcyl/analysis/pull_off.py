"""Pull-off: the path from first contact down to where the contact lets go, or why it does not.

The free pin touches the bottom of the hole and snaps in (jkrcyl.analysis.landing.first_contact: the zero-load
contact (8.1) under load control, the contact at zero approach under grip); the walk then lowers the held
quantity (P, delta or delta_work) through stable, feasible states to

* a fold where a further pull opens the edge (the fixed-arc derivative of the held quantity with respect to the
  edge coefficient is negative: G > w, the contact shrinks away): detachment, with its P, width and approach;
* a fold where a further pull closes the edge (G < w): the contact grows round into full contact;
* h(pi) = 0: the gap at the top closes first (confined; Contact.confined_events says what follows);
* full contact at first touch (no zero-load contact): the pin is bonded all round and does not detach;
* a pin floating in a cohesive range that reaches round goes on onto contacts that push and, pulled, back to the
  touch: no adherence force from first contact (jkrcyl.analysis.path.pull_path's 'float').
"""
from __future__ import annotations

import math

from ..model import full_contact as _full
from ..model.problem import Problem
from ..model.single_patch import solver
from ..results import PullOff
from ..units import Units
from . import path as _path
from . import reasons as _reasons


def grows_under_pull(pb: Problem, a: float, control: str, towards: int = 0) -> bool:
    """At the single patch a: does lowering the held quantity at fixed arc lower the edge coefficient (G < w),
    so that the contact grows?  (dX/dk)|_a > 0 (jkrcyl.model.stability; the solver's rule for other edge laws)."""
    return solver(pb).grows_under_pull(a, control, towards)


def pull_off(pb: Problem, un: Units, control: str) -> PullOff:
    """Detachment along the quasi-static path (module docstring) under ``control``."""
    if pb.M == 0:
        return PullOff(control, None, None, None, None, "no adhesion (w = 0): the contact vanishes at P = 0")
    # a branch not followed whole (a cohesive top bridge) still answers where the pin floats onto it at first
    # touch: the path back from there does not reach the part not followed
    unmodelled = solver(pb).unmodelled
    if unmodelled and solver(pb).floats_onto() is None:
        return PullOff(control, None, None, None, None, unmodelled)
    start, event, s, towards = _path.pull_path(pb, un, control)
    if not solver(pb).adheres and not _path_answers(pb, event, s, control, towards):
        return PullOff(control, None, None, None, None, solver(pb).no_adherence_reason)
    if event == "none":
        why = _reasons.no_first_contact_reason(pb, control)
        return PullOff(control, None, None, None, None, why + ": no path to follow")
    if event == "bonded":
        return PullOff(control, None, None, None, start, _bonded_reason(pb, un))
    if event == "round":
        return PullOff(control, None, None, None, s, f"the contact grows round into full contact without a jump "
                       f"(its cohesive zone closes at the top at P = {s.P:.6g} N/m): the bonded pin, no detachment")
    if event == "elsewhere":
        return PullOff(control, None, None, None, start, f"first contact lands on the {start.branch} branch")
    if event == "float":
        held = {"load": "load", "grip": "approach", "grip-work": "work-conjugate approach"}[control]
        return PullOff(control, None, None, None, start,
                       "no adherence force from first contact: the pin touches the bottom onto contacts whose "
                       "cohesive zone reaches round the hole, which push (P >= 0); lowering the "
                       f"{held} the contact shrinks back to the touch and the pin leaves it (a contact that pulls "
                       "is reached by pushing further: Contact.cycle)")
    if unmodelled:
        return PullOff(control, None, None, None, None, unmodelled)
    if event == "let-go":
        return _detached(control, s)
    if event == "gap":
        return PullOff(control, None, None, None, s, _reasons.gap_stop(pb, s))
    if event == "end":
        what = "load" if control == "load" else "approach"
        return PullOff(control, None, None, None, s,
                       f"no fold: along the stable branch the {what} decreases without bound (the contact grows "
                       f"towards a_crit or the full circle), so the pin does not detach; last state a = {s.a:.6g}")
    if s.branch == "contactless":
        return _detached(control, s)
    if grows_under_pull(pb, s.a, control, towards):
        why = pb.not_modelled("full-contact", "the contact growing round (two patches, full contact) is")
        return PullOff(control, None, None, None, s,
                       f"fold at P = {s.P:.6g} N/m on the {s.branch} branch: a further pull lowers G, the contact "
                       "grows round into full contact (no detachment)" + (f" -- {why}" if why else ""))
    return PullOff(control, s.P, s.contact_width, s.delta, s, "detachment: the contact shrinks away (G > w)")


def _path_answers(pb: Problem, event: str, s, control: str, towards) -> bool:
    """Whether the path from first contact says what happens where no single-patch state pulls: a law whose
    single-patch states all push may still hold the pin -- drawn round into full contact at first touch (those
    that pull overlap the top), onto the other side's patch (a range longer than half the clearance) or floating
    onto a round zone -- or zipping round into full contact at a fold (JKR's answer too: under grip, lambda 10.8,
    M 1, the super-critical fold at P = 1.940 N/m, JKR's 1.941)."""
    return event in ("bonded", "elsewhere", "float", "round") or (
        event == "fold" and s.branch != "contactless" and grows_under_pull(pb, s.a, control, towards))


def _bonded_reason(pb: Problem, un: Units) -> str:
    """Why the bonded pin of first contact does not detach: JKR's bond holds at any load; a law of finite strength
    (the cohesive one) holds it down to its bond limit, where it opens at the bottom and the contact recedes onto
    the top of the hole (jkrcyl.model.full_contact.bond_limit; Contact.cycle follows it) -- the pin never lets go
    of the hole."""
    why = ("no stable zero-load contact (M above the largest M with one): at first touch the contact zips round "
           "into full contact")
    limit = _full.bond_limit(pb, -1.0)
    if math.isinf(limit):
        return why + ", and a pin bonded all round does not detach"
    if math.isnan(limit):     # (not met: first contact lands only on a feasible bonded pin)
        return why + ", where the law's bond does not hold even at zero load"
    P = un.physical("load", limit)
    return (why.replace("(M above the largest M with one)", "on one patch") +
            f"; the bond holds down to P = {P:.6g} N/m (the tension at the bottom reaches the law's strength), "
            "where it opens at the bottom and the contact recedes onto the top of the hole: the pin does not detach")


def _detached(control, s):
    """Detachment where a branch ends on an unstable continuation (the cohesive contact at its touch end, s the
    touching zone-only state: under load the zone-only states hold less) or where the zone-only pin lets go."""
    where = ("the contact vanishes at its touch end (the zone-only states beyond are unstable)"
             if s.a == 1.0 else "the zone-only pin lets go")
    return PullOff(control, s.P, s.contact_width, s.delta, s, f"detachment: {where}")
