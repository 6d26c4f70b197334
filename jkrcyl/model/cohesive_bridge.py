"""The top bridge of the Maugis-Dugdale law in the model core: its families, their states, slopes and stability.

Kernel scale and notation of jkrcyl.numerics.cohesive (p = P beta*/(4 pi Delta), lengths over Delta, zones
|phi| < c at the bottom and |phi - pi| < c_top at the top, h0 = m^2/s0).  Where the single patch's gap has a local
minimum at the top and falls to the range, h(pi) = h0 (a *junction*), a zone at the top forms, held by its own
traction: the top bridge, one contact with its bottom zone and the top zone (jkrcyl.numerics.cohesive_top_zone).
One family per junction on the sub- or the super-critical branch (each on its side of the receding limit: the
README's pin, identical bodies at M 0.33, has its junction past it, at eps 1.605), traced in c_top from 0 (the
junction, whose state is the single patch's) until

* the top closes (h(pi) = 0): there the law's two patches begin (the top contact forms under its zone, as
  eps_top^2); end 'top closes';
* or the contact vanishes first (the touch): the family goes on without contact, the pin held by zones at the
  bottom and the top (jkrcyl.numerics.cohesive_contactless.two_zone_trace), from the two-zone state touching the
  bottom to the one touching the top (its mirror); end 'top touches' -- beyond, the mirror of the bridge (contact at
  the top) runs back to the mirror junction;
* or the trace cannot follow it (end 'receding limit', 'zones meet', 'no root', 'points', ... -- said, never
  silent).

Every state is unstable (the barrier between one patch and two, vanishing at the junction): with contact the top
zone grows at a held approach (G_22 < 0, jkrcyl.numerics.cohesive_top_zone.flags); without contact the held
energy is a maximum under grip and a saddle under load.  The parameter of a family j (0, 1, ... in increasing
junction contact) is a = j + c_top/pi, increasing along it.
"""
from __future__ import annotations

import math
from collections import namedtuple

import numpy as np

from ..numerics import cohesive as _co
from ..numerics import cohesive_contactless as _cl
from ..numerics import cohesive_top_zone as _tz
from .single_patch import solver

TOP_BRIDGE = "top-bridge"
RATIO = 2.0               # c_top grows by this factor per traced bridge state (from CT_START = 1e-9)

Family = namedtuple("Family", ["junction", "states", "end", "n_contact"])
Family.__doc__ = """One top-bridge family (jkrcyl.numerics.cohesive.CohesiveState each): junction, the single-patch
state where h(pi) = h0 (c_top = 0, not among the states); states, in increasing c_top: n_contact with contact
(zones 'bottom+top'), then those without contact (the two-zone continuation past the touch; none where the trace
stopped at once); end, why it ends (:data:`ENDS`)."""

ENDS = {
    "top closes": "the top closes (h(pi) = 0): the two patches begin, the top contact forming under its zone",
    "top touches": "the contact vanished (touch) and the pin, held by zones at the bottom and the top, reaches "
                   "the top (h(pi) = 0): from there the mirror of the bridge (contact at the top)",
    "touch": "the contact vanishes (touch): its continuation without contact not found",
    "receding limit": "the contact reaches the receding limit (the pole of the load): not traced beyond",
    "near full contact": "the contact reaches pi - 0.05 (the super-critical single patch's end): not traced beyond",
    "zones meet": "the bottom and the top zones meet: not traced beyond",
}


def end_text(end: str, n_states: int = 1) -> str:
    """A family's end in words (ENDS; any other end: the trace stopped there, not followed); a family without
    states (its trace stopped at once) says so."""
    text = ENDS.get(end, f"the trace stopped ({end}): not followed beyond")
    return text if n_states else f"no state traced from the junction: {text}"


def require(problem) -> None:
    """ValueError naming regime where the problem has no top bridge: a law of zero range (JKR's top adheres where
    the gap closes, h(pi) = 0) or one whose single patch never reaches h(pi) = h0 with a gap minimum at the top;
    or where no family has a state traced (said, with why)."""
    h0 = problem.edge.range_over_Delta(problem.m)
    if h0 == 0:
        raise ValueError("regime: 'top-bridge' needs a law of finite range (the cohesive law: give sigma0 or "
                         "lambda): JKR's top adheres where the gap closes, h(pi) = 0, with no zone at the top held "
                         "by its own traction")
    fams = families_of(problem)
    if not fams:
        raise ValueError(f"regime: no top bridge for this problem: its single patch's gap at the top never falls to "
                         f"the range h0 = {h0:.6g} Delta with a local minimum there (no junction h(pi) = h0)")
    if not any(f.states for f in fams):
        raise ValueError("regime: the top bridge is not traced for this problem: from each junction (eps = " +
                         ", ".join(f"{f.junction.eps:.6g}" for f in fams) + f" rad) {end_text(fams[0].end, 0)}")


