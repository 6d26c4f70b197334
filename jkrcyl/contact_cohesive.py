"""The cohesive (Maugis-Dugdale) side of :class:`jkrcyl.Contact`: the transition parameter, the range, the fields of
a cohesive state and the states at a given contact size for any law (a mixin; the law itself is ``Contact.law``,
jkrcyl.laws)."""
from __future__ import annotations

import math
from collections import namedtuple

import numpy as np
from numpy.typing import ArrayLike

from ._validate import finite_scalar
from .model.single_patch import solver
from .numerics import cohesive_scales as _scales

Fields = namedtuple("Fields", ["pressure", "gap"])
ContactStates = namedtuple("ContactStates", ["eps", "c", "P", "delta", "delta_work", "h_pi"])
ContactStates.__doc__ = """Single-patch states at given contact half-angles (arrays shaped like eps): eps, the zone
end c [rad] (eps for JKR, pi where the range reaches round), P [N/m], delta, delta_work, h_pi [m]."""
Fields.__doc__ = "pressure(phi) [Pa], compressive positive; gap(phi) [m]; phi [rad] from the bottom of the hole."


class CohesiveLaw:
    """Methods of :class:`jkrcyl.Contact` for the cohesive law (``Contact.sigma0`` [Pa]; None: JKR)."""

    @classmethod
    def with_lambda(cls, R: float, Delta: float, w: float, materials: "jkrcyl.Materials",
                    lambda_: float) -> "jkrcyl.Contact":
        """The Maugis-Dugdale contact of a given transition parameter lambda instead of sigma0.

        lambda = 4 sigma0/(pi^2 E*^2 w/R_eff)^(1/3) is Baney-Hui's with E* = 4/beta* and R_eff = R R_D/Delta, the
        conforming effective radius (half-plane convention, Delta/R -> 0: jkrcyl.numerics.cohesive_scales).

        Parameters
        ----------
        R, Delta, w, materials
            As :class:`jkrcyl.Contact` (w > 0 and Delta > 0 here).
        lambda_ : float
            The transition parameter, > 0 (large lambda: short range, towards JKR).

        Returns
        -------
        jkrcyl.Contact
            With ``sigma0`` [Pa] set.

        Raises
        ------
        ValueError
            Naming lambda (<= 0, or w = 0 or Delta = 0) or a parameter of :class:`jkrcyl.Contact`.

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> pin = jkrcyl.Contact.with_lambda(R=10e-3, Delta=1e-6, w=0.05, materials=m, lambda_=5.0)
        >>> round(pin.sigma0), round(pin.lambda_, 12)                    # Pa
        (269949, 5.0)
        >>> E, R_eff = 4 / pin.beta, pin.R * (pin.R - pin.Delta) / pin.Delta
        >>> round(4 * pin.sigma0 / (math.pi ** 2 * E ** 2 * pin.w / R_eff) ** (1 / 3), 12)
        5.0
        """
        jkr = cls(R, Delta, w, materials)
        lam = finite_scalar("lambda", lambda_, low=0.0, low_open=True)
        if jkr.w == 0 or jkr.Delta == 0:
            raise ValueError(f"lambda: the transition parameter needs w > 0 and Delta > 0, got w = {jkr.w!r}, "
                             f"Delta = {jkr.Delta!r}")
        s0 = _scales.zone_strength(lam, jkr.M * jkr.problem.scale, jkr.Delta / jkr.R)
        return cls(R, Delta, w, materials, s0 * 4 * math.pi * jkr.Delta / (jkr.R * jkr.beta))

    @property
    def lambda_(self) -> float | None:
        """The transition parameter lambda of the cohesive law (:meth:`with_lambda`); None for JKR (lambda = inf)."""
        if self.sigma0 is None:
            return None
        return _scales.transition_parameter(self.M * self.problem.scale, self.problem.edge.s0, self.Delta / self.R)

    @property
    def h0(self) -> float:
        """The range of the law's adhesive traction [m]: w/sigma0 for the cohesive law, 0 for JKR."""
        return self.law.range(self)

    def _physical(self, method="auto"):
        """The law's dimensional solver at a given contact parameter a (state(a), pressure, gap): Griffith
        laws only (jkrcyl.laws.griffith.Griffith.physical)."""
        if not hasattr(self.law, "physical"):
            raise ValueError(f"{self.law.param}: state(a), pressure(a, phi) and gap(a, phi) are the JKR (Griffith) "
                             f"single patch at a given a, not the {self.law.name} law's; use curve(), solve(), "
                             "pull_off(), cycle() (states carry eps and the zone end c in .extra) and fields(state) "
                             "for the pressure and the gap")
        return self.law.physical(self, method)

    def fields(self, state: "jkrcyl.results.Equilibrium") -> Fields:
        """The pressure N(phi) [Pa] and the gap h(phi) [m] of a cohesive single-patch state of this contact.

        N is compressive positive and -sigma0 on the zones; mirrored states at the top are turned by phi -> phi + pi.

        Parameters
        ----------
        state : jkrcyl.results.Equilibrium
            A single-patch or zone-only state of this contact (from :meth:`jkrcyl.Contact.solve`, ``pull_off``,
            ``cycle``) under the cohesive law.

        Returns
        -------
        Fields
            ``.pressure(phi)`` and ``.gap(phi)``, phi [rad] from the bottom of the hole (arrays).

        Raises
        ------
        ValueError
            Naming state, where it is not a cohesive single-patch state (or the contact is JKR's: use
            :meth:`jkrcyl.Contact.pressure` and ``gap``).

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> pin = jkrcyl.Contact.with_lambda(R=10e-3, Delta=1e-6, w=0.05, materials=m, lambda_=5.0)
        >>> s = pin.solve(P=0.0)[0]
        >>> f, c = pin.fields(s), s.extra["c"]                     # c: the end of the zone [rad]
        >>> [round(float(N) / pin.sigma0, 9) for N in f.pressure(np.array([s.eps, c + 0.01]))]   # zone, beyond
        [-1.0, 0.0]
        >>> round(float(f.gap(np.array([c]))[0] / pin.h0), 9)      # the zone ends where the gap is h0
        1.0
        """
        pb = self.problem
        sv = solver(pb)
        if self.sigma0 is None or state.branch.replace("-top", "") not in sv.regimes():
            raise ValueError(f"state: fields() needs a cohesive single-patch state of this contact, got {state!r}")
        f = sv.point(state.a).fields
        shift = math.pi if state.side == "top" else 0.0
        scale_N = 4 * math.pi * self.Delta / (self.R * self.beta)
        return Fields(lambda phi: scale_N * f.pressure(np.asarray(phi, dtype=float) + shift),
                       lambda phi: self.Delta * f.gap(np.asarray(phi, dtype=float) + shift))

    def at_contact(self, eps: ArrayLike) -> ContactStates:
        """The bottom single-patch state at each contact half-angle eps, dimensional, for any law.

        From the single-patch solver (jkrcyl.model.patch.SinglePatch.at_contact).  JKR: the state at
        a = tan(eps/2).  The cohesive law: the state of the contact branch joined to the touch, the zone end's first
        root above the Dugdale estimate (jkrcyl.numerics.cohesive.cohesive_state, ~1e-10), the root that tends to
        JKR as sigma0 -> inf.  A contact size picks one state of that branch below its first turn in eps
        (``curve().eps`` along the branch); where the branch turns back (large M at lambda of a few), widths beyond
        the turn have two states or none, and this gives the first root, which is then off the traced branch.

        Parameters
        ----------
        eps : float or array_like
            Contact half-angle(s) [rad] in (0, pi).

        Returns
        -------
        ContactStates
            eps, the zone end c [rad], P [N/m], delta, delta_work, h_pi [m], arrays shaped like eps.

        Raises
        ------
        ValueError
            Naming eps (not real, outside (0, pi)), or sigma0 beyond lambda = 1e4 (thin zones up to there: the
            Dugdale end layer subtracted; beyond, JKR's state to O(lambda^-2)).

        Examples
        --------
        >>> import jkrcyl
        >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
        >>> jkr = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
        >>> bool(abs(jkr.at_contact(0.9).P / jkr.state(math.tan(0.45)).P - 1) < 1e-12)
        True
        >>> coh = jkrcyl.Contact.with_lambda(R=10e-3, Delta=1e-6, w=0.05, materials=m, lambda_=5.0)
        >>> st = coh.at_contact([0.5, 0.9])
        >>> [round(float(c), 4) for c in st.c], [round(float(P), 1) for P in st.P]     # zone end [rad], N/m
        ([0.5777, 0.9768], [-1398.6, -1545.2])
        """
        raw = np.asarray(eps)
        if raw.dtype.kind not in "iuf":
            raise ValueError(f"eps must be real contact half-angles in (0, pi) [rad], got dtype {raw.dtype}")
        arr = raw.astype(float)
        flat = np.atleast_1d(arr).ravel()
        if flat.size == 0 or not np.all(np.isfinite(flat)) or np.any((flat <= 0) | (flat >= math.pi)):
            raise ValueError(f"eps must be in (0, pi) [rad], got {flat[~((flat > 0) & (flat < math.pi))][:1]!r}")
        c, p, dn, dw, h = solver(self.problem).at_contact(flat)
        cols = (flat, c, p * 4 * math.pi * self.Delta / self.beta, dn * self.Delta, dw * self.Delta, h * self.Delta)
        return ContactStates(*(np.reshape(np.asarray(col, dtype=float), arr.shape) for col in cols))
