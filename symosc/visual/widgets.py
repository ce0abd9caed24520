"""Interactive explorers for notebooks (ipywidgets): move a slider, see the operating point, the verdict and the
motion change.

* :func:`pivot_explorer` — the inverted chain on a vibrating pivot (Gribkov & Khokhlov 2015): pivot amplitude and
  frequency move the operating point across the modified Ince–Strutt diagram, the verdict is updated and the
  nonlinear equations are integrated from a small tilt.
* :func:`resonance_explorer` — the Duffing oscillator's resonance curve by averaging (Bulgakov 1954, ch. 6): forcing
  amplitude and damping.
* :func:`mathieu_explorer` — the Mathieu equation's stability chart (Ince–Strutt): a point ``(a, q)``, its verdict
  and the solution from ``y(0) = 1, y'(0) = 0``.

Each returns an explorer whose ``widget`` is an ``ipywidgets.VBox`` (shown when the explorer is the value of a
notebook cell); the figures are PNG images, so everything also works (and is tested) without a browser: set a
slider's ``value`` and read ``verdict.value``, ``point``, ``trajectory``.  Needs the ``widgets`` extra
(``pip install 'symosc[widgets]'``).
"""

from __future__ import annotations

import io
from typing import Any

import numpy as np

from .._plotting import require_matplotlib
from .._validate import check_choice, check_finite, check_positive, validated

__all__ = [
    "mathieu_explorer",
    "pivot_explorer",
    "resonance_explorer",
]


def _widgets() -> Any:
    try:
        import ipywidgets
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise ImportError("the explorers need ipywidgets: pip install 'symosc[widgets]'") from exc
    return ipywidgets


def _png(fig: Any) -> bytes:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=80)
    return buf.getvalue()


def _figure(width: float = 6.0, height: float = 3.6, right: float = 0.97) -> Any:
    """An Agg figure with fixed margins (a layout engine would cost most of each redraw)."""
    require_matplotlib()
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width, height))
    FigureCanvasAgg(fig)
    fig.subplots_adjust(left=0.12, right=right, bottom=0.15, top=0.9)
    return fig


class _Marker:
    """A chart drawn once, with one moving point blitted onto it for each update (PNG through Pillow)."""

    def __init__(self, fig: Any, ax: Any) -> None:
        fig.set_dpi(80)
        (self.point,) = ax.plot([], [], "o", color="C3", ms=8, zorder=5, animated=True)
        self.fig, self.ax = fig, ax
        fig.canvas.draw()
        self.background = fig.canvas.copy_from_bbox(fig.bbox)

    def png(self, x: float, y: float) -> bytes:
        from PIL import Image

        canvas = self.fig.canvas
        canvas.restore_region(self.background)
        self.point.set_data([x], [y])
        self.ax.draw_artist(self.point)
        image = Image.frombuffer("RGBA", canvas.get_width_height(), bytes(canvas.buffer_rgba()))
        buf = io.BytesIO()
        image.convert("RGB").save(buf, format="PNG", compress_level=1)
        return buf.getvalue()


class _Explorer:
    """An ipywidgets layout with its sliders; calls :meth:`update` whenever a slider moves."""

    widget: Any
    sliders: tuple

    def _connect(self) -> None:
        for s in self.sliders:
            s.observe(lambda change: self.update(), names="value")
        self.update()

    def update(self) -> None:  # pragma: no cover - overridden
        raise NotImplementedError

    def _ipython_display_(self) -> None:
        from IPython.display import display

        display(self.widget)

    def _repr_mimebundle_(self, **kwargs: Any) -> Any:
        return self.widget._repr_mimebundle_(**kwargs)


