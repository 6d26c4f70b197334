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

from .._validate import finite_scalar, theta as _check_theta
from ..materials import snap_alpha
from ..numerics import kernels as _k
from .edge import Edge
from .griffith import GRIFFITH_EDGE


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
    edge : jkrcyl.model.edge.Edge
        The normalised edge law: JKR's Griffith condition (default, jkrcyl.model.griffith.GRIFFITH_EDGE), or any
        other law's (e.g. the Maugis-Dugdale ``jkrcyl.laws.DugdaleEdge(s0)``).
    """

    M: float
    theta: float
    gb: float
    alpha_ratio: float = 0.0
    edge: Edge = GRIFFITH_EDGE
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
        object.__setattr__(self, "alpha_ratio", snap_alpha(ar))
        if not isinstance(self.edge, Edge):
            raise ValueError(f"edge must be a normalised edge law (jkrcyl.model.edge.Edge, e.g. "
                             f"jkrcyl.laws.GRIFFITH_EDGE or jkrcyl.laws.DugdaleEdge(s0)), got {self.edge!r}")
        self.edge.check(self)

    def require_material_pair(self):
        """alpha*/beta* < 1/(2 vartheta), which every material pair has (1/vartheta - 2 alpha*/beta* =
        (2/G + (kappa_I - 1)/G_I)/beta* > 0: the uniform mode of the pin in the hole has a positive compliance);
        full contact and two patches need it.  Returns the problem."""
        if not self.rigid_cradle and not self.alpha_ratio < 0.5 / self.theta:
            raise ValueError(f"alpha_ratio must be in (-1, 1/(2 theta)) = (-1, {0.5 / self.theta!r}) at theta = "
                             f"{self.theta!r} (no material pair has more), got {self.alpha_ratio!r}")
        return self

    def models(self, family: str) -> bool:
        """Whether the branch family (two-patch, full-contact, super-critical, contactless) is modelled for the
        problem's edge law."""
        return self.edge.models(family)

    def require(self, family: str, what: str = "", param: str = "") -> "Problem":
        """ValueError (the edge law's one message) unless the branch family is modelled for its law; returns the
        problem."""
        self.edge.require(family, what, param)
        return self

    def not_modelled(self, family: str, what: str = "", param: str = "") -> str:
        """The edge law's one message where the branch family is not modelled for it ('' where it is): for the
        analyses that say why a path stops rather than raise."""
        return self.edge.not_modelled(family, what, param)

    @classmethod
    def of(cls, contact) -> "Problem":
        """The normalised problem of a :class:`jkrcyl.Contact` with Delta > 0, with its law's normalised edge."""
        m = contact.materials
        return cls(contact.M, m.theta, m.inv_G_I / m.beta, m.alpha_ratio, contact.law.edge(contact), False)

    @classmethod
    def of_materials(cls, materials, M: float = 0.0) -> "Problem":
        """The problem of a :class:`jkrcyl.Materials` pair at adhesion M (M = 0: what does not depend on it)."""
        m = materials
        return cls(M, m.theta, m.inv_G_I / m.beta, m.alpha_ratio, GRIFFITH_EDGE, False)

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
        law = self.edge.name if self.edge == GRIFFITH_EDGE else repr(self.edge)
        return (f"Problem(M={self.M!r}, theta={self.theta!r}, gb={self.gb!r}, alpha_ratio={self.alpha_ratio!r}, "
                f"edge={law})")
