"""Scattering (S) and scattering-transfer (T) parameters of four-poles, and the bridge to scikit-rf.

With real reference impedances ``Z01``, ``Z02`` at the two ports (power waves ``a = (V + Z0 I)/(2 sqrt(Z0))``,
``b = (V - Z0 I)/(2 sqrt(Z0))``, currents into the ports) the chain matrix ``[[A, B], [C, D]]`` (Bulgakov's
``[Ex, Ix] = A [Ey, Iy]``, the usual ABCD matrix) gives

    Δ = A Z02 + B + C Z01 Z02 + D Z01,
    S11 = (A Z02 + B - C Z01 Z02 - D Z01)/Δ,     S12 = 2 (AD - BC) sqrt(Z01 Z02)/Δ,
    S21 = 2 sqrt(Z01 Z02)/Δ,                    S22 = (-A Z02 + B - C Z01 Z02 + D Z01)/Δ

(Pozar, *Microwave Engineering*, 4th ed. (2012), Table 4.2 for ``Z01 = Z02``; Frickey, IEEE Trans. MTT 42 (1994)
205–211, Table I for unequal references).  The T parameters are those of scikit-rf, ``[b1, a1] = T [a2, b2]``:
``T = [[-det S, S11], [-S22, 1]] / S21``, so that a cascade multiplies T matrices.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import sympy as sp

from ..._validate import check_choice, validated
from ...errors import ParameterError
from .conversions import (
    abcd_from_s,
    convert_parameters,
    parameter_kind,
    s_from_abcd,
    scattering_references,
    t_from_s,
)

__all__ = ["skrf_parameters"]


def numeric_chain(four_pole: Any, frequencies: Any) -> tuple[np.ndarray, np.ndarray]:
    """``(f, A)``: the chain matrix at ``p = 2 pi i f`` as an array of shape ``(len(f), 2, 2)``."""
    f = np.atleast_1d(np.asarray(frequencies, dtype=float))
    if f.ndim != 1 or not np.all(np.isfinite(f)) or np.any(f < 0):
        raise ParameterError("frequencies must be a 1-D array of finite frequencies >= 0 (Hz)")
    free = sorted(str(s) for s in four_pole.chain.free_symbols - {four_pole.p})
    if free:
        raise ParameterError(f"the chain matrix has free symbols {free}: substitute values first (.subs(...))")
    pp = 2j * np.pi * f
    out = np.empty((f.size, 2, 2), dtype=complex)
    for (i, j), entry in np.ndenumerate(np.array(four_pole.chain.tolist(), dtype=object)):
        fn = sp.lambdify(four_pole.p, entry, "numpy")
        out[:, i, j] = np.broadcast_to(np.asarray(fn(pp), dtype=complex), f.shape)
    return f, out


def to_skrf(four_pole: Any, frequencies: Any, z0: Any = 50, name: str | None = None) -> Any:
    """A ``skrf.Network`` of ``four_pole`` at ``frequencies`` (Hz), S parameters in ``z0``."""
    try:
        import skrf  # optional: scikit-rf, the RF network toolbox
    except ImportError as err:
        raise ImportError("this needs scikit-rf: pip install scikit-rf") from err
    f, A = numeric_chain(four_pole, frequencies)
    z1, z2 = (float(z) for z in scattering_references(z0))
    S = np.stack(s_from_abcd(A[:, 0, 0], A[:, 0, 1], A[:, 1, 0], A[:, 1, 1], z1, z2, np.sqrt), axis=-1)
    freq = skrf.Frequency.from_f(f, unit="hz")
    return skrf.Network(frequency=freq, s=S.reshape(-1, 2, 2), z0=[z1, z2], name=name or four_pole.name or None)


@validated
def skrf_parameters(network: Any, kind: str = "A", convention: str = "book") -> np.ndarray:
    """The parameters of a two-port ``skrf.Network`` as an array of shape ``(frequencies, 2, 2)``.

    Parameters
    ----------
    network : skrf.Network
        A two-port network with real, frequency-independent reference impedances.
    kind : {"A", "Z", "Y", "H", "G", "S", "T"}
        The parameter set: chain (ABCD), impedance, admittance, hybrid, inverse hybrid, scattering or
        scattering-transfer (the scikit-rf definition).
    convention : {"book", "ieee"}
        Sign convention of Z, Y, H, G (see :func:`convert_parameters`); A, S and T do not depend on it.

    Returns
    -------
    numpy.ndarray
        Complex array, one 2x2 matrix per frequency of the network.

    Raises
    ------
    ParameterError
        Not a two-port, or complex or frequency-dependent reference impedances.

    Examples
    --------
    >>> import numpy as np
    >>> import sympy as sp
    >>> from symosc.networks import series_element, skrf_parameters
    >>> net = series_element(sp.Integer(25)).to_skrf([1e6, 2e6])
    >>> np.round(skrf_parameters(net, "A")[0].real, 12).tolist()
    [[1.0, 25.0], [0.0, 1.0]]

    See Also
    --------
    FourPole.to_skrf, FourPole.s_parameters, convert_parameters
    """
    target = parameter_kind(kind, "kind")
    check_choice("convention", convention, ("book", "ieee"))
    s = np.asarray(getattr(network, "s", None))
    if s.ndim != 3 or s.shape[1:] != (2, 2):
        raise ParameterError(f"network must be a two-port skrf.Network, got S of shape {s.shape}")
    z0 = np.asarray(network.z0)
    if np.any(np.abs(z0.imag) > 0) or np.any(z0.real <= 0) or np.ptp(z0.real, axis=0).max() > 0:
        raise ParameterError("network.z0 must be real, positive and the same at every frequency")
    z1, z2 = float(z0[0, 0].real), float(z0[0, 1].real)
    A = np.stack(abcd_from_s(s[:, 0, 0], s[:, 0, 1], s[:, 1, 0], s[:, 1, 1], z1, z2, np.sqrt), axis=-1)
    A = A.reshape(-1, 2, 2)
    if target == "A":
        return A
    if target == "S":
        return s.copy()
    if target == "T":
        return np.stack(t_from_s(s[:, 0, 0], s[:, 0, 1], s[:, 1, 0], s[:, 1, 1]), axis=-1).reshape(-1, 2, 2)
    a, b, c, d = sp.symbols("a b c d")
    fn = sp.lambdify((a, b, c, d), convert_parameters([[a, b], [c, d]], "A", target, convention), "numpy")
    out = np.empty_like(A)
    for i in range(2):
        for j in range(2):
            entry = np.asarray(fn(A[:, 0, 0], A[:, 0, 1], A[:, 1, 0], A[:, 1, 1]), dtype=object)[i, j]
            out[:, i, j] = np.broadcast_to(np.asarray(entry, dtype=complex), out.shape[:1])
    return out
