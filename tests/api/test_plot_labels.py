"""Figures people can read: every drawn curve is named (legend entry or direct label) and no two labels overlap.

The checks run on every public ``.plot`` in ``test_plot_protocol.py`` (on the figure it draws there, rendered on an
Agg canvas: the text boxes come from the renderer, what a viewer sees); here they are shown to fail when they should,
and applied to the scene figures.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.lines import Line2D
from matplotlib.text import Annotation


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


def unnamed_curves(ax) -> list[str]:
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


def overlapping_texts(fig) -> list[tuple[str, str]]:
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


def test_the_checks_can_fail():
    """An unlabelled curve and two labels on one spot are reported."""
    fig, ax = plt.subplots()
    ax.plot([0, 1], [0, 1])
    ax.annotate("a_1", (0.5, 0.5))
    ax.annotate("b_2", (0.5, 0.5))
    assert overlapping_texts(fig) == [("a_1", "b_2")]
    _, ax2 = plt.subplots()
    ax2.plot([0, 1], [0, 1], label="x")
    ax2.plot([0, 1], [1, 0], color="C5", ls=":")
    ax2.legend(handles=ax2.get_lines()[:1])
    assert len(unnamed_curves(ax2)) == 1
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
        assert unnamed_curves(ax) == [], drawer
        assert overlapping_texts(fig) == [], drawer
        plt.close(fig)
