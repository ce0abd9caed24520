"""Figures people can read: every drawn curve is named (legend entry or direct label) and no two labels overlap.

Each public ``.plot`` is rendered on an Agg canvas; the text boxes come from the renderer (what a viewer sees).
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pytest
from matplotlib.lines import Line2D
from matplotlib.text import Annotation

from .examples import PLOT_ARGS
from .public import example_instances, public_classes

PLOTTING = [c for c in public_classes() if callable(getattr(c, "plot", None))]


def _curves(ax) -> list[Line2D]:
    """Lines that draw a curve (two or more finite points), not axis markers such as axhline/axvline."""
    out = []
    for line in ax.get_lines():
        x, y = (np.asarray(v, dtype=float) for v in line.get_data())
        ok = np.isfinite(x) & np.isfinite(y)
        if ok.sum() >= 2 and line.get_linestyle() not in ("None", "", " ") and np.ptp(x[ok]) + np.ptp(y[ok]) > 0:
            if line.get_transform() is ax.transData or line.get_transform().contains_branch(ax.transData):
                out.append(line)
    return out


def _unnamed(ax) -> list[str]:
    """Curves with neither a legend entry nor a direct label: a legend must exist when curves carry labels, and
    a curve without one needs an annotation of its own style (same color and line style as a labelled one)."""
    legend = ax.get_legend() or next((a.get_legend() for a in ax.figure.axes if a.get_legend()), None)
    names = {t.get_text() for t in legend.get_texts()} if legend else set()
    handles = legend.legend_handles if legend else []
    styles = {(h.get_color(), h.get_linestyle()) for h in handles if isinstance(h, Line2D)}
    annotations = [t for t in ax.texts if isinstance(t, Annotation) and t.get_text()]
    curves = _curves(ax)
    if len(curves) == 1 and ax.get_ylabel():
        return []  # a single curve is named by its axis label
    bad = []
    for line in curves:
        label = line.get_label()
        if label in names or (line.get_color(), line.get_linestyle()) in styles:
            continue
        if annotations:
            continue  # direct labels (e.g. a_n, b_n) name the curves of this style
        bad.append(label)
    return bad


def _overlaps(fig) -> list[tuple[str, str]]:
    """Pairs of visible texts inside the axes (annotations, in-axes text, legends) whose boxes intersect."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    boxes = []
    for ax in fig.axes:
        for t in ax.texts:
            if t.get_visible() and t.get_text():
                boxes.append((t.get_text(), t.get_window_extent(renderer)))
        legend = ax.get_legend()
        if legend is not None:
            boxes.append(("<legend>", legend.get_window_extent(renderer)))
    return [
        (a, b)
        for i, (a, ba) in enumerate(boxes)
        for b, bb in boxes[i + 1 :]
        if ba.overlaps(bb) and ba.intersection(ba, bb).width * ba.intersection(ba, bb).height > 4.0
    ]


@pytest.mark.parametrize("cls", PLOTTING, ids=lambda c: c.__name__)
def test_every_curve_is_named_and_no_labels_overlap(cls):
    obj = example_instances().get(cls)
    kwargs = PLOT_ARGS.get(cls.__name__, {})
    plt.close("all")
    try:
        ax = obj.plot(**kwargs)
        assert _unnamed(ax) == [], f"{cls.__name__}: curves without a legend entry or label"
        assert _overlaps(ax.figure) == [], f"{cls.__name__}: overlapping labels"
    finally:
        plt.close("all")


def test_the_checks_can_fail():
    """An unlabelled curve and two labels on one spot are reported."""
    fig, ax = plt.subplots()
    ax.plot([0, 1], [0, 1])
    ax.annotate("a_1", (0.5, 0.5))
    ax.annotate("b_2", (0.5, 0.5))
    assert _overlaps(fig) == [("a_1", "b_2")]
    _, ax2 = plt.subplots()
    ax2.plot([0, 1], [0, 1], label="x")
    ax2.plot([0, 1], [1, 0], color="C5", ls=":")
    ax2.legend(handles=ax2.get_lines()[:1])
    assert len(_unnamed(ax2)) == 1
    plt.close("all")


def test_scene_figures_are_labelled(tmp_path):
    """The scene's figures (modified Ince–Strutt with its operating point, classic Ince–Strutt, resonance curve)."""
    from symosc.scene import _figures

    cases = [
        ("modified_ince_strutt", {"ratios": [1.0, 0.2128], "point": (-0.00217, 0.0872), "q_max": 0.26}),
        ("ince_strutt", {"orders": 3, "q_max": 8.0}),
    ]
    for drawer, data in cases:
        fig, ax = plt.subplots(figsize=(6.5, 4.5))
        getattr(_figures, drawer)(ax, **data)
        fig.tight_layout()
        assert _unnamed(ax) == [], drawer
        assert _overlaps(fig) == [], drawer
        plt.close(fig)
