"""Save and load derived models and results: a pickle plus a readable JSON summary.

:func:`save` writes ``<name>.pkl`` (the object, reloadable with :func:`load`) and ``<name>.json``: the class, the
symosc version, the parameters and the equations or matrices as ``sympy.srepr`` strings, so the derivation can be
inspected without unpickling anything.  Load pickles only from sources you trust (a pickle can run code).
:func:`load_summary` reads the JSON side without running anything from it: the ``srepr`` strings are parsed against
an explicit grammar (calls of a listed set of SymPy classes and functions, symbol names, assumption flags), never
evaluated, and bounded in size.
"""

from __future__ import annotations

import dataclasses
import json
import pickle
from pathlib import Path
from typing import Any

import sympy as sp

from ._validate import validated
from .errors import ParameterError

__all__ = ["load", "load_summary", "save", "summary"]

_SUMMARY_ATTRIBUTES = (
    "coordinates",
    "parameters",
    "mass_matrix",
    "forcing",
    "kinetic_energy",
    "potential_energy",
    "dissipation",
    "M",
    "D",
    "K",
    "expr",
    "image",
    "original",
)


def _paths(path: str | Path) -> tuple[Path, Path]:
    p = Path(path)
    if p.suffix in (".pkl", ".json"):
        p = p.with_suffix("")
    return p.with_name(p.name + ".pkl"), p.with_name(p.name + ".json")


def _srepr_or_none(value: Any) -> Any:
    if isinstance(value, sp.Basic | sp.MatrixBase):
        return sp.srepr(value)
    if isinstance(value, tuple | list) and value and all(isinstance(v, sp.Basic) for v in value):
        return [sp.srepr(v) for v in value]
    return None


def summary(obj: Any) -> dict[str, Any]:
    """The JSON-ready summary :func:`save` writes: class, version and the symbolic content in ``srepr``.

    Parameters
    ----------
    obj : model or result
        Any symosc object (or SymPy object); the symbolic attributes it has (coordinates, parameters, matrices,
        energies, dataclass fields) are written as ``srepr`` strings, the others skipped.

    Examples
    --------
    >>> from symosc.models import n_link_pendulum
    >>> s = summary(n_link_pendulum(1))
    >>> s["class"], s["parameters"]
    ('symosc.mechanics.lagrange.LagrangianSystem', ['g', 'l1', 'm1'])
    >>> s["symbolic"]["mass_matrix"][:40]
    "MutableDenseMatrix([[Mul(Pow(Symbol('l1'"

    """
    from . import __version__

    symbolic: dict[str, Any] = {}
    names = list(_SUMMARY_ATTRIBUTES)
    if dataclasses.is_dataclass(obj):
        names += [f.name for f in dataclasses.fields(obj) if not f.name.startswith("_")]
    for name in dict.fromkeys(names):
        try:
            value = getattr(obj, name)
        except Exception:
            continue
        text = _srepr_or_none(value)
        if text is not None:
            symbolic[name] = text
    params = getattr(obj, "parameters", None)
    return {
        "class": f"{type(obj).__module__}.{type(obj).__qualname__}",
        "symosc_version": __version__,
        "repr": repr(obj),
        "parameters": [str(s) for s in params] if isinstance(params, tuple | list) else None,
        "symbolic": symbolic,
    }


@validated
def save(obj: Any, path: str | Path) -> tuple[Path, Path]:
    """Write ``obj`` to ``<path>.pkl`` and its summary to ``<path>.json``; return both paths.

    Parameters
    ----------
    obj : model or result
        Any picklable symosc object (every public result and model is).
    path : str or Path
        File name without extension (a ``.pkl``/``.json`` suffix is replaced).

    Examples
    --------
    >>> import tempfile, pathlib
    >>> from symosc.models import n_link_pendulum
    >>> system = n_link_pendulum(2)
    >>> with tempfile.TemporaryDirectory() as d:
    ...     pkl, js = save(system, pathlib.Path(d) / "pendulum")
    ...     again = load(pkl)
    ...     info = load_summary(js)
    >>> again.mass_matrix == system.mass_matrix, info["symbolic"]["forcing"] == system.forcing
    (True, True)

    See Also
    --------
    load, load_summary
    """
    pkl, js = _paths(path)
    try:
        blob = pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL)
    except (pickle.PicklingError, AttributeError, TypeError) as err:
        raise ParameterError(f"cannot save a {type(obj).__name__}: it does not pickle ({err})") from err
    pkl.write_bytes(blob)
    js.write_text(json.dumps(summary(obj), indent=1))
    return pkl, js


