"""Frequency estimation in white noise vs the Cramér–Rao lower bound (target: RMSE within 2x the bound).

A 3-mode damped signal at the dissertation's frequencies (Belyakov 2005, Table 3: 14.04726, 16.39794, 27.35160
rad/s), sampled at omega_d / omega_max = 4 (Belyakov's rule 43), N = 256 samples, with white Gaussian noise at
SNR 20, 30 and 40 dB (SNR = mean(s^2) / sigma^2).  For each SNR, >= 200 Monte Carlo runs (``symosc.sweep`` over
(snr, seed) on a process pool) of

* ``prony``          least-squares Prony (what the thesis used, and what a user would code from eqs 40-42),
* ``era``            Kung / ERA (Hankel SVD, least-squares shift; the thesis's preferred method; = python-control's
                     ``eigensys_realization`` algorithm),
* ``matrix_pencil``  Hua–Sarkar matrix pencil, pencil parameter N/3,
* ``esprit``         TLS-ESPRIT on the same subspace,
* ``pencil+ml``      matrix pencil refined by variable-projection nonlinear least squares (the ML estimator).

The CRLB is computed from the Fisher information of the real damped-sinusoid model with all amplitudes, phases,
damping rates and frequencies unknown (symosc.identification.cramer_rao_bound; cross-checked in the tests against
Kay's closed form and a finite-difference Fisher matrix).  The table reports var(omega_hat) / CRLB per mode
(target: <= 2 for the best estimator), the bias in units of the CRLB standard deviation, failures, and the time
per estimate.

Run:  python benchmarks/identification_crlb.py [--quick] [--runs N] [--plot] [--serial]
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # small SVDs: BLAS threads only contend (see docs)
os.environ.setdefault("OMP_NUM_THREADS", "1")

import argparse
import sys
import time

import numpy as np

import symosc
from symosc.errors import SymoscError
from symosc.identification import (
    cramer_rao_bound,
    era,
    esprit,
    matrix_pencil,
    noise_sigma,
    prony,
    refine,
)

W = np.array([14.04726, 16.39794, 27.35160])
DELTA = np.array([0.10, 0.15, 0.30])
AMP = np.array([1.0, 0.8, 0.6])
PHASE = np.array([0.3, -1.2, 2.0])
RATIO = 4.0
DT = 2 * np.pi / (RATIO * W.max())
N = 256
SNRS = (20.0, 30.0, 40.0)


def _ml(y, dt, **kw):
    return refine(matrix_pencil(y, dt, **kw), y)


METHODS = {"prony": prony, "era": era, "matrix_pencil": matrix_pencil, "esprit": esprit, "pencil+ml": _ml}


def clean_signal() -> np.ndarray:
    t = np.arange(N) * DT
    return (AMP[:, None] * np.exp(-np.outer(DELTA, t)) * np.cos(np.outer(W, t) + PHASE[:, None])).sum(axis=0)


def trial(snr_db: float, seed: int) -> np.ndarray:
    """One noise realisation; returns frequency estimates, shape (methods, modes), NaN where a method failed."""
    clean = clean_signal()
    rng = np.random.default_rng([int(seed), int(snr_db * 10)])
    y = clean + noise_sigma(clean, snr_db) * rng.standard_normal(N)
    out = np.full((len(METHODS), W.size), np.nan)
    for i, f in enumerate(METHODS.values()):
        try:
            out[i] = f(y, DT, n_modes=3, constant=False).frequencies
        except (SymoscError, np.linalg.LinAlgError):
            pass
    return out


def timing(reps: int = 20) -> dict[str, float]:
    clean = clean_signal()
    rng = np.random.default_rng(0)
    y = clean + noise_sigma(clean, 30) * rng.standard_normal(N)
    out = {}
    for name, f in METHODS.items():
        t0 = time.perf_counter()
        for _ in range(reps):
            try:
                f(y, DT, n_modes=3, constant=False)
            except SymoscError:
                pass
        out[name] = (time.perf_counter() - t0) / reps
    return out


def run(runs: int, executor: str | None) -> tuple[dict, dict]:
    t0 = time.perf_counter()
    res = symosc.sweep(trial, {"snr_db": list(SNRS), "seed": np.arange(runs)}, executor=executor, progress=True)
    wall = time.perf_counter() - t0
    est = res.values  # (snr, runs, methods, modes)
    table = {}
    for i, snr in enumerate(SNRS):
        sigma = noise_sigma(clean_signal(), snr)
        crlb = cramer_rao_bound(W, DELTA, AMP, PHASE, DT, N, sigma).frequency
        for j, name in enumerate(METHODS):
            e = est[i, :, j, :]
            ok = ~np.isnan(e).any(axis=1)
            fails = int((~ok).sum())
            if ok.sum() >= 20:  # fewer successes make a variance meaningless
                var = np.var(e[ok], axis=0, ddof=1)
                bias = (np.mean(e[ok], axis=0) - W) / np.sqrt(crlb)
            else:
                var = bias = np.full(W.size, np.nan)
            table[(snr, name)] = {"ratio": var / crlb, "bias": bias, "fails": fails, "crlb_std": np.sqrt(crlb)}
    info = {"wall": wall, "executor": res.executor, "runs": runs, "sweep_failures": len(res.failures)}
    return table, info


def report(table: dict, info: dict, times: dict) -> str:
    lines = [
        f"3 modes at {W.tolist()} rad/s, delta = {DELTA.tolist()} 1/s, amplitudes {AMP.tolist()}, "
        f"N = {N}, dt = {DT:.5f} s (omega_d/omega_max = {RATIO:g}), {info['runs']} runs per SNR",
        f"sweep: {3 * info['runs']} points on {info['executor']!r} in {info['wall']:.1f} s, "
        f"{info['sweep_failures']} crashed points",
        "",
        "| SNR (dB) | method | var/CRLB mode 1 | mode 2 | mode 3 | bias/CRLB-std (max) | failed runs | ms/estimate |",
        "|---:|---|---:|---:|---:|---:|---:|---:|",
    ]
    for snr in SNRS:
        for name in METHODS:
            r = table[(snr, name)]
            ratios = " | ".join("n/a" if np.isnan(v) else f"{v:.3g}" for v in r["ratio"])
            bias = "n/a" if np.isnan(r["bias"]).all() else f"{np.nanmax(np.abs(r['bias'])):.2g}"
            lines.append(f"| {snr:g} | {name} | {ratios} | {bias} | {r['fails']} | {1e3 * times[name]:.2f} |")
    lines.append("")
    lines.append("CRLB standard deviation of the frequencies (rad/s):")
    for snr in SNRS:
        s = table[(snr, "prony")]["crlb_std"]
        lines.append(f"  {snr:g} dB: " + ", ".join(f"{v:.3g}" for v in s))

    def worst(snr, m):
        r = table[(snr, m)]["ratio"]
        return np.inf if np.isnan(r).any() else float(np.max(r))

    best = {snr: min(METHODS, key=lambda m, snr=snr: worst(snr, m)) for snr in SNRS}
    verdict = all(worst(snr, best[snr]) <= 2 for snr in SNRS)
    lines.append("")
    lines.append(
        "best estimator per SNR: "
        + ", ".join(f"{snr:g} dB -> {best[snr]} (max var/CRLB {worst(snr, best[snr]):.3g})" for snr in SNRS)
        + f"; target var <= 2 CRLB: {'MET' if verdict else 'NOT MET'}"
    )
    return "\n".join(lines)


def figure_error_vs_noise(path: str = "docs/img/identification_crlb.png", runs: int = 100) -> str:
    """Frequency RMS error of each method vs SNR against the CRLB (mode 3), saved as PNG."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    snrs = np.arange(10.0, 61.0, 5.0)
    res = symosc.sweep(trial, {"snr_db": snrs, "seed": np.arange(runs)})
    est = res.values
    fig, ax = plt.subplots(figsize=(6, 4))
    for j, name in enumerate(METHODS):
        err = est[:, :, j, 2] - W[2]
        rmse = [np.sqrt(np.mean(e[~np.isnan(e)] ** 2)) if np.sum(~np.isnan(e)) >= 10 else np.nan for e in err]
        ax.semilogy(snrs, rmse, "o-", ms=3, label=name)
    crlb = [
        np.sqrt(cramer_rao_bound(W, DELTA, AMP, PHASE, DT, N, noise_sigma(clean_signal(), s)).frequency[2])
        for s in snrs
    ]
    ax.semilogy(snrs, crlb, "k--", label="CRLB")
    ax.set_xlabel("SNR (dB)")
    ax.set_ylabel("RMS error of omega_3 (rad/s)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="50 runs per SNR")
    ap.add_argument("--runs", type=int, default=200)
    ap.add_argument("--serial", action="store_true")
    ap.add_argument("--plot", action="store_true", help="also write docs/img/identification_crlb.png")
    args = ap.parse_args(argv)
    runs = 50 if args.quick else args.runs
    times = timing()
    table, info = run(runs, "serial" if args.serial else None)
    print(report(table, info, times))
    if args.plot:
        print("figure:", figure_error_vs_noise(runs=min(runs, 100)), file=sys.stderr)


if __name__ == "__main__":
    main()
