"""A small explicit table of accepted units (SI conversion with a dimension check).

Why not ``pint``: scene parameters need a few dozen units of mechanics (length, mass, time, inertia, frequency,
acceleration, force, stiffness, damping, angle).  An explicit table keeps ``symosc run`` fast (pint's registry
costs about 0.6 s at start-up, a third of the 2 s budget of a frequency scene), keeps results the same whether
or not an optional package is installed, and lets an error message list every accepted unit.
"""

from __future__ import annotations

import math
import re

__all__ = ["DIMENSIONS", "UNITS", "UnitError", "parse_quantity"]

# dimension = (kg, m, s) exponents
_M, _L, _T = (1, 0, 0), (0, 1, 0), (0, 0, 1)
_ONE = (0, 0, 0)

#: unit atom -> (factor to SI, dimension).  Angles are dimensionless (rad = 1); frequencies in the models are
#: angular (rad/s), so ``Hz`` (cycles per second) converts with a factor 2*pi, like ``rpm``.
UNITS: dict[str, tuple[float, tuple[int, int, int]]] = {
    "m": (1.0, _L), "km": (1e3, _L), "cm": (1e-2, _L), "mm": (1e-3, _L), "um": (1e-6, _L), "µm": (1e-6, _L),
    "in": (0.0254, _L), "ft": (0.3048, _L),
    "kg": (1.0, _M), "g": (1e-3, _M), "mg": (1e-6, _M), "t": (1e3, _M),
    "s": (1.0, _T), "ms": (1e-3, _T), "us": (1e-6, _T), "min": (60.0, _T), "h": (3600.0, _T),
    "Hz": (2 * math.pi, (0, 0, -1)), "kHz": (2e3 * math.pi, (0, 0, -1)),
    "rpm": (2 * math.pi / 60, (0, 0, -1)),
    "rad": (1.0, _ONE), "deg": (math.pi / 180, _ONE), "1": (1.0, _ONE),
    "N": (1.0, (1, 1, -2)), "mN": (1e-3, (1, 1, -2)), "kN": (1e3, (1, 1, -2)),
    "J": (1.0, (1, 2, -2)), "Pa": (1.0, (1, -1, -2)),
    "g0": (9.80665, (0, 1, -2)),  # standard gravity, as a unit of acceleration
}  # fmt: skip

#: names of the dimensions the catalogue uses -> exponents (kg, m, s)
DIMENSIONS: dict[str, tuple[int, int, int]] = {
    "dimensionless": _ONE,
    "mass": _M,
    "length": _L,
    "time": _T,
    "moment of inertia": (1, 2, 0),
    "angular frequency": (0, 0, -1),
    "acceleration": (0, 1, -2),
    "force": (1, 1, -2),
    "stiffness": (1, 0, -2),
    "damping": (1, 0, -1),
    "angular stiffness": (1, 2, -2),
}

_EXAMPLES = {
    "dimensionless": "1",
    "mass": "kg, g",
    "length": "m, cm, mm",
    "time": "s, ms",
    "moment of inertia": "kg*m^2, g*mm^2",
    "angular frequency": "rad/s, Hz, rpm",
    "acceleration": "m/s^2, g0",
    "force": "N",
    "stiffness": "N/m",
    "damping": "N*s/m",
    "angular stiffness": "N*m/rad",
}


class UnitError(ValueError):
    """A unit that is unknown or has the wrong dimension (message says which units are accepted)."""

    parameter: str | None = None  # the parameter at fault, when one is


def _dim_name(dim: tuple[int, int, int]) -> str:
    for name, d in DIMENSIONS.items():
        if d == dim:
            return name
    parts = [f"{b}^{e}" if e != 1 else b for b, e in zip(("kg", "m", "s"), dim, strict=True) if e]
    return "*".join(parts) or "dimensionless"


def _article(noun: str) -> str:
    return ("an " if noun[0] in "aeiou" else "a ") + noun


#: the largest power of a unit atom (m^4 for second moments of area; anything far beyond is a typo or an attack)
_MAX_UNIT_EXPONENT = 12

_TOKEN = re.compile(r"\s*([*/])?\s*([A-Za-zµ0-9]+)(?:\s*(?:\^|\*\*)\s*(-?\d+))?")


def parse_unit(text: str) -> tuple[float, tuple[int, int, int]]:
    factor, dim = 1.0, [0, 0, 0]
    pos, first = 0, True
    text = text.strip()
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m or m.end() == pos or (first and m.group(1)) or (not first and not m.group(1)):
            raise UnitError(f"cannot read the unit {text!r} (write e.g. 'kg*m^2', 'N/m', 'm/s^2')")
        op, atom, exp = m.group(1), m.group(2), int(m.group(3) or 1)
        if abs(exp) > _MAX_UNIT_EXPONENT:
            raise UnitError(
                f"the power {exp} of {atom!r} in {text!r} is not a unit of mechanics "
                f"(powers up to {_MAX_UNIT_EXPONENT})"
            )
        if atom not in UNITS:
            from ._errors import closest

            raise UnitError(f"unknown unit {atom!r}.{closest(atom, UNITS)} Accepted units: {', '.join(UNITS)}")
        f, d = UNITS[atom]
        sign = -1 if op == "/" else 1
        factor *= f ** (sign * exp)
        for i in range(3):
            dim[i] += sign * exp * d[i]
        pos, first = m.end(), False
    return factor, tuple(dim)


