"""The regime atlas under the Maugis-Dugdale law at a given lambda: the confined classes of :mod:`.classify` over
(M, vartheta), each pair through the model core's load path (jkrcyl.analysis.path.pull_path, the walker that
Contact.pull_off and confined_events read).

Per pair (M, vartheta): the law's zone strength s0 of lambda (jkrcyl.numerics.cohesive_scales.zone_strength, the
half-plane convention of ``jkrcyl cohesive``), gb of an incompressible pin (no class depends on gb: load control),
then the first event of slow pulling from first contact, as :func:`jkrcyl.analysis.confined.confined_events`
decides it:

* a fold (or the end of the branch): ``CONF_TRANSFER`` where a further pull opens the edge, ``CONF_ZIP`` where it
  closes it (jkrcyl.analysis.pull_off.grows_under_pull); a branch ending on an unstable continuation under a pull
  ('let-go': the pin lets go there) is a transfer too;
* the gap at the top reaches the law's range, h(pi) = h0 (JKR: 0): ``CONF_TOP`` at that onset
  (jkrcyl.analysis.landing.top_onset: the top adheres there, earlier than JKR's); with ``two_patch`` refined by
  the law's confined_events (where the walker lands from the onset: ``CONF_TOP_TRANSFER`` / ``CONF_TOP_FULL`` /
  ``CONF_TWO_PATCH``);
* full contact at first touch: ``CONF_BONDED``; no first contact: ``CONF_NONE`` (also M = 0: no adhesion, no law);
* two law-only codes: ``CONF_FLOAT`` (the pin touches onto contacts whose zone reaches round, which push: no
  adherence force from first contact; small lambda) and ``CONF_REFUSED`` (the law's solver refuses the pair; its
  message is in ``reasons``).

``event_a`` is the paper's contact parameter tan(eps/2) of the event's state, ``event_P`` its P* (P_R* of (7.6)
on the vartheta = inf row); 0 where there is no event.  ``jkr_confined`` / ``jkr_event_P`` hold JKR's atlas
(:func:`jkrcyl.atlas.classify`, the numba route) on the same grid, for comparison.

The pairs are independent: Dask (optional dependency, ``pip install 'jkrcyl[map]'``) runs one task per pair on
``workers`` local processes, as jkrcyl.analysis.cohesive_map.
"""
from __future__ import annotations

import contextlib
import math
import sys

import numpy as np

from .._validate import count, finite_scalar
from ..analysis import landing, path
from ..analysis.confined import confined_events
from ..analysis.pull_off import grows_under_pull
from ..equilibria import incompressible_gb
from ..laws.dugdale import edge_of_strength
from ..model.problem import Problem
from ..model.single_patch import solver
from ..numerics import cohesive_scales as scales
from ..units import Units
from .classify import (CONF_BONDED, CONF_NONE, CONF_TOP, CONF_TRANSFER, CONF_ZIP, CONFINED, FROM_TWOPATCH,
                       _check_grid, classify, default_grid)

CONF_FLOAT, CONF_REFUSED = 8, 9
LAW_CONFINED = {**CONFINED,
                CONF_TOP: "the gap at pi reaches the law's range h0 first: the top adheres (two-patch analysis "
                          "not run)",
                CONF_FLOAT: "no adherence force from first contact: the zone reaches round and the contacts push "
                            "(the pin floats back)",
                CONF_REFUSED: "no answer: the law's solver refuses this pair (see reasons)"}
LAW_FIELDS_INT = ("confined", "jkr_confined")
LAW_FIELDS_FLOAT = ("event_a", "event_P", "jkr_event_P", "s0", "h0_over_Delta")
WORKERS_MAX = 64


def check_lambda(lam) -> float:
    """lambda > 0 and finite (the transition parameter of jkrcyl.numerics.cohesive_scales)."""
    return finite_scalar("lambda", lam, low=0.0, low_open=True)


def law_problem(M: float, theta: float, lam: float):
    """The Maugis-Dugdale problem of the pair at lambda (gb of an incompressible pin), M > 0."""
    gb = incompressible_gb(theta)
    jkr = Problem(M, theta, gb, 0.0)
    return Problem(M, theta, gb, 0.0, edge_of_strength(scales.zone_strength(lam, jkr.m)))


def _event(pb, two_patch: bool):
    """(code, a, P*) of the pair's first event under load control (module docstring)."""
    sol = solver(pb)
    if sol.unmodelled and sol.floats_onto() is None:
        raise ValueError(sol.unmodelled)
    un = Units.normalised(pb, K_edge=1.0)             # normalised: P = P*
    start, event, s, towards = path.pull_path(pb, un, "load")
    if event in ("none", "elsewhere"):
        return CONF_NONE, 0.0, 0.0
    if event == "bonded":
        return CONF_BONDED, 0.0, 0.0
    if event == "float":
        return CONF_FLOAT, 0.0, 0.0
    a = lambda x: math.tan(x.eps / 2)
    if event == "let-go":                              # the branch ends on an unstable continuation: detaches
        return CONF_TRANSFER, a(s), s.P_star
    if event in ("fold", "end"):
        code = CONF_ZIP if grows_under_pull(pb, s.a, "load", towards) else CONF_TRANSFER
        return code, a(s), s.P_star
    on = landing.top_onset(pb, un, s, "load")          # 'gap': where the top adheres, h(pi) = h0
    if two_patch:
        return FROM_TWOPATCH[confined_events(pb).regime], a(on), on.P_star
    return CONF_TOP, a(on), on.P_star


