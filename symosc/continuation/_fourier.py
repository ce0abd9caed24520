"""Truncated Fourier series on a uniform phase grid, and Hill's matrix (private).

A coordinate is ``z(tau) = a0 + sum_k a_k cos(k tau) + b_k sin(k tau)`` (k = 1..H); its coefficient vector is
``[a0, a1, b1, ..., aH, bH]``.  On N equally spaced samples with ``N > 2H`` the projection ``P`` onto these
harmonics is exact for every trigonometric polynomial of degree ``< N - H``; a polynomial nonlinearity of degree d
in the unknowns, with forcing harmonics up to ``d_tau``, is projected exactly (no aliasing) when
``N > (d + 1) H + d_tau``.  The alternating frequency-time evaluation then equals the exact Fourier convolution
(Krack & Gross 2019, §3.3).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np


def sample_count(harmonics: int, degree: tuple[int, int] | None) -> int:
    """Time samples per period: alias-free for a polynomial, 8x oversampled (at least 64) otherwise."""
    H = harmonics
    if degree is not None:
        d, dt = degree
        n = (max(d, 1) + 1) * H + dt + 1
    else:
        n = max(64, 8 * (2 * H + 1))
    return int(n + (n % 2))


@lru_cache(maxsize=64)
def basis(harmonics: int, samples: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``tau`` (N,), ``E`` (N, m) values of the basis, ``D`` (m, m) d/dtau on coefficients, ``P`` (m, N)."""
    H, N = harmonics, samples
    m = 2 * H + 1
    tau = 2 * np.pi * np.arange(N) / N
    k = np.arange(1, H + 1)
    E = np.empty((N, m))
    E[:, 0] = 1.0
    E[:, 1::2] = np.cos(np.outer(tau, k))
    E[:, 2::2] = np.sin(np.outer(tau, k))
    D = np.zeros((m, m))
    for j in range(1, H + 1):  # (a cos + b sin)' = j b cos - j a sin
        D[2 * j - 1, 2 * j] = j
        D[2 * j, 2 * j - 1] = -j
    P = E.T * (2.0 / N)
    P[0] /= 2.0
    for a in (tau, E, D, P):
        a.setflags(write=False)
    return tau, E, D, P


@lru_cache(maxsize=64)
def derivative_bases(harmonics: int, samples: int) -> tuple[np.ndarray, np.ndarray]:
    """``E D`` and ``E D D`` (N, m): the first and second tau-derivatives of the basis at the samples (computed once:
    a product of this size per call is slow when a multithreaded BLAS competes for busy cores)."""
    _, E, D, _ = basis(harmonics, samples)
    B1 = E @ D
    B2 = B1 @ D
    for a in (B1, B2):
        a.setflags(write=False)
    return B1, B2


def evaluate(coefficients: np.ndarray, tau: np.ndarray) -> np.ndarray:
    """Values of the series with coefficient rows ``coefficients`` (n, 2H+1) at the phases ``tau``: (len(tau), n)."""
    c = np.atleast_2d(coefficients)
    H = (c.shape[1] - 1) // 2
    k = np.arange(1, H + 1)
    arg = np.outer(np.asarray(tau, dtype=float), k)
    return c[:, 0] + np.cos(arg) @ c[:, 1::2].T + np.sin(arg) @ c[:, 2::2].T


