"""Planar n-link pendulums (mathematical or physical links), hanging or inverted, fixed or vibrating pivot."""

from __future__ import annotations

import sympy as sp

from .._validate import check_bool
from ..errors import ModelError
from ..mechanics import LagrangianSystem
from ..symbols import dot, t

__all__ = ["gribkov_khokhlov_table1", "n_link_pendulum", "pendulum_symbols"]


def pendulum_symbols(n: int) -> dict[str, tuple[sp.Symbol, ...] | sp.Symbol]:
    """The parameter symbols of the catalogue's n-link pendulum (DESIGN.md naming).

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


def n_link_pendulum(n: int, *, links: str = "point", inverted: bool = False, pivot: str = "fixed") -> LagrangianSystem:
    """A planar chain of ``n`` links in a uniform gravity field (full nonlinear model).

    Parameters
    ----------
    n : int
        Number of links (>= 1), numbered from the pivot.
    links : {"point", "rigid"}
        ``"point"``: massless link ``i`` of length ``l_i`` with a point mass ``m_i`` at its end.
        ``"rigid"``: physical link with mass ``m_i``, hinge-to-hinge length ``l_i``, distance ``lc_i``
        from its root hinge to its centre of mass and moment of inertia ``I_i`` about the centre of mass.
    inverted : bool
        Angles ``phi_i`` are measured from the downward vertical (hanging, ``False``) or from the
        upward vertical (``True``); in both cases ``phi = 0`` is an equilibrium.
    pivot : {"fixed", "vertical"}
        ``"vertical"``: the pivot moves as ``y = a*cos(p*t)`` (a rheonomic system).

    Returns
    -------
    LagrangianSystem
        Coordinates ``phi1..phiN``; parameters ``m1..``, ``l1..``, ``lc1..``, ``I1..``, ``g``, ``a``, ``p``
        (only those that occur).

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
    if isinstance(n, bool) or not isinstance(n, int) or n < 1:
        raise ModelError(f"n must be a positive integer, got {n!r}")
    if links not in ("point", "rigid"):
        raise ModelError(f"links must be 'point' or 'rigid', got {links!r}")
    if pivot not in ("fixed", "vertical"):
        raise ModelError(f"pivot must be 'fixed' or 'vertical', got {pivot!r}")
    inverted = check_bool("inverted", inverted)
    s = pendulum_symbols(n)
    phi, m, l, lc, inertia, g = s["phi"], s["m"], s["l"], s["lc"], s["I"], s["g"]
    up = 1 if inverted else -1
    y0 = s["a"] * sp.cos(s["p"] * t) if pivot == "vertical" else sp.S.Zero
    y0_dot = y0.diff(t)

    T = sp.S.Zero
    V = sp.S.Zero
    for k in range(n):
        # Position of the body's mass centre: hinges 0..k-1 plus the distance along link k.
        arm = [l[i] for i in range(k)] + [l[k] if links == "point" else lc[k]]
        y = y0 + up * sum(arm[i] * sp.cos(phi[i]) for i in range(k + 1))
        xd = sum(arm[i] * sp.cos(phi[i]) * dot(phi[i]) for i in range(k + 1))
        yd = y0_dot - up * sum(arm[i] * sp.sin(phi[i]) * dot(phi[i]) for i in range(k + 1))
        T += m[k] * (xd**2 + yd**2) / 2
        if links == "rigid":
            T += inertia[k] * dot(phi[k]) ** 2 / 2
        V += m[k] * g * y
    return LagrangianSystem(T, V, list(phi))


def gribkov_khokhlov_table1() -> dict[str, float]:
    """Parameters of the double physical pendulum of Gribkov & Khokhlov (2015), Table 1, in SI units.

    Table 1 gives m in g, lengths in mm and I (about the centre of mass) in g*mm^2; g = 9.81 m/s^2.
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
