"""Numeric inversion fallback (Bulgakov §2.29 Bromwich integral; report feature 16)."""

import numpy as np
import pytest
import sympy as sp

from symosc.errors import ConvergenceError, ParameterError
from symosc.operational import invert_numeric

p = sp.Symbol("p")


def test_table_originals():
    """Table rows (2.52), (2.55) at several t against their closed forms."""
    ts = np.array([0.3, 1.0, 4.0])
    r = invert_numeric(p / (p + 1) ** 3, p, ts)
    assert np.allclose(r.values, ts**2 * np.exp(-ts) / 2, rtol=0, atol=1e-12)
    r = invert_numeric(p * 2 / ((p + 0.5) ** 2 + 4), p, ts, method="talbot")
    assert np.allclose(r.values, np.exp(-0.5 * ts) * np.sin(2 * ts), atol=1e-12)
    assert r.converged and np.all(r.error_estimate < 1e-10)
    assert "NumericInversion" in repr(r)


def test_image_without_closed_rational_form():
    """exp(-sqrt(p)) <-> erfc(1/(2 sqrt t)) (no rational form); p/sqrt(p^2+1) <-> J0(t) where Talbot alone fails
    (branch points on the imaginary axis) and the cross-check falls back to a third method."""
    import mpmath

    r = invert_numeric(sp.exp(-sp.sqrt(p)), p, [0.5, 2.0])
    assert np.allclose(r.values, [float(mpmath.erfc(1 / (2 * mpmath.sqrt(v)))) for v in (0.5, 2.0)], atol=1e-12)
    r = invert_numeric(p / sp.sqrt(p**2 + 1), p, [2.0, 5.0])
    assert np.allclose(r.values, [float(mpmath.besselj(0, v)) for v in (2.0, 5.0)], atol=1e-12)


def test_expanded_resonant_image():
    """``1/(p² + 4)³`` expanded: its singularities are triple roots, on which mpmath's polyroots need not converge;
    the oscillation rate that sets the working precision is found on the squarefree factors (the lookup raised
    AttributeError).  Values against SymPy's inverse Laplace transform of ``1/(p (p² + 4)³)``, and, with algebraic
    coefficients (whose numeric residues raised TypeError), against mpmath's de Hoog inversion."""
    t = sp.Symbol("t", positive=True)
    ts = [5.0, 40.0]
    r = invert_numeric(1 / sp.expand((p**2 + 4) ** 3), p, ts)
    original = sp.inverse_laplace_transform(1 / (p * (p**2 + 4) ** 3), p, t)
    assert np.allclose(r.values, [float(sp.re(sp.N(original.subs(t, v), 30))) for v in ts], rtol=1e-12, atol=1e-14)
    # algebraic coefficients, lightly damped: against mpmath's de Hoog inversion at 60 digits of the factored image
    import mpmath

    r = invert_numeric(1 / sp.expand((p**2 + sp.sqrt(2) * p / 10 + 4) ** 3), p, ts)
    with mpmath.workdps(60):
        image = lambda s: 1 / (s * (s**2 + mpmath.sqrt(2) * s / 10 + 4) ** 3)  # noqa: E731
        reference = [float(mpmath.invertlaplace(image, v, method="dehoog")) for v in ts]
    assert np.allclose(r.values, reference, rtol=1e-10, atol=1e-14)


def test_parameters_and_errors():
    a = sp.Symbol("a", positive=True)
    r = invert_numeric(p / (p + a), p, 1.0, values={"a": 2})
    assert abs(r.values[0] - np.exp(-2)) < 1e-12
    with pytest.raises(ParameterError, match="missing values for: a"):
        invert_numeric(p / (p + a), p, 1.0)
    with pytest.raises(ParameterError, match="t > 0"):
        invert_numeric(p / (p + 1), p, [0.0])
    with pytest.raises(ParameterError, match="unknown method"):
        invert_numeric(p / (p + 1), p, 1.0, method="fft")
    with pytest.raises(ConvergenceError, match="did not reach tol"):
        invert_numeric(p / (p + 1), p, [1.0], dps=15, tol=1e-30)


def test_plot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    r = invert_numeric(p / (p + 1), p, [0.5, 1.0, 2.0])
    fig, ax = plt.subplots()
    r.plot(ax=ax)
    assert np.allclose(ax.lines[0].get_ydata(), np.exp(-np.array([0.5, 1.0, 2.0])), atol=1e-12)
    plt.close(fig)
