"""The one parser of problem inputs, and the writers every command shares.

Problem inputs come in one of two sets:

* normalised (section 6): ``--M`` (M_R* when ``--theta inf``), ``--theta`` (default 1), ``--gb`` =
  (1/G_I)/beta* and ``--alpha-ratio`` = alpha*/beta* (default 0: the paper's closed forms);
* physical (SI units): ``--E --nu --E-I --nu-I --R --Delta --w``; M, vartheta, gb and alpha*/beta* are then the
  pair's, and the outputs carry physical columns too.

The edge law (both sets): JKR by default; the Maugis-Dugdale cohesive law with ``--sigma0`` [Pa] (physical inputs
only) or ``--lambda`` (the transition parameter; with normalised inputs lambda = 4 s0/m^(2/3), the half-plane
convention at Delta/R -> 0, s0 = sigma0 R beta*/(4 pi Delta), m = M vartheta).

gb: only delta/Delta, delta_work/Delta and the stability at fixed approach depend on it (never the load, the
contact size, h(pi) or the stability under load).  The library requires it; the command line keeps a default
for normalised input -- an incompressible pin, gb = 1 - 1/(2 vartheta) (:data:`GB_DEFAULT`) -- and prints the gb
it used, and where it came from, with every answer (:attr:`ProblemInput.gb_text`; JSON: ``gb``, ``gb_source``).

Numbers are printed with 10 significant digits, inf/nan spelled out, booleans as true/false, in every format.
"""
from __future__ import annotations

import argparse
import json
import math
import sys
from dataclasses import dataclass
from typing import Optional

import numpy as np

from .. import equilibria as eq
from ..contact import Contact
from ..laws import CrackKinetics
from ..materials import Materials
from ..units import CONTROLS

PHYSICAL = (("E", "Young's modulus of the body with the hole [Pa] (inf: rigid)"), ("nu", "its Poisson ratio"),
            ("E-I", "Young's modulus of the cylinder [Pa] (inf: rigid)"), ("nu-I", "its Poisson ratio"),
            ("R", "hole radius [m]"), ("Delta", "clearance R - R_D [m], > 0"), ("w", "work of adhesion [J/m^2]"))
GB_DEFAULT = "default: incompressible pin, 1 - 1/(2 theta); pass --gb"
GB_HELP = ("(1/G_I)/beta* in [0, 1]: only delta/Delta, delta_work/Delta and the stability at fixed approach depend "
           "on it. Default: an incompressible pin, 1 - 1/(2 vartheta) (0.5 at vartheta = 1; identical nu = 0.3 "
           "bodies have 1/2.8 = 0.3571, a rigid pin 0). The value used is printed with every answer")
UNITS = {"a": "", "a_top": "", "eps": "rad", "eps_top": "rad", "contact_width": "m", "P": "N/m", "delta": "m",
         "delta_work": "m", "h_pi": "m", "K": "Pa m^1/2", "P_star": "", "delta_over_Delta": "", "energy": "J/m"}
PHYSICAL_UNITS = {c.physical: c.unit for c in CONTROLS.values()}


def number_arg(text):
    """argparse type: a float ('inf', '-2e6' included), else an error naming the text."""
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None


def add_physical(p, title="physical inputs (SI units)"):
    g = p.add_argument_group(title)
    for name, helptext in PHYSICAL:
        g.add_argument(f"--{name}", type=number_arg, help=helptext)
    law = p.add_argument_group("edge law (default JKR; the Maugis-Dugdale cohesive law with one of)")
    law.add_argument("--sigma0", type=number_arg, default=None,
                     help="cohesive strength sigma0 [Pa] > 0 (physical inputs): traction sigma0 wherever "
                          "0 < gap <= h0 = w/sigma0")
    law.add_argument("--lambda", dest="lambda_", type=number_arg, default=None,
                     help="transition parameter lambda > 0 (Baney-Hui's, R_eff = R R_D/Delta; with --M: the "
                          "half-plane convention, s0 = lambda (M vartheta)^(2/3)/4)")


def add_kinetics(p):
    """--v-star, --n, --shift: crack kinetics at the contact edges (jkrcyl.CrackKinetics; physical inputs)."""
    g = p.add_argument_group("crack kinetics (rate-dependent adhesion: G = w [1 + (a_T v/v*)^n] at an opening edge)")
    g.add_argument("--v-star", type=number_arg, default=None, help="reference crack speed v* [m/s] > 0")
    g.add_argument("--n", dest="kinetic_n", type=number_arg, default=None, help="exponent n, 0 < n <= 2")
    g.add_argument("--shift", type=number_arg, default=None, help="temperature shift factor a_T > 0 (default 1)")


def kinetics_from(args):
    """The jkrcyl.CrackKinetics of --v-star --n --shift, or None when none is given (ValueError naming a missing
    one)."""
    v, n, shift = (getattr(args, k, None) for k in ("v_star", "kinetic_n", "shift"))
    if v is None and n is None and shift is None:
        return None
    if v is None or n is None:
        raise ValueError(f"{'v_star' if v is None else 'n'}: crack kinetics need --v-star and --n")
    return CrackKinetics(v_star=v, n=n, shift=shift)


def add_problem(p):
    """The normalised and the physical input sets (exactly one is used)."""
    g = p.add_argument_group("normalised inputs (section 6)")
    g.add_argument("--M", type=number_arg, help="adhesion parameter M = sqrt(wAR)/(sqrt(2) Delta vartheta) "
                   "(M_R* when --theta inf)")
    g.add_argument("--theta", type=number_arg, default=1.0, help="vartheta >= 0.5, or inf (default 1)")
    g.add_argument("--gb", type=number_arg, default=None, help=GB_HELP)
    g.add_argument("--alpha-ratio", type=number_arg, default=0.0,
                   help="alpha*/beta* in (-1, 1) (default 0: the paper's closed forms; otherwise the collocation "
                        "solver)")
    add_physical(p, "physical inputs (SI units; replace --M/--theta/--gb/--alpha-ratio)")


