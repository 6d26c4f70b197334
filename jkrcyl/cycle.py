"""Quasi-static load cycles: the path an experiment follows, its jumps and the energy it dissipates (issue 11).

``Contact.cycle(P_max=..., P_min=..., control="load")`` (or ``delta_max=, delta_min=`` with ``control="grip-work"``, the
work-conjugate approach held by a testing machine, or ``control="grip"``, the paper's approach (5.8)) starts at
first contact -- the free pin touching the bottom of the hole (P = 0, delta = 0) snaps in to the stable
zero-load contact (8.1) (to the stable contact at delta = 0 under grip) -- drives the load (approach) up to the
maximum, down to the minimum and up again, following the stable, feasible branch, and jumps where it ends:

* ``pull-off``: a sub-critical fold (minimum of P under load, of delta under grip): the contact shrinks
  away; under load the pin lands on the top of the hole (mirrored single patch at the same P), under grip
  it hangs free (P = 0) until it touches the other side;
* ``snap-in``: the free pin touches a side (delta = 0 or -2 Delta) and the contact jumps open;
* ``zip``: a super-critical fold: a further pull lowers G, the contact grows (two patches, full contact);
* ``top-contact``: the gap at phi = pi closes (h(pi) = 0): the next stable state at the same load/approach.

Jumps happen at fixed load (control='load') or fixed approach (control='grip', 'grip-work').  The energy dissipated per
cycle is the area of the closed steady loop, the work of the load around it, int P d(delta) [J/m]
(a closed loop has the same area in delta and in delta + c P, so the rigid-body term of (5.2) does not matter).
Along branches the integral is done by Gauss-Legendre in the contact parameter; a jump is a straight segment in
the P-delta plane (fixed P, fixed delta, or fixed delta + c P), so the trapezoid rule is exact on it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import List, Optional

import numpy as np

from . import forward as fw
from ._validate import count, finite_scalar

MAX_REPEATS = 3          # cycles driven until the loop closes (the state at the top of the cycle repeats)
GAUSS_NODES = 8
GAUSS_PANELS = 48


@dataclass(frozen=True, repr=False)
class Jump:
    """A jump of the quasi-static path at fixed load (load control) or fixed approach (grip control).

    Attributes
    ----------
    kind : str
        'snap-in', 'pull-off', 'zip' or 'top-contact' (see the module docstring).
    leg : int
        The leg of the path on which it happens (0: first loading, then alternately down and up).
    before, after : jkrcyl.forward.Equilibrium
        The states it joins (same P under load control, same delta under grip control).
    """

    kind: str
    leg: int
    before: fw.Equilibrium
    after: fw.Equilibrium

    def __repr__(self) -> str:
        return (f"Jump({self.kind}: P {self.before.P:.6g} -> {self.after.P:.6g} N/m, delta {self.before.delta:.4g}"
                f" -> {self.after.delta:.4g} m, {self.before.branch} -> {self.after.branch})")


@dataclass(frozen=True, repr=False)
class Cycle:
    """A quasi-static cycle.

    Attributes
    ----------
    control : str
        'load', 'grip' or 'grip-work' (jkrcyl.forward.CONTROLS).
    P, delta : ndarray
        The path in the load-approach plane [N/m], [m] (jumps are straight segments between two points); delta is
        the paper's approach (5.8), held under control='grip'.
    delta_work : ndarray
        The work-conjugate approach delta + P/(8 pi G_I) [m] (Contact.approach_work, derive/green.py) along the
        path, held under control='grip-work': the P-delta_work plane is where the loop area is the energy
        dissipated and the slope a stiffness.
    branch, a, stable : ndarray
        Branch name, contact parameter and stability (under the control) at each path point.
    leg : ndarray of int
        0: first loading from first contact, then alternately down and up.
    jumps : list of Jump
    dissipated : float or None
        Energy dissipated per cycle [J/m]: area of the closed steady loop (None if it did not close).
    closed_from_leg : int or None
        First leg of the steady loop (its two legs are the loop).
    note : str
        Why the path stopped early, if it did.
    """

    control: str
    P: np.ndarray
    delta: np.ndarray
    branch: np.ndarray
    a: np.ndarray
    stable: np.ndarray
    leg: np.ndarray
    jumps: List[Jump]
    dissipated: Optional[float]
    closed_from_leg: Optional[int]
    delta_work: np.ndarray = None
    note: str = ""

    def __repr__(self) -> str:
        e = "n/a" if self.dissipated is None else f"{self.dissipated:.6g} J/m"
        return f"Cycle({self.control}: {len(self.P)} points, {len(self.jumps)} jumps, dissipated {e})"

    def table(self) -> dict:
        """Columns for CSV output (physical units)."""
        return {"leg": self.leg, "branch": self.branch, "a": self.a, "P": self.P, "delta": self.delta,
                "delta_work": self.delta_work, "stable": self.stable}


# --- tracks: the branches as dense polylines --------------------------------------------------------------
class _Track:
    """A single-patch branch (bottom or top) on the dense grid of jkrcyl.forward, in physical units."""

    def __init__(self, pb, regime, side, control):
        c = fw.branch_curve(pb.key, regime)
        ct = pb.contact
        sgn = -1.0 if side == "top" else 1.0
        self.pb, self.regime, self.side, self.control = pb, regime, side, control
        self.name = regime + ("-top" if side == "top" else "")
        self.a = np.asarray(c.a)
        self.P = sgn * np.asarray(c.P_star) * ct.load_scale
        d = np.asarray(c.delta_over_Delta) * ct.Delta
        self.delta = -2 * ct.Delta - d if side == "top" else d
        self.delta_work = ct.approach_work(self.P, self.delta)
        self.stable = fw._stability(c, regime, pb.M)[control]
        self.feasible = np.asarray(c.feasible)

    def y(self):
        return getattr(self, fw.CONTROLS[self.control][3])

    def state_at(self, a):
        return fw.single_patch_states(self.pb, self.regime, a, self.control, self.side)[0]

    def exact(self, lo, hi, target):
        """The state between grid points lo, hi where the driven quantity equals target."""
        ct = self.pb.contact
        sgn = -1.0 if self.side == "top" else 1.0
        key = fw.CONTROLS[self.control][0]
        if self.control == "load":
            t = sgn * target / ct.load_scale
        else:                        # the mirror maps either approach to -2 Delta minus itself
            t = (-2 - target / ct.Delta) if self.side == "top" else target / ct.Delta
        f = lambda x: float(getattr(fw._curve(self.pb, self.regime, x), key)[0]) - t
        x0, x1 = float(self.a[lo]), float(self.a[hi])
        return self.state_at(fw._refine(f, min(x0, x1), max(x0, x1)) if f(x0) * f(x1) < 0 else x1)

    def fold(self, j):
        return self.state_at(fw._fold(self.pb, self.regime, j, self.control))

    def index(self, a):
        return int(np.argmin(np.abs(np.log(self.a) - math.log(a))))


def _walk(track, i, target):
    """From index i towards target (the driven quantity): (indices passed, event, end state)."""
    y, stable, feas = track.y(), track.stable, track.feasible
    up = target > y[i]
    sgn = 1 if up else -1
    nxt = [k for k in (i - 1, i + 1) if 0 <= k < y.size and sgn * (y[k] - y[i]) > 0 and stable[k] and feas[k]]
    if sgn * (target - y[i]) <= 0:
        return [i], "target", track.state_at(track.a[i])
    if not nxt:
        return [i], "fold", track.fold(i)
    step = nxt[0] - i
    j, path = i, [i]
    while 0 <= j + step < y.size:
        k = j + step
        if sgn * (y[k] - target) >= 0:
            return path, "target", track.exact(j, k, target)
        if not feas[k]:
            return path, "gap", track.state_at(track.a[j])
        if not stable[k] or sgn * (y[k] - y[j]) <= 0:
            return path, "fold", track.fold(j)
        j = k
        path.append(j)
    return path, "end", track.state_at(track.a[j])


# --- choosing where a jump lands ------------------------------------------------------------------------
def _other(side):
    return {"bottom": "top", "top": "bottom"}.get(side, side)


def _land(pb, s, event, control, value, up):
    """The state a jump from s lands on, at the same load / approach ``value``, and the jump's kind."""
    kw = {fw.CONTROLS[control][3]: value}
    # two-patch states are traced by continuation (seconds): only where the contact grows or the top closes
    quick = event == "touch" or (event == "fold" and s.branch.startswith("sub-critical"))
    names = [b for b in fw.BRANCH_SOLVERS if not (quick and b == "two-patch")]
    cands = [x for x in fw.solve(pb.contact, branches=names, **kw) if x.stable and x.feasible
             and not (x.branch == s.branch and abs(x.a - s.a) <= 1e-6 * max(s.a, 1e-300))]
    if s.branch == "separated":                          # free pin touching a side: snap-in there
        side = "bottom" if value >= -pb.contact.Delta else "top"
        if control == "load":
            side = "bottom" if up else "top"
        on = [x for x in cands if x.side == side] or [x for x in cands if x.side == "both"]
        return (min(on, key=lambda x: x.size), "snap-in") if on else (None, "snap-in")
    if event == "fold" and s.branch.startswith("sub-critical"):
        same = [x for x in cands if x.side == s.side and x.size < s.size]
        if same:
            return max(same, key=lambda x: x.size), "pull-off"
        if control != "load":
            sep = [x for x in cands if x.branch == "separated"]
            if sep:
                return sep[0], "pull-off"
        other = [x for x in cands if x.side == _other(s.side)]
        return (min(other, key=lambda x: x.size), "pull-off") if other else (None, "pull-off")
    if event == "fold":
        grow = [x for x in cands if x.size > s.size and x.side in (s.side, "both")]
        return (min(grow, key=lambda x: x.size), "zip") if grow else (None, "zip")
    key = (lambda x: abs(x.delta - s.delta)) if control == "load" else (lambda x: abs(x.P - s.P))
    pool = [x for x in cands if x.side in ("both", _other(s.side))] or cands
    return (min(pool, key=key), "top-contact") if pool else (None, "top-contact")