def families_of(problem):
    """The problem's top-bridge families (its single-patch solver's, traced once: jkrcyl.model.cohesive.Cohesive
    .top_bridges; () for a solver without them)."""
    return getattr(solver(problem), "top_bridges", ())


def trace(sv) -> tuple:
    """Every top-bridge family of the cohesive solver sv (jkrcyl.model.cohesive.Cohesive): junctions on its traced
    sub- and super-critical branches (jkrcyl.numerics.cohesive_top_zone.junctions; the super-critical one is traced
    for this), each traced on its side of the receding limit, and past a touch continued without contact.  c_top
    strictly increasing along each (a family whose c_top turns back ends there)."""
    law, out, starts = sv.law, [], []
    for br in (sv._sub,) + ((sv._super,) if sv.has("super-critical") else ()):
        if br.kind != "zone":
            continue
        eps = np.exp(br.x[:, 0])
        c = np.where(np.arange(len(eps)) < br.n_round, math.pi, eps + np.exp(br.x[:, 1]))
        starts += [st for st, _ in _tz.junctions(law, np.column_stack([eps, c]))]
    for start in starts:
        got = _tz.trace(law, start, ratio=RATIO)
        states, end = list(got.states) + ([got.onset] if got.onset is not None else []), got.end
        n_contact = len(states)
        if end == "touch" and states:
            touch = _cl.two_zone_touch(law, states[-1])
            if touch is not None:
                more, end = _cl.two_zone_trace(law, touch)
                states += more
        keep = np.concatenate([[True], np.diff([s.c_top for s in states]) > 0]) if states else []
        if not all(keep):                           # c_top turns back: the family's parameter ends there
            cut = int(np.argmin(keep))
            states, end, n_contact = states[:cut], "c_top turns back", min(n_contact, cut)
        out.append(Family(start, states, end, n_contact))       # none traced: kept, its end says why
    return tuple(out)


def _row(law, st, contact, work_shift):
    """(dp/da, d(delta/Delta)/da, stable under load, grip, grip-work) at one state (a = j + c_top/pi)."""
    if contact:
        dp, ddn, _ = _tz.slopes(law, st)
        f = _tz.flags(law, st, work_shift)
        return math.pi * dp, math.pi * ddn, f["load"], f["grip"], f["grip-work"]
    dp, ddn, dct = _cl.two_zone_slopes(law, st)
    definite = lambda G: bool(np.all(np.linalg.eigvalsh(0.5 * (G + G.T)) > 0))
    return (math.pi * dp / dct, math.pi * ddn / dct, False, definite(_cl.two_zone_matrix(law, st)),
            definite(_cl.two_zone_matrix(law, st, work_shift)))


def table(problem, sv) -> dict:
    """The families' states as arrays (kernel scale): a, eps, c, c_top, p, dn (delta/Delta), dw (delta_work/Delta),
    h (h(pi)/Delta), feasible (jkrcyl.numerics.cohesive.gap_check), stable_load/grip/grip-work, dp_da, ddn_da,
    ddw_da, family (j), and ends (one per family)."""
    law, cw = sv.law, problem.work_shift
    rows = []
    for j, fam in enumerate(sv.top_bridges):
        for i, st in enumerate(fam.states):
            dp, ddn, s_load, s_grip, s_gw = _row(law, st, i < fam.n_contact, cw)
            rows.append((j + st.c_top / math.pi, st.eps, st.c, st.c_top, st.p, st.delta_over_Delta,
                         st.delta_over_Delta + cw * st.p, st.h_pi_over_Delta, _co.gap_check(st).feasible, s_load,
                         s_grip, s_gw, dp, ddn, ddn + cw * dp, j))
    names = ("a", "eps", "c", "c_top", "p", "dn", "dw", "h", "feasible", "stable_load", "stable_grip",
             "stable_grip_work", "dp_da", "ddn_da", "ddw_da", "family")
    cols = {k: np.array(v) for k, v in zip(names, zip(*rows))}
    for k in ("feasible", "stable_load", "stable_grip", "stable_grip_work"):
        cols[k] = cols[k].astype(bool)
    cols["ends"] = tuple(end_text(f.end, len(f.states)) for f in sv.top_bridges)
    return cols


def states_of(sv):
    """Every family's states, in the order of :func:`table` (for energies: jkrcyl.numerics.cohesive_branch
    .potential)."""
    return [st for fam in sv.top_bridges for st in fam.states]
