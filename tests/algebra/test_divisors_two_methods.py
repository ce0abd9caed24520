"""Elementary divisors of regular pencils: the rank method (Weyr's characteristic, used by ``pencil_divisors`` and
the strict-equivalence test) and the Smith form of ``λB - A`` (``elementary_divisors``) agree."""

from __future__ import annotations

import random

import pytest
import sympy as sp

from symosc.algebra import elementary_divisors, pencil_divisors

LAM = sp.Symbol("l")


def _pencils(seed: int, count: int):
    rng = random.Random(seed)
    jordan = sp.Matrix([[2, 1, 0, 0], [0, 2, 0, 0], [0, 0, 2, 0], [0, 0, 0, -1]])
    while count:
        n = rng.randint(2, 4)
        A = sp.Matrix(n, n, lambda i, j: rng.randint(-2, 2))
        B = sp.Matrix(n, n, lambda i, j: rng.randint(-2, 2))
        if count % 3 == 0:
            B[0, :] = sp.zeros(1, n)  # infinite elementary divisors
        if count % 4 == 1:
            S = sp.Matrix(n, n, lambda i, j: rng.randint(-2, 2))
            if S.det() == 0:
                continue
            A, B = S * jordan[:n, :n] * S.inv(), sp.eye(n)  # repeated roots with Jordan blocks
        if sp.expand((LAM * B - A).det()) != 0:
            count -= 1
            yield A, B


@pytest.mark.parametrize("seed", [1, 2])
def test_rank_method_and_smith_form_give_the_same_divisors(seed):
    for A, B in _pencils(seed, 15):
        got = pencil_divisors(A, B, LAM)
        finite = elementary_divisors((LAM * B - A).applyfunc(sp.expand), LAM)
        mu = sp.Symbol("mu")
        infinite = elementary_divisors((B - mu * A).applyfunc(sp.expand), mu).get(sp.Integer(0), [])
        assert got.infinite == infinite
        assert len(got.finite) == len(finite)
        for key, sizes in finite.items():
            (match,) = [k for k in got.finite if sp.simplify(k - key) == 0]
            assert got.finite[match] == sizes


def test_cubic_factors_are_keys_not_cardano_radicals():
    A = sp.Matrix([[0, 1, 0], [0, 0, 1], [1, 1, 0]])  # companion of l^3 - l - 1 (irreducible)
    assert elementary_divisors(LAM * sp.eye(3) - A, LAM) == {LAM**3 - LAM - 1: [1]}
    assert pencil_divisors(A, sp.eye(3), LAM).finite == {LAM**3 - LAM - 1: [1]}
