"""The results of driving a contact with crack kinetics: :class:`RatePullOff` and :class:`RateCycle` (the
quasi-static :class:`~jkrcyl.results.PullOff` and :class:`~jkrcyl.results.Cycle` with the rate and the whole
time :class:`~jkrcyl.kinetics.history.History`)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

from ..results import Cycle, PullOff
from .history import History


@dataclass(frozen=True, repr=False)
class RatePullOff(PullOff):
    """A pull-off at a finite rate, from the zero-load contact at rest.

    kind: the first event that ends the single patch, 'separation' (the contact vanished) or 'top-contact' (the
    gap at phi = pi closed first); '' when none (reason says why).  P [N/m]: the largest tension up to that
    event (what a testing machine reads; the load at separation under load control); contact_width [m]: the
    width at that largest tension (0 under load control, where the tension grows until the contact is gone);
    delta [m] and :attr:`delta_work` [m]: the approaches at the event (the held one under grip: the approach at
    which the pin lets go); rate: N/m/s (load) or m/s (either approach); history: the whole record.
    """

    kind: str = ""
    rate: Optional[float] = None
    history: Optional[History] = None
    delta_work_at_event: Optional[float] = None

    @property
    def delta_work(self) -> Optional[float]:
        return self.delta_work_at_event

    def __repr__(self) -> str:
        if self.detached:
            return (f"RatePullOff({self.control} at {self.rate:.6g} {'N/m/s' if self.control == 'load' else 'm/s'}"
                    f": {self.kind}, P={self.P:.6g} N/m, delta_work={self.delta_work:.4g} m)")
        return f"RatePullOff({self.control}: none -- {self.reason})"


@dataclass(frozen=True, repr=False)
class RateCycle(Cycle):
    """A cycle at a finite rate: the held quantity driven up to the maximum, down to the minimum and up again at
    ``rate`` (N/m/s or m/s), from the zero-load contact at rest, until the loop repeats.

    The path (P, delta, delta_work, a, leg) is the history's, thinned; there are no jumps (the edges move
    at finite speed); dissipated [J/m]: int P d(delta_work) round the last loop (top to top), which equals the
    energy the edges dissipated over it (edge_dissipation, int (G - w) over the crack advance) once the loop
    repeats; closed_from_leg: the first leg of that loop where it repeated (to jkrcyl.kinetics.ramps.LOOP_REPEATS),
    None if not (note says why); dissipated None if an event ended the single patch first.  frequency [Hz] of
    the loop (rate over twice the held range); history: the record.
    """

    rate: Optional[float] = None
    frequency: Optional[float] = None
    history: Optional[History] = None
    edge_dissipation: Optional[float] = None

    def __repr__(self) -> str:
        e = "n/a" if self.dissipated is None else f"{self.dissipated:.6g} J/m"
        return (f"RateCycle({self.control} at {self.frequency:.6g} Hz: {len(self.P)} points, "
                f"{len(self.history.t)} states, dissipated {e})")
