"""Shared helpers for the algebra tests: exact matrices with a prescribed Jordan structure."""

from __future__ import annotations

import random

import sympy as sp


def jordan_matrix(blocks: list[tuple[object, int]]) -> sp.Matrix:
    """Block-diagonal Jordan matrix from ``[(eigenvalue, size), ...]``."""
    return sp.diag(*[sp.Matrix(k, k, lambda i, j, v=v: v if i == j else (1 if j == i + 1 else 0)) for v, k in blocks])


def unimodular(n: int, seed: int, steps: int = 6) -> sp.Matrix:
    """A random integer matrix with determinant ±1 (product of elementary integer operations)."""
    rng = random.Random(seed)
    S = sp.eye(n)
    for _ in range(steps):
        i, j = rng.sample(range(n), 2) if n > 1 else (0, 0)
        if i != j:
            S[i, :] = S[i, :] + rng.choice([-2, -1, 1, 2]) * S[j, :]
    if n > 1:
        S.row_swap(0, n - 1)
    return S


def similar(blocks: list[tuple[object, int]], seed: int) -> tuple[sp.Matrix, sp.Matrix, sp.Matrix]:
    """``(A, S, J)`` with ``A = S J S^-1`` exact."""
    J = jordan_matrix(blocks)
    S = unimodular(J.rows, seed)
    return S * J * S.inv(), S, J
