"""The vectorised Mathieu path: the same bits as scalar calls, seeds on a wrong branch rejected, SciPy's wrong
branches corrected -- for both kernels (compiled C, and the NumPy fallback used without a C compiler).
References: the independent 50-digit Sturm bisection of ``test_mathieu.reference_value``."""

from __future__ import annotations

import functools

import numpy as np
import pytest
import scipy.special as sp

from symosc.periodic import _hill, _hill_batch, _hill_c, mathieu_a, mathieu_b, mathieu_kernel

from .test_mathieu import reference_value, rel_err

# dense in [0, 100] (the fast path), a few large and negative q (fallbacks, symmetry swap)
GRID = np.concatenate([np.linspace(0.0, 100.0, 301), [150.0, 777.7, 2000.0, 1.5e4], -np.linspace(0.25, 60.0, 40)])


@pytest.fixture(params=["c", "numpy"])
def kernel(request, monkeypatch):
    """Run a test with the compiled kernel and with the NumPy fallback (forced as when no C compiler is found)."""
    if request.param == "numpy":
        monkeypatch.setenv("SYMOSC_MATHIEU_KERNEL", "numpy")
    else:
        monkeypatch.delenv("SYMOSC_MATHIEU_KERNEL", raising=False)
    _hill_c.reset()
    assert mathieu_kernel() == request.param  # this machine has a C compiler: the "c" case really compiles
    yield request.param
    _hill_c.reset()


@pytest.mark.parametrize(
    ("fun", "n"), [(mathieu_a, 0), (mathieu_a, 5), (mathieu_b, 1), (mathieu_b, 6), (mathieu_a, 20)]
)
def test_vectorised_and_scalar_calls_agree_bit_for_bit(fun, n, kernel):
    vec = fun(n, GRID)
    one_by_one = np.array([fun(n, float(q)) for q in GRID])
    assert vec.dtype == np.float64
    assert np.array_equal(vec.view(np.int64), one_by_one.view(np.int64))


@pytest.mark.parametrize(("kind", "n", "q"), [("a", 0, 30.0), ("a", 4, 7.0), ("b", 3, 55.0), ("b", 8, 1.0)])
def test_seed_on_a_neighbouring_branch_is_rejected(kind, n, q):
    fam, k = _hill.family_index(kind, n)
    size = _hill_batch.batch_size(k, q)
    right = float((sp.mathieu_a if kind == "a" else sp.mathieu_b)(n, q))
    wrong = float((sp.mathieu_a if kind == "a" else sp.mathieu_b)(n + 2, q))  # next value in the same family
    value, _err, ok = _hill_batch.refine_scalar(fam.offset, fam.q_sign, fam.sqrt2, k, q, right, size)
    assert ok
    assert rel_err(value, reference_value(kind, n, q)) <= 1e-14
    assert not _hill_batch.refine_scalar(fam.offset, fam.q_sign, fam.sqrt2, k, q, wrong, size)[2]
    _v, _e, ok_b = _hill_batch.refine_batch(
        fam.offset, fam.q_sign, fam.sqrt2, k, np.array([q, q]), np.array([right, wrong]), size
    )
    assert ok_b.tolist() == [True, False]


def test_values_where_scipy_takes_a_wrong_branch(kernel):
    """b_5(2000): SciPy's value is off by ~11 % (it returns a neighbour's value); ours matches the reference."""
    scipy_value = float(sp.mathieu_b(5, 2000.0))
    ref = reference_value("b", 5, 2000.0)
    assert rel_err(scipy_value, ref) > 1e-3
    assert rel_err(mathieu_b(5, 2000.0), ref) <= 1e-13
    assert rel_err(mathieu_b(5, np.array([2000.0]))[0], ref) <= 1e-13


@pytest.mark.parametrize(("kind", "n"), [("a", 0), ("b", 1), ("a", 7), ("b", 12), ("a", 20)])
def test_fast_path_accuracy_on_a_grid(kind, n, kernel):
    q = np.linspace(0.0, 100.0, 13)[1:]
    values = (mathieu_a if kind == "a" else mathieu_b)(n, q)
    worst = max(rel_err(v, reference_value(kind, n, float(x), dps=30)) for v, x in zip(values, q, strict=True))
    assert worst <= 1e-13


@pytest.mark.parametrize(("kind", "n", "q"), [("a", 4, 17.5), ("b", 5, 31.4), ("a", 20, 94.0), ("b", 5, 2000.0)])
def test_compiled_kernel_corrects_a_seed_on_a_wrong_branch(kind, n, q):
    """Where SciPy's value is another eigenvalue, the C kernel bisects on the Sturm count and returns the right one."""
    _hill_c.reset()
    lib = _hill_c.kernel()
    fam, k = _hill.family_index(kind, n)
    ref = reference_value(kind, n, q)
    wrong = float((sp.mathieu_a if kind == "a" else sp.mathieu_b)(n + 2, q))
    value, _err, ok = _hill_c.refine1(lib, fam, k, q, wrong, 1e-13)
    assert ok
    assert rel_err(value, ref) <= 1e-13
    values, _errs, oks = _hill_c.refine(lib, fam, k, np.array([q, q]), np.array([wrong, float(ref)]), 1e-13)
    assert oks.all()
    assert max(rel_err(v, ref) for v in values) <= 1e-13


@functools.cache
def _reference(kind: str, n: int, q: float):
    return reference_value(kind, n, q, dps=30)


@pytest.mark.parametrize("q", [-3.0, 0.5, 12.0, 48.0, 333.0, 1500.0])
def test_both_kernels_against_the_reference_and_ordering(q, kernel):
    """Every a_n, b_n (n <= 12) within 1e-13 of the 30-digit values, and the chain a_0 <= b_1 <= a_1 <= ... holds."""
    ns = np.arange(13)
    a = mathieu_a(ns, np.full(13, q))
    b = mathieu_b(ns[1:], np.full(12, q))
    for n in range(13):
        assert rel_err(a[n], _reference("a", n, q)) <= 1e-13
        if n:
            assert rel_err(b[n - 1], _reference("b", n, q)) <= 1e-13
    if q > 0:
        chain = np.ravel(np.column_stack([a[:-1], b]))
        assert np.all(np.diff(np.append(chain, a[-1])) >= 0)
