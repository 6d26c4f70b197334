"""What a path of slowly changed load or approach meets: :class:`PullOff`, :class:`Jump`, :class:`Cycle` and
:class:`ConfinedEvents` (the confined regime under load control)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import List, Optional

import numpy as np

from .states import Equilibrium

#: What slow pulling under load control does, from the load path (jkrcyl.analysis.confined).
REGIMES = {
    "detachment": "the fixed-load adherence point comes first (gap at pi still open) and a further pull makes "
                  "G > w: the contact shrinks, the pin leaves the bottom and, in the hole, lands on the top "
                  "(the mirrored single patch at the same load)",
    "zip-full": "the fixed-load adherence point comes first, but there a further pull makes G < w: the "
                "contact grows past h(pi) = 0 and zips round into full contact (no detachment)",
    "snap-in-full": "the gap closes at pi first; the two-patch state growing from there is unstable under "
                    "load: the top contact snaps in and the path runs into full contact",
    "snap-in-transfer": "the gap closes at pi first; the two-patch branch is unstable under load and leads to "
                        "the mirrored single patch (the pin is transferred to the top)",
    "two-patch": "the gap closes at pi first and a two-patch state stable under load follows",
    "bonded": "no zero-load contact (M above the largest M with one, (8.1)): at first touch the contact zips "
              "round into full contact, and a pin bonded all round does not detach under load",
    "no-path": "no stable single-patch state to start from (no stable, feasible equilibrium at any load)",
}


@dataclass(frozen=True, repr=False)
class PullOff:
    """Detachment along the path a user follows from first contact, or why there is none.

    What :meth:`jkrcyl.Contact.pull_off` returns; true when the pin detaches.

    Attributes
    ----------
    control : str
        'load', 'grip' (the paper's delta held) or 'grip-work' (delta_work held).
    P, contact_width, delta : float or None
        At detachment: the load [N/m] (negative: pulling), 2 R eps just before [m] and the approach [m]; None
        if the pin does not detach.
    state : jkrcyl.results.Equilibrium or None
        The last stable equilibrium (the fold), also without detachment.
    reason : str
        What happens at the end of the path.

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> po = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m).pull_off()
    >>> po
    PullOff(load: P=-1555.1 N/m, contact_width=0.01766 m, delta=-3.095e-07 m)
    >>> bool(po), po.reason
    (True, 'detachment: the contact shrinks away (G > w)')
    """

    control: str
    P: Optional[float]
    contact_width: Optional[float]
    delta: Optional[float]
    state: Optional[Equilibrium]
    reason: str

    @property
    def detached(self) -> bool:
        """Whether the pin detaches (P is not None)."""
        return self.P is not None

    @property
    def delta_work(self) -> Optional[float]:
        """Work-conjugate approach at detachment [m]; None without detachment."""
        return self.state.delta_work if self.detached else None

    def __bool__(self) -> bool:
        return self.detached

    def __repr__(self) -> str:
        if self.detached:
            return (f"PullOff({self.control}: P={self.P:.6g} N/m, contact_width={self.contact_width:.4g} m, "
                    f"delta={self.delta:.4g} m)")
        return f"PullOff({self.control}: none -- {self.reason})"


@dataclass(frozen=True, repr=False)
class Jump:
    """A jump of the quasi-static path at fixed load (load control) or fixed approach (grip controls).

    Attributes
    ----------
    kind : str
        'snap-in', 'pull-off', 'zip' or 'top-contact' (jkrcyl.analysis.cycle).
    leg : int
        0 for the first loading, then alternately down and up.
    before, after : jkrcyl.results.Equilibrium
        The states it joins (the same held quantity).

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> cy = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m).cycle(P_max=2000.0, P_min=-2000.0, n=100)
    >>> [(j.kind, j.leg, j.after.branch) for j in cy.jumps]
    [('snap-in', 0, 'sub-critical'), ('pull-off', 1, 'sub-critical-top'), ('pull-off', 2, 'sub-critical')]
    """

    kind: str
    leg: int
    before: Equilibrium
    after: Equilibrium

    def __repr__(self) -> str:
        return (f"Jump({self.kind}: P {self.before.P:.6g} -> {self.after.P:.6g} N/m, delta {self.before.delta:.4g}"
                f" -> {self.after.delta:.4g} m, {self.before.branch} -> {self.after.branch})")


@dataclass(frozen=True, repr=False)
class Cycle:
    """A quasi-static cycle from first contact: up to the maximum, down to the minimum and up again.

    What :meth:`jkrcyl.Contact.cycle` returns (jkrcyl.analysis.cycle).

    Attributes
    ----------
    control : str
        'load', 'grip' or 'grip-work'.
    P, delta, delta_work : ndarray
        The path [N/m], [m], [m]; a jump is the straight segment between two consecutive points.
    branch, a, stable, leg : ndarray
        Per point: the branch, the contact parameter, stable under ``control``, the leg (0: first loading).
    jumps : list of Jump
    dissipated : float or None
        The energy dissipated per cycle [J/m]: the area of the closed steady loop, int P d(delta); None if the
        loop did not close.
    closed_from_leg : int or None
        The first leg of that loop.
    note : str
        Why the path stopped early, if it did.
    limits : tuple
        The driven limits (minimum, maximum) of the held quantity.

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> cy = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m).cycle(P_max=2000.0, P_min=-2000.0, n=100)
    >>> cy
    Cycle(load: 101 points, 3 jumps, dissipated 0.00799783 J/m)
    >>> cy.limits, cy.closed_from_leg
    ((-2000.0, 2000.0), 1)
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
    delta_work: Optional[np.ndarray] = None
    note: str = ""
    limits: Optional[tuple] = None

    def __repr__(self) -> str:
        e = "n/a" if self.dissipated is None else f"{self.dissipated:.6g} J/m"
        return f"Cycle({self.control}: {len(self.P)} points, {len(self.jumps)} jumps, dissipated {e})"

    def table(self) -> dict:
        """Columns for CSV output (physical units): leg, branch, a, P, delta, delta_work, stable.

        Returns
        -------
        dict of ndarray

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> cy = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m).cycle(P_max=2000.0, P_min=-2000.0, n=100)
        >>> list(cy.table())
        ['leg', 'branch', 'a', 'P', 'delta', 'delta_work', 'stable']
        """
        return {"leg": self.leg, "branch": self.branch, "a": self.a, "P": self.P, "delta": self.delta,
                "delta_work": self.delta_work, "stable": self.stable}


