"""Fit the work of adhesion and the moduli to measurements (issue 20): ``jkrcyl.fit(P=..., width=..., ...)``.

The module is callable: ``jkrcyl.fit(...)`` is :func:`jkrcyl.fit.estimate.fit`, and ``jkrcyl.fit.read_csv``,
``jkrcyl.fit.FitResult`` are here too.  Parts: data (validation, CSV), model (the adapter to the library's
JKR model: the superposition surrogate), cohesive (the Maugis-Dugdale law: direct states through
Contact.at_contact, the lambda window of a fitted sigma0), params (names, coordinates), residuals (width and
delta_work data), estimate (least squares, checks), uncertainty (Jacobian covariance, profile-likelihood
intervals), result (FitResult, table, plot).
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
