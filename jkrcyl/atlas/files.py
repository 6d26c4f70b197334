"""Atlas output files: compressed npz (every field) and CSV (one row per (vartheta, M) pair)."""
import numpy as np

from .classify import CONFINED, FIELDS_BOOL, FIELDS_FLOAT, FIELDS_INT

NOTE = ("vartheta = inf row: M is M_R* = sqrt(wAR)/(sqrt(2) Delta) and P* is P_R* = P beta*/(4 pi Delta) "
        "of (7.6). Value fields are 0 where their mask is False (no NaN). confined codes: "
        + "; ".join(f"{k} = {v}" for k, v in CONFINED.items()))
CSV_COLUMNS = ("theta", "M") + FIELDS_BOOL + FIELDS_INT + FIELDS_FLOAT


def write_npz(path, atlas):
    np.savez_compressed(path, note=np.array(NOTE), fields_bool=np.array(FIELDS_BOOL),
                        fields_int=np.array(FIELDS_INT), fields_float=np.array(FIELDS_FLOAT), **atlas)


def write_csv(path, atlas):
    """One row per (vartheta, M) pair; booleans 0/1, theta 'inf' on the rigid-cradle row."""
    TH, MM = np.meshgrid(atlas["theta"], atlas["M"], indexing="ij")
    cols = [TH.ravel(), MM.ravel()]
    cols += [atlas[k].ravel().astype(np.int64) for k in FIELDS_BOOL + FIELDS_INT]
    cols += [atlas[k].ravel() for k in FIELDS_FLOAT]
    fmt = ["%.17g", "%.17g"] + ["%d"] * (len(FIELDS_BOOL) + len(FIELDS_INT)) + ["%.17g"] * len(FIELDS_FLOAT)
    with open(path, "w") as fh:
        fh.write(f"# {NOTE}\n")
        fh.write(",".join(CSV_COLUMNS) + "\n")
        np.savetxt(fh, np.column_stack(cols), fmt=fmt, delimiter=",")
