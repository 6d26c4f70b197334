"""Why a pull or a cycle has no path to follow: the one wording pull_off, cycle and the kinetics print."""
from __future__ import annotations

from ..model.problem import Problem
from ..model.single_patch import solver
from . import branches as _br


def unmodelled(pb: Problem) -> str:
    """Why no path can be followed on this problem's branch ('' when it can; the single-patch solver knows)."""
    return solver(pb).unmodelled


def no_first_contact_reason(pb: Problem, control: str = "load") -> str:
    """Why first contact snaps into no state: the reason pull_off and cycle print."""
    why = "no stable, feasible state at first contact"
    if not pb.models("two-patch"):      # e.g. the cohesive law: one patch, traced on its sub-critical branch
        return why + (_single_patch_only(pb) if control == "load" else "") + (
            f" (on the branches modelled for the {pb.edge.name} law: two patches are not)")
    if pb.rigid_cradle:      # full contact and two patches need a finite vartheta (model.full_contact)
        why += (" (a rigid cradle, vartheta = inf: a pin that zips round into full contact at first touch is not "
                "modelled, full contact and two patches needing a finite vartheta)")
    return why


def _single_patch_only(pb: Problem) -> str:
    """What a law with one patch only misses at first contact under load: its zero-load states overlap the top
    (h(pi) < 0, where JKR's pin forms a second patch), or it has none (M above the largest M with one, where
    JKR's pin zips round into full contact); '' otherwise -- each with the law's own message (Edge.require)."""
    sv = solver(pb)
    h = [sv.value("h", a) for regime in sv.regimes() if regime != _br.ZONE_ONLY for a, _ in _br.roots(pb, regime, "p")]
    if any(x < 0 for x in h):
        return (f": the zero-load contact overlaps the top of the hole (h(pi) = {min(h):.6g} Delta < 0), where "
                "a second patch forms -- " + pb.not_modelled("two-patch", "a contact at the bottom and the top "
                                                                          "(two patches) is"))
    if not h:             # reached only where the bond does not hold at P = 0 (a law of finite strength)
        return (": no zero-load contact on one patch (M above the largest M with one: the pin zips round at first "
                "touch)" + (" -- " + pb.not_modelled("full-contact", "the pin bonded all round (full contact) is")
                            if not pb.models("full-contact") else ", and the bond does not hold there"))
    return ""
