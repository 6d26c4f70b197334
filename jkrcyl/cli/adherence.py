"""``jkrcyl adherence``: fixed-load and fixed-grip adherence, the zero-load contact and what slow pulling does in
the hole (jkrcyl.equilibria.adherence, zero_load_contact, confined_events)."""
from __future__ import annotations

import json
import math
import sys

from .. import equilibria as eq
from ..model.single_patch import solver
from ..results.paths import REGIMES
from . import inputs


def _finite(x):
    return None if not math.isfinite(x) else x


def confined_dict(ev):
    """The JSON of a jkrcyl.results.ConfinedEvents (non-finite numbers as null)."""
    return {"regime": ev.regime, "description": ev.description, "summary": ev.summary,
            "start": [_finite(ev.start[0]), _finite(ev.start[1])], "P_fold": _finite(ev.P_fold),
            "P_top_contact": _finite(ev.P_top_contact), "onsets": [list(o) for o in ev.onsets],
            "grip_detachment": ev.grip_detachment, "two_patch_stable_load": ev.two_patch_stable_load,
            "two_patch_stable_grip": ev.two_patch_stable_grip, "full_contact": ev.full_contact,
            "fold_in_tension": ev.fold_in_tension}


def point_dict(p):
    return {k: getattr(p, k) for k in ("control", "regime", "kind", "a", "eps", "eps_star", "P_star",
                                        "delta_over_Delta", "h_pi_over_Delta", "feasible", "outcome")}


def _zero_load(pi):
    """(contact parameters a0 with P* = 0 on every branch, from the pair's single-patch solver (closed form or
    collocation: jkrcyl.model.single_patch decides), and the largest M with a zero-load contact by (8.1), an
    alpha* = 0 result (inf for vartheta = inf))."""
    pb = eq.problem(pi.M, pi.theta, pi.gb, pi.alpha_ratio, s0=pi.s0)
    roots = [r for regime in solver(pb).regimes()
             for r in eq.solve_load(pi.M, pi.theta, 0.0, regime, gb=pi.gb, alpha_ratio=pi.alpha_ratio, s0=pi.s0)]
    return sorted(roots), eq.zero_load_max_M(pi.theta)[0]


def _print_text(pi, load, grip, a0, Mmax, confined):
    print(f"M = {pi.M:.10g}, theta = {pi.theta:g}, gb = {pi.gb:.10g} ({pi.gb_source}), "
          f"alpha*/beta* = {pi.alpha_ratio:.6g}, edge law: {pi.law_text}")
    print("fixed-load adherence (minimum of P* per branch):")
    for p in load:
        print(f"  {p.regime:14s} a = {p.a:.10g}  eps = {p.eps:.10g}  P* = {p.P_star:.10g}  "
              f"delta/Delta = {p.delta_over_Delta:.10g}  feasible = {p.feasible}"
              + (f"  outcome = {p.outcome}" if p.outcome else ""))
    if not load:
        print("  none (no minimum of P* on any branch)")
    print("fixed-grip stationary points (d delta/da = 0):")
    for p in grip:
        print(f"  {p.regime:14s} {p.kind} a = {p.a:.10g}  P* = {p.P_star:.10g}  "
              f"delta/Delta = {p.delta_over_Delta:.10g}  feasible = {p.feasible}")
    if not grip:
        print("  none")
    print("zero-load contact (P* = 0): " + (", ".join(f"a0 = {x:.10g}" for x in a0) if a0 else "none"))
    if not math.isinf(Mmax):
        print(f"  (8.1), alpha* = 0: roots for M <= {Mmax:.10g}")
    if confined:
        print(f"confined regime (slow upward loading, jkrcyl.equilibria.confined_events): {confined['regime']}")
        print(f"  {confined['summary']}")
        for key in ("P_fold", "P_top_contact"):
            if confined[key] is not None:
                print(f"  {key} = {confined[key]:.12g}")
        for e, P, d, st in confined["onsets"]:
            print(f"  gap closes at pi (single patch): eps = {e:.12g}  P* = {P:.12g}  delta/Delta = {d:.12g}"
                  f"  stable under load = {st}")
        print(f"  two-patch states stable under load: {confined['two_patch_stable_load']}, under grip: "
              f"{confined['two_patch_stable_grip']}; pin can be held free (grip): {confined['grip_detachment']}")


def run(args):
    pi = inputs.resolve(args)
    modelled = eq.problem(pi.M, pi.theta, pi.gb, pi.alpha_ratio, s0=pi.s0).models("two-patch")
    want_confined = not math.isinf(pi.theta) and pi.M > 0 and not args.no_confined and modelled
    common = dict(gb=pi.gb, alpha_ratio=pi.alpha_ratio)
    load = eq.adherence(pi.M, pi.theta, "load", confined=want_confined, s0=pi.s0, **common)
    grip = eq.adherence(pi.M, pi.theta, "grip", s0=pi.s0, **common)
    a0, Mmax = _zero_load(pi)
    Mmax = Mmax if modelled else math.inf       # (8.1) is JKR's (cohesive law: two patches not modelled either)
    confined = confined_dict(eq.confined_events(pi.M, pi.theta, **common)) if want_confined else None
    if args.format == "json":
        json.dump({**pi.meta(), "confined": confined, "load": [point_dict(p) for p in load],
                   "grip": [point_dict(p) for p in grip], "zero_load_a0": list(a0),
                   "zero_load_M_max": None if math.isinf(Mmax) else Mmax}, sys.stdout)
        sys.stdout.write("\n")
        return 0
    _print_text(pi, load, grip, a0, Mmax, confined)
    return 0


def register(sub):
    a = sub.add_parser("adherence", help="adherence forces and the zero-load contact",
                       description="Fixed-load adherence (P* minima), fixed-grip points (d delta/da = 0), "
                                   "the zero-load contact parameters of (8.1) (the solver's P* = 0 roots when "
                                   "alpha* != 0) and what slow pulling does in the hole (the confined regime: "
                                   + ", ".join(REGIMES) + "; jkrcyl.results.paths.REGIMES), for any material "
                                   "pair. The first line names the problem, with the gb used.")
    inputs.add_problem(a)
    a.add_argument("--format", choices=("text", "json"), default="text", help="output format (default text)")
    a.add_argument("--no-confined", action="store_true",
                   help="skip the confined-regime analysis (jkrcyl.equilibria.confined_events)")
    a.set_defaults(func=run)
