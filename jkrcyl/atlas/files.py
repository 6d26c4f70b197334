"""Atlas output files: compressed npz (every field) and CSV (one row per (vartheta, M) pair).

:data:`NOTE` (what M and P* mean on the vartheta = inf row, the masks, the codes of ``confined``) heads both.
"""
import pathlib
from typing import Mapping

import numpy as np

from .classify import CONFINED, FIELDS_BOOL, FIELDS_FLOAT, FIELDS_INT
from .cohesive import LAW_CONFINED, LAW_FIELDS_FLOAT, LAW_FIELDS_INT

NOTE = ("vartheta = inf row: M is M_R* = sqrt(wAR)/(sqrt(2) Delta) and P* is P_R* = P beta*/(4 pi Delta) "
        "of (7.6). Value fields are 0 where their mask is False (no NaN). confined codes: "
        + "; ".join(f"{k} = {v}" for k, v in CONFINED.items()))
CSV_COLUMNS = ("theta", "M") + FIELDS_BOOL + FIELDS_INT + FIELDS_FLOAT


def write_npz(path: str, atlas: Mapping[str, np.ndarray]) -> None:
    """Every field of an atlas, compressed, with :data:`NOTE` and the lists of boolean, integer and float fields.

    Parameters
    ----------
    path : str
        The file (numpy adds .npz where it is missing).
    atlas : mapping of str to ndarray
        What :func:`jkrcyl.atlas.classify` returns.

    Returns
    -------
    None

    Raises
    ------
    OSError
        Where the file cannot be written.

    Examples
    --------
    >>> import os, tempfile
    >>> from jkrcyl import atlas
    >>> result = atlas.classify(*atlas.default_grid(n_M=5, n_theta=3, M_max=1.0, theta_max=2.0), parallel=False)
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     write_npz(os.path.join(folder, "atlas.npz"), result)
    ...     saved = np.load(os.path.join(folder, "atlas.npz"))
    ...     bool((saved["confined"] == result["confined"]).all()), str(saved["note"]) == NOTE
    (True, True)
    """
    np.savez_compressed(path, note=np.array(NOTE), fields_bool=np.array(FIELDS_BOOL),
                        fields_int=np.array(FIELDS_INT), fields_float=np.array(FIELDS_FLOAT), **atlas)


def write_csv(path: str, atlas: Mapping[str, np.ndarray]) -> None:
    """One row per (vartheta, M) pair (columns :data:`CSV_COLUMNS`), after a comment line with :data:`NOTE`.

    Booleans 0/1, floats to 17 digits, theta 'inf' on the rigid-cradle row.

    Parameters
    ----------
    path : str
        The file.
    atlas : mapping of str to ndarray
        What :func:`jkrcyl.atlas.classify` returns.

    Returns
    -------
    None

    Raises
    ------
    OSError
        Where the file cannot be written.

    Examples
    --------
    >>> import os, tempfile
    >>> from jkrcyl import atlas
    >>> result = atlas.classify(*atlas.default_grid(n_M=5, n_theta=3, M_max=1.0, theta_max=2.0), parallel=False)
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     write_csv(os.path.join(folder, "atlas.csv"), result)
    ...     lines = open(os.path.join(folder, "atlas.csv")).read().splitlines()
    >>> len(lines), lines[1].split(",")[:3], lines[-1].split(",")[:2]        # note, header, 4 x 5 pairs
    (22, ['theta', 'M', 'sub_min'], ['inf', '1'])
    """
    TH, MM = np.meshgrid(atlas["theta"], atlas["M"], indexing="ij")
    cols = [TH.ravel(), MM.ravel()]
    cols += [atlas[k].ravel().astype(np.int64) for k in FIELDS_BOOL + FIELDS_INT]
    cols += [atlas[k].ravel() for k in FIELDS_FLOAT]
    fmt = ["%.17g", "%.17g"] + ["%d"] * (len(FIELDS_BOOL) + len(FIELDS_INT)) + ["%.17g"] * len(FIELDS_FLOAT)
    with open(path, "w") as fh:
        fh.write(f"# {NOTE}\n")
        fh.write(",".join(CSV_COLUMNS) + "\n")
        np.savetxt(fh, np.column_stack(cols), fmt=fmt, delimiter=",")


def law_note(lam: float) -> str:
    """The head line of the law's atlas files (jkrcyl.atlas.cohesive): lambda, the fields, the codes."""
    return (f"Maugis-Dugdale law at lambda = {lam:.17g} (s0 of each pair: jkrcyl.numerics.cohesive_scales."
            "zone_strength; gb of an incompressible pin). event_a = tan(eps/2), event_P = P* of the first event; "
            "jkr_* = JKR's atlas (jkrcyl.atlas.classify) on the same grid. " + NOTE.split(" confined codes:")[0]
            + " confined codes: " + "; ".join(f"{k} = {v}" for k, v in LAW_CONFINED.items()))


def write_law_files(folder, atlas: Mapping[str, np.ndarray], csv: bool = True) -> list:
    """The law's atlas (jkrcyl.atlas.cohesive.classify_law) into folder/atlas.npz (+ atlas.csv, one row per pair;
    the refused pairs' messages in the npz's ``reasons``): the paths written.

    Parameters
    ----------
    folder : path-like
        An existing folder.
    atlas : mapping
        What :func:`jkrcyl.atlas.cohesive.classify_law` returns.
    csv : bool
        Write atlas.csv too.

    Returns
    -------
    list of pathlib.Path

    Raises
    ------
    OSError
        Where a file cannot be written.
    """
    folder = pathlib.Path(folder)
    note = law_note(float(atlas["lam"]))
    reasons = np.array([f"theta={t:.17g} M={m:.17g}: {r}" for t, m, r in atlas["reasons"]] or [""])
    arrays = {k: v for k, v in atlas.items() if k != "reasons"}
    np.savez_compressed(folder / "atlas.npz", note=np.array(note), reasons=reasons, **arrays)
    written = [folder / "atlas.npz"]
    if csv:
        TH, MM = np.meshgrid(atlas["theta"], atlas["M"], indexing="ij")
        cols = [TH.ravel(), MM.ravel()] + [atlas[k].ravel().astype(np.int64) for k in LAW_FIELDS_INT]
        cols += [atlas[k].ravel() for k in LAW_FIELDS_FLOAT]
        fmt = ["%.17g", "%.17g"] + ["%d"] * len(LAW_FIELDS_INT) + ["%.17g"] * len(LAW_FIELDS_FLOAT)
        with open(folder / "atlas.csv", "w") as fh:
            fh.write(f"# {note}\n")
            fh.write(",".join(("theta", "M") + LAW_FIELDS_INT + LAW_FIELDS_FLOAT) + "\n")
            np.savetxt(fh, np.column_stack(cols), fmt=fmt, delimiter=",")
        written.append(folder / "atlas.csv")
    return written
