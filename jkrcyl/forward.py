"""Forward problems: every equilibrium at a given load P [N/m] or approach [m] (issue 11).

A :class:`jkrcyl.Contact` answers ``solve(P=...)``, ``solve(delta_work=...)`` or ``solve(delta=...)`` with a list of
:class:`Equilibrium` -- one per state on every branch, sorted by contact size.  The branches are an
explicit registry, :data:`BRANCH_SOLVERS`, each entry a function ``(problem, key, target) -> [Equilibrium]``:

* ``sub-critical``, ``super-critical``: the single bottom patch of sections 4-6 (a < a_crit, a > a_crit);
* ``sub-critical-top``, ``super-critical-top``: the same patch at the top of the hole (the pin pulled up
  against phi = pi), the mirror image phi -> phi + pi: P -> -P, delta -> -2 Delta - delta;
* ``two-patch``: contact at the bottom and the top at once (jkrcyl.twopatch), present when a single patch
  can close the gap at phi = pi (the confined regime, :func:`confined`);
* ``full-contact``: the pin bonded all round (no edge, always stable), confined regime only;
* ``separated``: the free pin (no contact, P = 0), for a given approach -2 Delta < delta < 0 only.

Stability is that of the control given (:data:`CONTROLS`): fixed load for ``P``, fixed work-conjugate approach
for ``delta_work`` ('grip-work', a machine holding the pin), fixed paper's approach for ``delta`` ('grip')
(dG/da > 0 at the fixed quantity, section 8; the Hessians of jkrcyl.twopatch for two patches).
Signs as in the paper (section 6): P and delta are positive downward (pushing the pin into the bottom
of the hole); pulling is negative.
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field
from typing import Callable, Dict, List, Optional

import numpy as np

from . import equilibria as eq
from ._validate import finite_scalar
from .numerics import kernels as _k

ROOT_GRID = 4000          # grid points per single-patch branch (uniform in eps*) for sign changes
ROOT_GRID_ALPHA = 400     # alpha* != 0: one collocation solve per point
SMALL_A_POINTS = 200      # extra log-spaced points between A_MIN and the first grid point
A_MIN = 1e-15             # smallest contact parameter searched (states with a < A_MIN are not reported)

#: The controls: what is held fixed -> (normalised key on the branches, its slope along a Curve, the stability
#: field, the physical field).  'grip' holds the paper's approach delta (5.8) (the rims' approach, as in section
#: 8); 'grip-work' holds the work-conjugate approach delta_work = delta + P/(8 pi G_I) (derive/green.py), the
#: displacement a testing machine holding the pin controls.
CONTROLS = {"load": ("P_star", "dP_star_da", "stable_load", "P"),
            "grip": ("delta_over_Delta", "ddelta_da", "stable_grip", "delta"),
            "grip-work": ("delta_work_over_Delta", "ddelta_work_da", "stable_grip_work", "delta_work")}


def check_control(control: str) -> str:
    if control not in CONTROLS:
        raise ValueError(f"control must be one of {', '.join(repr(c) for c in CONTROLS)}, got {control!r}")
    return control


# --- the problem in normalised form ---------------------------------------------------------------------
@dataclass(frozen=True)
class Problem:
    """A Contact seen through the normalisation of section 6: (M, vartheta, gb, alpha*/beta*)."""

    contact: object
    M: float
    theta: float
    gb: float
    alpha_ratio: float

    @classmethod
    def of(cls, contact) -> "Problem":
        """The normalised problem (M, vartheta, gb, alpha*/beta*) of a :class:`jkrcyl.Contact` with Delta > 0."""
        M, th, gb = eq.from_contact(contact)
        return cls(contact, M, th, gb, contact.materials.alpha_ratio)

    @property
    def key(self):
        return (self.M, self.theta, self.gb, self.alpha_ratio)

    @property
    def load_scale(self) -> float:
        return self.contact.load_scale


# --- one equilibrium ----------------------------------------------------------------------------------
@dataclass(frozen=True, repr=False)
class Equilibrium:
    """One equilibrium state, dimensional and normalised.

    Attributes
    ----------
    branch : str
        Key of :data:`BRANCH_SOLVERS` (``regime`` is the same string).
    control : str
        'load', 'grip' or 'grip-work' (:data:`CONTROLS`): the control under which :attr:`stable` is judged.
    a, a_top : float
        Contact parameters tan(eps/2) of the bottom and the top patch (a_top = 0 for one patch; a = inf in
        full contact, a = 0 when separated).
    eps, eps_top : float
        Contact half-angles [rad].
    contact_width : float
        Arc length of contact 2 R (eps + eps_top) [m].
    P : float
        Load per unit length [N/m], positive downward.
    delta : float
        Approach [m] (5.1), (5.8), positive downward: the paper's, the rims' approach with the load at the pin's
        centre.
    delta_work : float
        Work-conjugate approach [m] (pin centroid, load spread over the pin; derive/green.py):
        delta + P/(8 pi G_I), so that P d(delta_work) is the work done (Contact.approach_work).
    h_pi : float
        Gap at phi = pi [m] (5.10); 0 when the top is in contact.
    K : float
        Stress intensity factor at the bottom edge [Pa m^1/2] (3.4); at equilibrium (pi/4) A K^2 = w.
    P_star, delta_over_Delta, delta_work_over_Delta : float
        Normalised load (section 6; P_R* of (7.6) for vartheta = inf) and approaches.
    feasible : bool
        Gap inequality h >= 0 outside the contact (section 5).
    stable_load, stable_grip, stable_grip_work : bool
        Stable at fixed load / fixed delta / fixed delta_work.
    side : str
        'bottom', 'top' (mirrored single patch), 'both' (two patches, full contact) or 'none' (separated).
    """

    branch: str
    control: str
    a: float
    eps: float
    contact_width: float
    P: float
    delta: float
    delta_work: float
    h_pi: float
    K: float
    P_star: float
    delta_over_Delta: float
    delta_work_over_Delta: float
    feasible: bool
    stable_load: bool
    stable_grip: bool
    stable_grip_work: bool
    side: str = "bottom"
    a_top: float = 0.0
    eps_top: float = 0.0
    extra: dict = field(default_factory=dict, compare=False)

    @property
    def regime(self) -> str:
        return self.branch

    @property
    def stable(self) -> bool:
        """Stable under the control given to :func:`solve`."""
        return getattr(self, CONTROLS[self.control][2])

    @property
    def size(self) -> float:
        """Total contact half-angle eps + eps_top [rad] (the sort key)."""
        return self.eps + self.eps_top

    def with_control(self, control: str) -> "Equilibrium":
        from dataclasses import replace
        return replace(self, control=control)

    def as_dict(self) -> dict:
        """Plain values (floats, bools, str) for CSV/JSON output."""
        keys = ("branch", "side", "a", "a_top", "eps", "eps_top", "contact_width", "P", "delta", "delta_work",
                "h_pi", "K", "P_star", "delta_over_Delta", "delta_work_over_Delta", "feasible", "stable_load",
                "stable_grip", "stable_grip_work", "stable")
        return {k: getattr(self, k) for k in keys}

    def __repr__(self) -> str:
        return (f"Equilibrium({self.branch}, a={self.a:.6g}, width={self.contact_width:.4g} m, "
                f"P={self.P:.6g} N/m, delta={self.delta:.4g} m, feasible={self.feasible}, "
                f"stable({self.control})={self.stable})")


# --- single patch ---------------------------------------------------------------------------------------
def _branch_grid(pb: Problem, regime: str) -> np.ndarray:
    """Increasing contact parameters covering one single-patch branch, with log-spaced small a."""
    ar, th = pb.alpha_ratio, pb.theta
    n = ROOT_GRID if ar == 0.0 else ROOT_GRID_ALPHA
    s = (np.arange(n) + 0.5) / n
    if math.isinf(th):                      # rigid cradle: a in (0, inf), no a_crit
        a = np.tan(0.5 * math.pi * s)
    else:
        ac = eq._ac(th, pb.gb, ar)
        lo, hi = (0.0, 0.5) if regime == "sub-critical" else (0.5, 1.0)
        a = ac * np.tan(0.5 * math.pi * (lo + (hi - lo) * s))
    if regime == "sub-critical" or math.isinf(th):
        k = SMALL_A_POINTS if ar == 0.0 else SMALL_A_POINTS // 8
        a = np.concatenate([np.geomspace(A_MIN, a[0], k, endpoint=False), a])
    return a


def _curve(pb: Problem, regime: str, a) -> "eq.Curve":
    return eq.curve(pb.M, pb.theta, regime=regime, gb=pb.gb, a=np.atleast_1d(np.asarray(a, float)),
                    alpha_ratio=pb.alpha_ratio)


@functools.lru_cache(maxsize=32)
def branch_curve(key, regime):
    """The dense single-patch branch (jkrcyl.equilibria.Curve on the solver's grid), cached."""
    pb = Problem(None, *key)
    return _curve(pb, regime, _branch_grid(pb, regime))


def _refine(f, lo, hi):
    from scipy.optimize import brentq
    return brentq(f, lo, hi, xtol=1e-300, rtol=4 * np.finfo(float).eps, maxiter=200)


def single_patch_roots(pb: Problem, regime: str, key: str, target: float) -> List[float]:
    """Contact parameters on a single-patch branch where the Curve field ``key`` (P_star, delta_over_Delta or
    delta_work_over_Delta) equals target."""
    if regime == "super-critical" and math.isinf(pb.theta):
        return []
    c = branch_curve(pb.key, regime)
    a, v = c.a, np.asarray(getattr(c, key)) - target
    f = lambda x: float(getattr(_curve(pb, regime, x), key)[0]) - target
    out = []
    for i in np.nonzero(np.sign(v[:-1]) * np.sign(v[1:]) < 0)[0]:
        if np.isfinite(v[i]) and np.isfinite(v[i + 1]):
            out.append(_refine(f, float(a[i]), float(a[i + 1])))
    out += [float(x) for x in a[v == 0]]
    return sorted(out)


def _stability(c, regime: str, M: float) -> Dict[str, np.ndarray]:
    """{control: stability array} along a Curve; M = 0 (no adhesion): the M -> 0+ limit of the sign rules (the
    load rule, for the paper's grip too, and the same rule on delta_work, whose fixed-arc compliance is > 0)."""
    if M > 0:
        return {ctl: np.asarray(getattr(c, spec[2])) for ctl, spec in CONTROLS.items()}
    sign = 1.0 if regime == "sub-critical" else -1.0
    ok = sign * np.asarray(c.dP_star_da) > 0
    return {"load": ok, "grip": ok, "grip-work": sign * np.asarray(c.ddelta_work_da) > 0}


def single_patch_states(pb: Problem, regime: str, a, control: str, side: str = "bottom") -> List[Equilibrium]:
    """Equilibria of one single-patch branch at contact parameters a (mirrored when side == 'top')."""
    a = np.atleast_1d(np.asarray(a, dtype=float))
    if a.size == 0:
        return []
    ct = pb.contact
    st = ct.state(a)
    c = _curve(pb, regime, a)
    stab = _stability(c, regime, pb.M)
    out = []
    for i in range(a.size):
        P, delta = float(np.ravel(st.P)[i]), float(np.ravel(st.delta)[i])
        h_pi = float(np.ravel(st.h_pi)[i])
        if side == "top":
            P, delta = -P, -2 * ct.Delta - delta
        dw = float(ct.approach_work(P, delta))
        eps = float(2 * math.atan(a[i]))
        out.append(Equilibrium(
            branch=regime if side == "bottom" else regime + "-top", control=control, a=float(a[i]), eps=eps,
            contact_width=2 * ct.R * eps, P=P, delta=delta, delta_work=dw, h_pi=h_pi, K=float(np.ravel(st.K)[i]),
            P_star=P / ct.load_scale, delta_over_Delta=delta / ct.Delta, delta_work_over_Delta=dw / ct.Delta,
            feasible=bool(h_pi >= 0), stable_load=bool(stab["load"][i]), stable_grip=bool(stab["grip"][i]),
            stable_grip_work=bool(stab["grip-work"][i]), side=side))
    return out


def _single(regime: str, side: str = "bottom"):
    def solver(pb: Problem, key: str, target: float, control: str) -> List[Equilibrium]:
        if side == "top":                        # mirror: P* -> -P*, delta/Delta -> -2 - delta/Delta
            target = -target if key == "P_star" else -2.0 - target
        return single_patch_states(pb, regime, single_patch_roots(pb, regime, key, target), control, side)
    solver.__doc__ = f"{regime} single patch at the {side} of the hole."
    return solver


# --- confined regime: two patches and full contact ---------------------------------------------------------
@functools.lru_cache(maxsize=32)
def _onsets(key):
    from . import twopatch
    M, th, gb, ar = key
    if math.isinf(th) or M <= 0:
        return ()
    kw = {"alpha_ratio": ar} if ar else {}
    return tuple(twopatch.onset_angles(M, th, gb, **kw))


def confined(pb: Problem) -> bool:
    """True when some single-patch state closes the gap at phi = pi (h(pi) = 0 of (5.10)): two-patch states exist.

    Parameters
    ----------
    pb : Problem
        The contact in the normalisation of section 6.

    Returns
    -------
    bool
    """
    return bool(_onsets(pb.key))


@functools.lru_cache(maxsize=8)
def two_patch_branches(key):
    """jkrcyl.twopatch.branches at (M, vartheta, gb, alpha*/beta*), cached (tracing takes seconds)."""
    from . import twopatch
    M, th, gb, ar = key
    kw = {"alpha_ratio": ar} if ar else {}
    return tuple(twopatch.branches(M, th, gb=gb, **kw))


def _two_patch_state(pb: Problem, eps: float, eps_top: float, control: str) -> Equilibrium:
    from . import twopatch
    kw = {"alpha_ratio": pb.alpha_ratio} if pb.alpha_ratio else {}
    s = twopatch.equilibrium_state(eps, eps_top, pb.M, pb.theta, pb.gb, **kw)
    stab = twopatch.stability(eps, eps_top, s.delta_over_Delta, pb.M, pb.theta, pb.gb, **kw)
    return _from_two_patch(pb, s, stab, control)


def work_over_Delta(pb: Problem, obj):
    """delta_work/Delta of anything with delta_over_Delta and P_star (states, two-patch branches)."""
    return _k.work_over_Delta(obj.delta_over_Delta, obj.P_star, theta=pb.theta, gb=pb.gb)


def _value(pb: Problem, obj, key: str):
    """The normalised field ``key`` of a two-patch state or branch (delta_work/Delta computed)."""
    return work_over_Delta(pb, obj) if key == "delta_work_over_Delta" else np.asarray(getattr(obj, key))


def _from_two_patch(pb, s, stab, control):
    """stab: (stable_load, stable_grip, stable_grip_work) of jkrcyl.twopatch.stability."""
    ct = pb.contact
    dw = float(work_over_Delta(pb, s))
    return Equilibrium(
        branch="two-patch", control=control, a=s.a, eps=s.eps, contact_width=2 * ct.R * (s.eps + s.eps_top),
        P=s.P_star * ct.load_scale, delta=s.delta_over_Delta * ct.Delta, delta_work=dw * ct.Delta, h_pi=0.0,
        K=math.sqrt(8 * ct.w / ct.beta), P_star=s.P_star, delta_over_Delta=s.delta_over_Delta,
        delta_work_over_Delta=dw, feasible=bool(s.feasible), stable_load=bool(stab[0]), stable_grip=bool(stab[1]),
        stable_grip_work=bool(stab[2]), side="both", a_top=s.a_top, eps_top=s.eps_top,
        extra={"gap_min_over_Delta": s.gap_min, "G_bot": s.G_bot, "G_top": s.G_top})


def _two_patch_solver(pb: Problem, key: str, target: float, control: str) -> List[Equilibrium]:
    """Two-patch states: sign changes along each traced branch, refined on the branch by Brent's method
    in the half-angle that varies most (the other from jkrcyl.twopatch.solve)."""
    from . import twopatch
    if not confined(pb):
        return []
    kw = {"alpha_ratio": pb.alpha_ratio} if pb.alpha_ratio else {}
    out = []
    for b in two_patch_branches(pb.key):
        v = _value(pb, b, key) - target
        for i in np.nonzero(np.sign(v[:-1]) * np.sign(v[1:]) < 0)[0]:
            e0, e1, t0, t1 = b.eps[i], b.eps[i + 1], b.eps_top[i], b.eps_top[i + 1]
            along_top = abs(t1 - t0) > abs(e1 - e0)
            lo, hi = (t0, t1) if along_top else (e0, e1)
            other = (lambda x: e0 + (e1 - e0) * (x - t0) / (t1 - t0)) if along_top else \
                    (lambda x: t0 + (t1 - t0) * (x - e0) / (e1 - e0))

            def state(x):
                if along_top:
                    return twopatch.solve(pb.M, pb.theta, eps_top=x, gb=pb.gb, guess=other(x), **kw)
                return twopatch.solve(pb.M, pb.theta, eps=x, gb=pb.gb, guess=other(x), **kw)
            try:
                f = lambda x: float(_value(pb, state(x), key)) - target
                x = _refine_loose(f, min(lo, hi), max(lo, hi))
                s = state(x)
            except ValueError:
                continue
            stab = twopatch.stability(s.eps, s.eps_top, s.delta_over_Delta, pb.M, pb.theta, pb.gb, **kw)
            out.append(_from_two_patch(pb, s, stab, control))
    return out


def _refine_loose(f, lo, hi):
    from scipy.optimize import brentq
    return brentq(f, lo, hi, xtol=1e-14, rtol=1e-13, maxiter=100)


def full_contact_state(pb: Problem, key: str, target: float, control: str) -> Optional[Equilibrium]:
    """The bonded pin (eps + eps_top = pi) at P*, delta/Delta or delta_work/Delta = target
    (jkrcyl.twopatch.full_contact)."""
    from . import twopatch
    kw = {"alpha_ratio": pb.alpha_ratio} if pb.alpha_ratio else {}
    try:
        if key == "delta_work_over_Delta":          # affine in P* in full contact: invert through two loads
            w0, w1 = (float(work_over_Delta(pb, twopatch.full_contact(pb.theta, gb=pb.gb, P_star=x, **kw)))
                      for x in (0.0, 1.0))
            args = {"P_star": (target - w0) / (w1 - w0)}
        else:
            args = {key: target}
        fc = twopatch.full_contact(pb.theta, gb=pb.gb, **args, **kw)
    except (ValueError, ZeroDivisionError):         # the approach fixes no load (e.g. delta when gb = 1/2)
        return None
    ct = pb.contact
    dw = float(work_over_Delta(pb, fc))
    return Equilibrium(
        branch="full-contact", control=control, a=math.inf, eps=math.pi, contact_width=2 * math.pi * ct.R,
        P=fc.P_star * ct.load_scale, delta=fc.delta_over_Delta * ct.Delta, delta_work=dw * ct.Delta, h_pi=0.0,
        K=0.0, P_star=fc.P_star, delta_over_Delta=fc.delta_over_Delta, delta_work_over_Delta=dw, feasible=True,
        stable_load=True, stable_grip=True, stable_grip_work=True, side="both", a_top=math.inf, eps_top=0.0,
        extra={"tension_everywhere": fc.tension_everywhere})


def _full_contact_solver(pb: Problem, key: str, target: float, control: str) -> List[Equilibrium]:
    if not confined(pb):
        return []
    s = full_contact_state(pb, key, target, control)
    return [] if s is None else [s]


def separated_state(pb: Problem, delta_over_Delta: float, control: str) -> Equilibrium:
    """The free pin at approach delta (no contact, P = 0): stable under grip, neutral under load."""
    ct = pb.contact
    return Equilibrium(
        branch="separated", control=control, a=0.0, eps=0.0, contact_width=0.0, P=0.0,
        delta=delta_over_Delta * ct.Delta, delta_work=delta_over_Delta * ct.Delta,   # P = 0: delta_work = delta
        h_pi=(2 + delta_over_Delta) * ct.Delta, K=0.0, P_star=0.0, delta_over_Delta=delta_over_Delta,
        delta_work_over_Delta=delta_over_Delta, feasible=True, stable_load=False, stable_grip=True,
        stable_grip_work=True, side="none")


def _separated_solver(pb: Problem, key: str, target: float, control: str) -> List[Equilibrium]:
    if key == "P_star" or not -2.0 < target < 0.0:       # P = 0: delta_work = delta
        return []
    return [separated_state(pb, target, control)]


BranchSolver = Callable[[Problem, str, float, str], List[Equilibrium]]

#: The branches searched by :func:`solve`, in this order; each maps (problem, key, target, control) to states.
BRANCH_SOLVERS: Dict[str, BranchSolver] = {
    "sub-critical": _single("sub-critical"),
    "super-critical": _single("super-critical"),
    "sub-critical-top": _single("sub-critical", "top"),
    "super-critical-top": _single("super-critical", "top"),
    "two-patch": _two_patch_solver,
    "full-contact": _full_contact_solver,
    "separated": _separated_solver,
}


# --- the forward problem ------------------------------------------------------------------------------
def solve(contact, P: Optional[float] = None, delta: Optional[float] = None, branches=None,
          delta_work: Optional[float] = None) -> List[Equilibrium]:
    """Every equilibrium of ``contact`` at load ``P`` [N/m], approach ``delta`` or ``delta_work`` [m] (exactly one).

    Parameters
    ----------
    contact : jkrcyl.Contact
        Needs a clearance Delta > 0 (the branches are found in the normalisation of section 6).
    P : float, optional
        Load per unit length [N/m], positive downward (section 6); stability is then judged at fixed load.
    delta : float, optional
        The paper's approach [m] (5.1), (5.8); stability is then judged at fixed delta (control 'grip').
    delta_work : float, optional
        The work-conjugate approach delta + P/(8 pi G_I) [m] (derive/green.py); stability is then judged at fixed
        delta_work (control 'grip-work': a testing machine holding the pin).
    branches : iterable of str, optional
        Keys of :data:`BRANCH_SOLVERS` to search (default: all).  Two-patch states are traced by continuation
        (seconds, cached per contact); leave out 'two-patch' for speed.

    Returns
    -------
    list of Equilibrium
        Sorted by contact size (eps + eps_top), then by branch.  Empty if no state exists.
    """
    given = {k: v for k, v in (("P", P), ("delta", delta), ("delta_work", delta_work)) if v is not None}
    if len(given) != 1:
        raise ValueError("P: give exactly one of P [N/m], delta [m] and delta_work [m]")
    contact._require_clearance("solve")
    pb = Problem.of(contact)
    (name, value), = given.items()
    control = next(c for c, spec in CONTROLS.items() if spec[3] == name)
    key = CONTROLS[control][0]
    target = finite_scalar(name, value) / (contact.load_scale if name == "P" else contact.Delta)
    names = list(BRANCH_SOLVERS) if branches is None else list(branches)
    for branch in names:
        if branch not in BRANCH_SOLVERS:
            raise ValueError(f"branches: unknown branch {branch!r} (choose from {', '.join(BRANCH_SOLVERS)})")
    out = []
    for branch in names:
        out += BRANCH_SOLVERS[branch](pb, key, target, control)
    order = {n: i for i, n in enumerate(BRANCH_SOLVERS)}
    return sorted(out, key=lambda s: (s.size, order[s.branch]))


# --- pull-off (issue 11 item 2) -----------------------------------------------------------------------------
@dataclass(frozen=True, repr=False)
class PullOff:
    """Detachment along the path a user follows, or why there is none.

    Attributes
    ----------
    control : str
        'load', 'grip' or 'grip-work'.
    P : float or None
        Load per unit length at detachment [N/m] (negative: pulling); None if the pin does not detach.
    contact_width : float or None
        Arc length of contact 2 R eps just before detachment [m].
    delta : float or None
        Approach at detachment [m].
    state : Equilibrium or None
        The last stable equilibrium (the fold), also when there is no detachment.
    reason : str
        What happens at the end of the stable, feasible path.
    """

    control: str
    P: Optional[float]
    contact_width: Optional[float]
    delta: Optional[float]
    state: Optional[Equilibrium]
    reason: str

    @property
    def detached(self) -> bool:
        """True when the pin detaches (``P`` is a number)."""
        return self.P is not None

    @property
    def delta_work(self) -> Optional[float]:
        """Work-conjugate approach at detachment [m] (derive/green.py); None without detachment."""
        return self.state.delta_work if self.detached else None

    def __bool__(self) -> bool:
        return self.detached

    def __repr__(self) -> str:
        if self.detached:
            return (f"PullOff({self.control}: P={self.P:.6g} N/m, contact_width={self.contact_width:.4g} m, "
                    f"delta={self.delta:.4g} m)")
        return f"PullOff({self.control}: none -- {self.reason})"


def start_state(pb: Problem):
    """(regime, index) on the dense bottom branches where a quasi-static load path starts: the stable,
    feasible zero-load contact reached by snap-in (8.1), else the stable feasible state of largest P*
    (the pin pushed in first).  None if no state is stable and feasible under load."""
    zero = [s for s in solve(pb.contact, P=0.0, branches=["sub-critical", "super-critical"])
            if s.stable_load and s.feasible]
    if zero:
        s = zero[0]
        c = branch_curve(pb.key, s.branch)
        return s.branch, int(np.argmin(np.abs(c.a - s.a)))
    best = None
    for regime in ("sub-critical", "super-critical"):
        if regime == "super-critical" and math.isinf(pb.theta):
            continue
        c = branch_curve(pb.key, regime)
        ok = np.nonzero(np.asarray(c.stable_load) & np.asarray(c.feasible))[0]
        if ok.size and (best is None or c.P_star[ok].max() > best[0]):
            best = (c.P_star[ok].max(), regime, int(ok[np.argmax(c.P_star[ok])]))
    return None if best is None else best[1:]


def walk_down(pb: Problem, regime: str, i: int, control: str):
    """Follow a branch from index i while the driven quantity (P* or delta/Delta) decreases and the states stay
    stable (under control) and feasible.  Returns (j, event): event 'fold' (a minimum of the driven
    quantity), 'gap' (the next state has h(pi) < 0) or 'end' (the grid ends)."""
    c = branch_curve(pb.key, regime)
    key = CONTROLS[control][0]
    y = np.asarray(getattr(c, key))
    stable = _stability(c, regime, pb.M)[control]
    feasible = np.asarray(c.feasible)
    step = -1 if i > 0 and y[i - 1] < y[i] else 1
    j = i
    while 0 <= j + step < y.size:
        k = j + step
        if not feasible[k]:
            return j, "gap"
        if y[k] >= y[j] or not stable[k]:
            return j, "fold"
        j = k
    return j, "end"


def _fold(pb: Problem, regime: str, j: int, control: str) -> float:
    """Contact parameter of the minimum of the held quantity (P*, delta/Delta, delta_work/Delta) next to grid
    index j."""
    c = branch_curve(pb.key, regime)
    key = CONTROLS[control][1]
    lo, hi = float(c.a[max(j - 1, 0)]), float(c.a[min(j + 1, c.a.size - 1)])
    f = lambda x: float(getattr(_curve(pb, regime, x), key)[0])
    if f(lo) * f(hi) < 0:
        return _refine(f, lo, hi)
    return float(c.a[j])


def pull_off(contact, control: str = "load") -> PullOff:
    """Detachment force [N/m], contact width [m] and approach [m] along the quasi-static path.

    The path starts at the stable zero-load contact (snap-in, (8.1)) -- or, without one, at the stable state of
    largest load -- and follows its branch towards lower load (control='load') or lower approach
    (control='grip') through stable, feasible states (section 9).  It ends at

    * a sub-critical minimum: the contact shrinks away (G > w), the pin detaches: P, width and delta there;
    * a super-critical minimum: a further pull lowers G, the contact grows round into full contact -- no
      detachment (jkrcyl.twopatch);
    * h(pi) = 0: the gap at the top closes first (confined) -- no detachment; see
      :meth:`jkrcyl.Contact.confined_events` for what follows.

    Parameters
    ----------
    contact : jkrcyl.Contact
        Needs a clearance Delta > 0.
    control : {'load', 'grip', 'grip-work'}
        Fixed load (the detachment is a minimum of P along the stable branch), fixed grip on the paper's approach
        delta (5.8) (a minimum of delta) or on the work-conjugate delta_work (a minimum of delta_work: a testing
        machine holding the pin).

    Returns
    -------
    PullOff
        ``P`` [N/m], ``contact_width`` = 2 R eps [m] and ``delta`` [m] at detachment; ``P`` is None (and ``reason``
        says why) when the pin does not detach.

    Raises
    ------
    ValueError
        Naming ``control`` (not one of :data:`CONTROLS`) or ``Delta`` (Delta = 0: the neat fit, section 7.3).
    """
    check_control(control)
    contact._require_clearance("pull_off")
    pb = Problem.of(contact)
    if pb.M == 0:
        return PullOff(control, None, None, None, None, "no adhesion (w = 0): the contact vanishes at P = 0")
    start = start_state(pb)
    if start is None:
        return PullOff(control, None, None, None, None,
                       "no single-patch state is stable and feasible under load: no path to follow")
    regime, i = start
    j, event = walk_down(pb, regime, i, control)
    c = branch_curve(pb.key, regime)
    if event == "gap":
        s = single_patch_states(pb, regime, c.a[j], control)[0]
        return PullOff(control, None, None, None, s,
                       f"confined: the gap at phi = pi closes first (P = {s.P:.6g} N/m, delta = {s.delta:.4g} m); "
                       "the top contact forms before detachment (see Contact.confined_events)")
    a = _fold(pb, regime, j, control) if event == "fold" else float(c.a[j])
    s = single_patch_states(pb, regime, a, control)[0]
    if event == "end":
        what = "load" if control == "load" else "approach"
        return PullOff(control, None, None, None, s,
                       f"no fold: along the stable branch the {what} decreases without bound (the contact grows "
                       f"towards a_crit or the full circle), so the pin does not detach; last state a = {s.a:.6g}")
    if regime == "super-critical":
        return PullOff(control, None, None, None, s,
                       f"fold at P = {s.P:.6g} N/m on the super-critical branch: a further pull lowers G, the "
                       "contact grows round into full contact (no detachment)")
    return PullOff(control, s.P, s.contact_width, s.delta, s, "detachment: the contact shrinks away (G > w)")
