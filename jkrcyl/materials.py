"""Material pair of section 2: (G, kappa) the confining body with the hole, (G_I, kappa_I) the indenter."""
from __future__ import annotations

import math
from dataclasses import dataclass

from ._validate import THETA_MAX, finite_scalar

ALPHA_TOLERANCE = 1e-9   # |alpha*| / beta* below this counts as alpha* = 0


def snap_alpha(ratio: float) -> float:
    """alpha*/beta*, exactly 0.0 where |alpha*/beta*| <= ALPHA_TOLERANCE: the one place that decides alpha* = 0.

    The closed forms, the engine's enrichment and every other test of alpha* read the snapped value.

    Parameters
    ----------
    ratio : float
        alpha*/beta* as computed (dimensionless).

    Returns
    -------
    float
        0.0 within the tolerance, else ``ratio`` unchanged.

    Examples
    --------
    >>> snap_alpha(3e-12), snap_alpha(0.1)
    (0.0, 0.1)
    """
    return 0.0 if abs(ratio) <= ALPHA_TOLERANCE else ratio


@dataclass(frozen=True)
class Materials:
    """The plane-strain material pair of section 2: the body with the hole (G, kappa) and the pin (G_I, kappa_I).

    kappa = 3 - 4 nu in plane strain (:meth:`from_young`).  Any pair is accepted: the closed forms of the paper need
    the second Dundurs parameter alpha* = (kappa - 1)/(2G) - (kappa_I - 1)/(2G_I) to vanish (section 2,
    :attr:`closed_form`); otherwise the collocation solver (jkrcyl.model.collocation) solves (2.1) numerically.

    Parameters
    ----------
    G : float
        Shear modulus of the body with the hole [Pa]; math.inf for a rigid cradle (vartheta = inf, section 7.2).
    kappa : float
        Its Kolosov constant, >= 1 (3 - 4 nu in plane strain, 1 when incompressible).
    G_I : float
        Shear modulus of the indenter (the pin) [Pa]; math.inf for a rigid pin.
    kappa_I : float
        Its Kolosov constant, >= 1.

    Raises
    ------
    ValueError
        Naming the parameter: not a real number, G or G_I <= 0, kappa < 1, both bodies rigid, a magnitude outside
        the documented domain (jkrcyl._validate), beta* not finite or vartheta above 1e100 (finite G), or kappa,
        kappa_I so far apart that |alpha*/beta*| rounds to 1.

    Examples
    --------
    >>> m = Materials(G=1e9, kappa=1.8, G_I=1e9, kappa_I=1.8)           # identical bodies, nu = 0.3
    >>> m.beta, m.theta, m.closed_form                                   # beta* = 2 (1.8 + 1)/(2e9)
    (2.8e-09, 1.0, True)
    >>> rigid_pin = Materials(G=1e6, kappa=2.0, G_I=math.inf, kappa_I=2.0)
    >>> rigid_pin.theta, round(rigid_pin.alpha_ratio, 12)              # vartheta = 1/2; (kappa - 1)/(kappa + 1)
    (0.5, 0.333333333333)
    """

    G: float
    kappa: float
    G_I: float
    kappa_I: float

    def __post_init__(self):
        for name in ("G", "G_I"):
            v = finite_scalar(name, getattr(self, name), low=0.0, low_open=True, allow_inf=True)
            object.__setattr__(self, name, v)
        for name in ("kappa", "kappa_I"):
            object.__setattr__(self, name, finite_scalar(name, getattr(self, name), low=1.0))
        if math.isinf(self.G) and math.isinf(self.G_I):
            raise ValueError("G and G_I are both inf: at least one body must be deformable")
        if not (math.isfinite(self.beta) and self.beta > 0 and (self.theta <= THETA_MAX or math.isinf(self.G))):
            raise ValueError(f"G, G_I: beta* must be finite and vartheta <= {THETA_MAX:g} or inf (supported domain), "
                             f"got G = {self.G!r}, G_I = {self.G_I!r}")
        if not abs(self.alpha_ratio) < 1.0:     # |alpha*| < beta* in exact arithmetic; rounds to 1 for huge kappa
            raise ValueError(f"kappa, kappa_I: alpha*/beta* must be in (-1, 1), got {self.alpha_ratio!r} (kappa = "
                             f"{self.kappa!r}, kappa_I = {self.kappa_I!r}: too far apart for double precision)")

    @classmethod
    def from_young(cls, E: float, nu: float, E_I: float, nu_I: float) -> "Materials":
        """The pair from Young's moduli and Poisson ratios, in plane strain (section 2).

        Parameters
        ----------
        E, E_I : float
            Young's moduli of the body with the hole and of the indenter [Pa], > 0; math.inf for a rigid body.
        nu, nu_I : float
            Poisson ratios, in (-1, 0.5].

        Returns
        -------
        Materials
            G = E/(2(1 + nu)) [Pa], kappa = 3 - 4 nu (and likewise for the indenter).

        Raises
        ------
        ValueError
            Naming E, nu, E_I or nu_I (or G, G_I for a pair outside the domain), with the allowed range.

        Examples
        --------
        >>> Materials.from_young(E=2.6e9, nu=0.3, E_I=2.6e9, nu_I=0.3)      # G = E/(2 (1 + nu)) = 1 GPa
        Materials(G=1000000000.0, kappa=1.8, G_I=1000000000.0, kappa_I=1.8)
        >>> steel_in_aluminium = Materials.from_young(E=70e9, nu=0.33, E_I=210e9, nu_I=0.3)
        >>> round(steel_in_aluminium.theta, 4), round(steel_in_aluminium.alpha_ratio, 4)
        (0.6702, 0.1167)
        """
        pairs = []
        for e_name, e, n_name, n in (("E", E, "nu", nu), ("E_I", E_I, "nu_I", nu_I)):
            e = finite_scalar(e_name, e, low=0.0, low_open=True, allow_inf=True)
            n = finite_scalar(n_name, n, low=-1.0, high=0.5, low_open=True)
            pairs.append((e / (2 * (1 + n)), 3 - 4 * n))
        (G, kappa), (G_I, kappa_I) = pairs
        return cls(G=G, kappa=kappa, G_I=G_I, kappa_I=kappa_I)

    @property
    def beta(self) -> float:
        """beta* = (kappa + 1)/(2G) + (kappa_I + 1)/(2G_I) [1/Pa] (section 2)."""
        return (self.kappa + 1) / (2 * self.G) + (self.kappa_I + 1) / (2 * self.G_I)

    @property
    def alpha_star(self) -> float:
        """Second Dundurs parameter in compliance form, (kappa - 1)/(2G) - (kappa_I - 1)/(2G_I) [1/Pa]."""
        return (self.kappa - 1) / (2 * self.G) - (self.kappa_I - 1) / (2 * self.G_I)

    @property
    def alpha_ratio(self) -> float:
        """alpha*/beta* (dimensionless, in (-1, 1); <= 1/2 in size for nu, nu_I >= 0); exactly 0 for the closed
        forms (:func:`snap_alpha`)."""
        return snap_alpha(self.alpha_star / self.beta)

    @property
    def closed_form(self) -> bool:
        """True when alpha* = 0 (|alpha*/beta*| <= ALPHA_TOLERANCE): the paper's closed forms hold exactly."""
        return self.alpha_ratio == 0.0

    def require_closed_form(self, what: str = "the closed form") -> None:
        """Raise ValueError (naming alpha*) unless alpha* = 0, the condition of the paper's closed forms.

        Parameters
        ----------
        what : str
            The operation that needs the closed form, quoted in the message.

        Returns
        -------
        None

        Raises
        ------
        ValueError
            Naming alpha* and its value where alpha* != 0 (|alpha*/beta*| > ALPHA_TOLERANCE).

        Examples
        --------
        >>> Materials.from_young(E=70e9, nu=0.33, E_I=210e9, nu_I=0.3).require_closed_form("Fig. 2")
        Traceback (most recent call last):
        ...
        ValueError: Fig. 2 needs alpha* = 0, got alpha* = ...
        """
        if not self.closed_form:
            raise ValueError(
                f"{what} needs alpha* = 0, got alpha* = (kappa - 1)/(2G) - (kappa_I - 1)/(2G_I) = "
                f"{self.alpha_star:.6g} (alpha*/beta* = {self.alpha_ratio:.3g}): the closed form of the paper "
                "holds only for (kappa - 1)/G = (kappa_I - 1)/G_I; use method='numeric' or 'auto'")

    @property
    def inv_theta(self) -> float:
        """1/vartheta (dimensionless, section 4); 0 for a rigid cradle (G = inf)."""
        th = self.theta
        return 0.0 if math.isinf(th) else 1 / th

    @property
    def theta(self) -> float:
        """vartheta = G beta*/(1 + kappa) = 1/2 + G (kappa_I + 1)/(2 G_I (1 + kappa)) >= 1/2 (section 4).

        Summed in the second form, so a rigid indenter (G_I = inf) gives exactly 1/2 (the first form rounds
        to 0.4999999999999999 for nu = 0.5)."""
        if math.isinf(self.G):
            return math.inf
        return 0.5 + self.G * (self.kappa_I + 1) / (2 * self.G_I * (1 + self.kappa))

    @property
    def inv_G_I(self) -> float:
        """1/G_I [1/Pa]; 0 for a rigid indenter."""
        return 1 / self.G_I
