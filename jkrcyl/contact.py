"""A pin in a conforming hole: physical inputs in, equilibrium states out (thin layer over the kernels).

Units: any consistent set (SI: R, Delta [m], w [J/m^2], moduli [Pa], loads per unit length [N/m]).
"""
import functools
import math
import warnings
from dataclasses import dataclass
from typing import Optional

from ._validate import finite_scalar
from .contact_analyses import Analyses
from .contact_cohesive import CohesiveLaw
from .contact_fields import AtContactSize, State  # noqa: F401  (State: jkrcyl.State)
from .materials import Materials
from .laws import Dugdale, EdgeLaw, Griffith
from .laws import kinetic as _kinetic
from .model.problem import Problem
from .model.single_patch import solver
from .notices import ValidityWarning
from .numerics import kernels as _k
from .units import Units

PARALLEL_MIN = _k.PARALLEL_MIN   # state() uses the prange kernel from this many contact parameters on


#: Delta/R above which Contact warns: the gap Delta (1 - cos phi) of section 2 is the first order in Delta/R
#: of the exact gap between the circles, so the states carry relative errors of order Delta/R
DELTA_OVER_R_WARN = 0.05


@dataclass(frozen=True)
class Contact(Analyses, CohesiveLaw, AtContactSize):
    """A pin of radius R_D = R - Delta in a hole of radius R: the contact of the paper (SI units throughout).

    Parameters
    ----------
    R : float
        Hole radius [m], > 0.
    Delta : float
        Radial clearance R - R_D [m], in [0, R).  The theory assumes Delta << R (a
        :class:`ValidityWarning` above Delta/R = 0.05).
    w : float
        Work of adhesion [J/m^2], >= 0.
    materials : jkrcyl.Materials
        The plane-strain material pair (hole and pin; either may be rigid).
    sigma0 : float, optional
        Shorthand for ``law=jkrcyl.laws.Dugdale(sigma0)``: the Maugis-Dugdale cohesive strength [Pa] > 0 (the
        traction sigma0 wherever 0 < gap <= h0 = w/sigma0; needs w > 0 and Delta > 0; or give the transition
        parameter: :meth:`with_lambda`).  The two spellings make the same contact.
    law : jkrcyl.laws.EdgeLaw, optional
        The edge law: ``jkrcyl.laws.Griffith()`` (JKR, the default), ``jkrcyl.laws.Dugdale(sigma0)`` or a law of
        one's own (jkrcyl.laws).  Every analysis (solve, pull_off, cycle, curve, adherence, two_patch) uses it;
        a branch family the law does not model is a ValueError naming the law's parameter.
    kinetics : jkrcyl.laws.Kinetic, optional
        Crack kinetics at the contact edges, e.g. ``jkrcyl.CrackKinetics(v_star=1e-6, n=0.6)``: shorthand for
        ``law=`` a :class:`jkrcyl.laws.Kinetic` (JKR at rest, so every quasi-static answer is unchanged); then
        ``pull_off(..., rate=...)``, ``respond`` and ``cycle(..., rate=...)`` answer in time (jkrcyl.kinetics).

    Raises
    ------
    ValueError
        Naming the parameter and its allowed range, for any input outside it.

    Examples
    --------
    >>> import jkrcyl
    >>> m = jkrcyl.Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)
    >>> pin = jkrcyl.Contact(R=10e-3, Delta=1e-6, w=0.05, materials=m)
    >>> round(pin.pull_off().P)                  # N/m
    -1555
    """

    R: float
    Delta: float
    w: float
    materials: Materials
    sigma0: Optional[float] = None
    law: Optional[EdgeLaw] = None
    kinetics: Optional[EdgeLaw] = None

    def __post_init__(self):
        object.__setattr__(self, "R", finite_scalar("R", self.R, low=0.0, low_open=True))
        object.__setattr__(self, "Delta", finite_scalar("Delta", self.Delta, low=0.0))
        if self.Delta >= self.R:
            raise ValueError(f"Delta must be in [0, R) = [0, {self.R:g}) (the pin radius R_D = R - Delta must be "
                             f"> 0), got {self.Delta!r}")
        object.__setattr__(self, "w", finite_scalar("w", self.w, low=0.0))
        if not isinstance(self.materials, Materials):
            raise ValueError(f"materials must be a jkrcyl.Materials, got {type(self.materials).__name__}")
        object.__setattr__(self, "law", _law(self.sigma0, _kinetic.law_with(self.kinetics, self.law, self.sigma0)))
        object.__setattr__(self, "sigma0", getattr(self.law, "sigma0", None))
        object.__setattr__(self, "kinetics", _kinetic.kinetics_or_none(self.law))
        self.law.check(self)
        if self.Delta > DELTA_OVER_R_WARN * self.R:
            warnings.warn(f"Delta/R = {self.Delta / self.R:.3g}: the theory assumes a clearance small against the "
                          f"hole radius (the gap of section 2 is first order in Delta/R); expect relative errors of "
                          f"order Delta/R", ValidityWarning, stacklevel=3)

    # --- parameters of sections 3-6 ---------------------------------------------------------------
    @property
    def beta(self):
        """beta* [1/Pa]."""
        return self.materials.beta

    @property
    def theta(self):
        """vartheta (section 4); inf for a rigid cradle."""
        return self.materials.theta

    @property
    def A(self):
        """A = beta*/(2 pi) of (3.5)."""
        return self.beta / (2 * math.pi)

    @property
    def zeta(self):
        """zeta* = sqrt(2 w R/A) of (3.6) (w: the law's edge work, jkrcyl.model.edge_law.EdgeLaw.edge_work)."""
        return math.sqrt(2 * self.law.edge_work(self.w) * self.R / self.A)

    @property
    def a_crit(self):
        """The receding contact a_crit (section 4: the pole of the load), for this material pair (alpha* != 0
        included: the single-patch solver's pole); inf for a rigid cradle at alpha* = 0 (section 7.2)."""
        return solver(Problem.of_materials(self.materials)).a_crit

    @property
    def problem(self):
        """The normalised problem (section 6) of this contact (needs Delta > 0)."""
        return Problem.of(self)

    @property
    def load_scale(self):
        """P / P*: 4 pi Delta vartheta/beta* (section 6), or 4 pi Delta/beta* for vartheta = inf (7.6)."""
        self._require_clearance("P_star")
        th = self.theta
        return 4 * math.pi * self.Delta * (1 if math.isinf(th) else th) / self.beta

    @functools.cached_property
    def units(self) -> Units:
        """The factors between this contact's physical, normalised and kernel scales (jkrcyl.units.Units)."""
        self._require_clearance("units")
        return Units.of(self)

    @property
    def M(self):
        """M = sqrt(w A R)/(sqrt(2) Delta vartheta) (section 6); M_R* of (7.6) when vartheta = inf."""
        self._require_clearance("M")
        return self.zeta / self.load_scale

    def _require_clearance(self, what):
        if self.Delta == 0:
            raise ValueError(f"{what} is undefined for Delta = 0 (neat fit, section 7.3): "
                             "it normalises by Delta; use the dimensional values")


def _law(sigma0, law) -> EdgeLaw:
    """The contact's law from the shorthand sigma0 or law= (both: they must agree)."""
    if law is not None and not isinstance(law, EdgeLaw):
        raise ValueError(f"law must be a jkrcyl.laws.EdgeLaw (e.g. jkrcyl.laws.Griffith() or "
                         f"jkrcyl.laws.Dugdale(sigma0)), got {law!r}")
    if sigma0 is None:
        return Griffith() if law is None else law
    shorthand = Dugdale(sigma0)
    if law is not None and law != shorthand:
        raise ValueError(f"sigma0: give the law once (sigma0={sigma0!r} is Dugdale(sigma0), law={law!r})")
    return shorthand
