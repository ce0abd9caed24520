"""Result objects of symosc.linear are picklable, print, and plot onto the Axes they are given."""

from __future__ import annotations

import pickle

import matplotlib
import numpy as np
import sympy as sp

from symosc.linear import (
    conservative_modes,
    d_partition,
    dunkerley_bounds,
    frequency_response,
    hurwitz,
    linear_filter,
    nyquist,
    power_iteration,
    routh_array,
    stability_degree,
)

matplotlib.use("Agg")


def _results():
    lam, mu, nu, D = sp.symbols("lambda mu nu D")
    k = sp.symbols("k0:4")
    return {
        "hurwitz": hurwitz([1, 2, 3, 1]),
        "hurwitz_sym": hurwitz(k),
        "routh": routh_array(k),
        "degree": stability_degree([1, 2, 2]),
        "dpart": d_partition(lam**3 + mu * lam**2 + nu * lam + 1, lam, (mu, nu)),
        "bounds": dunkerley_bounds(np.array([[2.0, 1.0], [1.0, 3.0]])),
        "power": power_iteration([[2.0, 1.0], [1.0, 3.0]]),
        "modes": conservative_modes(sp.eye(2), sp.Matrix([[2, -1], [-1, 2]])),
        "nyquist": nyquist([2], [1, 3, 3, 1]),
        "freq": frequency_response([[D + 1]], [[1]], D, [0.5, 1.0]),
        "filter": linear_filter(1, 0.5, 2),
    }


def test_pickle_round_trip_and_repr():
    for name, r in _results().items():
        back = pickle.loads(pickle.dumps(r))
        assert repr(back) == repr(r), name
        assert type(r).__name__ in repr(r) or name == "filter"


def test_sympy_printer_hooks():
    r = _results()
    assert sp.sstr(r["hurwitz_sym"]) == sp.sstr(r["hurwitz_sym"].stable)
    assert "k_{1}" in sp.latex(r["routh"])
    assert r"\mu" in sp.latex(r["dpart"])


def test_plots_use_given_axes():
    import matplotlib.pyplot as plt

    r = _results()
    lf = r["filter"]
    for name in ("degree", "bounds", "power", "modes", "nyquist", "freq"):
        fig, ax = plt.subplots()
        assert r[name].plot(ax=ax) is ax and len(ax.lines) > 0, name
        plt.close(fig)
    fig, ax = plt.subplots()
    t = np.linspace(0, 5, 50)
    lf.plot(t, ax=ax)
    assert np.allclose(ax.lines[1].get_ydata(), lf.N(t))  # the drawn N(t) is the computed one
    plt.close(fig)
    # the Nyquist curve drawn is K(D) on the contour (clipped)
    fig, ax = plt.subplots()
    r["nyquist"].plot(ax=ax, clip=1e9)
    x, y = ax.lines[0].get_data()
    assert np.allclose(x + 1j * y, r["nyquist"].values)
    plt.close(fig)
