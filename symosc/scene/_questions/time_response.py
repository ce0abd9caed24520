"""The ``time_response`` question: simulate the model from an initial state, plot the outputs, write the data and,
on request, an animated GIF of the motion."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from .._result import Figure, QuestionResult, Table

__all__ = ["OPTIONS", "animation", "time_response", "time_series"]

_METHODS = ("LSODA", "DOP853", "RK45", "Radau", "BDF")


def _initial(ctx: Any, value: Any, key: str) -> dict[str, float]:
    table = ctx.table(value, key)
    return {str(k): ctx.quantity(v, f"{key}.{k}", None) for k, v in table.items()}


def _names(ctx: Any, value: Any, key: str) -> list[str]:
    if isinstance(value, str):
        value = [value]
    if not isinstance(value, list) or not value or not all(isinstance(v, str) for v in value):
        raise ctx.error(key, f"expected a list of output names, got {value!r}", 'write outputs = ["phi1", "energy"]')
    return list(value)


def _tolerance(ctx: Any, value: Any, key: str) -> float:
    x = ctx.quantity(value, key, "dimensionless", positive=True)
    if not 1e-15 <= x < 1:
        raise ctx.error(
            key, f"expected a tolerance between 1e-15 and 1, got {x!r}", f"write {key.split('.')[-1]} = 1e-9"
        )
    return x


#: option name -> (parser(ctx, value, key), default); ``duration`` is required
OPTIONS: dict[str, tuple] = {
    "initial": (_initial, {}),
    "duration": (lambda c, v, k: c.quantity(v, k, "time", positive=True), None),
    "outputs": (_names, None),
    "points": (lambda c, v, k: c.integer(v, k, minimum=2), 1001),
    "amplitude": (lambda c, v, k: c.quantity(v, k, "length", positive=True), None),
    "frequency": (lambda c, v, k: c.quantity(v, k, "angular frequency", positive=True), None),
    "method": (lambda c, v, k: c.choice(v, k, list(_METHODS)), "LSODA"),
    "rtol": (_tolerance, 1e-9),
    "atol": (_tolerance, 1e-11),
    "animate": (lambda c, v, k: c.boolean(v, k), False),
    "speed": (lambda c, v, k: c.quantity(v, k, "dimensionless", positive=True), 1.0),
    "figure": (lambda c, v, k: c.boolean(v, k), True),
}


def _values(q: Any) -> dict[str, float]:
    """Parameter values, with the excitation (pivot amplitude and frequency) from the question or [excitation]."""
    values = dict(q.values)
    for key, symbol in (getattr(q.model, "excitation_symbols", None) or {}).items():
        value = q.opts.get(key) if q.opts.get(key) is not None else q.excitation.get(key)
        if value is None:
            raise q.fail(
                f"the {q.model.describe} needs the excitation {key} ({symbol}) for a time response",
                f"add [excitation] {key} = ... or {key} = ... to this question",
            )
        values[symbol] = float(value)
    return values


def _simulate(q: Any, times: np.ndarray, values: Mapping[str, float]) -> Any:
    from ...errors import ParameterError

    opts = q.opts
    kwargs = {"method": opts["method"], "rtol": opts["rtol"], "atol": opts["atol"]}
    body = getattr(q.model, "_body", None)
    try:
        if body is not None:
            coords = [c.name for c in body.coordinates]
            _check_initial(q, coords)
            return body.simulate(times, opts["initial"], values, **kwargs)
        system = q.model.system
        _check_initial(q, [c.name for c in system.coordinates])
        return system.simulate(times, opts["initial"], values, **kwargs)
    except ParameterError as exc:
        raise q.fail(f"time_response: {exc}", "check initial and the parameters", "initial") from exc


def _check_initial(q: Any, coords: list[str]) -> None:
    valid = [*coords, *(f"{c}_dot" for c in coords)]
    for name in q.opts["initial"]:
        if name not in valid:
            raise q.fail(
                f"initial names {name!r}, which is not a coordinate or velocity; valid: {', '.join(valid)}",
                f"write initial = {{ {coords[0]} = 0.1 }}",
                "initial",
            )


def time_response(q: Any) -> QuestionResult:
    """Handler of ``kind = "time_response"``."""
    opts = q.opts
    if opts["duration"] is None:
        raise q.fail("time_response needs the option 'duration'", 'add duration = "5 s" to this question')
    values = _values(q)
    times = np.linspace(0.0, opts["duration"], opts["points"])
    with q.log.step("simulate the motion", f"{opts['method']}, rtol = {opts['rtol']:g}, compiled rhs and Jacobian"):
        traj = _simulate(q, times, values)
    available = [*traj.coordinates, *(f"{c}_dot" for c in traj.coordinates), "energy"]
    outputs = opts["outputs"] or list(traj.coordinates)
    for name in outputs:
        if name not in available:
            raise q.fail(
                f"unknown output {name!r}; outputs: {', '.join(available)}", "name coordinates or 'energy'", "outputs"
            )
    series = {name: traj[name] for name in outputs}
    start = ", ".join(f"{k} = {v:g}" for k, v in opts["initial"].items()) or "rest"
    lines = [
        f"simulated from {start} over {opts['duration']:g} s: {traj.method}, rtol = {traj.rtol:g}, "
        f"atol = {traj.atol:g}, {traj.nfev} evaluations of the compiled right-hand side",
    ]
    exc = getattr(q.model, "excitation_symbols", None) or {}
    if exc:
        a, p = values[exc["amplitude"]], values[exc["frequency"]]
        lines.append(f"pivot y = a cos(p t) with a = {a * 1e3:.6g} mm, p = {p:.6g} rad/s ({p / 2 / np.pi:.6g} Hz)")
    if traj.energy_drift is not None:
        lines.append(f"{traj.energy_name} conserved to a relative drift of {traj.energy_drift:.2g}")
    rows = tuple(
        (name, f"{v[0]:.6g}", f"{v[-1]:.6g}", f"{np.min(v):.6g}", f"{np.max(v):.6g}") for name, v in series.items()
    )
    table = Table(("output", "initial", "final", "min", "max"), rows, "Outputs over the simulated interval (SI)")
    figures: list[Figure] = []
    tag = f"{q.stem}-motion-{q.index + 1}"
    if opts["figure"]:
        figures.append(
            Figure(f"{tag}.png", "Time response", "time_series", {"t": traj.t, "series": series, "title": start})
        )
        lines.append(f"figure: {tag}.png")
    if opts["animate"]:
        if traj.geometry is None:
            raise q.fail("this model has no drawing to animate", "set animate = false", "animate")
        figures.append(Figure(f"{tag}.gif", "Animation", "animation", {"trajectory": traj, "speed": opts["speed"]}))
        lines.append(f"animation: {tag}.gif")
    data = {
        "t": traj.t.tolist(),
        "outputs": {k: v.tolist() for k, v in series.items()},
        "final_state": {k: float(v[-1]) for k, v in {**traj.q, **{f"{c}_dot": x for c, x in traj.qd.items()}}.items()},
        "method": traj.method,
        "rtol": traj.rtol,
        "atol": traj.atol,
        "evaluations": traj.nfev,
        "energy_name": traj.energy_name,
        "energy_drift": traj.energy_drift,
    }
    return QuestionResult("time_response", "Time response", tuple(lines), (table,), tuple(figures), data)


# ------------------------------------------------------------------------------------------ drawers
def time_series(ax: Any, *, t: Any, series: Mapping[str, Any], title: str = "") -> Any:
    """Outputs against time, one labelled line each (the energy, if asked, on a second axis)."""
    from ..._plotting import tex_name

    lines = []
    energy = series.get("energy")
    for name, v in series.items():
        if name == "energy":
            continue
        base, dot = (name[:-4], True) if name.endswith("_dot") else (name, False)
        lines += ax.plot(t, v, label=tex_name(base, dot=dot))
    ax.set_xlabel("time $t$, s")
    ax.set_ylabel("coordinates (SI)")
    ax.grid(True, lw=0.4, alpha=0.5)
    if energy is not None:
        twin = ax.twinx()
        lines += twin.plot(t, energy, color="0.4", ls="--", lw=1.0, label="energy")
        twin.set_ylabel("energy, J")
    ax.legend(lines, [line.get_label() for line in lines], loc="best", fontsize=9)
    if title:
        ax.set_title(f"from {title}", fontsize=10)
    return ax


def animation(ax: Any, *, trajectory: Any, speed: float = 1.0) -> Any:
    """The motion as an :class:`~symosc.visual.Animation` (written as a GIF by ``SceneResult.write``)."""
    return trajectory.animate(speed=speed, max_frames=200, trail=0.0)
