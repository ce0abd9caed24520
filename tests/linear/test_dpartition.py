"""D-partition (Neimark), discriminant curve and Vyshnegradsky diagram (Bulgakov (1954), §8.25–8.27, E13).

The reference is brute force written here: root counts by numpy.roots on a grid, bisection for the parameter where
the count jumps, and the root that sits on Re λ = ε there.  Every jump must lie on the computed boundary or on a
singular line, and the shading must point to the side with fewer roots.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from symosc.errors import ParameterError
from symosc.linear import d_partition, discriminant_curve, vyshnegradsky_diagram

lam, mu, nu = sp.symbols("lambda mu nu")


def _counter(F, params, eps):
    poly = sp.Poly(sp.expand(F), lam)
    cs = [sp.lambdify(params, c, "numpy") for c in poly.all_coeffs()]

    def count(p):
        c = np.array([complex(f(*p)) for f in cs])
        c = c[np.flatnonzero(np.abs(c) > 1e-14)[0] :]
        return int(np.sum(np.roots(c).real > eps)), np.roots(c)

    return count


CASES = [
    ((lam**2 + lam) * mu + (lam**2 + 1) * nu - lam**2 + 2, (mu, nu), 0),  # Neimark's example (E13)
    (lam**3 + mu * lam**2 + nu * lam + 1, (mu, nu), 0),  # Vyshnegradsky
    (lam**3 + mu * lam**2 + nu * lam + 1, (mu, nu), -0.3),  # stability degree 0.3
    (lam**3 + (1 + 2 * sp.I) * lam**2 + mu * lam + nu * (1 + sp.I * lam) + 1, (mu, nu), 0),  # complex coefficients
    (lam**3 + 2 * lam**2 + 3 * lam + mu, (mu,), 0),  # one complex parameter
]


@pytest.mark.parametrize("F, params, eps", CASES)
def test_boundary_and_shading_match_brute_force(F, params, eps):
    dp = d_partition(F, lam, params, epsilon=eps)
    if len(params) == 1:
        z = sp.symbols("x y", real=True)
        Fxy = F.subs(params[0], z[0] + sp.I * z[1])
        count = _counter(Fxy, z, eps)
    else:
        count = _counter(F, params, eps)
    xs = np.linspace(-4, 4, 33)
    checked = 0
    for y in np.linspace(-4, 4, 17) + 0.0123:
        counts = [count((x, y))[0] for x in xs]
        for i in range(len(xs) - 1):
            if counts[i] == counts[i + 1]:
                continue
            a, b = xs[i], xs[i + 1]
            ca = counts[i]
            for _ in range(50):
                m = 0.5 * (a + b)
                a, b = (m, b) if count((m, y))[0] == ca else (a, m)
            x_star = 0.5 * (a + b)
            roots = count((x_star, y))[1]
            root = roots[np.argmin(np.abs(roots.real - eps))]
            w = root.imag
            on_singular = any(
                abs(complex(sa) * x_star + complex(sb) * y + complex(sc)) < 1e-6 * (1 + abs(complex(sc)))
                for sa, sb, sc, _ in dp.singular_lines
            )
            if not on_singular:
                pm, pn, _d = dp.curve(np.array([w]))
                assert abs(pm[0] - x_star) < 1e-6 * (1 + abs(x_star)) and abs(pn[0] - y) < 1e-6 * (1 + abs(y))
                _, normal = dp.shaded_normal(w)
                h = 1e-4
                shaded = count((x_star + h * normal[0], y + h * normal[1]))[0]
                unshaded = count((x_star - h * normal[0], y - h * normal[1]))[0]
                jump = 2 if dp.real and abs(w) > 1e-8 else 1
                assert unshaded - shaded == jump
            # the partition's own label agrees with brute force on both sides
            assert dp.roots_right(xs[i], y) == counts[i] and dp.roots_right(xs[i + 1], y) == counts[i + 1]
            checked += 1
    assert checked > 0


def test_neimark_example_e13():
    """§8.26: μ = 0, ν = (ω²+2)/(ω²-1); singular lines ν + 2 = 0 (λ = 0) and μ + ν - 1 = 0 (λ = ∞);
    (0, 0) lies in C0(1) (λ = ±√2) and (1, 1) is stable."""
    dp = d_partition((lam**2 + lam) * mu + (lam**2 + 1) * nu - lam**2 + 2, lam, (mu, nu))
    w = dp.omega
    assert dp.mu == 0 and sp.simplify(dp.nu - (w**2 + 2) / (w**2 - 1)) == 0
    assert sp.expand(dp.Delta - w * (w**2 - 1)) == 0 or sp.expand(dp.Delta + w * (w**2 - 1)) == 0
    lines = {(sp.nsimplify(a), sp.nsimplify(b), sp.nsimplify(c)) for a, b, c, _ in dp.singular_lines}
    assert (0, 1, 2) in lines and (1, 1, -1) in lines
    assert dp.roots_right(0, 0) == 1 and dp.roots_right(1, 1) == 0
    disc = discriminant_curve((lam**2 + lam) * mu + (lam**2 + 1) * nu - lam**2 + 2, lam, (mu, nu))
    e = disc.e
    assert sp.simplify(disc.mu - 6 * e / (-(e**2) + 2 * e + 1)) == 0
    assert sp.simplify(disc.nu - (e**2 + 4 * e + 2) / (e**2 - 2 * e - 1)) == 0


def test_vyshnegradsky_cusp_and_double_roots():
    """Cusp (3, 3) = (λ+1)³; every point of the discriminant curve has a double real root; xy = 1 is T."""
    dp, disc = vyshnegradsky_diagram()
    _x, _y = dp.params
    for e in (-0.3, -1.0, -2.5, 0.7):
        mx, ny = disc.curve(np.array([e]))
        p = np.array([1.0, mx[0], ny[0], 1.0])
        assert abs(np.polyval(p, e)) < 1e-10 and abs(np.polyval(np.polyder(p), e)) < 1e-10
    assert sp.simplify(dp.mu * dp.nu - 1) == 0  # the boundary lies on the hyperbola xy = 1


def test_bad_input():
    with pytest.raises(ParameterError, match="linearly"):
        d_partition(lam**2 + mu**2 * lam + nu, lam, (mu, nu))
    with pytest.raises(ParameterError, match="linearly"):
        d_partition(lam**2 + mu * nu * lam + 1, lam, (mu, nu))
    k = sp.Symbol("k")
    with pytest.raises(ParameterError, match="free symbols"):
        d_partition(lam**2 + mu * lam + k * nu, lam, (mu, nu))


def test_plot_draws_on_given_axes():
    """The plot draws the boundary on the Axes it is given: the drawn points satisfy xy = 1 (Vyshnegradsky)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    dp, disc = vyshnegradsky_diagram()
    fig, ax = plt.subplots()
    out = dp.plot(ax=ax, xlim=(0, 6), ylim=(0, 6), grid=12)
    assert out is ax
    x, y = ax.lines[0].get_data()
    ok = np.isfinite(x) & np.isfinite(y)
    assert ok.sum() > 100 and np.allclose(x[ok] * y[ok], 1, rtol=1e-9)
    disc.plot(ax=ax)
    assert len(ax.lines) > 1
    plt.close(fig)


