"""Question handlers for the Mathieu equation, weakly nonlinear oscillators, operator equations and records."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from .._result import Figure, QuestionResult, Table
from .mechanical import Question, _fmt

__all__: list[str] = []


# ------------------------------------------------------------------------------------------ Mathieu
def mathieu_values(q: Question) -> QuestionResult:
    from ...periodic import mathieu_characteristic

    ns, qs = q.opts["n"], q.opts["q"]
    rows, data = [], []
    with q.log.step("Mathieu characteristic values", f"{q.opts['characteristic']}_n(q), {len(ns)} x {len(qs)} values"):
        for n in ns:
            res = mathieu_characteristic(q.opts["characteristic"], n, qs)
            for qq, v, err in zip(qs, np.atleast_1d(res.values), np.atleast_1d(res.error_estimate), strict=True):
                rows.append((str(n), f"{qq:g}", f"{float(v):.15g}", f"{float(err):.1e}"))
                data.append({"n": n, "q": qq, "value": float(v), "error_estimate": float(err)})
    name = q.opts["characteristic"]
    table = Table(("n", "q", f"{name}_n(q)", "error estimate"), tuple(rows))
    return QuestionResult(
        "mathieu_values", f"Mathieu characteristic values {name}_n(q)", (), (table,), data={"values": data}
    )


def ince_strutt(q: Question) -> QuestionResult:
    fig = Figure(
        f"{q.stem}-ince-strutt-classic.png",
        "Ince–Strutt diagram of the Mathieu equation",
        "ince_strutt",
        {"orders": q.opts["orders"], "q_max": q.opts["q_max"]},
    )
    return QuestionResult(
        "ince_strutt",
        "Ince–Strutt diagram",
        (f"figure: {fig.filename}",),
        figures=(fig,),
        data={"figure": fig.filename},
    )


# ------------------------------------------------------------------------------------------ nonlinear series
def limit_cycle(q: Question) -> QuestionResult:
    import sympy as sp

    from ...nonlinear import limit_cycle as poincare
    from ...nonlinear import validate_limit_cycle

    d = q.model.data
    with q.log.step("Poincaré series of the limit cycle", f"order {q.opts['order']}, exact arithmetic"):
        lc = poincare(d["f"], q.opts["order"], x=d["x"], v=d["v"])
    lines = [
        f"amplitude  x(0) = {lc.amplitude.expr}",
        f"frequency  omega = {lc.frequency.expr}",
        f"stable: {lc.stable}",
    ]
    tables = ()
    data: dict[str, Any] = {"order": lc.order, "amplitude": str(lc.amplitude.expr), "frequency": str(lc.frequency.expr)}
    eps = q.opts.get("validate_eps")
    if eps:
        with q.log.step("validate against the numerical limit cycle", f"eps = {eps}"):
            val = validate_limit_cycle(lc, eps)
        rows = tuple(
            (
                f"{r['eps']:g}",
                str(r["order"]),
                f"{r['amplitude_series']:.10f}",
                f"{r['amplitude_numeric']:.10f}",
                f"{r['amplitude_error']:.2e}",
                f"{r['frequency_error']:.2e}",
                "" if r["in_validity"] else "outside series validity",
            )
            for r in val.rows
        )
        tables = (
            Table(
                ("eps", "order", "amplitude (series)", "amplitude (numeric)", "amp. error", "freq. error", "note"),
                rows,
                "Series against the numerically integrated cycle",
            ),
        )
        data["validation"] = [{k: v for k, v in r.items() if isinstance(v, int | float | bool)} for r in val.rows]
    return QuestionResult(
        "limit_cycle",
        f"Limit cycle by Poincaré's method to order {lc.order} (Bulgakov 1954, §8)",
        tuple(lines),
        tables,
        data=data,
        math=((0, sp.Function("x")(0), lc.amplitude.expr), (1, sp.Symbol("omega"), lc.frequency.expr)),
    )


def lindstedt_series(q: Question) -> QuestionResult:
    import sympy as sp

    from ...nonlinear import lindstedt, validate_lindstedt

    d = q.model.data
    if d["v"] in d["f"].free_symbols:
        raise q.fail(
            "a Lindstedt series needs a conservative f(x) (no v)", "use a limit_cycle question for self-excited systems"
        )
    with q.log.step("Lindstedt frequency series", f"order {q.opts['order']}"):
        ls = lindstedt(d["f"], q.opts["order"], x=d["x"])
    lines = [f"omega(eps, A) = {ls.frequency.expr}"]
    data: dict[str, Any] = {"order": ls.order, "frequency": str(ls.frequency.expr)}
    tables = ()
    if q.opts.get("validate_eps") and q.opts.get("amplitude") is not None:
        rows = []
        for e in q.opts["validate_eps"]:
            with q.log.step("validate against the integrated period", f"eps = {e}"):
                r = validate_lindstedt(ls, e, q.opts["amplitude"]).rows[0]
            rows.append(
                (
                    f"{e:g}",
                    f"{r['frequency_series']:.12f}",
                    f"{r['frequency_numeric']:.12f}",
                    f"{r['frequency_error']:.2e}",
                )
            )
        tables = (Table(("eps", "omega (series)", "omega (numeric)", "error"), tuple(rows)),)
        data["validation"] = [list(r) for r in rows]
    math = ((0, sp.Symbol("omega"), ls.frequency.expr),)
    return QuestionResult(
        "lindstedt", f"Lindstedt series to order {ls.order}", tuple(lines), tables, data=data, math=math
    )


def resonance_curve(q: Question) -> QuestionResult:
    import sympy as sp

    from ...nonlinear import averaged_equations

    R = q.excitation.get("amplitude")
    if R is None:
        raise q.fail("a resonance curve needs the forcing amplitude", "add [excitation] amplitude = 0.1")
    x, v = sp.symbols("x v", real=True)
    w0, zeta, mu = (sp.Symbol(s, positive=True) for s in ("w0", "zeta", "mu"))
    with q.log.step("averaged (shortened) equations", "Krylov–Bogoliubov, exact harmonic means"):
        avg = averaged_equations(
            w0**2 * x + mu * x**3 + 2 * zeta * w0 * v, forcing=sp.Symbol("R", positive=True), x=x, v=v
        )
    vals = {"w0": q.values["w0"], "zeta": q.values["zeta"], "mu": q.values["mu"], "R": R}
    lo, hi = q.opts["frequency_range"]
    with q.log.step("resonance curve W(nu, a) = 0", f"{q.opts['points']} frequencies"):
        fr = avg.frequency_response(vals, (lo, hi), q.opts["points"])
    jumps = fr.jump_frequencies
    lines = [
        f"jump (fold) frequencies: {', '.join(f'{j:.6g} rad/s' for j in jumps) or 'none'}",
        f"largest steady amplitude: {np.nanmax(fr.amplitudes):.6g}",
    ]
    fig = Figure(
        f"{q.stem}-resonance.png",
        "Resonance curve (Bulgakov 1954, ch. 6)",
        "resonance",
        {
            "nu": fr.nu.tolist(),
            "amplitudes": np.where(np.isfinite(fr.amplitudes), fr.amplitudes, np.nan).tolist(),
            "stable": fr.stable.tolist(),
            "folds": [[f.nu, f.amplitude] for f in fr.folds],
        },
    )
    data = {
        "nu": fr.nu.tolist(),
        "max_amplitude": [float(np.nanmax(r)) if np.any(np.isfinite(r)) else None for r in fr.amplitudes],
        "jump_frequencies": list(jumps),
    }
    return QuestionResult("resonance_curve", "Resonance curve by averaging", tuple(lines), figures=(fig,), data=data)


# ------------------------------------------------------------------------------------------ operational
def operational_solution(q: Question) -> QuestionResult:
    import sympy as sp

    from ...operational import solve_operational
    from ...symbols import t

    d = q.model.data
    with q.log.step("Carson transform solution", "Heaviside expansion of the image"):
        sol = solve_operational(d["lhs"], d["rhs"], [d["input"]], [d["initial"]], D=d["D"], t=t)
    y = sp.simplify(sol.response[0])
    lines = [f"y(t) = {y}", f"Carson image of the step response: {sp.simplify(sol.transfer[0])}"]
    data: dict[str, Any] = {"response": str(y), "latex": sp.latex(y)}
    ts = q.opts.get("times")
    tables = ()
    if ts:
        f = sp.lambdify(t, y, "numpy")
        rows = tuple((f"{tt:g}", f"{float(f(tt)):.12g}") for tt in ts)
        tables = (Table(("t", "y(t)"), rows),)
        data["values"] = [[float(tt), float(f(tt))] for tt in ts]
    return QuestionResult(
        "operational_solution",
        "Solution by the Carson (operational) transform (Bulgakov 1954, ch. 2)",
        tuple(lines),
        tables,
        data=data,
        math=((0, sp.Function("y")(t), y),),
    )


# ------------------------------------------------------------------------------------------ identification
def read_record(q: Question) -> tuple[np.ndarray, float]:
    path = Path(q.opts["record"])
    if not path.is_absolute():
        path = Path(q.base) / path
    if not path.is_file():
        raise q.fail(f"record file {str(path)!r} not found", "give a CSV path relative to the scene file", "record")
    try:
        raw = np.genfromtxt(path, delimiter=",", names=True)
    except (ValueError, IndexError) as exc:  # IndexError: an empty file
        raise q.fail(
            f"cannot read {path.name} as CSV with a header row: {exc}",
            "write a header line, then one row per sample",
            "record",
        ) from None
    names = list(raw.dtype.names or ())
    cols = np.array([raw[n] for n in names], dtype=float)
    if not np.all(np.isfinite(cols)) or cols.shape[-1] < 8:
        raise q.fail(f"{path.name} must hold at least 8 rows of finite numbers", "check the file", "record")
    dt = q.opts.get("dt")
    if names and names[0] in ("t", "time"):
        steps = np.diff(cols[0])
        if dt is None:
            dt = float(np.mean(steps))
        cols = cols[1:]
    if dt is None:
        raise q.fail(
            "the sampling period is unknown: the record has no 't' column", "add dt = 0.002 (s) to the question", "dt"
        )
    return cols, float(dt)


def identify(q: Question) -> QuestionResult:
    from ... import identification as ident

    signals, dt = read_record(q)
    method = getattr(ident, q.opts["method"])
    with q.log.step(
        f"modal estimate ({q.opts['method']})",
        f"{signals.shape[0]} channels x {signals.shape[1]} samples, dt = {dt:g} s",
    ):
        est = method(signals, dt, q.opts["n_modes"], constant=False)
    if q.opts["refine"]:
        with q.log.step("refine poles (variable projection)"):
            est = ident.refine(est, signals)
    rows = tuple(
        (str(i + 1), f"{w:.8g}", f"{w / 2 / np.pi:.8g}", f"{z:.3e}")
        for i, (w, z) in enumerate(zip(est.undamped_frequencies, est.damping_ratios, strict=True))
    )
    tables = [
        Table(
            ("mode", "omega, rad/s", "f, Hz", "damping ratio"),
            rows,
            f"{q.opts['method']} on {Path(q.opts['record']).name}",
        )
    ]
    data: dict[str, Any] = {
        "omega_rad_s": est.undamped_frequencies.tolist(),
        "damping_ratios": est.damping_ratios.tolist(),
    }
    lines = [f"residual {est.residual:.3e}"]
    if q.opts.get("force") is not None:
        with q.log.step("inertia reconstruction (Algorithm 1)", "Belyakov (2005), ch. II §1"):
            res = ident.inertia_from_release(
                est.undamped_frequencies,
                est.mode_shapes,
                q.opts["force"],
                tuple(q.opts["positions"]),
                product_of_inertia=q.opts["product_of_inertia"],
            )
        d = res.as_dict()
        tables.append(
            Table(
                ("quantity", "estimate"),
                tuple((k, _fmt(v, ".8g")) for k, v in d.items()),
                "Body parameters (Belyakov 2005, Algorithm 1)",
            )
        )
        data["inertia"] = {k: float(v) for k, v in d.items()}
    return QuestionResult(
        "identify", "Identification of a free-oscillation record", tuple(lines), tuple(tables), data=data
    )
