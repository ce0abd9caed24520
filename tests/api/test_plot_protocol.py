"""One plotting protocol for every ``.plot`` of a public class: ``ax`` keyword-only, drawn on when given, otherwise a
new figure; the Axes is returned; figure text carries no internal references."""

from __future__ import annotations

import inspect

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import pytest

from ..test_user_text import scan
from .examples import PLOT_ARGS
from .public import public_classes
from .test_plot_labels import overlapping_texts, unnamed_curves

PLOTTING = [c for c in public_classes() if callable(getattr(c, "plot", None))]


def _texts(ax) -> list[str]:
    fig = ax.figure
    out = [t.get_text() for t in fig.findobj(matplotlib.text.Text)]
    return [t for t in out if t]


def test_there_are_plot_methods_to_check():
    assert len(PLOTTING) >= 15


@pytest.mark.parametrize("cls", PLOTTING, ids=lambda c: c.__name__)
def test_plot_signature(cls):
    sig = inspect.signature(cls.plot)
    ax = sig.parameters.get("ax")
    assert ax is not None and ax.kind is inspect.Parameter.KEYWORD_ONLY and ax.default is None, str(sig)


@pytest.mark.parametrize("cls", PLOTTING, ids=lambda c: c.__name__)
def test_plot_draws_on_given_axes_or_a_new_figure(cls, examples):
    obj = examples.get(cls)
    assert obj is not None, f"no documented example builds a {cls.__name__}"
    kwargs = PLOT_ARGS.get(cls.__name__, {})
    plt.close("all")
    try:
        fig, ax = plt.subplots()
        got = obj.plot(**kwargs, ax=ax)
        assert got is ax and plt.get_fignums() == [fig.number]
        assert ax.has_data() or ax.images or ax.collections or ax.patches
        bad = [hit for t in _texts(ax) for hit in scan(t)]
        assert bad == [], bad
        own = obj.plot(**kwargs)
        assert own is not ax and own.figure is not fig and len(plt.get_fignums()) == 2
        assert own.has_data() or own.images or own.collections or own.patches
        # readable figures: every curve named (legend entry or direct label), no two labels on top of each other
        assert unnamed_curves(own) == [], f"{cls.__name__}: curves without a legend entry or label"
        assert overlapping_texts(own.figure) == [], f"{cls.__name__}: overlapping labels"
    finally:
        plt.close("all")


def test_positional_axes_still_works_with_a_warning():
    from symosc import _deprecation
    from symosc.periodic import ince_strutt_diagram

    _deprecation.reset_warnings()
    d = ince_strutt_diagram(n_max=1, q_max=1.0, num=5)
    _, ax = plt.subplots()
    with pytest.warns(DeprecationWarning, match="ax="):
        assert d.plot(ax) is ax
    plt.close("all")
