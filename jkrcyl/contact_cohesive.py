"""The cohesive (Maugis-Dugdale) side of :class:`jkrcyl.Contact`: the transition parameter, the range, the fields of
a cohesive state and the guard of the JKR-only methods (a mixin; the law itself is Contact.sigma0, issue 19)."""
import math
from collections import namedtuple

import numpy as np

from ._validate import finite_scalar
from .model.single_patch import solver
from .numerics import cohesive_scales as _scales

Fields = namedtuple("Fields", ["pressure", "gap"])
ContactStates = namedtuple("ContactStates", ["eps", "c", "P", "delta", "delta_work", "h_pi"])
ContactStates.__doc__ = """Single-patch states at given contact half-angles (arrays shaped like eps): eps, the zone
end c [rad] (eps for JKR, pi where the range reaches round), P [N/m], delta, delta_work, h_pi [m]."""
Fields.__doc__ = "pressure(phi) [Pa], compressive positive; gap(phi) [m]; phi [rad] from the bottom of the hole."


class CohesiveLaw:
    """Methods of Contact for the cohesive law (Contact.sigma0 [Pa]; None: JKR)."""

    @classmethod
    def with_lambda(cls, R, Delta, w, materials, lambda_):
        """The cohesive contact with transition parameter lambda = 4 sigma0/(pi^2 E*^2 w/R_eff)^(1/3) (Baney-Hui's,
        E* = 4/beta*, R_eff = R R_D/Delta: the conforming effective radius), lambda_ > 0; needs w > 0, Delta > 0."""
        jkr = cls(R, Delta, w, materials)
        lam = finite_scalar("lambda", lambda_, low=0.0, low_open=True)
        if jkr.w == 0 or jkr.Delta == 0:
            raise ValueError(f"lambda: the transition parameter needs w > 0 and Delta > 0, got w = {jkr.w!r}, "
                             f"Delta = {jkr.Delta!r}")
        s0 = _scales.zone_strength(lam, jkr.M * jkr.problem.scale, jkr.Delta / jkr.R)
        return cls(R, Delta, w, materials, s0 * 4 * math.pi * jkr.Delta / (jkr.R * jkr.beta))

    @property
    def lambda_(self):
        """The transition parameter lambda of the cohesive law (Baney-Hui's with R_eff = R R_D/Delta); None for
        JKR (lambda = inf)."""
        if self.sigma0 is None:
            return None
        return _scales.transition_parameter(self.M * self.problem.scale, self.problem.edge.s0, self.Delta / self.R)

    @property
    def h0(self):
        """The range of the cohesive law, w/sigma0 [m]; 0 for JKR."""
        return 0.0 if self.sigma0 is None else self.w / self.sigma0

    def _require_griffith(self, what):
        if self.sigma0 is not None:
            raise ValueError(f"sigma0: {what} is the JKR (Griffith) single patch at a given a; for the cohesive law "
                             "use curve(), solve(), pull_off(), cycle() (states carry eps and the zone end c in "
                             ".extra) and fields(state) for the pressure and the gap")

    def fields(self, state):
        """Pressure N(phi) [Pa] (compressive positive: -sigma0 on the zones) and gap h(phi) [m] of a cohesive
        Equilibrium made by this contact (single patch or zone only; mirrored states at the top by phi -> phi +
        pi): an object with .pressure(phi) and .gap(phi), phi [rad] from the bottom of the hole."""
        pb = self.problem
        sv = solver(pb)
        if self.sigma0 is None or state.branch.replace("-top", "") not in sv.regimes():
            raise ValueError(f"state: fields() needs a cohesive single-patch state of this contact, got {state!r}")
        f = sv.point(state.a).fields
        shift = math.pi if state.side == "top" else 0.0
        scale_N = 4 * math.pi * self.Delta / (self.R * self.beta)
        return Fields(lambda phi: scale_N * f.pressure(np.asarray(phi, dtype=float) + shift),
                       lambda phi: self.Delta * f.gap(np.asarray(phi, dtype=float) + shift))



    def at_contact(self, eps):
        """The bottom single-patch state at each contact half-angle eps [rad] in (0, pi) (scalar or array): a
        ContactStates of arrays, dimensional, from the single-patch solver (jkrcyl.model: SinglePatch.at_contact).
        JKR: the state at a = tan(eps/2).  The cohesive law: the state of the contact branch joined to the touch,
        the zone end's first root above the Dugdale estimate
        (jkrcyl.numerics.cohesive.cohesive_state, ~1e-10), the root that tends to JKR as sigma0 -> inf.  A contact
        size picks one state of that branch below its first turn in eps (curve().eps along the branch); where the
        branch turns back (large M at lambda of a few), widths beyond the turn have two states or none, and this
        gives the first root, which is then off the traced branch.  ValueError naming sigma0 beyond lambda = 1e4
        (thin zones up to there: the Dugdale end layer subtracted; beyond, JKR's state to O(lambda^-2))."""
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
