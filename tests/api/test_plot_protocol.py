"""One plotting protocol for every ``.plot`` of a public class: ``ax`` keyword-only, drawn on when given, otherwise a
new figure; the Axes is returned; figure text carries no internal references."""

from __future__ import annotations

import inspect
import subprocess
import sys
import textwrap
from pathlib import Path

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


def test_without_matplotlib_plotting_names_the_extra():
    """In an interpreter where matplotlib cannot be imported, a plot method, an animation and the scene writer say
    what to install (the ``plot`` extra) instead of failing with a bare ModuleNotFoundError."""
    code = textwrap.dedent(
        """
        import sys, tempfile
        sys.modules["matplotlib"] = None  # what an environment without matplotlib looks like to an import
        import sympy as sp
        from symosc.models import n_link_pendulum
        from symosc.periodic import ince_strutt_diagram
        from symosc.scene import loads
        messages = []
        for call in (
            lambda: ince_strutt_diagram(n_max=1, q_max=1.0, num=5).plot(),
            lambda: n_link_pendulum(1).simulate(1.0, [0.1, 0.0], {"m1": 1.0, "l1": 1.0, "g": 9.81}).animate(),
        ):
            try:
                call()
                messages.append("no error")
            except ImportError as exc:
                messages.append(str(exc))
        res = loads('[system]\\nmodel = "mathieu"\\n[[questions]]\\nkind = "ince_strutt"\\n').run()
        with tempfile.TemporaryDirectory() as d:
            res.write(d + "/out")
            messages.append(open(d + "/out/report.md").read())
        print("\\n=====\\n".join(messages))
        """
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300, check=False)
    assert out.returncode == 0, out.stderr[-3000:]
    first, second, report = out.stdout.split("\n=====\n")[-3:]
    first = first.splitlines()[-1]  # after what SceneResult.write printed
    assert first.startswith("drawing needs matplotlib") and "symosc[plot]" in first
    assert second.startswith("drawing needs matplotlib") and "symosc[plot]" in second
    assert "figures skipped: matplotlib is not installed" in report and "symosc[plot]" in report


def test_every_drawing_imports_matplotlib_through_the_helper():
    """pyplot is imported only by symosc._plotting (which names the extra when it is missing)."""
    root = Path(__file__).resolve().parents[2] / "symosc"
    offenders = [
        str(p.relative_to(root))
        for p in root.rglob("*.py")
        if p.name != "_plotting.py" and "import matplotlib.pyplot" in p.read_text(encoding="utf-8")
    ]
    assert offenders == []