def derivative(coefficients: np.ndarray) -> np.ndarray:
    """Coefficients of d/dtau."""
    c = np.atleast_2d(coefficients)
    out = np.zeros_like(c)
    k = np.arange(1, (c.shape[1] - 1) // 2 + 1)
    out[:, 1::2] = k * c[:, 2::2]
    out[:, 2::2] = -k * c[:, 1::2]
    return out


def amplitudes(coefficients: np.ndarray) -> np.ndarray:
    """``max |z_i(tau)|`` for every coordinate, refined by Newton's method on ``z_i' = 0`` at the sampled maximum."""
    c = np.atleast_2d(coefficients)
    H = (c.shape[1] - 1) // 2
    N = max(256, 16 * (2 * H + 1))
    tau = 2 * np.pi * np.arange(N) / N
    z = evaluate(c, tau)
    k = np.arange(1, H + 1)
    a, b = c[:, 1::2], c[:, 2::2]
    out = np.empty(c.shape[0])
    for i in range(c.shape[0]):
        j = int(np.argmax(np.abs(z[:, i])))
        s = tau[j]
        best = abs(z[j, i])
        for _ in range(4):
            cs, sn = np.cos(k * s), np.sin(k * s)
            f1 = k @ (b[i] * cs - a[i] * sn)
            f2 = -(k * k) @ (a[i] * cs + b[i] * sn)
            if f2 == 0 or abs(f1 / f2) > 4 * np.pi / N:
                break
            s -= f1 / f2
        value = abs(c[i, 0] + a[i] @ np.cos(k * s) + b[i] @ np.sin(k * s))
        out[i] = max(value, best)
    return out


def hill_exponents(D0: np.ndarray, D1: np.ndarray, D2: np.ndarray, n: int, omega: float) -> np.ndarray:
    """Floquet exponents from Hill's quadratic eigenvalue problem in the real Fourier basis.

    With ``delta q = exp(lambda t) p(tau)``, ``p`` in the basis ``[1, cos k tau, sin k tau]`` (k <= H, coordinate
    blocks of 2H+1), the linearized equations projected on the same harmonics give
    ``(lambda**2 D2 + lambda D1 + D0) p = 0``: ``D0`` is the harmonic-balance Jacobian,
    ``D1 = P[C E + 2 omega M E D]`` and ``D2 = P[M E]`` with ``C = dr/dq'`` and ``M = dr/dq''`` (Krack & Gross 2019,
    §4.1).  It is solved as a linear eigenproblem of size ``2 n (2H + 1)``.  Each Floquet exponent appears as a
    family ``lambda + i k omega``; one member of each family lies in the strip ``|Im| <= omega/2``, and of those the
    2n whose eigenvectors are centred on the low harmonics are kept, the others being truncation artefacts spread
    over the outer harmonics (Lazarus & Thomas 2010).  A family on the strip's edge (a multiplier on the negative
    real axis) shows both conjugate members: one is kept.
    """
    import scipy.linalg as sla

    size = D0.shape[0]
    m = size // n
    H = (m - 1) // 2
    A = B = None
    try:
        A = np.block([[np.zeros((size, size)), np.eye(size)], [-np.linalg.solve(D2, D0), -np.linalg.solve(D2, D1)]])
    except np.linalg.LinAlgError:
        Z, I = np.zeros((size, size)), np.eye(size)
        A, B = np.block([[Z, I], [-D0, -D1]]), np.block([[I, Z], [Z, D2]])
    half = omega / 2
    if B is None:  # first try: the accurate members are the strip's (the others sit near |Im| = H omega)
        lam = sla.eigvals(A, check_finite=False)
        chosen = _strip_members(lam, np.zeros(len(lam)), half, n)
        if len(chosen) == 2 * n and np.sum(np.abs(lam.imag) <= half * (1 + 1e-7)) <= 2 * n + 2:
            return lam[chosen]
    lam, vec = sla.eig(A, B, check_finite=False)
    ok = np.isfinite(lam)
    lam, vec = lam[ok], vec[:, ok]
    p = np.abs(vec[:size].reshape(n, m, -1)) ** 2
    harmonic = np.concatenate([[0], np.repeat(np.arange(1, H + 1), 2)])
    w = p.sum(axis=0)
    spread = (harmonic[:, None] * w).sum(axis=0) / np.maximum(w.sum(axis=0), 1e-300)
    return lam[_strip_members(lam, spread, half, n)]


def _strip_members(lam: np.ndarray, spread: np.ndarray, half: float, n: int) -> list[int]:
    strip = np.flatnonzero(np.abs(lam.imag) <= half * (1 + 1e-7))
    chosen: list[int] = []
    for j in strip[np.argsort(spread[strip], kind="stable")]:
        if len(chosen) == 2 * n:
            break
        edge = abs(abs(lam[j].imag) - half) < 1e-7 * max(half, 1.0)
        if edge and any(abs(np.conj(lam[j]) - lam[a]) < 1e-6 * (1 + abs(lam[a])) for a in chosen):
            continue
        chosen.append(int(j))
    return chosen