def parse_quantity_unit(value: object) -> tuple[int, int, int] | None:
    """The (kg, m, s) exponents of the unit in a ``"VALUE UNIT"`` string (None for a bare number, in SI)."""
    if not isinstance(value, str):
        return None
    m = re.fullmatch(r"\s*[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?\s*(.*?)\s*", value)
    if not m or not m.group(1):
        return None
    return parse_unit(m.group(1))[1]


def parse_quantity(value: object, dimension: str | None) -> float:
    """SI value of a number or of a string ``"VALUE UNIT"``, checked against ``dimension``.

    A bare number is taken in SI units.  ``dimension=None`` accepts any unit (converted to SI).

    Examples
    --------
    >>> parse_quantity("45 mm", "length")
    0.045
    >>> round(parse_quantity("146.804 g*mm^2", "moment of inertia"), 15)
    1.46804e-07
    >>> round(parse_quantity("50 Hz", "angular frequency"), 6)
    314.159265
    >>> parse_quantity("2 kg", "length")
    Traceback (most recent call last):
    ...
    symosc.scene._units.UnitError: '2 kg' is a mass, expected a length (units such as m, cm, mm)
    """
    if isinstance(value, bool):
        raise UnitError(f"expected a number or a 'VALUE UNIT' string, got the boolean {value}")
    if isinstance(value, int | float):
        if not math.isfinite(value):
            raise UnitError(f"expected a finite number, got {value}")
        return float(value)
    if not isinstance(value, str):
        raise UnitError(f"expected a number or a 'VALUE UNIT' string, got {type(value).__name__} {value!r}")
    m = re.fullmatch(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*", value)
    if not m:
        raise UnitError(f"cannot read {value!r} as 'VALUE UNIT' (e.g. '45 mm', '1.032 g', '50 Hz')")
    number, unit = float(m.group(1)), m.group(2)
    if not math.isfinite(number):
        raise UnitError(f"{value!r}: the number is beyond the range of floating point")
    if not unit:
        return number
    factor, dim = parse_unit(unit)
    if dimension is not None and dim != DIMENSIONS[dimension]:
        raise UnitError(
            f"{value!r} is {_article(_dim_name(dim))}, expected {_article(dimension)} "
            f"(units such as {_EXAMPLES[dimension]})"
        )
    out = number * factor
    if not math.isfinite(out) or (out == 0 and number != 0):
        raise UnitError(f"{value!r} is beyond the range of floating point in SI units")
    return out


# ------------------------------------------------------------------------------------- dimensions of a Lagrangian
#: (kg, m, s) exponents of the quantities a Lagrangian's parts must have
_ENERGY, _POWER = (1, 2, -2), (1, 2, -3)


class _Dims:
    """Dimensional analysis of a Lagrangian system: every symbol's dimension is an unknown vector of exponents;
    each additive term of T and V is an energy, of R a power, ``Q_i q_i`` an energy, a velocity is its coordinate
    per second, function arguments are dimensionless.  The constraints are linear in the unknowns."""

    def __init__(self, coordinates, velocities: dict, t) -> None:
        self.rows: list[tuple[dict, tuple]] = []  # (coefficients by symbol, constant vector) == 0
        self.velocities, self.t, self.coordinates = velocities, t, list(coordinates)

    def dim(self, e) -> tuple[dict, tuple]:
        import sympy as sp

        if e.is_Number or e is sp.pi or e is sp.E or e is sp.I:
            return {}, (0, 0, 0)
        if e == self.t:
            return {}, (0, 0, 1)
        if e.is_Symbol:
            if e in self.velocities:
                return {self.velocities[e]: 1}, (0, 0, -1)
            return {e: 1}, (0, 0, 0)
        if e.is_Add:
            first, *rest = (self.dim(a) for a in e.args)
            for other in rest:
                self.equal(other, first)
            return first
        if e.is_Mul:
            coeffs: dict = {}
            const = (0, 0, 0)
            for a in e.args:
                c, k = self.dim(a)
                for s, v in c.items():
                    coeffs[s] = coeffs.get(s, 0) + v
                const = tuple(x + y for x, y in zip(const, k, strict=True))
            return coeffs, const
        if e.is_Pow:
            base, exp = e.args
            if exp.is_Rational:
                c, k = self.dim(base)
                return {s: v * exp for s, v in c.items()}, tuple(x * exp for x in k)
            self.equal(self.dim(base), ({}, (0, 0, 0)))
            self.equal(self.dim(exp), ({}, (0, 0, 0)))
            return {}, (0, 0, 0)
        if isinstance(e, sp.Abs):
            return self.dim(e.args[0])
        for a in e.args:  # sin, cos, exp, log, ...: dimensionless arguments and value
            self.equal(self.dim(a), ({}, (0, 0, 0)))
        return {}, (0, 0, 0)

    def equal(self, a: tuple[dict, tuple], b: tuple[dict, tuple]) -> None:
        coeffs = dict(a[0])
        for s, v in b[0].items():
            coeffs[s] = coeffs.get(s, 0) - v
        const = tuple(x - y for x, y in zip(a[1], b[1], strict=True))
        self.rows.append(({s: v for s, v in coeffs.items() if v != 0}, const))

    def solve(self, known: dict) -> tuple[bool, dict]:
        """Consistency of the constraints with ``known`` dimensions, and every symbol's dimension when determined
        (reduced row echelon form over the rationals)."""
        from sympy import QQ
        from sympy.polys.matrices import DomainMatrix

        symbols = sorted({s for c, _ in self.rows for s in c} | set(known) | set(self.coordinates), key=str)
        index = {s: i for i, s in enumerate(symbols)}
        n = len(symbols)
        rows = []
        for c, k in [*self.rows, *(({s: 1}, tuple(-x for x in vec)) for s, vec in known.items())]:
            row = [QQ(0)] * (n + 3)
            for s, v in c.items():
                row[index[s]] = QQ(v.p, v.q) if hasattr(v, "p") else QQ(v)
            for j in range(3):
                kj = k[j]
                row[n + j] = -(QQ(kj.p, kj.q) if hasattr(kj, "p") else QQ(kj))
            rows.append(row)
        red, pivots = DomainMatrix(rows, (len(rows), n + 3), QQ).rref()
        if any(col >= n for col in pivots):  # a row 0 = nonzero: inconsistent
            return False, {}
        dense = red.to_list()
        out = {}
        for i, col in enumerate(pivots):
            if all(dense[i][j] == 0 for j in range(n) if j != col):
                out[symbols[col]] = tuple(dense[i][n + j] for j in range(3))
        return True, out


def check_lagrangian_units(T, V, R, forces, coordinates, velocities: dict, t, given: dict) -> None:
    """Check the units of the parameters of a Lagrangian system against the dimensions their places in T, V, R and
    the forces imply.

    Parameters
    ----------
    T, V, R : sympy.Expr
        Kinetic energy, potential energy and Rayleigh dissipation function.
    forces : sequence of sympy.Expr or None
        Generalised forces, one per coordinate.
    coordinates : sequence of Symbol
        The coordinates.
    velocities : dict
        Velocity symbol -> its coordinate.
    t : Symbol
        Time.
    given : dict
        Parameter symbol -> ``(text, (kg, m, s) exponents)`` for each parameter the file gives with a unit.

    Raises
    ------
    UnitError
        A parameter whose unit contradicts its place; the message names it, its unit's dimension and the implied one.
    """
    dims = _Dims(coordinates, velocities, t)
    for part, target in ((T, _ENERGY), (V, _ENERGY), (R, _POWER)):
        if part != 0:
            dims.equal(dims.dim(part), ({}, target))
    for q, Q in zip(coordinates, forces or (), strict=False):
        if Q != 0:
            c, k = dims.dim(Q)
            dims.equal(({**c, q: c.get(q, 0) + 1}, k), ({}, _ENERGY))
    known = {s: vec for s, (_, vec) in given.items()}
    consistent, _ = dims.solve(known)
    if consistent:
        return
    suspects = []  # parameters whose unit alone, changed, would make the whole consistent
    for s, (text, vec) in given.items():
        others = {o: v for o, v in known.items() if o != s}
        ok, solved = dims.solve(others)
        if ok and s in solved:
            implied = tuple(int(x) if x.denominator == 1 else x for x in solved[s])
            expected = _dim_name(implied) if all(isinstance(x, int) for x in implied) else str(implied)
            examples = _EXAMPLES.get(expected)
            suspects.append(
                (
                    str(s),
                    f"{s} = {text!r} is {_article(_dim_name(vec))}, but its place in T, V, R and the forces makes "
                    f"it {_article(expected)}" + (f" (units such as {examples})" if examples else ""),
                )
            )
    if suspects:
        text = suspects[0][1] if len(suspects) == 1 else "; or ".join(m for _, m in suspects)
        if len(suspects) > 1:
            text = f"the units of {', '.join(n for n, _ in suspects)} contradict each other: {text}"
        error = UnitError(text)
        error.parameter = suspects[0][0]
        raise error
    raise UnitError(
        "the units of the parameters are not consistent with T, V, R and the forces (no single parameter is at "
        f"fault; check the units of {', '.join(sorted(str(s) for s in given))})"
    )
