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
    """Detachment along the path a user follows, or why there is none.

    control: 'load', 'grip' or 'grip-work'; P [N/m] (negative: pulling), contact_width [m] (2 R eps just
    before detachment) and delta [m] at detachment, None if the pin does not detach; state: the last stable
    equilibrium (the fold), also without detachment; reason: what happens at the end of the path.
    """

    control: str
    P: Optional[float]
    contact_width: Optional[float]
    delta: Optional[float]
    state: Optional[Equilibrium]
    reason: str

    @property
    def detached(self) -> bool:
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

    kind: 'snap-in', 'pull-off', 'zip' or 'top-contact' (jkrcyl.analysis.cycle); leg: 0 for the first loading,
    then alternately down and up; before, after: the states it joins (same held quantity).
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
    """A quasi-static cycle: the path P [N/m], delta, delta_work [m] (jumps are straight segments between two
    points), branch, a, stable and leg per point, the jumps, the energy dissipated per cycle [J/m] (the area of
    the closed steady loop, int P d(delta); None if it did not close), the first leg of that loop, the driven
    limits and why the path stopped early, if it did.
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
    limits: tuple = None

    def __repr__(self) -> str:
        e = "n/a" if self.dissipated is None else f"{self.dissipated:.6g} J/m"
        return f"Cycle({self.control}: {len(self.P)} points, {len(self.jumps)} jumps, dissipated {e})"

    def table(self) -> dict:
        """Columns for CSV output (physical units)."""
        return {"leg": self.leg, "branch": self.branch, "a": self.a, "P": self.P, "delta": self.delta,
                "delta_work": self.delta_work, "stable": self.stable}


@dataclass(frozen=True)
class ConfinedEvents:
    """What happens to the pin under slow upward loading (load control) at (M, vartheta).

    regime: a key of :data:`REGIMES`; start: (a, P*) where the load path starts (the stable zero-load contact;
    (inf, nan) when the pin is bonded from first touch); P_fold: P* at the fixed-load adherence point met first
    (nan if the gap closes first); P_top_contact: P* at which the top contact forms on that path (nan if the
    fold comes first); onsets: every single-patch state with h(pi) = 0 as (eps, P*, delta/Delta, stable under
    load); grip_detachment: a feasible fixed-grip stationary point (min of delta) before the gap closes, i.e.
    the pin can be held free in the hole; two_patch_stable_load / _grip: any two-patch state stable under load /
    grip; full_contact: some two-patch branch runs into full contact; branches: the TwoPatchCurve list; gb,
    alpha_ratio of the analysis; fold_in_tension: at a zip-full fold, full contact at that load is entirely in
    tension (None otherwise).
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
    gb: float = None
    alpha_ratio: float = 0.0
    fold_in_tension: bool = None

    def __repr__(self):
        return (f"ConfinedEvents({self.regime}: M={self.M:.6g}, theta={self.theta:.6g}, P_fold={self.P_fold:.6g}, "
                f"P_top_contact={self.P_top_contact:.6g}, {len(self.branches)} two-patch branches)")

    @property
    def description(self):
        return REGIMES[self.regime]

    @property
    def summary(self):
        """One line: the event, its load and what follows (no true detachment under load control in a hole)."""
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