# --- the path ---------------------------------------------------------------------------------------------
class _Path:
    def __init__(self, pb, control):
        self.pb, self.control = pb, control
        self.pts = []          # (P, delta, branch, a, stable, leg)
        self.jumps = []
        self.tracks = {}

    def track(self, s):
        if s.branch not in self.tracks:
            regime = s.branch.replace("-top", "")
            self.tracks[s.branch] = _Track(self.pb, regime, "top" if s.branch.endswith("-top") else "bottom",
                                           self.control)
        return self.tracks[s.branch]

    def add(self, s, leg):
        self.pts.append((s.P, s.delta, s.branch, s.a, s.stable, leg))

    def leg(self, s, target, leg):
        """Drive from state s to target; returns the end state or (None, note)."""
        held = fw.CONTROLS[self.control][3]
        up = target > getattr(s, held)
        self.add(s, leg)                                  # the leg starts where the last one ended
        for _ in range(20):                              # at most 20 jumps per leg
            s, event = self._follow(s, target, leg)
            if event == "target":
                return s, ""
            value = getattr(s, held)
            if s.branch == "separated" and self.control != "load":
                value = 0.0 if up else -2 * self.pb.contact.Delta
                s = fw.separated_state(self.pb, value / self.pb.contact.Delta, self.control)
                self.add(s, leg)
            to, kind = _land(self.pb, s, event, self.control, value, up)
            if to is None:
                return None, f"leg {leg}: no stable state to jump to after the {kind} at {s!r}"
            self.jumps.append(Jump(kind, leg, s, to))
            s = to
            self.add(s, leg)
        return None, f"leg {leg}: more than 20 jumps"

    def _follow(self, s, target, leg):
        """Move along the current branch; returns (state, event)."""
        ctl = self.control
        if s.branch == "full-contact":
            t = target / (self.pb.load_scale if ctl == "load" else self.pb.contact.Delta)
            e = fw.full_contact_state(self.pb, fw.CONTROLS[ctl][0], t, ctl)
            self.add(e, leg)
            return e, "target"
        if s.branch == "separated":
            if ctl != "load" and -2 * self.pb.contact.Delta < target < 0:
                e = fw.separated_state(self.pb, target / self.pb.contact.Delta, ctl)
                self.add(e, leg)
                return e, "target"
            return s, "touch"
        if s.branch == "two-patch":
            return self._follow_two_patch(s, target, leg)
        tr = self.track(s)
        path, event, end = _walk(tr, tr.index(s.a), target)
        for k in path[1:]:
            self.pts.append((tr.P[k], tr.delta[k], tr.name, tr.a[k], True, leg))
        self.add(end, leg)
        return end, event

    def _follow_two_patch(self, s, target, leg):
        """On a traced two-patch branch: polyline walk (states linearly interpolated at the target)."""
        ct, ctl = self.pb.contact, self.control
        best = None
        for b in fw.two_patch_branches(self.pb.key):
            d = np.hypot(b.eps - s.eps, b.eps_top - s.eps_top)
            if best is None or d.min() < best[0]:
                best = (d.min(), b, int(np.argmin(d)))
        _, b, i = best
        key, _, stab, _ = fw.CONTROLS[ctl]
        y = fw._value(self.pb, b, key) * (ct.load_scale if ctl == "load" else ct.Delta)
        stable = getattr(b, stab)
        sgn = 1 if target > y[i] else -1
        step = next((k - i for k in (i - 1, i + 1) if 0 <= k < y.size and sgn * (y[k] - y[i]) > 0), None)
        if step is None:
            return s, "fold"
        j = i
        while 0 <= j + step < y.size:
            k = j + step
            if sgn * (y[k] - target) >= 0:
                e = self._two_patch_at(b, j, k, y, target)
                self.add(e, leg)
                return e, "target"
            if not stable[k] or not b.feasible[k] or sgn * (y[k] - y[j]) <= 0:
                e = fw._two_patch_state(self.pb, float(b.eps[j]), float(b.eps_top[j]), ctl)
                self.add(e, leg)
                return e, "fold"
            j = k
            self.pts.append((b.P_star[j] * ct.load_scale, b.delta_over_Delta[j] * ct.Delta, "two-patch", b.a[j],
                             True, leg))
        e = fw._two_patch_state(self.pb, float(b.eps[j]), float(b.eps_top[j]), ctl)
        return e, "fold"

    def _two_patch_at(self, b, j, k, y, target):
        t = (target - y[j]) / (y[k] - y[j])
        eps = float(b.eps[j] + t * (b.eps[k] - b.eps[j]))
        eps_top = float(b.eps_top[j] + t * (b.eps_top[k] - b.eps_top[j]))
        return fw._two_patch_state(self.pb, eps, eps_top, self.control)