@validated
def load(path: str | Path) -> Any:
    """The object saved by :func:`save` (give the ``.pkl`` path or the name without extension).

    Only load files from sources you trust: unpickling can run code.

    Parameters
    ----------
    path : str or Path
        The path given to :func:`save`, with or without the ``.pkl`` (or ``.json``) suffix; the ``.pkl`` file
        must exist.

    See Also
    --------
    save, load_summary

    Examples
    --------
    >>> import pathlib, tempfile
    >>> import sympy as sp
    >>> from symosc import load, save
    >>> with tempfile.TemporaryDirectory() as d:
    ...     _ = save(sp.Matrix([[1, 2]]), pathlib.Path(d) / "row")
    ...     load(pathlib.Path(d) / "row.pkl")
    Matrix([[1, 2]])
    """
    pkl, _ = _paths(path)
    if not pkl.exists():
        raise ParameterError(f"no saved object at {pkl}; pass the path given to save()")
    return pickle.loads(pkl.read_bytes())


#: the largest summary file read (bytes): a summary of a 40-link pendulum is about 3 MB
MAX_SUMMARY_BYTES = 64 * 2**20


@validated
def load_summary(path: str | Path) -> dict[str, Any]:
    """The JSON summary written by :func:`save`, with the ``srepr`` strings turned back into SymPy objects.

    Nothing in the file is executed: each ``srepr`` string is parsed by :func:`symosc._parsing.parse_srepr`
    (calls of listed SymPy classes and functions only, sizes bounded), so a summary from anyone can be read.

    Parameters
    ----------
    path : str or Path
        The ``.json`` file written by :func:`save` (or the name without extension).

    Returns
    -------
    dict
        ``class``, ``symosc_version``, ``repr``, ``parameters`` and ``symbolic`` (name -> SymPy object or list).

    Raises
    ------
    ParameterError
        No such file, a file that is not a summary, or an entry outside the ``srepr`` grammar (the message names the
        entry).

    See Also
    --------
    save, load

    Examples
    --------
    >>> import pathlib, tempfile
    >>> import sympy as sp
    >>> from symosc.io import load_summary, save
    >>> with tempfile.TemporaryDirectory() as d:
    ...     _ = save(sp.Matrix([[1, 2]]), pathlib.Path(d) / "row")
    ...     load_summary(pathlib.Path(d) / "row")["class"]
    'sympy.matrices.dense.MutableDenseMatrix'
    """
    from ._parsing import ExpressionError, parse_srepr

    _, js = _paths(path)
    if not js.is_file():
        raise ParameterError(f"no summary at {js}; pass the path given to save()")
    if js.stat().st_size > MAX_SUMMARY_BYTES:
        raise ParameterError(
            f"{js} is {js.stat().st_size:,} bytes, more than a summary ({MAX_SUMMARY_BYTES:,} at most)"
        )
    try:
        data = json.loads(js.read_text(encoding="utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise ParameterError(f"{js} is not a summary written by save(): {exc}") from None
    if not isinstance(data, dict) or not isinstance(data.get("symbolic", {}), dict):
        raise ParameterError(f"{js} is not a summary written by save(): expected a JSON object with 'symbolic'")
    sym = {}
    for k, v in data.get("symbolic", {}).items():
        try:
            sym[k] = [parse_srepr(x) for x in v] if isinstance(v, list) else parse_srepr(v)
        except ExpressionError as exc:
            raise ParameterError(f"{js}: entry {k!r} of 'symbolic': {exc}") from None
    data["symbolic"] = sym
    return data
