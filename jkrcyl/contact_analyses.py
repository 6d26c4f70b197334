"""What a :class:`jkrcyl.Contact` answers beyond its states: branches (sections 6 and 8), forward problems, paths
and cycles (jkrcyl.analysis), and their histories in time with crack kinetics (jkrcyl.kinetics).

A mixin of :class:`jkrcyl.Contact` (which brings R, Delta, w, the law, ``problem``, ``units``): each method
validates its own arguments and passes the normalised problem to the analysis that answers it."""
from __future__ import annotations

from typing import TYPE_CHECKING, List, Optional, Sequence, Tuple

from . import equilibria
from . import equilibria_bridge as _bridge
from ._validate import control as _check_control, count, finite_scalar
from .analysis import branches as _br
from .analysis import confined as _confined
from .analysis import cycle as _cycle
from .analysis import forward as _fw
from .analysis import pull_off as _pull_off
from .analysis.two_patch_family import family as _family
from .model import two_patch as _two
from .results import ConfinedEvents, Curve, Cycle, Equilibrium, Point, PullOff, TwoPatchCurve
from .units import control_of_physical

if TYPE_CHECKING:                             # jkrcyl.kinetics is loaded on first use
    from .kinetics import History

class Analyses:
    """Branches, forward problems, pull-off and cycles of a contact (mixed into :class:`jkrcyl.Contact`)."""

    # --- sections 6 and 8 ----------------------------------------------------------------------------
    def curve(self, regime: str = "sub-critical", n: int = 2000) -> Curve:
        """One equilibrium branch with P [N/m], delta and delta_work [m] (jkrcyl.equilibria.curve, section 6).

        Parameters
        ----------
        regime : str
            'sub-critical' or 'super-critical' (contact parameter a below or above a_crit, section 4); the
            cohesive law also 'contactless' (the zone alone) and 'top-bridge' (a second zone at the top, held by
            its own traction, from where the single patch's gap at the top falls to the range h0 up to where the
            top closes or, past the touch, the pin held by two zones touches the top: every state a saddle;
            the states as traced, a = j + c_top/pi on the family j, ``Curve.ends`` says how each ends).
        n : int
            Points, uniform in eps* = 2 atan(a/a_crit)/pi, >= 2 (not used for 'top-bridge').

        Returns
        -------
        jkrcyl.results.Curve
            Normalised and dimensional fields with the stability flags (8.3) under the three controls.

        Raises
        ------
        ValueError
            Naming regime (a branch this pair or law does not have: 'top-bridge' for JKR, whose top adheres at
            h(pi) = 0, or where the gap at the top never falls to the range with a minimum there) or n.

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> cv = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m).curve(n=50)
        >>> round(float(cv.P.min()))                         # N/m: the load-control pull-off
        -1555
        """
        n = count("n", n, low=2)
        if _bridge.check_regime(regime) == _bridge.TOP_BRIDGE:
            return _bridge.curve(self.problem).with_units(self.units)
        return _br.curve(self.problem, regime, n).with_units(self.units)

    def adherence(self, control: str = "load", confined: bool = True) -> List[Point]:
        """The adherence points: minima of P* (control 'load') or stationary approaches ('grip', 'grip-work').

        Parameters
        ----------
        control : str
            'load', 'grip' (the paper's delta held) or 'grip-work' (delta_work held).
        confined : bool
            Under load, say what a further pull does at each point (``outcome``: 'detachment', 'zip-full', or
            what the confined analysis finds where the gap at the top closes first).

        Returns
        -------
        list of jkrcyl.results.Point
            With P [N/m], delta and delta_work [m] (jkrcyl.equilibria.adherence).

        Raises
        ------
        ValueError
            Naming control.

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> pt, = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m).adherence()
        >>> round(pt.P), pt.outcome                              # N/m
        (-1555, 'detachment')
        """
        return equilibria.adherence_of(self.problem, control, confined=confined, units=self.units)

    def two_patch(self, n: Optional[int] = None) -> Tuple[TwoPatchCurve, ...]:
        """The two-patch branches (a second contact at the top of the hole, section 9), traced by continuation.

        Parameters
        ----------
        n : int, optional
            Points per branch after resampling (None: as traced), at most 100000.

        Returns
        -------
        tuple of jkrcyl.results.TwoPatchCurve
            With P [N/m], delta and delta_work [m].

        Raises
        ------
        ValueError
            For Delta = 0, a law without two patches (naming its
            parameter), materials with alpha* != 0 under the Maugis-Dugdale law, or n out of range.

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> branches = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m).two_patch()
        >>> len(branches), branches[0].ends                  # from the single patch to its mirror at the top
        (1, ('single', 'mirror'))
        """
        return tuple(b.with_units(self.units) for b in _family(self.problem, "two_patch() is").branches(n))

    def confined_events(self) -> ConfinedEvents:
        """What follows when the gap at phi = pi closes under slow pulling (jkrcyl.analysis.confined).

        Returns
        -------
        jkrcyl.results.ConfinedEvents
            The regime ('detachment', 'top-contact', ...) with the loads of the fold and of the top contact.

        Raises
        ------
        ValueError
            For Delta = 0 or a law without two patches (the Maugis-Dugdale law: naming sigma0 where its
            two-patch branches are not followed, jkrcyl.analysis.cohesive_two_patch).

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m).confined_events().regime
        'detachment'
        """
        pb = self.problem.require("two-patch-branches", "confined_events() is")
        return _confined.confined_events(_two.require_two_patch(pb))

    # --- forward problems and paths (jkrcyl.analysis) -----------------------------------------------------
    def solve(self, P: Optional[float] = None, delta: Optional[float] = None,
              branches: Optional[Sequence[str]] = None, delta_work: Optional[float] = None) -> List[Equilibrium]:
        """Every equilibrium at a given load or approach (exactly one of P, delta, delta_work).

        Parameters
        ----------
        P : float, optional
            Load [N/m] (positive pressing the pin down); stability judged at fixed load.
        delta : float, optional
            The paper's approach (5.8) [m]; stability at fixed delta.
        delta_work : float, optional
            The work-conjugate approach delta + P/(8 pi G_I) [m] (what a machine holding the pin's axis holds).
        branches : sequence of str, optional
            Branches to search (keys of jkrcyl.analysis.forward.BRANCH_SOLVERS; None: every one the law
            models).  Two-patch states are traced by continuation: seconds the first time, cached per contact.

        Returns
        -------
        list of jkrcyl.results.Equilibrium
            Sorted by contact size, each with its stability under the control given.

        Raises
        ------
        ValueError
            Naming P (not exactly one given), the value (not finite), branches or Delta (= 0).

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
        >>> [s.branch for s in pin.solve(P=-1000.0) if s.stable and s.feasible]
        ['sub-critical', 'sub-critical-top', 'full-contact']
        """
        given = {k: v for k, v in (("P", P), ("delta", delta), ("delta_work", delta_work)) if v is not None}
        if len(given) != 1:
            raise ValueError("P: give exactly one of P [N/m], delta [m] and delta_work [m]")
        self._require_clearance("solve")
        (name, value), = given.items()
        control, units = control_of_physical(name).name, self.units
        names = _fw.check_branches(branches, self.problem)
        return _fw.solve_normalised(self.problem, units, control, units.normalise(control, finite_scalar(name, value)),
                                    names, by_name=branches is not None)

    def pull_off(self, control: str = "load", rate: Optional[float] = None) -> PullOff:
        """Detachment along the stable path from first contact, or why there is none.

        Parameters
        ----------
        control : str
            'load', 'grip-work' (a machine holding delta_work) or 'grip' (the paper's delta held).
        rate : float, optional
            Crack kinetics only (``Contact(..., kinetics=...)``): the load ramped down at ``rate`` [N/m/s], or
            the held approach at ``rate`` [m/s], from the zero-load contact at rest (jkrcyl.kinetics).

        Returns
        -------
        jkrcyl.results.PullOff
            The force [N/m], contact width and approach [m] at detachment; P None with the reason where the pin
            does not detach (confined, zips into full contact, no adhesion).  With a rate:
            jkrcyl.kinetics.RatePullOff (the largest tension, the first event, the history).

        Raises
        ------
        ValueError
            Naming control, rate (not > 0 and finite; a rate without kinetics) or Delta (= 0).

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
        >>> po = pin.pull_off()
        >>> round(po.P), po.reason                               # N/m
        (-1555, 'detachment: the contact shrinks away (G > w)')
        >>> round(pin.pull_off("grip-work").P)                   # a machine lets go at a smaller tension
        -839
        """
        _check_control(control)
        self._require_clearance("pull_off")
        if rate is not None:
            from .kinetics import ramps           # loaded on first use (scipy's integrators)
            return ramps.pull_off(self, control, rate)
        return _pull_off.pull_off(self.problem, self.units, control)

    def respond(self, t, P=None, delta_work=None, delta=None) -> History:
        """The contact under a prescribed history, with crack kinetics at its edges.

        Parameters
        ----------
        t : array_like
            Increasing instants [s] (at least two).
        P, delta_work, delta : array_like, optional
            Exactly one: the load [N/m] or the held approach [m] at those instants, linear in between.  The
            contact starts from the equilibrium at rest at its first value.

        Returns
        -------
        jkrcyl.kinetics.History
            t, P, delta, delta_work, eps, contact width, G and speed of the edges, h(pi), work, dissipation and
            the events (separation, top contact).

        Raises
        ------
        ValueError
            Without crack kinetics (``Contact(..., kinetics=...)``), or naming t, P, delta_work or delta.

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> k = jkrcyl.CrackKinetics(v_star=1e-3, n=0.6)                         # v* [m/s]
        >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m, kinetics=k)
        >>> h = pin.respond([0.0, 1.0, 1000.0], P=[0.0, -1000.0, -1000.0])      # a step, then held
        >>> round(float(h.G[-1] / pin.w), 2)                    # G/w at the edges: creeping back to rest
        1.0
        >>> at_rest = pin.solve(P=-1000.0)[1]                   # the stable equilibrium at that load
        >>> round(float(h.contact_width[-1] / at_rest.contact_width), 2)
        1.0
        """
        self._require_clearance("respond")
        from .kinetics import ramps               # loaded on first use (scipy's integrators)
        return ramps.respond(self, t, P=P, delta_work=delta_work, delta=delta)

    def cycle(self, P_max: Optional[float] = None, P_min: Optional[float] = None, control: str = "load",
              n: int = 2000, delta_max: Optional[float] = None, delta_min: Optional[float] = None,
              rate: Optional[float] = None) -> Cycle:
        """A cycle from first contact up to the maximum, down to the minimum and up again.

        Parameters
        ----------
        P_max, P_min : float, optional
            The load limits [N/m] under control 'load'.
        control : str
            'load', 'grip' or 'grip-work'.
        n : int
            Points along the path, >= 10.
        delta_max, delta_min : float, optional
            The limits [m] of the held approach (delta for 'grip', delta_work for 'grip-work').
        rate : float, optional
            Crack kinetics only: the held quantity driven at ``rate`` [N/m/s or m/s] from the zero-load contact
            at rest until the loop repeats (jkrcyl.kinetics.RateCycle).

        Returns
        -------
        jkrcyl.results.Cycle
            The path, its jumps and the energy dissipated per cycle [J/m] (the area of the steady loop).

        Raises
        ------
        ValueError
            Naming a limit (missing, not finite, min >= max, or one of the other control), control, n or rate.

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
        >>> cy = pin.cycle(delta_max=0.0, delta_min=-1.5e-6, control="grip-work", n=200)
        >>> [j.kind for j in cy.jumps], cy.dissipated > 0        # snap in, let go, snap in again: a loop
        (['snap-in', 'pull-off', 'snap-in'], True)
        """
        _check_control(control)
        self._require_clearance("cycle")
        n = count("n", n, low=10)
        hi, lo = _limits(control, P_max=P_max, P_min=P_min, delta_max=delta_max, delta_min=delta_min)
        if rate is not None:
            from .kinetics import ramps           # loaded on first use (scipy's integrators)
            return ramps.cycle(self, control, hi, lo, rate, n)
        return _cycle.cycle(self.problem, self.units, control, hi, lo, n, self.approach_work)


def _limits(control, **given):
    """(maximum, minimum) of the held quantity under control, from the keywords given (ValueError naming one)."""
    names = ("P_max", "P_min") if control == "load" else ("delta_max", "delta_min")
    other = [k for k, v in given.items() if v is not None and k not in names]
    if other:
        raise ValueError(f"{other[0]} does not apply to control={control!r} (give {' and '.join(names)})")
    if given[names[0]] is None or given[names[1]] is None:
        raise ValueError(f"{names[0]}: control={control!r} needs {names[0]} and {names[1]}")
    hi, lo = finite_scalar(names[0], given[names[0]]), finite_scalar(names[1], given[names[1]])
    if not lo < hi:
        raise ValueError(f"{names[1]} must be < {names[0]}, got {names[1]} = {lo!r}, {names[0]} = {hi!r}")
    return hi, lo