@dataclass(frozen=True)
class ConfinedEvents:
    """What happens to the pin under slow pulling (load control) at (M, vartheta): jkrcyl.analysis.confined.

    What :func:`jkrcyl.equilibria.confined_events` and :meth:`jkrcyl.Contact.confined_events` return.

    Attributes
    ----------
    M, theta, gb, alpha_ratio : float
        The problem (section 6).
    regime : str
        A key of :data:`REGIMES`.
    start : tuple
        (a, P*) where the load path starts: the stable zero-load contact; (inf, nan) when bonded from first touch.
    P_fold, P_top_contact : float
        P* at the fixed-load adherence point met first (nan if the gap closes first); P* at which the top
        contact forms on that path (nan if the fold comes first).
    onsets : tuple
        Every single-patch state with h(pi) = 0 as (eps, P*, delta/Delta, stable under load).
    grip_detachment : bool
        A feasible fixed-grip stationary point (min of delta) before the gap closes: the pin can be held free.
    two_patch_stable_load, two_patch_stable_grip, full_contact : bool
        Some two-patch state is stable under load, under grip; some two-patch branch runs into full contact.
    branches : tuple of jkrcyl.results.TwoPatchCurve
    fold_in_tension : bool or None
        At a zip-full fold: full contact at that load is entirely in tension (None otherwise).

    Examples
    --------
    >>> import jkrcyl
    >>> ev = jkrcyl.equilibria.confined_events(0.3, 1.0, gb=1 / 2.8)
    >>> ev.regime, round(ev.P_fold, 4), ev.grip_detachment
    ('detachment', -0.2856, True)
    """

    M: float
    theta: float
    regime: str
    start: tuple
    P_fold: float
    P_top_contact: float
    onsets: tuple
    grip_detachment: bool
    two_patch_stable_load: bool
    two_patch_stable_grip: bool
    full_contact: bool
    branches: tuple
    gb: Optional[float] = None
    alpha_ratio: float = 0.0
    fold_in_tension: Optional[bool] = None

    def __repr__(self) -> str:
        return (f"ConfinedEvents({self.regime}: M={self.M:.6g}, theta={self.theta:.6g}, P_fold={self.P_fold:.6g}, "
                f"P_top_contact={self.P_top_contact:.6g}, {len(self.branches)} two-patch branches)")

    @property
    def description(self) -> str:
        """The regime in words (:data:`REGIMES`)."""
        return REGIMES[self.regime]

    @property
    def summary(self) -> str:
        """One line: the event, its load and what follows (no true detachment under load control in a hole).

        Examples
        --------
        >>> import jkrcyl
        >>> ev = jkrcyl.equilibria.confined_events(0.5, 1.0, gb=1 / 2.8)
        >>> ev.summary.split("; ")                                  # doctest: +NORMALIZE_WHITESPACE
        ['fold at P* = -0.288025', 'the contact grows into full contact (entirely in tension there)',
         'no detachment under load']
        """
        if self.regime == "detachment":
            return (f"fixed-load detachment at P* = {self.P_fold:.6g}; the pin lands on the top of the hole "
                    f"(transfer); held at fixed grip it can be freed: {self.grip_detachment}")
        if self.regime == "zip-full":
            fc = "entirely in tension" if self.fold_in_tension else "partly compressed"
            return (f"fold at P* = {self.P_fold:.6g}; the contact grows into full contact ({fc} there); "
                    f"no detachment under load")
        if self.regime in ("no-path", "bonded"):
            return REGIMES[self.regime]
        return f"top contact forms at P* = {self.P_top_contact:.6g}: {REGIMES[self.regime]}"
