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


def _parse_unit(text: str) -> tuple[float, tuple[int, int, int]]:
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
    factor, dim = _parse_unit(unit)
    if dimension is not None and dim != DIMENSIONS[dimension]:
        raise UnitError(
            f"{value!r} is {_article(_dim_name(dim))}, expected {_article(dimension)} "
            f"(units such as {_EXAMPLES[dimension]})"
        )
    out = number * factor
    if not math.isfinite(out) or (out == 0 and number != 0):
        raise UnitError(f"{value!r} is beyond the range of floating point in SI units")
    return out
