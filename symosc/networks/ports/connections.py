"""Connections of four-poles and chains of identical sections (Bulgakov (1954), §8.33, §8.40–8.41).

Cascade multiplies chain matrices, ``A = A' A''`` (8.270).  The other four connections add a parameter set —
series: Z, parallel: Y, series–parallel: H, parallel–series: G — but only when every component keeps equal and
opposite currents in the two terminals of each port.  This is checked by the Brune test: the connected network
is solved at terminal level (nodal analysis, exact rational arithmetic at random sample points) and compared with
the sum.

>>> from symosc.networks import series_element, shunt_element, cascade
>>> import sympy as sp
>>> Za, Zb = sp.symbols("Z_a Z_b")
>>> cascade(series_element(Za), shunt_element(Zb)).chain
Matrix([
[(Z_a + Z_b)/Z_b, Z_a],
[          1/Z_b,   1]])
"""

from __future__ import annotations

from typing import Any

import sympy as sp

from ..._validate import check_sympy_matrix, validated
from ...errors import ModelError, ParameterError
from .._util import as_expr
from ._nodal import Netlist, chain_from_netlist, sample_points
from .conversions import convert_parameters
from .fourpoles import FourPole, cascade

__all__ = [
    "brune_test",
    "cascade",
    "chain_power",
    "parallel",
    "parallel_series",
    "series",
    "series_parallel",
]

# (input connection, output connection, parameter set that adds)
_KINDS = {
    "series": ("series", "series", "Z"),
    "parallel": ("parallel", "parallel", "Y"),
    "series_parallel": ("series", "parallel", "H"),
    "parallel_series": ("parallel", "series", "G"),
}


def _four_pole(x: Any, name: str) -> FourPole:
    if not isinstance(x, FourPole):
        raise ParameterError(f"{name} must be a FourPole, got {type(x).__name__}")
    return x


def _connected_netlist(a: FourPole, b: FourPole, kind: str) -> Netlist:
    inp, out, _ = _KINDS[kind]
    ta, tb = a.netlist.terminals, b.netlist.terminals
    parent: dict = {}

    def find(x):
        while parent.get(x, x) != x:
            x = parent[x]
        return x

    def join(x, y):
        rx, ry = find(x), find(y)
        if rx != ry:
            parent[ry] = rx

    A = [f"a.{t}" for t in ta]
    B = [f"b.{t}" for t in tb]
    if inp == "series":
        join(A[1], B[0])
        ports = [A[0], B[1]]
    else:
        join(A[0], B[0])
        join(A[1], B[1])
        ports = [A[0], A[1]]
    if out == "series":
        join(A[3], B[2])
        ports += [A[2], B[3]]
    else:
        join(A[2], B[2])
        join(A[3], B[3])
        ports += [A[2], A[3]]
    every = set(A + B)
    na = a.netlist.renamed("a.", {})
    nb = b.netlist.renamed("b.", {})
    every |= set(na.nodes) | set(nb.nodes)
    merge = {x: find(x) for x in every}
    na = a.netlist.renamed("a.", merge)
    nb = b.netlist.renamed("b.", merge)
    return Netlist(na.branches + nb.branches, tuple(find(x) for x in ports))


@validated
def brune_test(a: FourPole, b: FourPole, kind: str = "series") -> bool:
    """Brune's validity test of a non-cascade connection of two four-poles (Bulgakov (1954), §8.33).

    The connection adds the parameters (Z for ``"series"``, Y for ``"parallel"``, H for ``"series_parallel"``,
    G for ``"parallel_series"``) only if the port currents of each component stay balanced.  The connected network
    is solved at terminal level (modified nodal analysis in exact rational arithmetic at two random sample points
    of ``p`` and of every element symbol) and its chain matrix compared with the one the sum predicts.

    Parameters
    ----------
    a : FourPole
        The first component, which must carry a terminal-level netlist (any section of the library does) unless it is
        isolated.
    b : FourPole
        The second component, with a netlist as for ``a``.
    kind : {"series", "parallel", "series_parallel", "parallel_series"}, optional
        The connection to test: inputs and outputs in series (Z adds), in parallel (Y adds), inputs in series and
        outputs in parallel (H adds), or the reverse (G adds); default "series".

    Returns
    -------
    bool
        True when the connection is valid; always True when either component is ``isolated``.

    Raises
    ------
    ModelError
        When a component has no terminal-level netlist (build it from the section library) or the sum does not
        exist.

    Examples
    --------
    >>> from symosc.networks import t_section, lattice, brune_test
    >>> brune_test(t_section(1, 2, 3), t_section(4, 5, 6), "parallel")   # common ground: valid
    True
    >>> brune_test(t_section(1, 2, 3), t_section(4, 5, 6), "series")     # shorts the second T's shunt arm
    False

    See Also
    --------
    series, parallel, series_parallel, parallel_series
    """
    if kind not in _KINDS:
        raise ParameterError(f"kind must be one of {sorted(_KINDS)}, got {kind!r}")
    a, b = _four_pole(a, "a"), _four_pole(b, "b")
    if a.isolated or b.isolated:
        return True
    for name, f in (("a", a), ("b", b)):
        if f.netlist is None:
            raise ModelError(
                f"{name} has no terminal-level netlist, so the Brune test cannot be applied; build it from the "
                "section library, or pass check=False if you know the connection is valid"
            )
    predicted = _summed_chain(a, b, kind)
    net = _connected_netlist(a, b, kind)
    exprs = list(predicted) + [Zb for _, Zbm in net.branches for Zb in sp.Matrix(Zbm)]
    for point in sample_points(exprs, a.p):
        try:
            actual = chain_from_netlist(net, point)
        except ModelError:
            return False
        if not (actual - predicted.xreplace(point)).applyfunc(sp.cancel).is_zero_matrix:
            return False
    return True