class PivotExplorer(_Explorer):
    """Sliders for the pivot amplitude (mm) and frequency (Hz) of an inverted chain; see :func:`pivot_explorer`.

    Attributes
    ----------
    amplitude, frequency : ipywidgets.FloatSlider
        Pivot amplitude ``a`` in mm and frequency ``p / 2 pi`` in Hz.
    verdict : ipywidgets.HTML
        Stable or not, the first-tone point and the stable amplitude interval at this frequency.
    chart, motion : ipywidgets.Image
        The modified Ince–Strutt diagram with the operating point; the simulated angles.
    point : tuple of float
        The operating point ``(a^1, q^1)``.
    stable : bool
        Verdict of the linearized system (principal region).
    trajectory : Trajectory
        The last simulated motion.
    """

    def __init__(self, system: Any, values: dict, amplitude: float, frequency: float, duration: float, tilt: float):
        from ..periodic import stability_region

        w = _widgets()
        self.system, self.values, self.duration, self.tilt = system, dict(values), duration, tilt
        self.region = stability_region(system.linearize(), values)
        style = {"description_width": "9em"}
        self.amplitude = w.FloatSlider(
            value=amplitude, min=0.0, max=10.0, step=0.05, description="amplitude a, mm", style=style,
            continuous_update=False,
        )  # fmt: skip
        self.frequency = w.FloatSlider(
            value=frequency, min=5.0, max=300.0, step=1.0, description="frequency, Hz", style=style,
            continuous_update=False,
        )  # fmt: skip
        self.sliders = (self.amplitude, self.frequency)
        self.verdict = w.HTML()
        self.chart, self.motion = w.Image(format="png"), w.Image(format="png")
        self.widget = w.VBox(
            [w.HBox([self.amplitude, self.frequency]), self.verdict, w.HBox([self.chart, self.motion])]
        )
        self._connect()

    def update(self) -> None:
        """Recompute the point, the verdict and the motion for the sliders' values."""
        a, p = self.amplitude.value * 1e-3, 2 * np.pi * self.frequency.value
        a1, q1 = (float(x) for x in self.region.first_tone(p, a))
        self.point = (a1, q1)
        self.stable = bool(a > 0 and self.region.is_stable(p, a))
        lo, hi = (float(x) for x in self.region.amplitude_bounds(p))
        interval = "none" if np.isnan(lo) else f"{lo * 1e3:.3g} mm &lt; a &lt; {hi * 1e3:.3g} mm"
        word = "<b style='color:#1a7f37'>STABLE</b>" if self.stable else "<b style='color:#cf222e'>unstable</b>"
        self.verdict.value = (
            f"{word} at a = {a * 1e3:.3g} mm, p = {self.frequency.value:.4g} Hz: first-tone point "
            f"(a<sup>1</sup>, q<sup>1</sup>) = ({a1:.4g}, {q1:.4g}); stable amplitudes at this frequency: {interval}"
        )
        fig = _figure(7.0, 3.8, right=0.62)
        ax = fig.add_subplot()
        q_max = max(1.2 * self.region.ratios[-1], 1.3 * q1)
        self.region.plot(ax=ax, q_max=q_max, point=self.point)
        self.chart.value = _png(fig)
        coords = [c.name for c in self.system.coordinates]
        initial = {c: (self.tilt if k == 0 else -0.5 * self.tilt) for k, c in enumerate(coords)}
        values = {**self.values, "a": max(a, 1e-12), "p": p}
        times = np.linspace(0.0, self.duration, 801)
        try:
            self.trajectory = self.system.simulate(times, initial, values, rtol=1e-8, atol=1e-10)
        except Exception as exc:
            self.trajectory = None
            self.verdict.value += f"<br>simulation stopped: {exc}"
        fig = _figure()
        ax = fig.add_subplot()
        if self.trajectory is not None:
            self.trajectory.plot(ax=ax)
            ax.set_ylim(-3.2, 3.2)
            ax.set_title("nonlinear motion from a small tilt", fontsize=9)
        self.motion.value = _png(fig)


