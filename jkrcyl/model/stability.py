"""Stability of equilibria, one home: the chain rule on one patch, the second variation on two.

One patch (section 8.3).  An equilibrium is stable under a control X (P, delta or delta_work held) when the edge
coefficient k of nu ~ -k/sqrt(eps - |phi|) grows with the contact at fixed X: G = w (pi k/m)^2 > w then opens the
crack, so a grown contact shrinks back (JKR: dG/da|_X > 0; the M -> 0 limit and the cohesive law read the same).
Along the equilibrium (k fixed by the edge law) the chain rule gives

    dk/da|_X = -(dX/da) / (dX/dk)|_a,          so stable under X  <=>  (dX/da) (dX/dk)|_a < 0,

with (dX/dk)|_a the fixed-arc derivative of the single-patch solver (p_k, dn_k; for delta_work
dn_k + c p_k).  Writing the rule with dX/dk rather than dk/dX keeps it finite where the fixed-arc system is
singular.  The release rates (1/w) dG/da|_X = (2 pi/m) dk/da|_X (section 8.3) follow (NaN without adhesion).

Two patches (jkrcyl.model.two_patch): the total potential must be a minimum -- :func:`two_patch_flags`.
"""
from __future__ import annotations

import math

import numpy as np

from ..units import CONTROLS


def stable(dX_da, dX_dk):
    """The one rule: stable under the held X where (dX/da) (dX/dk)|_a < 0 (module docstring); arrays or scalars."""
    return np.asarray(dX_da * dX_dk < 0)


def fixed_arc_derivatives(s, work_shift):
    """{control: (dX/dk)|_a} of a Slice: p_k, dn_k and dn_k + c p_k (c = Problem.work_shift)."""
    return {"load": s.p_k, "grip": s.dn_k, "grip-work": s.dn_k + work_shift * s.p_k}


def single_patch_flags(s, work_shift):
    """{control: stable (bool array)} of a single-patch Slice (module docstring)."""
    d = fixed_arc_derivatives(s, work_shift)
    return {ctl: stable(getattr(s, CONTROLS[ctl].field_slope), d[ctl]) for ctl in CONTROLS}


def release_rates(s, m, work_shift):
    """{control: (1/w) dG/da at fixed X} (section 8.3), NaN without adhesion (m = 0: w = 0)."""
    d = fixed_arc_derivatives(s, work_shift)
    with np.errstate(divide="ignore", invalid="ignore"):
        return {ctl: (-2 * math.pi / m * getattr(s, CONTROLS[ctl].field_slope) / d[ctl]) if m > 0
                else np.full(np.shape(s.p), np.nan) for ctl in CONTROLS}


def positive_definite(H) -> bool:
    return bool(np.all(np.linalg.eigvalsh(H) > 0))


def two_patch_flags(H, grad_p, work_shift):
    """(stable_load, stable_grip, stable_grip_work) of a two-patch state from the Hessian H of the total
    potential Pi* = U* - 2 vartheta M^2 (eps + eps_top) in (eps, eps_top, delta/Delta) at fixed load and the
    gradient grad_p of p in the same variables (jkrcyl.model.two_patch.hessian).

    U* is the energy of the paper's approach delta; the true elastic energy adds the pin's own n = 1 field,
    (c/2) p^2 with c = work_shift (the step from delta to delta_work = delta + c p, derive/green.py), so:
    load: H + c g g^T positive definite (3x3); grip (delta held, section 8): the eps block of H (2x2);
    grip-work (delta_work held): H + c g g^T on the directions keeping delta_work fixed (d delta = -c dp).
    """
    c = work_shift
    Ht = H + c * np.outer(grad_p, grad_p)
    T = np.vstack([np.eye(2), -c * grad_p[:2] / (1.0 + c * grad_p[2])])
    return positive_definite(Ht), positive_definite(H[:2, :2]), positive_definite(T.T @ Ht @ T)
