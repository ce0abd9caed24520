"""Command line: ``symosc double-pendulum`` (the README's main job) and friends."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence

import numpy as np

__all__ = ["main"]


def _double_pendulum(args: argparse.Namespace) -> int:
    from .models import gribkov_khokhlov_table1, n_link_pendulum

    values = gribkov_khokhlov_table1()
    for item in args.set or []:
        name, _, val = item.partition("=")
        values[name] = float(val)
    system = n_link_pendulum(2, links="rigid")
    lin = system.linearize()
    omega, modes = lin.modes(values)
    hz = omega / (2 * np.pi)
    print("Double physical pendulum (Gribkov & Khokhlov 2015, Table 1), hanging, fixed pivot")
    print("parameters (SI): " + ", ".join(f"{k}={v:g}" for k, v in values.items()))
    print()
    print("linearized model  M phi'' + K phi = 0:")
    print(f"  M = {lin.M.tolist()}")
    print(f"  K = {lin.K.tolist()}")
    print()
    print(f"{'mode':>4} {'omega, rad/s':>14} {'f, Hz':>10}   mass-normalised shape (phi1, phi2)")
    for i in range(2):
        shape = ", ".join(f"{c:+.6g}" for c in modes[:, i])
        print(f"{i + 1:>4} {omega[i]:>14.6f} {hz[i]:>10.6f}   ({shape})")
    ratio = (omega[0] / omega[1]) ** 2
    print()
    print(f"squared frequency ratio r = (p1/p2)^2 = {ratio:.6f}")
    print("paper (Table 1 text): 2.289 Hz, 5.094 Hz, r = 0.2019 -- see derivations/gribkov_khokhlov_2015.py")
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``symosc`` console script.

    >>> main(["--version"])
    symosc 0.1.0
    0
    """
    from . import __version__

    parser = argparse.ArgumentParser(prog="symosc", description="Symbolic-first theory of oscillations.")
    parser.add_argument("--version", action="store_true", help="print the version and exit")
    sub = parser.add_subparsers(dest="command")
    dp = sub.add_parser("double-pendulum", help="natural frequencies and modes of the Table 1 double pendulum")
    dp.add_argument("--set", action="append", metavar="NAME=VALUE", help="override a parameter (SI units)")
    dp.set_defaults(func=_double_pendulum)
    args = parser.parse_args(argv)
    if args.version:
        print(f"symosc {__version__}")
        return 0
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    return args.func(args)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
