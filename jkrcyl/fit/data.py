"""Measured data for jkrcyl.fit: validation (a ValueError naming the row and the column) and the CSV reader.

Columns (SI units): P [N/m] the load per unit length (positive pushing the pin into the bottom of the hole, section
6); width [m] the contact width 2 R eps, or delta_work [m] the work-conjugate approach (docs/guide/forward.md,
"Which approach"); optional sigma_P [N/m], sigma_width [m], sigma_delta_work [m] (one standard deviation of each
measurement) and leg ('loading' or 'unloading', for separate works of adhesion on the two legs).
"""
from __future__ import annotations

import csv
import math
import re
from dataclasses import dataclass, field
from typing import Optional

import numpy as np

LEGS = ("loading", "unloading")
COLUMNS = ("P", "width", "delta_work", "sigma_P", "sigma_width", "sigma_delta_work", "leg")
SETUP_KEYS = ("R", "Delta", "E", "nu", "E_I", "nu_I", "control", "w")   # '# key=value' comment lines of a CSV


@dataclass(frozen=True)
class Data:
    """Validated measurements: P [N/m] against x = width or delta_work [m] (``kind``), per-point standard
    deviations (None: not stated) and the leg of each point (None: one leg)."""

    P: np.ndarray
    x: np.ndarray
    kind: str
    sigma_P: Optional[np.ndarray]
    sigma_x: Optional[np.ndarray]
    unloading: Optional[np.ndarray]      # bool per point, or None

    @property
    def n(self):
        return self.P.size


def _array(name, values, n=None):
    """A 1-D float array (ValueError naming the column for text, booleans, complex, wrong length)."""
    if isinstance(values, (str, bytes)):
        raise ValueError(f"{name} must be an array of numbers, got a string")
    try:
        arr = np.asarray(values)
    except Exception as exc:     # ragged nested sequences
        raise ValueError(f"{name} must be a 1-D array of numbers ({exc})") from None
    if arr.dtype.kind == "b" or arr.dtype.kind not in "iuf":
        raise ValueError(f"{name} must be an array of real numbers, got dtype {arr.dtype}")
    arr = np.atleast_1d(arr.astype(float))
    if arr.ndim != 1:
        raise ValueError(f"{name} must be 1-D, got shape {arr.shape}")
    if n is not None and arr.size != n:
        raise ValueError(f"{name} has {arr.size} values, P has {n}: one per measured point")
    return arr


def _rows(mask):
    idx = np.nonzero(mask)[0]
    head = ", ".join(str(int(i)) for i in idx[:5])
    return f"row{'s' if idx.size > 1 else ''} {head}{', ...' if idx.size > 5 else ''}"


def _finite(name, arr):
    bad = ~np.isfinite(arr)
    if bad.any():
        raise ValueError(f"{name}: {_rows(bad)} {'is' if bad.sum() == 1 else 'are'} NaN or inf "
                         "(remove or repair those rows; nothing is dropped silently)")


def _sigma(name, values, n):
    """A per-point standard deviation (scalar broadcast), finite and > 0; None stays None."""
    if values is None:
        return None
    arr = _array(name, values)
    if arr.size == 1:
        arr = np.full(n, arr[0])
    elif arr.size != n:
        raise ValueError(f"{name} has {arr.size} values, P has {n}: give one per point or one for all")
    _finite(name, arr)
    if (arr <= 0).any():
        raise ValueError(f"{name} must be > 0 (a standard deviation), {_rows(arr <= 0)} not")
    return arr


def _legs(leg, n):
    if leg is None:
        return None
    if isinstance(leg, (str, bytes)):
        raise ValueError("leg must be one of 'loading', 'unloading' per point, got a single string")
    values = [str(v).strip() for v in np.atleast_1d(np.asarray(leg, dtype=object))]
    if len(values) != n:
        raise ValueError(f"leg has {len(values)} values, P has {n}: one per measured point")
    bad = [i for i, v in enumerate(values) if v not in LEGS]
    if bad:
        raise ValueError(f"leg must be 'loading' or 'unloading', row {bad[0]} is {values[bad[0]]!r}")
    return np.array([v == "unloading" for v in values])