def classify_pair(M: float, theta: float, lam: float, two_patch: bool = False):
    """(code, event_a, event_P, s0, h0/Delta, reason) of one pair under the law at lambda (module docstring);
    reason is '' unless the code is CONF_REFUSED."""
    if M == 0:
        return CONF_NONE, 0.0, 0.0, 0.0, 0.0, ""
    pb = law_problem(M, theta, lam)
    s0, h0 = pb.edge.s0, pb.edge.range_over_Delta(pb.m)
    try:
        code, a, P = _event(pb, two_patch)
    except ValueError as exc:                          # the law's refusal: recorded, never a wrong class
        return CONF_REFUSED, 0.0, 0.0, s0, h0, str(exc)
    return code, float(a), float(P), s0, h0, ""


def _pairs(pairs, lam, two_patch):
    return [classify_pair(M, th, lam, two_patch) for M, th in pairs]


def classify_law(Ms, thetas, lam, workers: int = 2, two_patch: bool = False, progress: bool = False) -> dict:
    """The law's atlas on the grid Ms x thetas at lambda.

    Parameters
    ----------
    Ms, thetas : array_like
        1-D grids: M >= 0, vartheta >= 1/2 or inf (the rigid cradle: M and P* are M_R*, P_R* of (7.6)).
    lam : float
        The transition parameter lambda > 0 (jkrcyl.numerics.cohesive_scales; the s0 of each pair follows).
    workers : int
        Dask local processes (1: serial, in this process).
    two_patch : bool
        Refine every ``CONF_TOP`` pair by the law's confined_events (its two-patch landing).
    progress : bool
        A progress bar on stderr (tqdm over the pairs; Dask's over its tasks).

    Returns
    -------
    dict
        M, theta, lam, zero_load_M_max (JKR's (8.1), drawn for reference), every field of
        :data:`LAW_FIELDS_INT` / :data:`LAW_FIELDS_FLOAT` as an (n_theta, n_M) array, and reasons: a list of
        (theta, M, message) of the refused pairs.

    Raises
    ------
    ValueError
        Naming lambda, workers, M or theta.

    Examples
    --------
    >>> r = classify_law([0.0, 0.2], [math.inf], lam=50.0, workers=1)
    >>> [LAW_CONFINED[int(c)].split(":")[0] for c in r["confined"][0]]
    ['no load path (M = 0', 'pull-off at the sub-critical fold']
    >>> round(float(r["event_P"][0, 1]), 6), round(float(r["jkr_event_P"][0, 1]), 6)
    (-0.146345, -0.146345)
    """
    from tqdm import tqdm
    lam = check_lambda(lam)
    workers = count("workers", workers, 1, WORKERS_MAX)
    Ms, thetas = _check_grid(Ms, thetas)
    pairs = [(float(M), float(th)) for th in thetas for M in Ms]
    if workers == 1:
        done = [classify_pair(M, th, lam, two_patch)
                for M, th in tqdm(pairs, unit="pairs", disable=not progress, file=sys.stderr)]
    else:
        try:
            import dask
        except ImportError as exc:                     # pragma: no cover - depends on the install
            raise ValueError("workers: the law's atlas on more than 1 worker needs dask "
                             "(pip install 'jkrcyl[map]')") from exc
        from dask.diagnostics import ProgressBar
        n_chunks = min(len(pairs), 8 * workers)
        chunks = [pairs[k::n_chunks] for k in range(n_chunks)]        # interleaved: rows differ in cost
        with ProgressBar(dt=1.0, out=sys.stderr) if progress else contextlib.nullcontext():
            parts = dask.compute(*[dask.delayed(_pairs)(c, lam, two_patch) for c in chunks],
                                 scheduler="processes", num_workers=workers)
        done = [None] * len(pairs)
        for k, part in enumerate(parts):
            done[k::n_chunks] = part
    jkr = classify(Ms, thetas, parallel=False)
    shape = (thetas.size, Ms.size)
    out = {"M": Ms, "theta": thetas, "lam": np.array(lam), "zero_load_M_max": jkr["zero_load_M_max"],
           "confined": np.array([d[0] for d in done], dtype=np.int8).reshape(shape),
           "jkr_confined": jkr["confined"].astype(np.int8), "jkr_event_P": jkr["event_P"]}
    for q, name in enumerate(("event_a", "event_P", "s0", "h0_over_Delta"), start=1):
        out[name] = np.array([d[q] for d in done], dtype=float).reshape(shape)
    out["reasons"] = [(th, M, d[5]) for (M, th), d in zip(pairs, done) if d[5]]
    return out


def default_law_grid(n_M=24, n_theta=24, M_max=2.0, theta_min=0.5, theta_max=5.0, with_inf=True):
    """The law's coarse grid: M = linspace(0, M_max, n_M), vartheta = linspace(theta_min, theta_max, n_theta)
    (+ inf), as :func:`jkrcyl.atlas.default_grid`."""
    return default_grid(n_M, n_theta, M_max, theta_min, theta_max, with_inf)
