"""jkrcyl: JKR adhesion of a cylinder in a conforming cylindrical hole, in closed form.

    m = jkrcyl.Materials(G=1.0, kappa=2.0, G_I=1.0, kappa_I=2.0)
    c = jkrcyl.Contact(R=1.0, Delta=0.01, w=1e-4, materials=m)
    s = c.state(a)       # a = tan(eps/2): P, B, C, P_star, K, delta, h_pi, feasible, ...

The kernels are emitted by ``make derive`` into jkrcyl.generated and reached through jkrcyl.numerics;
the printed formulas the tests compare with live in the top-level package reference/ (not shipped).
"""
from . import laws
from .contact import Contact, State
from .notices import BranchLimitWarning, ValidityWarning
from .critical import a_crit
from .laws import CrackKinetics
from .equilibria import zero_load_contact, zero_load_max_M
from .materials import Materials
from .units import Units

try:
    from importlib.metadata import PackageNotFoundError, version as _version
    __version__ = _version("jkrcyl")
except PackageNotFoundError:         # running from a source tree that was never installed
    __version__ = "0.1.0"

__all__ = ["__version__", "Contact", "Materials", "State", "ValidityWarning", "BranchLimitWarning", "a_crit", "laws", "fit", "zero_load_contact", "zero_load_max_M", "CrackKinetics", "kinetics",
           "Units"]


def __getattr__(name):
    """jkrcyl.fit (fit w and the moduli to measurements) and jkrcyl.kinetics (rate-dependent adhesion in time)
    are imported on first use: they load scipy.optimize and scipy.integrate."""
    if name in ("fit", "kinetics"):
        import importlib
        return importlib.import_module("." + name, __name__)
    raise AttributeError(f"module 'jkrcyl' has no attribute {name!r}")
