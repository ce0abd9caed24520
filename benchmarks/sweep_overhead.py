"""Overhead of symosc.sweep on a trivial function, against the plain loops a user would write, in one run.

* serial: ``sweep(f, {"x": xs}, executor="serial")`` vs ``[f(x=x) for x in xs]`` (the same keyword call) and
  ``[f(x) for x in xs]``;
* Dask LocalCluster(2 workers): ``sweep(f, grid, executor=client)`` vs ``client.map`` over pre-built chunks
  (each chunk one task running a list comprehension) -- the best one can do by hand;
* ``executor="auto"`` on the same trivial function (decides serial from the first chunk's measured cost).

    python benchmarks/sweep_overhead.py [--points 10000] [--no-dask]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

import symosc


def trivial(x):
    return x + 1.0


def chunk_by_hand(xs):
    return [trivial(x) for x in xs]


def best(fn, repeat):
    t = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        t = min(t, time.perf_counter() - t0)
    return t


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--points", type=int, default=10_000)
    ap.add_argument("--repeat", type=int, default=7)
    ap.add_argument("--no-dask", action="store_true")
    args = ap.parse_args()
    xs = np.linspace(0.0, 1.0, args.points)
    xl = xs.tolist()
    n = args.points
    t_kw = best(lambda: [trivial(x=x) for x in xl], args.repeat)
    t_pos = best(lambda: [trivial(x) for x in xl], args.repeat)
    t_sw = best(lambda: symosc.sweep(trivial, {"x": xs}, executor="serial"), args.repeat)
    t_auto = best(lambda: symosc.sweep(trivial, {"x": xs}), args.repeat)
    note = symosc.sweep(trivial, {"x": xs}).executor_note
    print(f"{n} points, best of {args.repeat}; machine shared (ratios measured in this run)")
    print(f"{'what':44s} {'ms':>8s} {'us/pt':>7s} {'ratio':>6s}")
    print(f"{'[f(x=x) for x in xs]':44s} {t_kw * 1e3:8.2f} {t_kw / n * 1e6:7.3f} {1.0:6.2f}")
    print(f"{'[f(x) for x in xs]':44s} {t_pos * 1e3:8.2f} {t_pos / n * 1e6:7.3f} {t_pos / t_kw:6.2f}")
    print(f"{'sweep(executor=serial)':44s} {t_sw * 1e3:8.2f} {t_sw / n * 1e6:7.3f} {t_sw / t_kw:6.2f}")
    print(f"{'sweep(executor=auto)':44s} {t_auto * 1e3:8.2f} {t_auto / n * 1e6:7.3f} {t_auto / t_kw:6.2f}")
    print(f"  auto chose: {note}")
    if args.no_dask:
        return
    from distributed import Client, LocalCluster

    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with Client(cluster) as client:
            chunks = [xl[i : i + n // 8] for i in range(0, n, n // 8)]

            def by_hand():
                futs = client.map(chunk_by_hand, chunks, pure=False)
                return [v for f in futs for v in f.result()]

            by_hand()
            symosc.sweep(trivial, {"x": xs}, executor=client)
            t_hand = best(by_hand, args.repeat)
            t_dask = best(lambda: symosc.sweep(trivial, {"x": xs}, executor=client), args.repeat)
    print(f"{'Dask: client.map over 8 pre-built chunks':44s} {t_hand * 1e3:8.2f} {t_hand / n * 1e6:7.3f} {1.0:6.2f}")
    print(f"{'Dask: sweep(executor=client)':44s} {t_dask * 1e3:8.2f} {t_dask / n * 1e6:7.3f} {t_dask / t_hand:6.2f}")


if __name__ == "__main__":
    main()