def _same(s1, s2, rel=1e-6):
    return s1.branch == s2.branch and abs(s1.a - s2.a) <= rel * max(abs(s1.a), 1e-300) + 1e-12 and \
        abs(s1.P - s2.P) <= rel * max(abs(s1.P), 1e-300) + 1e-300


def cycle(contact, P_max: Optional[float] = None, P_min: Optional[float] = None, control: str = "load",
          n: int = 2000, delta_max: Optional[float] = None, delta_min: Optional[float] = None) -> Cycle:
    """Quasi-static cycle from first contact up to the maximum, down to the minimum and up again.

    First contact is the free pin touching the bottom of the hole (P = 0, delta = 0), which snaps in to the stable
    zero-load contact (8.1) (under grip: the stable contact at delta = 0).

    Parameters
    ----------
    contact : jkrcyl.Contact
        Needs Delta > 0.
    P_max, P_min : float
        Load limits [N/m] (control='load'), P_min < P_max; positive pushes the pin into the hole (section 6).
    control : {'load', 'grip', 'grip-work'}
        What is driven; jumps happen at fixed load or fixed approach ('grip': the paper's delta (5.8);
        'grip-work': the work-conjugate delta_work = delta + P/(8 pi G_I), a testing machine holding the pin).
    n : int
        Points of the returned path at most, 10 <= n <= 1e6 (the path is thinned evenly; jumps and turning points
        kept).
    delta_max, delta_min : float
        Limits [m] of the held approach (delta for control='grip', delta_work for 'grip-work'), delta_min < delta_max.

    Returns
    -------
    Cycle
        The path, every jump (kind, before, after) and the energy dissipated per cycle [J/m] (the loop area
        int P d(delta); None if the loop did not close).

    Raises
    ------
    ValueError
        Naming the parameter: a missing or reversed limit pair, ``control``, ``n``, or Delta = 0.
    """
    fw.check_control(control)
    contact._require_clearance("cycle")
    n = count("n", n, low=10)
    if control == "load":
        if P_max is None or P_min is None:
            raise ValueError("P_max: control='load' needs P_max and P_min [N/m]")
        hi, lo = finite_scalar("P_max", P_max), finite_scalar("P_min", P_min)
        if not lo < hi:
            raise ValueError(f"P_min must be < P_max, got P_min = {lo:g}, P_max = {hi:g}")
    else:
        if delta_max is None or delta_min is None:
            raise ValueError(f"delta_max: control={control!r} needs delta_max and delta_min [m]")
        hi, lo = finite_scalar("delta_max", delta_max), finite_scalar("delta_min", delta_min)
        if not lo < hi:
            raise ValueError(f"delta_min must be < delta_max, got delta_min = {lo:g}, delta_max = {hi:g}")
    pb = fw.Problem.of(contact)
    path = _Path(pb, control)
    s = fw.separated_state(pb, 0.0, control)          # first contact: the free pin touches the bottom
    path.add(s, 0)
    to, kind = _land(pb, s, "touch", control, 0.0, True)
    note = ""
    if to is None:
        return _finish(path, contact, n, None, "no stable contact at first touch")
    path.jumps.append(Jump("snap-in", 0, s, to))
    s = to
    path.add(s, 0)
    s, note = path.leg(s, hi, 0)
    tops = [s]
    closed = None
    leg = 1
    while s is not None and leg < 2 * MAX_REPEATS + 1:
        s, note = path.leg(s, lo, leg)
        if s is None:
            break
        s, note = path.leg(s, hi, leg + 1)
        if s is None:
            break
        if _same(s, tops[-1]):
            closed = leg
            break
        tops.append(s)
        leg += 2
    return _finish(path, contact, n, closed, note)


