"""``jkrcyl``: equilibrium curves, adherence forces, forward problems, cycles and the paper's figures from the
command line.

    jkrcyl figures --out figures            # Figures 2-12 as PNG, PDF and CSV
    jkrcyl curve --M 0.3 --theta 1 --gb 0.5 # one equilibrium branch as CSV (or --format json)
    jkrcyl curve --E 1e6 --nu 0.45 --E-I inf --nu-I 0.3 --R 0.01 --Delta 1e-4 --w 0.05
    jkrcyl adherence --M 0.3 --theta 1      # fixed-load and fixed-grip adherence, zero-load contact
    jkrcyl two-patch --M 0.4 --theta 1      # two-patch branches (top contact formed) as CSV or JSON
    jkrcyl two-patch --figure docs/confined.png   # load-approach paths through the confined regime
    jkrcyl solve | pull-off | cycle --E ... --w ...   # forward problems in physical units
    jkrcyl fit data.csv --free w,E          # fit w and the moduli to measured load against width or approach
    jkrcyl atlas --out atlas                # regime map over (M, vartheta): atlas.npz, atlas.csv, PNG, PDF
    jkrcyl cohesive --out figures           # Maugis-Dugdale: pull-off against lambda, the (lambda, M) map
    jkrcyl explore                          # the interactive explorer in the browser (prints its URL)
    jkrcyl pull-off ... --v-star 1e-6 --n 0.6 --rate 1e-5 --control grip-work   # crack kinetics: at a rate
    jkrcyl rate-sweep ... --v-star 1e-6 --n 0.6 --rate-min 1 --rate-max 1e4 --figure sweep.png

Every command taking a problem takes the edge law too: --sigma0 [Pa] (physical inputs) or --lambda.

Normalised input (--M, --theta, --gb, --alpha-ratio) or physical input (--E --nu --E-I --nu-I --R --Delta --w):
jkrcyl.cli.inputs.  gb = (1/G_I)/beta* defaults to an incompressible pin, 1 - 1/(2 vartheta), and every answer
prints the gb it used.  Errors are one line on stderr naming the bad parameter; exit status 2.
"""
import argparse
import os
import re
import sys

from .. import __version__
from . import adherence, atlas, cohesive, curve, cycle, explore, figures, fit, pull_off, rate_sweep, solve, \
    two_patch

EXIT_USAGE = 2
COMMANDS = (figures, curve, adherence, two_patch, solve, pull_off, cycle, fit, atlas, cohesive, explore,
            rate_sweep)


class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors (exit status 2) and negative numbers as values."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        # "-2e6" and "-inf" are values, not options (argparse alone knows only "-2" and "-.5")
        self._negative_number_matcher = re.compile(r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$|^-inf$")

    def error(self, message):
        sys.stderr.write(f"{self.prog}: error: {message}\n")
        raise SystemExit(EXIT_USAGE)


def build_parser():
    p = _Parser(prog="jkrcyl", description=__doc__.split("\n\n")[0])
    p.add_argument("--version", action="version", version=f"jkrcyl {__version__}")
    sub = p.add_subparsers(dest="command", metavar="command", parser_class=_Parser,
                           title="commands (figures, curve, adherence, two-patch, solve, pull-off, cycle, fit, atlas, "
                                 "cohesive, explore, rate-sweep)")
    sub.required = True
    for module in COMMANDS:
        module.register(sub)
    return p


def main(argv=None):
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return args.func(args)
    except BrokenPipeError:                       # `jkrcyl curve ... | head`: the reader left; no traceback
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except (ValueError, ArithmeticError) as exc:  # ArithmeticError: outside the domain the checks know
        msg = str(exc).splitlines()[0] if str(exc) else "invalid input"
        sys.stderr.write(f"jkrcyl {args.command}: error: {msg}\n")
        return EXIT_USAGE
    except OSError as exc:
        sys.stderr.write(f"jkrcyl {args.command}: error: out: {exc}\n")
        return EXIT_USAGE