def _summed_chain(a: FourPole, b: FourPole, kind: str) -> sp.Matrix:
    ptype = _KINDS[kind][2]
    total = a.parameters(ptype) + b.parameters(ptype)
    return convert_parameters(total, ptype, "A")


def _connect(a: FourPole, b: FourPole, kind: str, check: bool) -> FourPole:
    a, b = _four_pole(a, "a"), _four_pole(b, "b")
    if check and not brune_test(a, b, kind):
        raise ModelError(
            f"the {kind.replace('_', '-')} connection fails the Brune test: the components' port currents are "
            "not balanced, so their parameters do not add; insert an ideal 1:1 isolating transformer "
            "(ideal_transformer(1)) at one component's port"
        )
    A = _summed_chain(a, b, kind)
    net = _connected_netlist(a, b, kind) if a.netlist is not None and b.netlist is not None else None
    return FourPole(A, a.p, net, a.isolated or b.isolated)


@validated
def series(a: FourPole, b: FourPole, check: bool = True) -> FourPole:
    """Series–series connection: ``Z = Z' + Z''`` (Bulgakov (1954), §8.33), Brune-tested unless ``check=False``.

    Parameters
    ----------
    a : FourPole
        The first component of the connection.
    b : FourPole
        The second component; its input and output are in series with those of ``a``.
    check : bool, optional
        Whether to run :func:`brune_test` first and raise ModelError when the connection is not valid (default True);
        False skips it for a connection known to be valid.

    Examples
    --------
    >>> from symosc.networks import series, lattice, ideal_transformer, cascade, t_section
    >>> net = series(cascade(t_section(1, 2, 3), ideal_transformer(1)), t_section(1, 1, 1))
    >>> net.Z
    Matrix([
    [5, -3],
    [3, -7]])

    See Also
    --------
    brune_test, parallel, cascade
    """
    return _connect(a, b, "series", check)


@validated
def parallel(a: FourPole, b: FourPole, check: bool = True) -> FourPole:
    """Parallel–parallel connection: ``Y = Y' + Y''`` (§8.33), Brune-tested unless ``check=False``.

    Parameters
    ----------
    a : FourPole
        The first component of the connection.
    b : FourPole
        The second component; its input and output are in parallel with those of ``a``.
    check : bool, optional
        Whether to run :func:`brune_test` first and raise ModelError when the connection is not valid (default True);
        False skips it for a connection known to be valid.

    Examples
    --------
    >>> from symosc.networks import parallel, t_section, series_element
    >>> parallel(t_section(1, 1, 1), series_element(3)).Y
    Matrix([
    [  1, -2/3],
    [2/3,   -1]])

    See Also
    --------
    brune_test, series, cascade
    """
    return _connect(a, b, "parallel", check)


@validated
def series_parallel(a: FourPole, b: FourPole, check: bool = True) -> FourPole:
    """Inputs in series, outputs in parallel: ``H = H' + H''``; Brune-tested unless ``check=False``.

    Parameters
    ----------
    a : FourPole
        The first component of the connection.
    b : FourPole
        The second component; its input is in series and its output in parallel with those of ``a``.
    check : bool, optional
        Whether to run :func:`brune_test` first and raise ModelError when the connection is not valid (default True);
        False skips it for a connection known to be valid.

    Examples
    --------
    >>> from symosc.networks import series_parallel, shunt_element, ideal_transformer, cascade
    >>> series_parallel(cascade(ideal_transformer(1), shunt_element(2)), shunt_element(2)).H
    Matrix([
    [0,  2],
    [2, -1]])

    See Also
    --------
    parallel_series, brune_test
    """
    return _connect(a, b, "series_parallel", check)