def _finish(path, contact, n, closed, note):
    P, d, br, a, st, lg = (np.array(v) for v in zip(*path.pts))
    energy = None if closed is None else loop_energy(path, closed)
    keep = _thin(len(P), n, path, lg)
    P, d = P[keep].astype(float), d[keep].astype(float)
    return Cycle(control=path.control, P=P, delta=d, branch=br[keep], a=a[keep].astype(float),
                 stable=st[keep].astype(bool), leg=lg[keep].astype(int), jumps=path.jumps, dissipated=energy,
                 closed_from_leg=closed, delta_work=contact.approach_work(P, d), note=note)


def _thin(m, n, path, legs):
    if m <= n:
        return np.arange(m)
    keep = set(np.linspace(0, m - 1, n - 2 * len(path.jumps) - 2).astype(int))
    keep |= {0, m - 1}
    P = [p[0] for p in path.pts]
    for i in range(1, m):                       # keep both ends of every jump and every leg change
        if legs[i] != legs[i - 1] or path.pts[i][2] != path.pts[i - 1][2]:
            keep |= {i - 1, i}
    return np.array(sorted(keep))[:max(n, 2)] if len(keep) > n else np.array(sorted(keep))


# --- energy -----------------------------------------------------------------------------------------------
def loop_energy(path, first_leg: int) -> float:
    """int P d(delta) [J/m] around the steady loop (legs first_leg, first_leg + 1).

    Parameters
    ----------
    path : _Path
        The recorded path (points, tracks, jumps) of :func:`cycle`.
    first_leg : int
        First leg of the steady loop.

    Returns
    -------
    float
        The energy dissipated per cycle per unit length [J/m].

    Single-patch stretches by Gauss-Legendre in a, P d(delta)/da from jkrcyl.equilibria slopes; jumps (straight
    segments at fixed P, delta or delta_work) and two-patch and full-contact stretches by the trapezoid rule on
    their points (exact on straight segments; full contact: delta is linear in P).
    """
    pts = [p for p in path.pts if p[5] in (first_leg, first_leg + 1)]
    total, k = 0.0, 0
    while k < len(pts) - 1:
        p, q = pts[k], pts[k + 1]
        if p[2] != q[2]:                                  # a jump between branches
            total += 0.5 * (p[0] + q[0]) * (q[1] - p[1])     # straight segment: exact
            k += 1
            continue
        m = k + 1                                         # the monotone run of a on this branch
        while m + 1 < len(pts) and pts[m + 1][2] == p[2] and \
                (pts[m + 1][3] - pts[m][3]) * (pts[k + 1][3] - p[3]) > 0:
            m += 1
        if p[2] in path.tracks and p[3] != pts[m][3]:
            total += _gauss(path, path.tracks[p[2]], p[3], pts[m][3])
        elif p[2] not in path.tracks:                     # two-patch, full contact, separated: trapezoid
            seg = pts[k:m + 1]
            total += sum(0.5 * (u[0] + v[0]) * (v[1] - u[1]) for u, v in zip(seg[:-1], seg[1:]))
        k = m
    return float(total)