def test_stability_region_vs_roots():
    """§8.19: the region of λ³ + xλ² + yλ + 1 is x > 0, xy > 1; checked against numpy root locations; on the
    paraboloid k1k2 = k0k3 the roots are -k1/k0 and ±i sqrt(k2/k0)."""
    from symosc.linear import stability_region

    x, y = sp.symbols("x y")
    r = stability_region([1, x, y, 1], (x, y))
    rng = np.random.default_rng(3)
    for xv, yv in rng.uniform(-2, 4, (200, 2)):
        assert r.contains({x: float(xv), y: float(yv)}) == (np.roots([1, xv, yv, 1]).real.max() < 0)
    k1, k2 = 1.7, 2.3
    roots = np.sort_complex(np.roots([1.0, k1, k2, k1 * k2]))
    assert np.allclose(roots, np.sort_complex([-k1, 1j * np.sqrt(k2), -1j * np.sqrt(k2)]))
    with pytest.raises(ParameterError, match="not parameters"):
        stability_region([1, x, y, sp.Symbol("k")], (x, y))


def test_e10_robust_envelope():
    """§8.23 (E10): the envelope of (xz+1)(yz+k) = z over unreliable z is k²x² - 2kxy + y² - 2(kx+y) + 1 = 0,
    tangent to the axes at (1/k, 0), (0, 1); at z = 4k the boundary touches it at (1/(4k), 1/4)."""
    from symosc.linear import robust_boundary

    x, y, z, k = sp.symbols("x y z k")
    F = (x * z + 1) * (y * z + k) - z
    (env,) = robust_boundary(F, (x, y), z)
    book = k**2 * x**2 - 2 * k * x * y + y**2 - 2 * (k * x + y) + 1
    assert sp.expand(env - book) == 0 or sp.expand(env + book) == 0
    kv = sp.Rational(1, 2)
    pt = {x: 1 / (4 * kv), y: sp.Rational(1, 4), k: kv}
    assert F.subs(pt).subs(z, 4 * kv) == 0 and book.subs(pt) == 0
    assert book.subs({x: 1 / k, y: 0}) == 0 and book.subs({x: 0, y: 1}) == 0