def validate(P, width=None, delta_work=None, sigma_P=None, sigma_width=None, sigma_delta_work=None, leg=None,
             R=None) -> Data:
    """Check the measurements (R [m], already validated, bounds the width by the circumference 2 pi R).

    Parameters
    ----------
    P : array_like
        Measured loads [N/m].
    width, delta_work : array_like, optional
        Exactly one abscissa: contact widths [m] in (0, 2 pi R) or work-conjugate approaches [m].
    sigma_P, sigma_width, sigma_delta_work : float or array_like, optional
        Standard deviations (> 0) of the columns.
    leg : array_like of str, optional
        'loading' or 'unloading' per row.
    R : float, optional
        Hole radius [m].

    Returns
    -------
    Data
        The validated columns (float arrays), the abscissa's kind and the rows' legs.

    Raises
    ------
    ValueError
        Naming the column and the rows: not numbers, unequal lengths, NaN or inf, width <= 0 or >= 2 pi R,
        sigma <= 0, both or neither of width and delta_work, a leg other than loading/unloading.

    Examples
    --------
    >>> from jkrcyl.fit import validate
    >>> validate([-100.0, 50.0], width=[2e-3, 5e-3], R=0.01).kind
    'width'
    >>> validate([-100.0, 50.0], width=[2e-3, 0.07], R=0.01)
    Traceback (most recent call last):
    ...
    ValueError: width must be < 2 pi R = 0.0628319 m (the hole's circumference), row 1 not: max 0.07
    """
    if (width is None) == (delta_work is None):
        raise ValueError("width, delta_work: give exactly one abscissa (contact width [m] or delta_work [m])")
    if P is None:
        raise ValueError("P: the measured loads [N/m] are required")
    P = _array("P", P)
    if P.size == 0:
        raise ValueError("P: no data points")
    kind = "width" if width is not None else "delta_work"
    x = _array(kind, width if width is not None else delta_work, P.size)
    _finite("P", P)
    _finite(kind, x)
    if kind == "width":
        if (x <= 0).any():
            raise ValueError(f"width must be > 0 (a contact width 2 R eps [m]), {_rows(x <= 0)} not: "
                             f"min {x.min():g}")
        if R is not None and (x >= 2 * math.pi * R).any():
            raise ValueError(f"width must be < 2 pi R = {2 * math.pi * R:g} m (the hole's circumference), "
                             f"{_rows(x >= 2 * math.pi * R)} not: max {x.max():g}")
        if sigma_delta_work is not None:
            raise ValueError("sigma_delta_work: given with width data (use sigma_width)")
        sx = _sigma("sigma_width", sigma_width, P.size)
    else:
        if sigma_width is not None:
            raise ValueError("sigma_width: given with delta_work data (use sigma_delta_work)")
        sx = _sigma("sigma_delta_work", sigma_delta_work, P.size)
    return Data(P=P, x=x, kind=kind, sigma_P=_sigma("sigma_P", sigma_P, P.size), sigma_x=sx,
                unloading=_legs(leg, P.size))


# --- CSV -----------------------------------------------------------------------------------------------------
@dataclass
class Table:
    """A CSV file read by :func:`read_csv`: ``columns`` (keyword arguments of jkrcyl.fit: P, width or delta_work,
    sigma_*, leg) and ``meta`` (the '# key=value' settings of its comment lines: R, Delta, E, nu, E_I, nu_I,
    control, w).

    Examples
    --------
    >>> import pathlib, jkrcyl
    >>> t = jkrcyl.fit.read_csv(pathlib.Path(jkrcyl.__file__).parents[1] / "docs" / "fit_example.csv")
    >>> type(t).__name__, len(t.columns["P"]) == len(t.columns["width"]), t.meta["Delta"]
    ('Table', True, 3e-06)
    """

    columns: dict
    meta: dict = field(default_factory=dict)


_UNIT = re.compile(r"\s*\[.*\]\s*$")


def read_csv(path) -> Table:
    """Read measurements from a CSV file with a header row (units in brackets allowed: ``P [N/m]``).

    Lines starting with '#' are comments; tokens ``key=value`` in them with key in R, Delta, E, nu, E_I, nu_I,
    control, w set :attr:`Table.meta` (numbers, 'inf', or a control name).  Empty cells are NaN (and rejected by
    the fit).

    Parameters
    ----------
    path : str or path-like
        The CSV file.

    Returns
    -------
    Table
        ``columns`` (name -> float array or the legs) and ``meta`` (the setup read from the comments).

    Raises
    ------
    ValueError
        An unknown column (a typo must not drop a column silently) or an unreadable number.

    Examples
    --------
    >>> import pathlib, jkrcyl
    >>> from jkrcyl.fit import read_csv
    >>> t = read_csv(pathlib.Path(jkrcyl.__file__).parents[1] / "docs" / "fit_example.csv")    # the repository's
    >>> t.meta["R"], t.meta["control"], sorted(t.columns)[:2]
    (0.01, 'load', ['P', 'sigma_P'])
    """
    with open(path, newline="") as fh:
        lines = fh.read().splitlines()
    meta, body = {}, []
    for line in lines:
        if line.lstrip().startswith("#"):
            for key, value in re.findall(r"(?<!\S)(\w+)=(\S+)", line):
                if key in SETUP_KEYS:
                    meta[key] = value if key == "control" else _number(key, value)
        elif line.strip():
            body.append(line)
    if not body:
        raise ValueError(f"{path}: no header row")
    rows = list(csv.reader(body))
    header = [_UNIT.sub("", h).strip() for h in rows[0]]
    unknown = [h for h in header if h not in COLUMNS]
    if unknown:
        raise ValueError(f"{path}: unknown column {unknown[0]!r} (allowed: {', '.join(COLUMNS)})")
    if len(set(header)) != len(header):
        raise ValueError(f"{path}: a column appears twice in the header")
    columns = {h: [] for h in header}
    for i, row in enumerate(rows[1:], start=1):
        if len(row) != len(header):
            raise ValueError(f"{path}: data row {i} has {len(row)} fields, the header {len(header)}")
        for h, cell in zip(header, row):
            columns[h].append(cell.strip() if h == "leg" else _number(f"{h} (data row {i})", cell))
    out = {h: (v if h == "leg" else np.array(v, dtype=float)) for h, v in columns.items()}
    return Table(columns=out, meta=meta)


def _number(name, text):
    text = text.strip()
    if text == "":
        return math.nan
    try:
        return float(text)
    except ValueError:
        raise ValueError(f"{name}: not a number: {text!r}") from None
