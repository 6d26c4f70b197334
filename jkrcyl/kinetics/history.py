"""What a time history records: :class:`History` (the states against time, SI units) and its :class:`Event` s."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Tuple

import numpy as np

#: the events of a history, and what each means
EVENTS = {
    "separation": "the contact vanished (both edges met at the bottom of the hole): the pin let go",
    "top-contact": "the gap at phi = pi closed while the bottom patch still existed (a second patch forms)",
    "peak-tension": "the largest tension so far under a held approach (the load turns back towards 0)",
    "range-end": "the contact grew to the end of the modelled single patch (towards a_crit, the pole of the load)",
}
#: the events that end the single patch (and the history)
TERMINAL = ("separation", "top-contact", "range-end")
COLUMNS = ("t", "P", "delta", "delta_work", "eps", "contact_width", "G", "v", "h_pi", "work", "dissipated",
           "potential")
UNITS = {"t": "s", "P": "N/m", "delta": "m", "delta_work": "m", "eps": "rad", "contact_width": "m",
         "G": "J/m^2", "v": "m/s", "h_pi": "m", "work": "J/m", "dissipated": "J/m", "potential": "J/m"}


@dataclass(frozen=True)
class Event:
    """An event of a history: its kind (:data:`EVENTS`), time t [s], load P [N/m] and held approaches delta,
    delta_work [m] there, and its row in the History's arrays."""

    kind: str
    t: float
    P: float
    delta: float
    delta_work: float
    index: int

    def __repr__(self):
        return f"Event({self.kind} at t={self.t:.10g} s: P={self.P:.6g} N/m, delta_work={self.delta_work:.6g} m)"


@dataclass(frozen=True, repr=False)
class History:
    """A single bottom patch under a prescribed load or approach, against time (SI units).

    t [s]; P [N/m] (negative: tension), delta and delta_work [m] (the paper's and the work-conjugate approach);
    eps [rad] the contact half-angle and contact_width = 2 R eps [m]; G [J/m^2] the energy release rate at
    both edges (the patch is symmetric); v [m/s] the crack speed of each edge, R |d eps/dt|, signed: positive
    where the crack opens (the contact recedes, G > w), negative where it closes; h_pi [m] the gap at the top
    of the hole; work [J/m] the work done on the pin since t[0], int P d(delta_work); dissipated [J/m] the energy
    the edges dissipated since t[0], int (G - w) over the crack advance of both edges (>= 0); potential [J/m] the
    total potential (elastic energy less w times the contact width; work = change of potential + dissipated).
    events: the :class:`Event` s in time order (the terminal one, if any, last and its row the last row);
    control: the held quantity ('load', 'grip', 'grip-work').
    """

    control: str
    t: np.ndarray
    P: np.ndarray
    delta: np.ndarray
    delta_work: np.ndarray
    eps: np.ndarray
    contact_width: np.ndarray
    G: np.ndarray
    v: np.ndarray
    h_pi: np.ndarray
    work: np.ndarray
    dissipated: np.ndarray
    potential: np.ndarray
    events: Tuple[Event, ...] = ()
    note: str = ""

    @property
    def end(self) -> str:
        """The terminal event's kind, or 'end' where the prescribed history ran out first."""
        last = self.events[-1].kind if self.events else ""
        return last if last in TERMINAL else "end"

    def first(self, kind: str):
        """The first event of a kind, or None."""
        return next((e for e in self.events if e.kind == kind), None)

    @property
    def peak(self) -> int:
        """The row of the largest tension (the smallest P)."""
        return int(np.argmin(self.P))

    def table(self) -> dict:
        """Columns for CSV output (:data:`UNITS`)."""
        return {k: getattr(self, k) for k in COLUMNS}

    def __len__(self):
        return len(self.t)

    def __repr__(self):
        ev = ", ".join(f"{e.kind} at {e.t:.6g} s" for e in self.events) or "no event"
        return f"History({self.control}: {len(self.t)} points from {self.t[0]:.6g} to {self.t[-1]:.6g} s; {ev})"
