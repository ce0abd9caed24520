"""The scene question ``continuation``: a branch of periodic solutions by harmonic balance and arclength continuation.

For the ``duffing`` model ``x'' + 2 zeta w0 x' + w0^2 x + mu x^3 = R cos(nu t)`` the parameter is ``nu`` (forcing
frequency, the default) or any of ``R, w0, zeta, mu``; for ``van_der_pol`` / ``weakly_nonlinear``
(``x'' + x = eps f(x, x')``) it is ``eps``, continued from a self-excited cycle.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .._result import Figure, QuestionResult, Table
from .mechanical import Question, QuestionSpec

__all__ = ["SPEC", "draw_branch"]

_SHORT = {
    "fold": "fold (saddle-node)",
    "period_doubling": "period doubling",
    "neimark_sacker": "Neimark–Sacker",
    "branch_point": "branch point",
}


def _span(ctx: Any, value: Any, key: str) -> tuple[float, float]:
    vals = ctx.quantities(value, key, None)
    if len(vals) != 2 or vals[0] == vals[1]:
        raise ctx.error(key, f"expected [start, end] with start != end, got {value!r}", "write range = [0.5, 3.0]")
    return float(vals[0]), float(vals[1])


def _str(ctx: Any, value: Any, key: str) -> str:
    return ctx.string(value, key)


def _plot(ctx: Any, value: Any, key: str) -> str:
    return ctx.choice(value, key, ["amplitude", "frequency", "period"])


def _harmonics(ctx: Any, value: Any, key: str) -> int:
    return ctx.integer(value, key, minimum=1)


def _points(ctx: Any, value: Any, key: str) -> int:
    return ctx.integer(value, key, minimum=10)


def _problem(q: Question):
    import sympy as sp

    from ...continuation import harmonic_balance

    x, v, t = sp.symbols("x v t", real=True)
    harmonics = q.opts.get("harmonics")
    if q.model.category == "forced_oscillator":
        w0, zeta, mu, R, nu = (sp.Symbol(s, positive=True) for s in ("w0", "zeta", "mu", "R", "nu"))
        acc = -2 * zeta * w0 * v - w0**2 * x - mu * x**3 + R * sp.cos(nu * t)
        values = {"w0": q.values["w0"], "zeta": q.values["zeta"], "mu": q.values["mu"]}
        if q.excitation.get("amplitude") is not None:
            values["R"] = q.excitation["amplitude"]
        if q.excitation.get("frequency") is not None:
            values["nu"] = q.excitation["frequency"]
        hb = harmonic_balance(acc, x, v, t, forcing_frequency=nu, values=values, harmonics=harmonics, tol=q.opts["tol"])
        return hb, q.opts.get("parameter") or "nu", x
    d = q.model.data
    eps = sp.Symbol("eps", positive=True)
    acc = -d["x"] + eps * d["f"]
    hb = harmonic_balance(acc, d["x"], d["v"], t, autonomous=True, harmonics=harmonics, tol=q.opts["tol"])
    return hb, q.opts.get("parameter") or "eps", d["x"]


def continuation(q: Question) -> QuestionResult:
    from ...continuation import continue_periodic

    hb, name, _ = _problem(q)
    names = [s.name for s in hb.parameters]
    if name not in names:
        raise q.fail(
            f"parameter {name!r} is not a parameter of this model", f"use one of {', '.join(names)}", "parameter"
        )
    missing = [
        s.name for s, val in zip(hb.parameters, hb.values, strict=True) if not np.isfinite(val) and s.name != name
    ]
    if missing:
        raise q.fail(f"missing values for {', '.join(missing)}", "give them in [parameters] or [excitation]")
    lo, hi = q.opts["range"]
    length = abs(hi - lo)
    with q.log.step(
        "harmonic balance + pseudo-arclength continuation",
        f"{name} from {lo:g} to {hi:g}, harmonics {'adaptive' if hb.adaptive else hb.harmonics}",
    ):
        br = continue_periodic(
            hb, name, (lo, hi), max_step=length / q.opts["points"] * 4, max_points=4 * q.opts["points"]
        )
    rows = tuple(
        (
            _SHORT[b.kind],
            f"{b.parameter:.10g}",
            f"{b.amplitude:.8g}",
            f"{b.frequency:.8g}",
            ", ".join(f"{r:.4g}" for r in b.multipliers),
        )
        for b in br.bifurcations
    )
    table = Table(
        ("bifurcation", name, "amplitude", "frequency, rad/s", "Floquet multipliers"),
        rows,
        "Bifurcations located on the branch",
    )
    lines = (
        f"{len(br)} points, {int(br.stable.sum())} stable; harmonics {int(br.size.min())}..{int(br.size.max())}; "
        f"largest relative residual {float(br.residual.max()):.1e}",
        "bifurcations: "
        + (", ".join(f"{_SHORT[b.kind]} at {name} = {b.parameter:.8g}" for b in br.bifurcations) or "none"),
    )
    fig = Figure(
        f"{q.stem}-continuation.png",
        "Branch of periodic solutions (solid stable, dashed unstable)",
        "branch",
        {
            "parameter": br.parameter.tolist(),
            "y": {"amplitude": br.amplitude, "frequency": br.frequency, "period": 2 * np.pi / br.frequency}[
                q.opts["plot"]
            ].tolist(),
            "stable": br.stable.tolist(),
            "name": name,
            "what": q.opts["plot"],
            "marks": [
                (
                    b.parameter,
                    {"amplitude": b.amplitude, "frequency": b.frequency, "period": 2 * np.pi / b.frequency}[
                        q.opts["plot"]
                    ],
                )
                for b in br.bifurcations
            ],
        },
    )
    data = {
        "parameter": name,
        "points": len(br),
        "bifurcations": [
            {
                "kind": b.kind,
                "parameter": b.parameter,
                "amplitude": b.amplitude,
                "initial_state": [float(y) for y in b.initial_state],
            }
            for b in br.bifurcations
        ],
        "max_residual": float(br.residual.max()),
        "harmonics": [int(br.size.min()), int(br.size.max())],
    }
    return QuestionResult("continuation", f"Continuation in {name} (harmonic balance)", lines, (table,), (fig,), data)


def draw_branch(ax: Any, *, parameter: list, y: list, stable: list, name: str, what: str, marks: list) -> Any:
    """Stable parts solid, unstable dashed, bifurcations circled."""
    p, yy, st = np.asarray(parameter), np.asarray(y), np.asarray(stable, dtype=bool)
    start = 0
    for k in range(1, len(p) + 1):
        if k == len(p) or st[k] != st[start]:
            ax.plot(
                p[start : min(k + 1, len(p))], yy[start : min(k + 1, len(p))], "-" if st[start] else "--", color="C0"
            )
            start = k
    for a, b in marks:
        ax.plot([a], [b], "o", mfc="none", color="k")
    ax.set_xlabel(name)
    ax.set_ylabel(what)
    return ax


SPEC = QuestionSpec(
    "continuation",
    "branch of periodic solutions by harmonic balance and arclength continuation, with stability and bifurcations",
    ("forced_oscillator", "weakly_nonlinear"),
    {
        "parameter": (_str, None),
        "range": (_span, None),
        "plot": (_plot, "amplitude"),
        "harmonics": (_harmonics, None),
        "points": (_points, 200),
        "tol": (lambda c, v, k: c.quantity(v, k, None, positive=True), 1e-8),
    },
    continuation,
)
