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
    """A pull-off at a finite rate, from the zero-load contact at rest: what ``Contact.pull_off(control,
    rate=...)`` returns (true when an event ended the single patch).

    Attributes
    ----------
    control : str
        'load' (the load ramped down), 'grip-work' or 'grip' (the approach pulled).
    kind : str
        The first event that ends the single patch, 'separation' (the contact vanished) or 'top-contact' (the
        gap at phi = pi closed first); '' when none (``reason`` says why).
    P : float or None
        The largest tension up to that event [N/m] (what a testing machine reads; the load at the event under
        load control).
    contact_width : float or None
        The width at that largest tension [m] (0 under load control at separation).
    delta, delta_work : float or None
        The approaches at the event [m] (the held one under grip: the approach at which the pin lets go).
    rate : float
        N/m/s (load) or m/s (either approach).
    history : History
        The whole record.
    reason : str
        What ended the ramp, in words.

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m,
    ...                      kinetics=jkrcyl.CrackKinetics(v_star=1e-6, n=0.6))
    >>> po = pin.pull_off("grip-work", rate=1e-11)            # m/s
    >>> po.kind, round(po.P, -1), round(pin.pull_off("grip-work").P)   # N/m: at the rate, and quasi-static
    ('separation', -2100.0, -839)
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
    ``rate`` from the zero-load contact at rest, until the loop repeats; what ``Contact.cycle(..., rate=...)``
    returns.

    Attributes
    ----------
    P, delta, delta_work, a, leg : numpy.ndarray
        The path (the history's, thinned): load [N/m], approaches [m], contact parameter, leg number.
    jumps : list
        Empty: the edges move at finite speed.
    dissipated : float or None
        int P d(delta_work) round the last loop, top to top [J/m]: once the loop repeats, the energy the edges
        dissipated over it; None if an event ended the single patch first.
    edge_dissipation : float or None
        The edges' dissipation over that loop, int (G - w) over the crack advance [J/m].
    closed_from_leg : int or None
        The first leg of the loop where it repeated (to jkrcyl.kinetics.ramps.LOOP_REPEATS), None if not
        (``note`` says why).
    rate : float
        N/m/s (load) or m/s (either approach).
    frequency : float
        Of the loop [Hz]: the rate over twice the held range.
    history : History
        The record.

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m,
    ...                      kinetics=jkrcyl.CrackKinetics(v_star=1e-6, n=0.6))
    >>> cy = pin.cycle(P_max=1000.0, P_min=-1000.0, rate=0.04)    # N/m/s: 1e-5 Hz
    >>> cy.frequency, cy.closed_from_leg is not None, abs(cy.edge_dissipation / cy.dissipated - 1) < 1e-6
    (1e-05, True, True)
    """

    rate: Optional[float] = None
    frequency: Optional[float] = None
    history: Optional[History] = None
    edge_dissipation: Optional[float] = None

    def __repr__(self) -> str:
        e = "n/a" if self.dissipated is None else f"{self.dissipated:.6g} J/m"
        return (f"RateCycle({self.control} at {self.frequency:.6g} Hz: {len(self.P)} points, "
                f"{len(self.history.t)} states, dissipated {e})")
