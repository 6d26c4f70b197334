"""The normalised problem of section 6, validated once: (M, vartheta, gb, alpha*/beta*) and the edge law.

Normalisation (section 6): M = sqrt(w A R)/(sqrt(2) Delta vartheta), P* = P beta*/(4 pi Delta vartheta); for the
rigid cradle vartheta = inf (section 7.2) the same names carry M_R* = sqrt(w A R)/(sqrt(2) Delta) and
P_R* = P beta*/(4 pi Delta) of (7.6).  The solvers work in the kernel scale, vartheta-free: m = M vartheta
(M_R* for vartheta = inf) and p = P beta*/(4 pi Delta) = scale P*, scale = vartheta (1 for vartheta = inf).

``gb = (1/G_I)/beta*`` enters the approach delta (and so the stability at fixed delta) only; it has no default:
a material pair fixes it (identical nu = 0.3 bodies: 1/2.8; an incompressible pin: 1 - 1/(2 vartheta)).
``alpha_ratio = alpha*/beta*`` (second Dundurs parameter over beta*, in (-1, 1)); 0 is the paper's closed form.
"""
from __future__ import annotations

import math
from dataclasses import InitVar, dataclass

from .._validate import HUGE, TINY, finite_scalar, theta as _check_theta
from ..numerics import kernels as _k


@dataclass(frozen=True)
class Griffith:
    """JKR's edge law: the contact edge is a crack tip in equilibrium when G = w (3.5)-(3.6), i.e. the edge
    coefficient of nu ~ -k/sqrt(eps - |phi|) is k = m/pi (m = M vartheta)."""

    name: str = "JKR"

    def edge_coefficient(self, m: float) -> float:
        """k of nu = N R beta*/(4 pi Delta) at an edge in equilibrium (Griffith: (pi k/m)^2 = G/w = 1)."""
        return m / math.pi


    def stress_intensity(self, w: float, beta: float) -> float:
        """K [Pa m^1/2] at an edge in equilibrium: (pi/4) A K^2 = w (3.5)-(3.6), A = beta*/(2 pi)."""
        return math.sqrt(8 * w / beta)


GRIFFITH = Griffith()


@dataclass(frozen=True)
class Dugdale:
    """The Maugis-Dugdale cohesive law (issue 19): the traction sigma0 wherever 0 < gap <= h0 (anywhere on the
    circumference), w = sigma0 h0.  Normalised: s0 = sigma0 R beta*/(4 pi Delta) > 0 (the zone traction in the
    units of nu = N R beta*/(4 pi Delta)); the range h0/Delta = m^2/s0 (m = M vartheta).  The contact edge has a
    finite stress in equilibrium (edge coefficient k = 0); the states are those of jkrcyl.model.cohesive."""

    s0: float
    name: str = "Dugdale"

    def __post_init__(self):
        object.__setattr__(self, "s0", finite_scalar("s0", self.s0, low=0.0, low_open=True))

    def edge_coefficient(self, m: float) -> float:
        """k of nu ~ -k/sqrt(eps - |phi|) at a contact edge in equilibrium: 0 (finite stress, Maugis)."""
        return 0.0

    def stress_intensity(self, w: float, beta: float) -> float:
        """K at the contact edge in equilibrium: 0 (the zone carries the adhesion)."""
        return 0.0

    def range_over_Delta(self, m: float) -> float:
        """h0/Delta = m^2/s0."""
        return m * m / self.s0


def edge_law(s0=None):
    """The edge law of a normalised cohesive strength s0: None -> Griffith (JKR), else Dugdale(s0)."""
    return GRIFFITH if s0 is None else Dugdale(s0)


