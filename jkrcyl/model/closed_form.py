"""The paper's closed forms (alpha* = 0) behind the single-patch interface: the emitted kernels, normalised
(generated/derivatives.py: p, delta, delta_work and their slopes, the fixed-arc (1/w) dG/dp and d delta/dp) and
physical (generated/state.py, load.py, gap.py: (4.4)-(5.10) in SI units)."""
from __future__ import annotations

import functools
import math

import numpy as np

from .._validate import A_MAX
from ..numerics import kernels as _k
from ..numerics import roots as _roots
from .patch import SinglePatch, Slice

_STAR_FIELD = {"p": _k.STAR_FIELDS["P_star"], "dp_da": _k.STAR_FIELDS["dP_star_da"],
               "dn": _k.STAR_FIELDS["delta_over_Delta"], "ddn_da": _k.STAR_FIELDS["ddelta_da"],
               "dw": _k.STAR_FIELDS["delta_work_over_Delta"], "ddw_da": _k.STAR_FIELDS["ddelta_work_da"],
               "h": _k.STAR_FIELDS["h_pi"]}
_star_root = _roots.brent_solver(_k.star_residual_nb)


class ClosedForm(SinglePatch):
    """The normalised single patch from the closed forms."""

    dense_points = 4000        # points of a branch's search table (jkrcyl.analysis.branches)
    a_max = A_MAX              # the closed forms hold (and are stable) over the whole domain of a
    noise = 1e-15
    pole_needs_gb = False      # the root of 2 vartheta - log(1 + a^2) - 2 a^4 (section 4)

    def __init__(self, problem):
        self.problem = problem

    @functools.cached_property
    def a_crit(self) -> float:
        return float(_k.a_crit_nb(self.problem.theta))

    def _m(self):
        return self.problem.m if self.problem.m > 0 else 1e-150   # p, delta exact; m dG/dp is m-free

    def states(self, a) -> Slice:
        pb = self.problem
        a = np.ascontiguousarray(np.atleast_1d(np.asarray(a, dtype=float)))
        m = self._m()
        s = _k.star_m(a, inv_theta=pb.inv_theta, m=m, gb=pb.gb)
        p_k = 2 * math.pi / (m * s.dG_dp)              # (1/w) dG/dp = 2 pi/(m p_k) at k = m/pi
        return Slice(a=a, p=s.p, dp_da=s.dp_da, dn=s.delta_over_Delta, ddn_da=s.ddelta_da,
                     dw=s.delta_work_over_Delta, ddw_da=s.ddelta_work_da, h=s.h_pi_over_Delta,
                     p_k=p_k, dn_k=s.ddelta_dp * p_k, B=_k.bond_star(a, inv_theta=pb.inv_theta, m=m))

    def root(self, field, lo, hi, flo, fhi, target=0.0):
        pb = self.problem
        args = (pb.inv_theta, self._m(), pb.gb, _STAR_FIELD[field], 1.0, target)
        return _roots.brent_or_pole_nb(_star_root, _k.star_residual_nb, lo, hi, flo, fhi, args)


class ClosedFormPhysical:
    """States (4.4)-(5.10), pressure (5.4) and gap (5.9) of a Contact in SI units (any Delta >= 0)."""

    def __init__(self, contact):
        self.R, self.inv_G_I = contact.R, contact.materials.inv_G_I
        self._args = dict(Delta=contact.Delta, beta=contact.beta, inv_theta=contact.materials.inv_theta,
                          zeta=contact.zeta)

    def states(self, a):
        """{field: array} of jkrcyl.numerics.kernels.FullState at the 1-D contact parameters a."""
        return _k.full_state(a, R=self.R, inv_G_I=self.inv_G_I, **self._args)._asdict()

    def pressure(self, a, phi):
        """(bounded, unbounded) parts of N(phi) [Pa] at one a, phi 1-D in (-pi, pi]; 0 outside the contact."""
        inside = np.abs(phi) < 2 * math.atan(a)
        nb, nu = _k.pressure(a, np.ascontiguousarray(np.where(inside, phi, 0.0)), R=self.R, **self._args)
        return np.where(inside, nb, 0.0), np.where(inside, nu, 0.0)

    def gap(self, a, phi):
        """h(phi) [m] (5.9), a and phi 1-D of equal length; 0 inside the contact."""
        return _k.gap(a, phi, **self._args)