@dataclass(frozen=True)
class ProblemInput:
    """What a command computes for: the normalised problem, where gb came from, and the Contact (physical
    inputs only)."""

    M: float
    theta: float
    gb: float
    alpha_ratio: float
    gb_source: str
    contact: Optional[object] = None
    s0: Optional[float] = None        # the cohesive law (normalised), None: JKR

    @property
    def law_text(self) -> str:
        """The edge law in words: JKR, or the cohesive law's s0 (and lambda in the half-plane convention)."""
        return "JKR" if self.s0 is None else f"Dugdale(s0={number(self.s0)})"

    @property
    def gb_text(self) -> str:
        return f"gb={number(self.gb)} ({self.gb_source})"

    def meta(self) -> dict:
        """The JSON fields naming the problem."""
        return {"M": json_value(self.M), "theta": json_value(self.theta), "gb": json_value(self.gb),
                "gb_source": self.gb_source, "alpha_ratio": json_value(self.alpha_ratio), "s0": json_value(self.s0)}


def _physical_values(args):
    return [getattr(args, name.replace("-", "_"), None) for name, _ in PHYSICAL]


def physical_given(args) -> bool:
    """Whether any physical input was given."""
    return any(v is not None for v in _physical_values(args))


def contact_from(args):
    """A jkrcyl.Contact from --E --nu --E-I --nu-I --R --Delta --w (ValueError naming a missing one)."""
    values = _physical_values(args)
    for (name, _), v in zip(PHYSICAL, values):
        if v is None:
            raise ValueError(f"{name}: --{name} is required ({', '.join('--' + n for n, _ in PHYSICAL)})")
    E, nu, E_I, nu_I, R, Delta, w = values
    mats = Materials.from_young(E, nu, E_I, nu_I)
    sigma0, lam = getattr(args, "sigma0", None), getattr(args, "lambda_", None)
    if sigma0 is not None and lam is not None:
        raise ValueError("sigma0: give either --sigma0 or --lambda, not both")
    if lam is not None:
        return Contact.with_lambda(R, Delta, w, mats, lam)
    return Contact(R=R, Delta=Delta, w=w, materials=mats, sigma0=sigma0, kinetics=kinetics_from(args))


def resolve(args) -> ProblemInput:
    """The problem of either input set, validated (ValueError naming the parameter)."""
    if physical_given(args):
        if args.M is not None:
            raise ValueError("M: give either --M (with --theta, --gb) or the physical inputs, not both")
        c = contact_from(args)
        if c.Delta == 0:
            raise ValueError("Delta must be > 0 here (M and P* divide by Delta; neat fit: see jkrcyl.special)")
        M, th, gb = eq.from_contact(c)
        return ProblemInput(M, th, gb, c.materials.alpha_ratio, "physical inputs: (1/G_I)/beta* of the pair", c,
                            getattr(c.problem.edge, "s0", None))
    if args.M is None:
        raise ValueError("M is required (--M, or the physical inputs --E --nu --E-I --nu-I --R --Delta --w)")
    given = args.gb is not None
    th = eq.problem(args.M, args.theta, 0.0).theta           # validates M and theta before gb
    gb = args.gb if given else eq.incompressible_gb(th)
    if args.sigma0 is not None:
        raise ValueError("sigma0: --sigma0 [Pa] needs the physical inputs; with --M give --lambda")
    s0 = None if args.lambda_ is None else eq.zone_strength(args.lambda_, args.M, th)
    pb = eq.problem(args.M, th, gb, args.alpha_ratio, s0=s0)
    return ProblemInput(pb.M, pb.theta, pb.gb, pb.alpha_ratio, "--gb" if given else GB_DEFAULT, s0=s0)


def number(x) -> str:
    """10 significant digits, no noise; inf/nan spelled out; booleans true/false."""
    if isinstance(x, (bool, np.bool_)):
        return "true" if x else "false"
    if isinstance(x, str):
        return x
    x = float(x)
    return f"{x:.10g}" if math.isfinite(x) else ("inf" if x > 0 else "-inf" if x < 0 else "nan")


def json_value(x):
    if isinstance(x, str) or x is None:
        return x
    if isinstance(x, (bool, np.bool_)):
        return bool(x)
    x = float(x)
    return float(f"{x:.10g}") if math.isfinite(x) else None


def header(keys, units=None):
    """CSV header with units in brackets (default :data:`UNITS`; pass e.g. PHYSICAL_UNITS for P, delta only)."""
    units = UNITS if units is None else units
    return ",".join(f"{k} [{units[k]}]" if units.get(k) else k for k in keys)


def write_rows(rows, fmt, out=None, meta=None):
    """rows: list of dicts with equal keys; fmt 'csv' (a '# key=value' line first when meta) or 'json'."""
    out = sys.stdout if out is None else out
    if fmt == "json":
        json.dump({**({k: json_value(v) for k, v in (meta or {}).items()}),
                   "rows": [{k: json_value(v) for k, v in r.items()} for r in rows]}, out)
        out.write("\n")
        return
    if meta:
        out.write("# " + " ".join(f"{k}={number(v)}" for k, v in meta.items()) + "\n")
    if not rows:
        out.write("# no equilibrium\n")
        return
    out.write(header(rows[0]) + "\n")
    for r in rows:
        out.write(",".join(number(v) for v in r.values()) + "\n")


def positive_count(name, value, low):
    """An integer option >= low (ValueError naming it)."""
    if value is not None and value < low:
        raise ValueError(f"{name} must be >= {low}, got {value}")
    return value