@validated
def pivot_explorer(
    n: int = 2,
    *,
    links: str = "rigid",
    values: dict | None = None,
    amplitude: float = 2.0,
    frequency: float = 100.0,
    duration: float = 1.0,
    tilt: float = 0.05,
) -> PivotExplorer:
    """Explore the inverted chain on a vibrating pivot: sliders for the pivot amplitude and frequency.

    Parameters
    ----------
    n : int
        Number of links.
    links : {"point", "rigid"}
        Link model (see :func:`symosc.models.n_link_pendulum`).
    values : dict, optional
        Parameters of the chain (SI); default: the double physical pendulum of Gribkov & Khokhlov (2015), Table 1.
    amplitude : float
        Initial pivot amplitude, mm (>= 0).
    frequency : float
        Initial pivot frequency, Hz.
    duration : float
        Simulated seconds after each change.
    tilt : float
        Initial angle of the first link (rad, finite); the others start at minus half of it.

    Returns
    -------
    PivotExplorer

    Examples
    --------
    >>> ex = pivot_explorer(duration=0.1)
    >>> ex.stable                       # 2 mm at 100 Hz keeps the double pendulum of Table 1 up
    True
    >>> ex.amplitude.value = 1.0        # what moving the slider does: the verdict is updated
    >>> ex.stable
    False

    See Also
    --------
    symosc.periodic.stability_region, symosc.mechanics.LagrangianSystem.simulate
    """
    from ..models import gribkov_khokhlov_table1, n_link_pendulum

    check_choice("links", links, ("point", "rigid"))
    if values is None:
        if n != 2 or links != "rigid":
            from ..errors import ParameterError

            raise ParameterError("values are needed for a chain other than the double rigid pendulum of Table 1")
        values = gribkov_khokhlov_table1()
    check_positive("duration", duration)
    check_positive("amplitude", amplitude, allow_zero=True)
    check_finite("tilt", tilt)
    system = n_link_pendulum(n, links=links, inverted=True, pivot="vertical")
    return PivotExplorer(system, values, amplitude, frequency, duration, tilt)


class ResonanceExplorer(_Explorer):
    """Sliders for the forcing amplitude and the damping ratio of a Duffing oscillator; see
    :func:`resonance_explorer`.

    Attributes
    ----------
    forcing, damping : ipywidgets.FloatSlider
        ``R`` (force per unit mass) and ``zeta``.
    verdict : ipywidgets.HTML
        Jump frequencies and the largest amplitude.
    chart : ipywidgets.Image
        The resonance curve.
    response : FrequencyResponse
        The last computed curve.
    """

    def __init__(self, w0: float, mu: float, forcing: float, damping: float, nu_range: tuple) -> None:
        import sympy as sp

        from ..nonlinear import averaged_equations

        w = _widgets()
        x, v = sp.symbols("x v", real=True)
        z, m = sp.symbols("zeta mu", positive=True)
        self.w0, self.mu_value, self.nu_range = w0, mu, nu_range
        self.averaged = averaged_equations(w0**2 * x + m * x**3 + 2 * z * w0 * v, forcing=sp.Symbol("R"), x=x, v=v)
        style = {"description_width": "9em"}
        self.forcing = w.FloatSlider(
            value=forcing, min=0.005, max=0.5, step=0.005, description="forcing R", style=style,
            continuous_update=False, readout_format=".3f",
        )  # fmt: skip
        self.damping = w.FloatSlider(
            value=damping, min=0.005, max=0.3, step=0.005, description="damping ζ", style=style,
            continuous_update=False, readout_format=".3f",
        )  # fmt: skip
        self.sliders = (self.forcing, self.damping)
        self.verdict, self.chart = w.HTML(), w.Image(format="png")
        self.widget = w.VBox([w.HBox([self.forcing, self.damping]), self.verdict, self.chart])
        self._connect()

    def update(self) -> None:
        """Recompute the resonance curve for the sliders' values."""
        vals = {"zeta": self.damping.value, "mu": self.mu_value, "R": self.forcing.value}
        self.response = self.averaged.frequency_response(vals, self.nu_range, 300)
        jumps = ", ".join(f"{j:.4g}" for j in self.response.jump_frequencies) or "none"
        self.verdict.value = (
            f"jump frequencies: {jumps} rad/s; largest steady amplitude {np.nanmax(self.response.amplitudes):.4g}"
        )
        fig = _figure(6.5, 3.8)
        ax = fig.add_subplot()
        self.response.plot(ax=ax)
        self.chart.value = _png(fig)


