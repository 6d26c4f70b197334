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
    """An event of a :class:`History`.

    Attributes
    ----------
    kind : str
        One of :data:`EVENTS`: 'separation', 'top-contact', 'peak-tension' or 'range-end'.
    t : float
        The time [s].
    P : float
        The load there [N/m].
    delta, delta_work : float
        The paper's and the work-conjugate approach there [m].
    index : int
        Its row in the History's arrays.

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m,
    ...                      kinetics=jkrcyl.CrackKinetics(v_star=1e-6, n=0.6))
    >>> pin.pull_off("grip-work", rate=1e-11).history.events[-1].kind
    'separation'
    """

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

    What :meth:`jkrcyl.Contact.respond` returns, and the record of a pull-off or a cycle at a rate.

    Attributes
    ----------
    control : str
        The held quantity: 'load', 'grip' or 'grip-work'.
    t : numpy.ndarray
        Time [s].
    P : numpy.ndarray
        Load [N/m] (negative: tension).
    delta, delta_work : numpy.ndarray
        The paper's and the work-conjugate approach [m].
    eps, contact_width : numpy.ndarray
        The contact half-angle [rad] and the width 2 R eps [m].
    G : numpy.ndarray
        The energy release rate at both edges [J/m^2] (the patch is symmetric).
    v : numpy.ndarray
        The crack speed of each edge, R abs(d eps/dt) [m/s], signed: positive where the crack opens (the contact
        recedes, G > w), negative where it closes.
    h_pi : numpy.ndarray
        The gap at the top of the hole [m].
    work : numpy.ndarray
        The work done on the pin since t[0], int P d(delta_work) [J/m].
    dissipated : numpy.ndarray
        The energy the edges dissipated since t[0], int (G - w) over the crack advance of both edges [J/m] (>= 0).
    potential : numpy.ndarray
        The total potential [J/m] (elastic energy less w times the contact width): work = change of potential +
        dissipated.
    events : tuple of Event
        In time order; the terminal one (if any) last, its row the last row.
    note : str
        What else the integration has to say (a restart past a fold), or ''.

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m,
    ...                      kinetics=jkrcyl.CrackKinetics(v_star=1e-6, n=0.6))
    >>> h = pin.respond([0.0, 1.0, 10.0], P=[0.0, -1000.0, -1000.0])   # a load step, then held
    >>> h.end, round(float(h.contact_width[-1]) * 1e3, 1), bool(h.G[-1] > pin.w)  # receding: G > w
    ('end', 27.0, True)
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
        """The first :class:`Event` of a kind (:data:`EVENTS`), or None."""
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