@pytest.mark.parametrize("F, params, eps", CASES)
def test_grid_labels_match_numpy_roots_per_point(F, params, eps):
    """Vectorised labels of a grid equal numpy.roots point by point (coefficients lambdified here from F), including
    points where the degree drops (leading coefficient 0) and where λ = 0 is an exact root (constant term 0)."""
    dp = d_partition(F, lam, params, epsilon=eps)
    if len(params) == 1:
        z = sp.symbols("x y", real=True)
        count = _counter(F.subs(params[0], z[0] + sp.I * z[1]), z, eps)
    else:
        count = _counter(F, params, eps)
    xs = np.concatenate([np.linspace(-3.3, 3.1, 15), [0.0, 1.0, -2.0]])
    ys = np.concatenate([np.linspace(-2.9, 3.4, 12), [0.0, 1.0, -2.0]])
    X, Y = np.meshgrid(xs, ys)
    grid = dp.roots_right(X, Y)
    assert grid.shape == X.shape and grid.dtype.kind == "i"
    for i, j in np.ndindex(X.shape):
        expected = count((X[i, j], Y[i, j]))[0]
        assert grid[i, j] == expected == dp.roots_right(X[i, j], Y[i, j]), (X[i, j], Y[i, j])


def test_degree_drop_and_zero_roots_in_one_grid():
    """Neimark's example: on μ + ν = 1 the λ² term vanishes (one root goes to infinity), on ν = -2 λ = 0 is a root;
    the labels there are those of the lower-degree polynomial (numpy.roots strips the same coefficients)."""
    dp = d_partition((lam**2 + lam) * mu + (lam**2 + 1) * nu - lam**2 + 2, lam, (mu, nu))
    pts = np.array([[0.5, 0.5], [-1.0, 2.0], [-3.0, 4.0], [1.0, -2.0], [-1.0, -2.0], [0.0, 0.0], [0.0, 1.0]])
    got = dp.roots_right(pts[:, 0], pts[:, 1])
    # F at each point by hand: (m + n - 1) λ² + m λ + (n + 2)
    expected = []
    for m, n in pts:
        c = np.trim_zeros(np.array([m + n - 1, m, n + 2]), "f")
        expected.append(int(np.sum(np.roots(c).real > 0)))
    assert got.tolist() == expected == [0, 1, 1, 1, 0, 1, 0]
    with pytest.raises(ParameterError, match="vanishes"):
        d_partition(lam * mu + nu, lam, (mu, nu)).roots_right(np.array([1.0, 0.0]), np.array([2.0, 0.0]))


def test_stability_region_numeric_labels():
    """StabilityRegion.roots_right (coefficients compiled once, batched) against the exact Hurwitz verdict."""
    from symosc.linear import stability_region

    x, y = sp.symbols("x y")
    r = stability_region([1, x, y, 1], (x, y))
    rng = np.random.default_rng(7)
    xv, yv = rng.uniform(-2, 4, (2, 150))
    counts = r.roots_right({"x": xv, y: yv})
    assert counts.shape == (150,)
    for a, b, n in zip(xv, yv, counts, strict=True):
        assert (n == 0) == r.contains({x: float(a), y: float(b)})
        assert n == int(np.sum(np.roots([1, a, b, 1]).real > 0))
    assert r.roots_right({x: 2.0, y: 1.0}) == 0
