"""Why a pull or a cycle has no path to follow: the one wording pull_off, cycle and the kinetics print."""
from __future__ import annotations

import numpy as np

from ..model import full_contact as _full
from ..model.problem import Problem
from ..model.single_patch import solver
from ..units import CONTROLS
from . import branches as _br
from . import forward as _fw


def unmodelled(pb: Problem) -> str:
    """Why no path can be followed on this problem's branch ('' when it can; the single-patch solver knows)."""
    return solver(pb).unmodelled


def no_first_contact_reason(pb: Problem, control: str = "load") -> str:
    """Why first contact snaps into no state: the reason pull_off and cycle print."""
    why = "no stable, feasible state at first contact"
    if not pb.models("two-patch"):      # e.g. the cohesive law: one patch, traced on its sub-critical branch
        return why + (_single_patch_only(pb) if control == "load" else "") + (
            f" (on the branches modelled for the {pb.edge.name} law: two patches are not)")
    return why


def bond_breaks(pb: Problem, un, s, control: str, value: float) -> str:
    """Why a zip finds no state to land on where the law's bonded pin cannot hold at the held value (the full-
    contact state there infeasible: its load past the bond limit) and no stable contact on the zipping one's side,
    nor a larger one, takes the jump: where the bond then breaks is not modelled (no reason printed before:
    E 47.9 GPa, nu 0.302 round E_I 12.2 GPa, nu_I 0.395, lambda 2, M 0.730, grip to -1.95 Delta)."""
    full = _fw.full_contact_state(pb, un, CONTROLS[control].normalised, un.normalise(control, value), control)
    if full is None or full.feasible:
        return ""
    limit = un.physical("load", _full.bond_limit(pb, full.P_star))
    return (f"the pin drawn round from the {s.branch} contact would need P = {full.P:.6g} N/m in full contact, past "
            f"the bond limit {limit:.6g} N/m, and no stable state on its side or larger takes the jump: where the "
            "bond breaks as it zips is not modelled")


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


def gap_stop(pb: Problem, s) -> str:
    """Why the walk stopped at the feasible state s next to an infeasible table point ('gap'): the reason
    pull_off prints.  JKR's only gap condition is h(pi) >= 0 (derive/gap.py: the gap's minimum is min(0, h(pi))),
    so there the top closes; a law with more (the cohesive one: h >= 0 everywhere outside the contact, h <= h0 on
    its zone) can fail beside the contact with the top still open (h(pi) > h0 at the infeasible neighbour; below h0
    the top adheres: jkrcyl.analysis.landing.top_onset)."""
    where = f"P = {s.P:.6g} N/m, delta = {s.delta:.4g} m"
    t = _br.table(pb, s.branch.replace("-top", ""))
    a, feasible, h = np.asarray(t.a), np.asarray(t.feasible), np.asarray(t.h_pi_over_Delta)
    i = int(np.argmin(np.abs(a - s.a)))
    h0 = pb.edge.range_over_Delta(pb.m)      # the top adheres where h(pi) falls below the range (JKR: 0)
    beside = [k for k in (i - 1, i + 1) if 0 <= k < a.size and not feasible[k] and h[k] > h0 * (1 + 1e-9)]
    if not beside:
        top = "the gap at phi = pi closes first" if h0 == 0 else \
            f"the top of the hole comes within the law's range first (h(pi) = h0 = {h0:.4g} Delta: it adheres)"
        return f"confined: {top} ({where}); the top contact forms before detachment (see Contact.confined_events)"
    return (f"no detachment on one patch: beyond this state ({where}) the gap outside the contact closes beside it "
            f"with the top still open (h(pi) = {h[beside[0]]:.4g} Delta): the {pb.edge.name} law's pull there "
            "draws the surfaces into a second contact, which is not modelled")
