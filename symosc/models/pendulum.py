"""Planar n-link pendulums (mathematical or physical links), hanging or inverted, fixed or vibrating pivot."""

from __future__ import annotations

import functools
import itertools

import numpy as np
import sympy as sp

from .._validate import check_bool, check_choice, validated
from ..errors import ModelError, ParameterError
from ..mechanics import Geometry, LagrangianSystem, LinearModel, _terms
from ..mechanics.lagrange import DeferredGeometry
from ..symbols import dot, t

__all__ = ["gribkov_khokhlov_table1", "n_link_pendulum", "n_link_pendulum_linearization", "pendulum_symbols"]

#: Largest chain for the full symbolic model.  Deriving the equations (model, mass matrix and forcing) costs about
#: 0.3 s of CPU at n = 20, 1.4 s at n = 40 and 2.7 s at n = 50 (growth about n**3 from 40 on); the symbolic model of a
#: very long chain is still large (its forcing has O(n**2) terms per equation), so longer chains are refused unless
#: asked.
MAX_SYMBOLIC_LINKS = 40
_COST_AT_MAX_S = 1.4
_COST_EXPONENT = 3.0


def _check_chain_arguments(n, links, inverted, pivot, *, max_links=None):
    """Validated ``(n, inverted)``; the errors are ParameterErrors that are also ModelErrors (callers such as the
    scene loader catch ModelError for a bad catalogue entry)."""
    try:
        if isinstance(n, bool) or not isinstance(n, int | np.integer) or n < 1:
            raise ParameterError(f"n must be a positive integer (the number of links, n >= 1), got {n!r}")
        n = int(n)
        if max_links is not None and n > max_links:
            estimate = _COST_AT_MAX_S * (n / MAX_SYMBOLIC_LINKS) ** _COST_EXPONENT
            raise ParameterError(
                f"n_link_pendulum(n={n}) is beyond the supported size n <= {max_links}: building the symbolic "
                f"model costs about {_COST_AT_MAX_S:.1f} s of CPU at n = {MAX_SYMBOLIC_LINKS} and grows like "
                f"n**{_COST_EXPONENT} (measured), so n = {n} would take about {estimate:.0f} s. For small "
                f"oscillations of a long chain use n_link_pendulum_linearization({n}, ...) (closed-form M and K, "
                "built in O(n**2)); for large motions integrate a shorter chain's compiled equations, or pass "
                "max_links=None to build it anyway"
            )
        check_choice("links", links, ("point", "rigid"))
        check_choice("pivot", pivot, ("fixed", "vertical"))
        return n, check_bool("inverted", inverted)
    except ParameterError as exc:
        raise _CatalogueError(str(exc)) from None


class _CatalogueError(ParameterError, ModelError):
    """A bad argument of a catalogue model: a ParameterError, and a ModelError for callers that catch those."""


@validated
def pendulum_symbols(n: int) -> dict[str, tuple[sp.Symbol, ...] | sp.Symbol]:
    """The symbols of the catalogue's n-link pendulum (names ``phi1, m1, l1, lc1, I1, ..., g, a, p``).

    Parameters
    ----------
    n : int
        Number of links, a positive integer (one symbol of each per-link family per link).

    Examples
    --------
    >>> s = pendulum_symbols(2)
    >>> s["m"], s["lc"], s["g"], s["a"]
    ((m1, m2), (lc1, lc2), g, a)
    """
    pos = {"positive": True}
    return {
        "phi": tuple(sp.Symbol(f"phi{i}", real=True) for i in range(1, n + 1)),
        "m": tuple(sp.Symbol(f"m{i}", **pos) for i in range(1, n + 1)),
        "l": tuple(sp.Symbol(f"l{i}", **pos) for i in range(1, n + 1)),
        "lc": tuple(sp.Symbol(f"lc{i}", **pos) for i in range(1, n + 1)),
        "I": tuple(sp.Symbol(f"I{i}", **pos) for i in range(1, n + 1)),
        "g": sp.Symbol("g", positive=True),
        "a": sp.Symbol("a", nonnegative=True),
        "p": sp.Symbol("p", positive=True),
    }