@validated
def parallel_series(a: FourPole, b: FourPole, check: bool = True) -> FourPole:
    """Inputs in parallel, outputs in series: ``G = G' + G''``; Brune-tested unless ``check=False``.

    Parameters
    ----------
    a : FourPole
        The first component of the connection.
    b : FourPole
        The second component; its input is in parallel and its output in series with those of ``a``.
    check : bool, optional
        Whether to run :func:`brune_test` first and raise ModelError when the connection is not valid (default True);
        False skips it for a connection known to be valid.

    Examples
    --------
    >>> from symosc.networks import parallel_series, series_element, ideal_transformer, cascade
    >>> parallel_series(cascade(ideal_transformer(1), series_element(2)), series_element(2)).G
    Matrix([
    [0,  2],
    [2, -4]])

    See Also
    --------
    series_parallel, brune_test
    """
    return _connect(a, b, "parallel_series", check)


@validated
def chain_power(section: Any, n: Any) -> FourPole | sp.Matrix:
    """``n`` identical sections in cascade: the four-pole ``section**n``, or the closed form for a symbolic ``n``.

    For an integer ``n`` and a :class:`FourPole` the result is the four-pole of the chain (``section**n``): its
    exact chain matrix is ``A**n`` by repeated squaring in the polynomial ring (or rational function field) of the
    entries, formed when first read, and :meth:`FourPole.evaluate_numeric` evaluates it as the ``n``-th power of the
    section's numeric matrix at every frequency (accurate where the multiplied-out polynomials of degree ``n``
    cancel).  For a matrix ``section`` the result is the exact matrix ``A**n``.

    For a symbolic ``n`` the result is the closed form (Sylvester's formula, Chebyshev polynomials): with
    ``Δ = det A`` and ``x = tr A / (2 sqrt(Δ))``,

    ``A**n = Δ**((n-1)/2) (U_{n-1}(x) A - sqrt(Δ) U_{n-2}(x) I)``,

    ``U_k`` the Chebyshev polynomials of the second kind (for a reciprocal section, ``Δ = 1`` and
    ``U_{n-1}(x) = sinh(n g)/sinh(g)`` with ``cosh g = x``, Bulgakov (1954), §8.40).

    Parameters
    ----------
    section : FourPole or 2x2 matrix
        The repeated section (a four-pole, or its chain matrix).
    n : int or SymPy symbol
        Number of sections, a positive integer (a symbol gives the closed form for general ``n``).

    Returns
    -------
    FourPole or sympy.Matrix
        A :class:`FourPole` when ``section`` is one and ``n`` an integer; otherwise the chain matrix.

    Examples
    --------
    >>> import numpy as np, sympy as sp
    >>> from symosc.networks import chain_power, series_element, shunt_element
    >>> n = sp.Symbol("n", integer=True, positive=True)
    >>> chain_power([[2, 1], [3, 2]], n)[0, 1]
    chebyshevu(n - 1, 2)
    >>> chain_power([[2, 1], [3, 2]], 3)
    Matrix([
    [26, 15],
    [45, 26]])
    >>> p = sp.Symbol("p")
    >>> line = chain_power(series_element(p) @ shunt_element(1 / p), 100)   # 100 L-C sections
    >>> line.chain[0, 1].as_poly(p).degree()
    199
    >>> line.evaluate_numeric([0.5, 1.5]).shape                              # ABCD at omega = 0.5, 1.5 rad/s
    (2, 2, 2)

    See Also
    --------
    cascade, image_parameters, FourPole.evaluate_numeric
    """
    if isinstance(section, FourPole):
        A = None
    else:
        A = check_sympy_matrix("section", section)
        if A.shape != (2, 2):
            raise ParameterError(f"section must be a FourPole or 2x2 matrix, got shape {A.shape}")
    n = as_expr(n, "n")
    if n.is_integer is False or n.is_positive is False:
        raise ParameterError(f"n must be a positive integer (number of sections), got {n}")
    if n.is_Integer:
        if A is None:
            return section ** int(n)
        if sp.cancel(A.det()) == 0:
            raise ModelError("the section's chain matrix is singular (det A = 0)")
        return _exact_power(A, int(n))
    A = section.chain if A is None else A
    delta = sp.cancel(A.det())
    if delta == 0:
        raise ModelError("the section's chain matrix is singular (det A = 0)")
    root = sp.sqrt(delta) if delta != 1 else sp.Integer(1)
    x = sp.cancel(A.trace() / (2 * root)) if root == 1 else A.trace() / (2 * root)
    factor = delta ** ((n - 1) / 2) if delta != 1 else sp.Integer(1)
    return factor * (sp.chebyshevu(n - 1, x) * A - root * sp.chebyshevu(n - 2, x) * sp.eye(2))


def _exact_power(A: sp.Matrix, n: int) -> sp.Matrix:
    """``A**n`` by repeated squaring in the ring of the entries (SymPy expressions for the ``EX`` domain)."""
    from sympy.polys.matrices import DomainMatrix

    D = DomainMatrix.from_Matrix(A)
    if D.domain.is_EX or D.domain.is_EXRAW:
        return (A**n).applyfunc(lambda e: sp.cancel(sp.expand(e)))
    return (D**n).to_Matrix().applyfunc(sp.cancel)
