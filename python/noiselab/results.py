"""An experiment folder as data: its tables, manifest and verdicts.

  r = noiselab.results.load("results/s3_fbm")
  r.tables["gain_distribution"]["sd"]      # a column of a numpy structured array
  r.frame("gain_distribution")             # the same as a pandas DataFrame
  r.manifest["seed"], r.verdicts["verdict"]

Tables are read by the library's own reader (nl_table_read, text columns
allowed), so a file the harness would refuse is refused here with the same
"FILE:LINE: reason" message. A column whose every cell is a number is
float64; any other column holds the cells' text (str), numbers written as
the harness writes them.
"""

import ctypes
import os
from typing import Any, Dict, List, Optional, Tuple, Union

import numpy as np
from numpy.typing import NDArray

from ._lib import Error, check, fn, mirror

__all__ = ["load", "read_table", "report", "Results"]


@mirror("nl_table")
class _Table(ctypes.Structure):
    _fields_ = [("nrows", ctypes.c_size_t), ("ncols", ctypes.c_size_t),
                ("names", ctypes.POINTER(ctypes.c_char_p)),
                ("num", ctypes.POINTER(ctypes.c_double)),
                ("text", ctypes.POINTER(ctypes.c_char_p)), ("cap", ctypes.c_size_t)]


_NL_TABLE_TEXT = 1
_read = fn("nl_table_read", ctypes.c_int, ctypes.c_char_p, ctypes.c_int,
           ctypes.POINTER(ctypes.POINTER(_Table)), ctypes.POINTER(Error))
_free = fn("nl_table_free", None, ctypes.POINTER(_Table))
_cell_text = fn("nl_table_cell_text", ctypes.c_char_p, ctypes.POINTER(_Table), ctypes.c_size_t,
                ctypes.c_size_t, ctypes.c_char_p)


def read_table(path: Union[str, "os.PathLike[str]"]) -> NDArray[Any]:
    """One TSV table as a numpy structured array, fields named by its header.

    Parameters
    ----------
    path : str or os.PathLike    a TSV file with a header

    Returns
    -------
    numpy structured array : numbers as float64 (to the bit), text as str

    Example
    -------
    >>> t = read_table("results/quick/s3_fbm/gain_distribution.tsv")   # doctest: +SKIP
    >>> t["gain"], t["sd"]                                               # doctest: +SKIP
    """
    if not os.path.exists(path):
        raise FileNotFoundError(f"{path}: no such file")
    t, err = ctypes.POINTER(_Table)(), Error()
    check(_read(os.fsencode(path), _NL_TABLE_TEXT, ctypes.byref(t), ctypes.byref(err)), err)
    try:
        c = t.contents
        nr, nc = c.nrows, c.ncols
        names = [c.names[j].decode() for j in range(nc)]
        num = np.ctypeslib.as_array(c.num, shape=(nr * nc,)).reshape(nr, nc) if nr else \
            np.empty((0, nc))
        buf = ctypes.create_string_buffer(32)
        cols: List[Any] = []
        dtypes: List[Tuple[str, Any]] = []
        for j in range(nc):
            if all(not c.text[r * nc + j] for r in range(nr)):
                cols.append(num[:, j].copy())
                dtypes.append((names[j], np.float64))
            else:
                col = [_cell_text(t, r, j, buf).decode() for r in range(nr)]
                cols.append(np.array(col, dtype=str))
                dtypes.append((names[j], cols[-1].dtype if nr else "U1"))
    finally:
        _free(t)
    table = np.empty(nr, dtype=dtypes)
    for (name, _), col in zip(dtypes, cols):
        table[name] = col
    return table


def _value(s):
    try:
        return int(s)
    except ValueError:
        pass
    try:
        return float(s)
    except ValueError:
        return s