def _gauss(path, tr, a0, a1):
    """int_{a0}^{a1} P (d delta/da) da on a single-patch track (panels uniform in log a)."""
    x, wts = np.polynomial.legendre.leggauss(GAUSS_NODES)
    lo, hi = math.log(a0), math.log(a1)
    edges = np.linspace(lo, hi, max(2, int(GAUSS_PANELS * min(1.0, abs(hi - lo))) + 1))
    mid, half = 0.5 * (edges[1:] + edges[:-1]), 0.5 * (edges[1:] - edges[:-1])
    u = (mid[:, None] + half[:, None] * x[None, :]).ravel()
    a = np.exp(u)
    order = np.argsort(a)
    c = fw._curve(path.pb, tr.regime, a[order])
    ct = path.pb.contact
    sgn = -1.0 if tr.side == "top" else 1.0
    P = np.empty_like(a)
    dd = np.empty_like(a)
    P[order] = sgn * np.asarray(c.P_star) * ct.load_scale
    dd[order] = sgn * np.asarray(c.ddelta_da) * ct.Delta            # top: delta = -2 Delta - delta_bottom
    integrand = (P * dd * a).reshape(mid.size, -1)                  # da = a du
    return float(np.sum(half[:, None] * wts[None, :] * integrand))


# --- output -----------------------------------------------------------------------------------------------
def plot(cy: Cycle, path, title: str = ""):
    """The P-delta_work path of a cycle (the work-conjugate approach, whose loop area is the energy dissipated)
    with its jumps drawn as arrows (PNG/PDF by the file extension)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    jump_at = {(j.before.P, j.before.delta) for j in cy.jumps}
    x = np.asarray(cy.delta_work) * 1e6
    segs, cur = [], [0]
    for i in range(1, len(cy.P)):
        if (cy.P[i - 1], cy.delta[i - 1]) in jump_at and cy.branch[i] != cy.branch[i - 1]:
            segs.append(cur)
            cur = []
        cur.append(i)
    segs.append(cur)
    for k, idx in enumerate(segs):
        ax.plot(x[idx], cy.P[idx], "-", color="C0", lw=1.5, label="quasi-static path" if k == 0 else None)
    for k, j in enumerate(cy.jumps):
        ax.annotate("", xy=(j.after.delta_work * 1e6, j.after.P), xytext=(j.before.delta_work * 1e6, j.before.P),
                    arrowprops=dict(arrowstyle="->", color="C3", lw=1.2))
        ax.plot([j.before.delta_work * 1e6], [j.before.P], "o", color="C3", ms=3,
                label="jump (snap-in, pull-off, ...)" if k == 0 else None)
    ax.axhline(0, color="0.8", lw=0.6)
    ax.set_xlabel(r"work-conjugate approach $\delta_{work} = \delta + P/(8\pi G_I)$ [$\mu$m]")
    ax.set_ylabel("load P [N/m]")
    e = "" if cy.dissipated is None else f"; dissipated {cy.dissipated:.4g} J/m per cycle"
    ax.set_title((title + "\n" if title else "") + f"{cy.control} control{e}", fontsize=9)
    ax.legend(fontsize=8, loc="best")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path