@validated
def resonance_explorer(
    *,
    w0: float = 1.0,
    mu: float = 0.5,
    forcing: float = 0.1,
    damping: float = 0.05,
    nu_range: tuple[float, float] = (0.5, 1.8),
) -> ResonanceExplorer:
    """Explore the Duffing resonance curve ``x'' + 2 zeta w0 x' + w0^2 x + mu x^3 = R cos(nu t)`` (averaging,
    Bulgakov 1954, ch. 6): sliders for the forcing amplitude ``R`` and the damping ratio ``zeta``.

    Parameters
    ----------
    w0 : float
        Linear natural frequency.
    mu : float
        Cubic stiffness.
    forcing : float
        Initial ``R``.
    damping : float
        Initial ``zeta``.
    nu_range : (float, float)
        Forcing frequencies drawn.

    Returns
    -------
    ResonanceExplorer

    See Also
    --------
    symosc.nonlinear.averaged_equations
    """
    return ResonanceExplorer(w0, mu, forcing, damping, nu_range)


class MathieuExplorer(_Explorer):
    """Sliders for ``a`` and ``q`` of the Mathieu equation; see :func:`mathieu_explorer`.

    Attributes
    ----------
    a, q : ipywidgets.FloatSlider
        The equation's parameters.
    verdict : ipywidgets.HTML
        Stable or unstable (Floquet multipliers of one period).
    chart, motion : ipywidgets.Image
        The Ince–Strutt chart with the point; the solution from ``y(0) = 1, y'(0) = 0``.
    stable : bool
        Verdict at the sliders' point.
    """

    def __init__(self, a: float, q: float, periods: int) -> None:
        from ..periodic import ince_strutt_diagram

        w = _widgets()
        self.periods = periods
        self.diagram = ince_strutt_diagram(3, 8.0)
        fig = _figure(7.0, 3.8, right=0.8)
        self._chart = _Marker(fig, self.diagram.plot(ax=fig.add_subplot()))
        style = {"description_width": "3em"}
        self.a = w.FloatSlider(
            value=a, min=-2.0, max=14.0, step=0.05, description="a", style=style, continuous_update=False
        )
        self.q = w.FloatSlider(
            value=q, min=0.0, max=8.0, step=0.05, description="q", style=style, continuous_update=False
        )
        self.sliders = (self.a, self.q)
        self.verdict, self.chart, self.motion = w.HTML(), w.Image(format="png"), w.Image(format="png")
        self.widget = w.VBox([w.HBox([self.a, self.q]), self.verdict, w.HBox([self.chart, self.motion])])
        self._connect()

    def update(self) -> None:
        """Verdict, chart and solution for the sliders' ``(a, q)``."""
        from scipy.integrate import solve_ivp

        a, q = self.a.value, self.q.value

        def rhs(x: float, y: np.ndarray) -> np.ndarray:
            return np.array([y[1], -(a - 2 * q * np.cos(2 * x)) * y[0]])

        period = np.pi
        mono = np.column_stack(
            [solve_ivp(rhs, (0, period), e, rtol=1e-10, atol=1e-12).y[:, -1] for e in ([1.0, 0.0], [0.0, 1.0])]
        )
        half_trace = 0.5 * float(np.trace(mono))
        self.stable = bool(abs(half_trace) < 1.0)
        self.verdict.value = (
            "<b style='color:#1a7f37'>stable</b>" if self.stable else "<b style='color:#cf222e'>unstable</b>"
        ) + f" at (a, q) = ({a:.3g}, {q:.3g}): half the trace of the monodromy matrix is {half_trace:.4g}"
        self.chart.value = self._chart.png(a, q)
        xs = np.linspace(0, self.periods * period, 1200)
        sol = solve_ivp(rhs, (0, xs[-1]), [1.0, 0.0], t_eval=xs, rtol=1e-9, atol=1e-12)
        fig = _figure()
        ax = fig.add_subplot()
        ax.plot(sol.t, sol.y[0], label="y(x)")
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.legend(loc="upper right")
        self.motion.value = _png(fig)


@validated
def mathieu_explorer(a: float = 1.5, q: float = 0.5, *, periods: int = 20) -> MathieuExplorer:
    """Explore the Mathieu equation ``y'' + (a - 2 q cos 2x) y = 0``: sliders for ``a`` and ``q``.

    Parameters
    ----------
    a, q : float
        Initial point.
    periods : int
        Periods ``pi`` of the coefficient shown in the solution.

    Returns
    -------
    MathieuExplorer

    See Also
    --------
    symosc.periodic.ince_strutt_diagram, symosc.periodic.mathieu_a
    """
    return MathieuExplorer(a, q, periods)