@validated
def n_link_pendulum(
    n: int,
    *,
    links: str = "point",
    inverted: bool = False,
    pivot: str = "fixed",
    max_links: int | None = MAX_SYMBOLIC_LINKS,
) -> LagrangianSystem:
    """A planar chain of ``n`` links in a uniform gravity field (full nonlinear model).

    Parameters
    ----------
    n : int
        Number of links, numbered from the pivot (1 <= n <= 40; deriving the equations costs about n**2 to n**3,
        about 1.4 s of CPU at n = 40: for small oscillations of longer chains use
        :func:`n_link_pendulum_linearization`).
    links : {"point", "rigid"}
        ``"point"``: massless link ``i`` of length ``l_i`` with a point mass ``m_i`` at its end.
        ``"rigid"``: physical link with mass ``m_i``, hinge-to-hinge length ``l_i``, distance ``lc_i``
        from its root hinge to its center of mass and moment of inertia ``I_i`` about the center of mass.
    inverted : bool
        Angles ``phi_i`` are measured from the downward vertical (hanging, ``False``) or from the
        upward vertical (``True``); in both cases ``phi = 0`` is an equilibrium.
    pivot : {"fixed", "vertical"}
        ``"vertical"``: the pivot moves as ``y = a*cos(p*t)`` (a rheonomic system).
    max_links : int or None
        Refuse chains longer than this up front (default 40) with the estimated cost; ``None`` builds any
        length (about 30 s of CPU at n = 130).

    Returns
    -------
    LagrangianSystem
        Coordinates ``phi1..phiN``; parameters ``m1..``, ``l1..``, ``lc1..``, ``I1..``, ``g``, ``a``, ``p``
        (only those that occur).

    See Also
    --------
    n_link_pendulum_linearization : closed-form small-oscillation model, for chains of any length.
    pendulum_symbols
    gribkov_khokhlov_table1

    Examples
    --------
    >>> s = n_link_pendulum(2, links="rigid", inverted=True, pivot="vertical")
    >>> s
    LagrangianSystem(rheonomic; coordinates: phi1, phi2; parameters: I1, I2, a, g, l1, lc1, lc2, m1, m2, p)
    >>> lin = s.linearize()
    >>> K0, K1, p = lin.periodic_stiffness()
    >>> sp.simplify(K1 + K0 * p**2 * s.parameters[2] / sp.Symbol("g", positive=True))
    Matrix([
    [0, 0],
    [0, 0]])
    """
    if max_links is not None and (isinstance(max_links, bool) or not isinstance(max_links, int) or max_links < 1):
        raise ParameterError(f"max_links must be a positive integer or None, got {max_links!r}")
    n, inverted = _check_chain_arguments(n, links, inverted, pivot, max_links=max_links)
    s = pendulum_symbols(n)
    phi, m, l, lc, inertia, g = s["phi"], s["m"], s["l"], s["lc"], s["I"], s["g"]
    up = 1 if inverted else -1
    y0 = s["a"] * sp.cos(s["p"] * t) if pivot == "vertical" else sp.S.Zero
    y0_dot = y0.diff(t)

    # Sums are built in one sp.Add each (adding term by term re-sorts a growing sum: O(n**2) work per energy).
    cos, sin = [_terms.trig(sp.cos, p) for p in phi], [_terms.trig(sp.sin, p) for p in phi]
    T_terms, V_terms = [], []
    for k in range(n):
        # Position of the body's mass center: hinges 0..k-1 plus the distance along link k.
        arm = [l[i] for i in range(k)] + [l[k] if links == "point" else lc[k]]
        y = sp.Add(y0, *(up * arm[i] * cos[i] for i in range(k + 1)))
        xd = sp.Add(*(arm[i] * cos[i] * dot(phi[i]) for i in range(k + 1)))
        yd = sp.Add(y0_dot, *(-up * arm[i] * sin[i] * dot(phi[i]) for i in range(k + 1)))
        T_terms.append(m[k] * (_terms.power(xd, 2) + _terms.power(yd, 2)) / 2)
        if links == "rigid":
            T_terms.append(inertia[k] * dot(phi[k]) ** 2 / 2)
        V_terms.append(m[k] * g * y)
    system = LagrangianSystem(sp.Add(*T_terms), sp.Add(*V_terms), list(phi))
    system.geometry = DeferredGeometry(functools.partial(_chain_geometry, n, links, up, y0, s))
    return system


def _chain_geometry(n: int, links: str, up: int, y0: sp.Expr, s: dict) -> Geometry:
    """Pivot, hinges and bodies of the chain in the plane of motion (for animations).

    Point links: the masses at the link ends.  Rigid links: hinge ``k`` at ``l_k`` along link ``k``; the last link is
    drawn as a uniform bar of length ``2 lc_n`` (its own length does not enter the equations), the centers of mass
    as bodies.
    """
    phi, l, lc = s["phi"], s["l"], s["lc"]
    points: dict[str, tuple[sp.Expr, sp.Expr]] = {"pivot": (sp.S.Zero, y0)}
    x, y = sp.S.Zero, y0
    chain = ["pivot"]
    masses = []
    for k in range(n):
        direction = (sp.sin(phi[k]), up * sp.cos(phi[k]))
        if links == "rigid":
            points[f"m{k + 1}"] = (x + lc[k] * direction[0], y + lc[k] * direction[1])
            masses.append(f"m{k + 1}")
        reach = l[k] if (links == "point" or k < n - 1) else 2 * lc[k]
        x, y = x + reach * direction[0], y + reach * direction[1]
        name = f"m{k + 1}" if links == "point" else (f"hinge{k + 1}" if k < n - 1 else "end")
        points[name] = (x, y)
        chain.append(name)
        if links == "point":
            masses.append(name)
    lines = tuple(itertools.pairwise(chain))
    return Geometry(points, lines, tuple(masses), ("pivot",))