@dataclass(frozen=True)
class Problem:
    """A pin in a hole in the normalisation of section 6; frozen and hashable (the cache key of every solver).

    Attributes
    ----------
    M : float
        Normalised adhesion (section 6; M_R* of (7.6) when theta = inf), >= 0.
    theta : float
        vartheta = G beta*/(1 + kappa) >= 1/2 (section 4), or inf (rigid cradle).
    gb : float
        (1/G_I)/beta* in [0, 1]: enters the approach delta only.
    alpha_ratio : float
        alpha*/beta* in (-1, 1) (0: the paper's closed forms); every material pair has it below 1/(2 vartheta)
        (:meth:`require_material_pair`, which full contact and two patches need).
    edge : Griffith or Dugdale
        The edge law: JKR's Griffith condition (default), or the Maugis-Dugdale cohesive law ``Dugdale(s0)``.
    """

    M: float
    theta: float
    gb: float
    alpha_ratio: float = 0.0
    edge: object = GRIFFITH
    strict: InitVar[bool] = True     # False: derived from a validated Contact (no magnitude floor on M, gb)

    def __post_init__(self, strict):
        tiny = {} if strict else {"tiny": 0.0}
        object.__setattr__(self, "M", finite_scalar("M", self.M, low=0.0, **tiny))
        th = _check_theta(self.theta)
        object.__setattr__(self, "theta", th)
        if self.gb is None:
            raise ValueError("gb must be given: (1/G_I)/beta* in [0, 1] (the approach delta and the stability at "
                             "fixed delta depend on it; e.g. 1/2.8 for identical nu = 0.3 bodies, "
                             "1 - 1/(2 theta) for an incompressible pin)")
        object.__setattr__(self, "gb", finite_scalar("gb", self.gb, low=0.0, high=1.0, **tiny))
        ar = finite_scalar("alpha_ratio", self.alpha_ratio, low=-1.0, high=1.0, low_open=True, **tiny)
        if ar == 1.0:
            raise ValueError("alpha_ratio must be in (-1, 1) (|alpha*| < beta* for every elastic pair), got 1")
        object.__setattr__(self, "alpha_ratio", ar)
        if not isinstance(self.edge, (Griffith, Dugdale)):
            raise ValueError(f"edge must be jkrcyl.model.problem.Griffith() or Dugdale(s0), got {self.edge!r}")
        if isinstance(self.edge, Dugdale) and self.M == 0:
            raise ValueError("M must be > 0 with a Dugdale edge law (w > 0: lambda and h0 = w/sigma0 need it)")

    def require_material_pair(self):
        """alpha*/beta* < 1/(2 vartheta), which every material pair has (1/vartheta - 2 alpha*/beta* =
        (2/G + (kappa_I - 1)/G_I)/beta* > 0: the uniform mode of the pin in the hole has a positive compliance);
        full contact and two patches need it.  Returns the problem."""
        if not self.rigid_cradle and not self.alpha_ratio < 0.5 / self.theta:
            raise ValueError(f"alpha_ratio must be in (-1, 1/(2 theta)) = (-1, {0.5 / self.theta!r}) at theta = "
                             f"{self.theta!r} (no material pair has more), got {self.alpha_ratio!r}")
        return self

    def require_confined(self, what="two patches and full contact are", param="sigma0"):
        """ValueError for an edge law whose two-patch and full-contact states are not modelled (the cohesive law);
        returns the problem."""
        if not isinstance(self.edge, Griffith):
            raise ValueError(f"{param}: {what} not modelled for the cohesive (Maugis-Dugdale) law (two patches and "
                             "full contact are JKR's only, issue 19); use sigma0=None")
        return self

    @classmethod
    def of(cls, contact) -> "Problem":
        """The normalised problem of a :class:`jkrcyl.Contact` with Delta > 0, with its edge law (Griffith, or
        Dugdale(s0) when the contact has sigma0: s0 = sigma0 R beta*/(4 pi Delta))."""
        m = contact.materials
        edge = GRIFFITH
        if contact.sigma0 is not None:
            unit = contact.R * m.beta / (4 * math.pi * contact.Delta)          # s0 per sigma0 [1/Pa]
            if not TINY <= contact.sigma0 * unit <= HUGE:
                raise ValueError(f"sigma0 must be in [{TINY / unit:.3g}, {HUGE / unit:.3g}] Pa for this contact (its "
                                 f"normalised s0 = sigma0 R beta*/(4 pi Delta) within the supported domain), got "
                                 f"{contact.sigma0!r}")
            edge = Dugdale(contact.sigma0 * unit)
        return cls(contact.M, m.theta, m.inv_G_I / m.beta, m.alpha_ratio, edge, False)

    @classmethod
    def of_materials(cls, materials, M: float = 0.0) -> "Problem":
        """The problem of a :class:`jkrcyl.Materials` pair at adhesion M (M = 0: what does not depend on it)."""
        m = materials
        return cls(M, m.theta, m.inv_G_I / m.beta, m.alpha_ratio, GRIFFITH, False)

    @property
    def rigid_cradle(self) -> bool:
        """vartheta = inf (section 7.2): M and P* are M_R* and P_R*."""
        return math.isinf(self.theta)

    @property
    def scale(self) -> float:
        """p/P*: vartheta, or 1 for the rigid cradle."""
        return 1.0 if self.rigid_cradle else self.theta

    @property
    def inv_theta(self) -> float:
        return 0.0 if self.rigid_cradle else 1.0 / self.theta

    @property
    def m(self) -> float:
        """M vartheta (M_R* for vartheta = inf): the adhesion in the kernel scale."""
        return self.M * self.scale

    @property
    def work_shift(self) -> float:
        """c in delta_work/Delta = delta/Delta + c p (p = scale P*): the derived k1_work - k1 = gb/2 of
        derive/green.py, read off the emitted kernel (not retyped)."""
        return _k.work_shift(self.gb)


    def __repr__(self):
        law = self.edge.name if isinstance(self.edge, Griffith) else f"{self.edge.name}(s0={self.edge.s0!r})"
        return (f"Problem(M={self.M!r}, theta={self.theta!r}, gb={self.gb!r}, alpha_ratio={self.alpha_ratio!r}, "
                f"edge={law})")
