"""Fit the work of adhesion and the moduli to measurements: ``jkrcyl.fit(P=..., width=..., ...)``.

The module is callable: ``jkrcyl.fit(...)`` is :func:`jkrcyl.fit.estimate.fit`, and ``jkrcyl.fit.read_csv``,
``jkrcyl.fit.FitResult`` are here too.  Parts: data (validation, CSV), model (the library's contacts and
single-patch states, superposed from unit parts per material pair), branch (the sub-critical branch of a
contact: the library's walker and stability flags on the fit's table, the stable segment, the pull-off),
cohesive (the Maugis-Dugdale law: direct states through Contact.at_contact, the lambda window of a fitted sigma0,
the work budget), params (names, coordinates), residuals (width and delta_work data), start (starting values),
descent (least squares from several starts, divergence detection), checks (rows beyond the pull-off), estimate
(the fit), uncertainty (Jacobian covariance, profile-likelihood intervals), result (FitResult, table, plot).
"""
import sys
import types

from .data import Table, read_csv, validate
from .estimate import fit
from .params import DESCRIPTION as PARAMETERS
from .result import FitResult

__all__ = ["fit", "read_csv", "FitResult", "Table", "PARAMETERS", "validate"]


class _CallableModule(types.ModuleType):
    """jkrcyl.fit is both the package and the function: calling the module calls :func:`fit`."""

    def __call__(self, *args, **kwargs):
        return fit(*args, **kwargs)


sys.modules[__name__].__class__ = _CallableModule