@validated
def n_link_pendulum_linearization(
    n: int, *, links: str = "point", inverted: bool = False, pivot: str = "fixed"
) -> LinearModel:
    """The n-link pendulum linearized about ``phi = 0`` in closed form (no Lagrangian derivation), for any ``n``.

    With ``S_i = m_i lc_i + l_i (m_{i+1} + ... + m_n)`` (``lc_i = l_i`` for point links) the kinetic and potential
    energies give

    ``M_ii = I_i + m_i lc_i**2 + l_i**2 (m_{i+1} + ... + m_n)``, ``M_ij = l_i S_j`` for ``i < j``,
    ``K = diag(S_i) * s * (g - a p**2 cos(p t))``,

    with ``s = 1`` hanging and ``s = -1`` inverted (``a = 0`` for a fixed pivot); the terms ``I_i`` are absent for
    point links.  The result equals ``n_link_pendulum(n, ...).linearize()`` (same symbols), but costs O(n**2)
    without forming the full nonlinear model.

    Parameters
    ----------
    n : int
        Number of links (n >= 1).
    links : {"point", "rigid"}
        As in :func:`n_link_pendulum`.
    inverted : bool
        Hanging (``False``) or inverted (``True``) equilibrium.
    pivot : {"fixed", "vertical"}
        ``"vertical"``: the pivot moves as ``y = a*cos(p*t)``; K then has the periodic part.

    Returns
    -------
    LinearModel
        ``M q'' + K q = 0`` with ``D = 0`` and ``f = 0``; coordinates ``phi1..phiN``.

    See Also
    --------
    n_link_pendulum : the full nonlinear model (n <= 40).
    symosc.mechanics.LinearModel.natural_frequencies

    Examples
    --------
    >>> lin = n_link_pendulum_linearization(2)
    >>> lin.M
    Matrix([
    [l1**2*m1 + l1**2*m2, l1*l2*m2],
    [           l1*l2*m2, l2**2*m2]])
    >>> lin.natural_frequencies({"m1": 1, "m2": 1, "l1": 1, "l2": 1, "g": 1}).round(6).tolist()
    [0.765367, 1.847759]
    >>> long = n_link_pendulum_linearization(200)
    >>> long.M.shape
    (200, 200)
    """
    n, inverted = _check_chain_arguments(n, links, inverted, pivot)
    s = pendulum_symbols(n)
    m, l = s["m"], s["l"]
    lc = l if links == "point" else s["lc"]
    outboard = [sp.Add(*m[i + 1 :]) for i in range(n)]  # mass beyond hinge i+1
    S = [m[i] * lc[i] + l[i] * outboard[i] for i in range(n)]
    M = sp.zeros(n, n)
    for i in range(n):
        M[i, i] = m[i] * lc[i] ** 2 + l[i] ** 2 * outboard[i] + (s["I"][i] if links == "rigid" else 0)
        for j in range(i + 1, n):
            M[i, j] = M[j, i] = l[i] * S[j]
    sign = -1 if inverted else 1
    factors = [sign * s["g"]] + ([-sign * s["a"] * s["p"] ** 2 * sp.cos(s["p"] * t)] if pivot == "vertical" else [])
    # K_ii = S_i * factor, written out term by term (sympy.expand of these products costs O(n**3) in total)
    terms = [[m[i] * lc[i]] + [l[i] * mk for mk in m[i + 1 :]] for i in range(n)]
    K = sp.diag(*[sp.Add(*[f * x for f in factors for x in terms[i]]) for i in range(n)])
    zero = sp.zeros(n, n)
    return LinearModel(
        M=M, D=zero, K=K, f=sp.zeros(n, 1), coordinates=tuple(s["phi"]), point=dict.fromkeys(s["phi"], 0)
    )


@validated
def gribkov_khokhlov_table1() -> dict[str, float]:
    """Parameters of the double physical pendulum of Gribkov & Khokhlov (2015), Table 1, in SI units.

    Table 1 gives m in g, lengths in mm and I (about the center of mass) in g*mm^2; g = 9.81 m/s^2.
    The paper reports natural frequencies 2.289 Hz and 5.094 Hz for this pendulum, which these values
    do not reproduce (about 1.7 % off; see ``derivations/gribkov_khokhlov_2015.py``).

    >>> v = gribkov_khokhlov_table1()
    >>> v["m1"], v["l1"], v["I2"]
    (0.001032, 0.045, 3.2871e-08)
    """
    return {
        "m1": 1.032e-3, "m2": 0.424e-3,            # 1.032 g, 0.424 g
        "l1": 45.0e-3, "l2": 26.2e-3,              # 45.0 mm, 26.2 mm
        "lc1": 24.917e-3, "lc2": 12.838e-3,        # 24.917 mm, 12.838 mm
        "I1": 146.804e-9, "I2": 32.871e-9,         # g*mm^2 = 1e-9 kg*m^2
        "g": 9.81,
    }  # fmt: skip