class Results:
    """An experiment folder: tables (by file name without .tsv), manifest
    (dict; a key written several times, like param, maps to a list),
    verdicts (the verdict rows, a structured array), checks (the regression
    rule of each column: table, column, rule; a structured array) and run
    (dict: when the run started and the time and memory it took, from the
    untracked run.tsv; empty for the committed results of a fresh clone)."""

    def __init__(self, folder: str, tables: Dict[str, NDArray[Any]], manifest: Dict[str, Any],
                 verdicts: NDArray[Any], checks: Optional[NDArray[Any]] = None,
                 run: Optional[Dict[str, Any]] = None) -> None:
        self.folder, self.tables, self.manifest, self.verdicts = folder, tables, manifest, verdicts
        self.checks = checks if checks is not None else np.empty(0, dtype=[])
        self.run = run if run is not None else {}

    def frame(self, name: str) -> Any:
        """Table name as a pandas DataFrame (pandas must be installed)."""
        try:
            import pandas as pd  # type: ignore[import]
        except ImportError:
            raise ImportError("frame: pandas is not installed; use .tables[name], a numpy "
                              "structured array") from None
        if name not in self.tables:
            raise KeyError(f"{name}: no such table in {self.folder} "
                           f"(tables: {', '.join(sorted(self.tables))})")
        return pd.DataFrame.from_records(self.tables[name])

    def __repr__(self):
        return (f"Results({self.folder!r}: {self.manifest.get('experiment', '?')}, "
                f"{len(self.tables)} tables, {len(self.verdicts)} verdicts)")


def load(folder: Union[str, "os.PathLike[str]"]) -> Results:
    """An experiment's folder (a complete one: it holds manifest.tsv) as data.

    Parameters
    ----------
    folder : str or os.PathLike
        e.g. "results/s3_fbm" or a --out folder of `scripts/noiselab reproduce`.

    Returns
    -------
    Results with .tables, .manifest, .verdicts, .checks, .run, .frame(name)

    Example
    -------
    >>> import noiselab.results as nr
    >>> r = nr.load("results/quick/s3_fbm")                      # doctest: +SKIP
    >>> r.tables["gain_distribution"]["sd"]                      # doctest: +SKIP
    """
    folder = os.fspath(folder)
    if not os.path.isdir(folder):
        raise FileNotFoundError(f"{folder}: no such experiment folder")
    mpath = os.path.join(folder, "manifest.tsv")
    if not os.path.exists(mpath):
        raise FileNotFoundError(f"{folder}: no manifest.tsv (not a complete experiment folder)")
    manifest: Dict[str, Any] = {}
    for row in read_table(mpath):
        k, v = str(row["key"]), _value(str(row["value"]))
        if k in manifest:
            if not isinstance(manifest[k], list):
                manifest[k] = [manifest[k]]
            manifest[k].append(v)
        else:
            manifest[k] = [v] if k == "param" else v
    tables = {}
    for f in sorted(os.listdir(folder)):
        if f.endswith(".tsv") and f not in ("manifest.tsv", "verdicts.tsv"):
            tables[f[:-4]] = read_table(os.path.join(folder, f))
    vpath = os.path.join(folder, "verdicts.tsv")
    verdicts = read_table(vpath) if os.path.exists(vpath) else np.empty(0, dtype=[])
    checks = tables.get("checks", np.empty(0, dtype=[]))
    rpath = os.path.join(folder, "run.tsv")
    run = {str(row["key"]): _value(str(row["value"])) for row in read_table(rpath)} \
        if os.path.exists(rpath) else {}
    return Results(folder, tables, manifest, verdicts, checks, run)


def report(folder: Union[str, "os.PathLike[str]"]) -> NDArray[Any]:
    """The verdict rows of an experiment folder (quantity, paper, ours,
    verdict, reason, ...), as a structured array.

    Parameters
    ----------
    folder : str or os.PathLike    an experiment folder

    Returns
    -------
    numpy structured array : load(folder).verdicts

    Example
    -------
    >>> for v in report("results/quick/s3_fbm"):                  # doctest: +SKIP
    ...     print(v["quantity"], v["verdict"])
    """
    return load(folder).verdicts
