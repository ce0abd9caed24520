"""Question handlers for mechanical models: frequencies, matrices, equations, stability, Floquet, sweeps."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._result import Figure, QuestionResult, Table

__all__ = ["Question", "QuestionSpec"]


@dataclass
class Question:
    """Everything a handler may use: the model, SI parameter values, excitation, parsed options, the log."""

    index: int
    kind: str
    model: Any
    values: dict
    excitation: dict
    opts: dict
    ctx: Any
    base: Any  # folder of the scene file (for relative paths)
    stem: str
    log: Any

    def key(self, name: str = "kind") -> str:
        return f"questions[{self.index}].{name}"

    def fail(self, message: str, fix: str = "", name: str = "kind"):
        return self.ctx.error(self.key(name), message, fix)


@dataclass(frozen=True)
class QuestionSpec:
    """A question kind: the model categories it applies to (``None``: no system needed), options and handler."""

    kind: str
    summary: str
    categories: tuple[str, ...] | None
    options: dict = field(default_factory=dict)  # name -> (parser(ctx, value, key), default)
    handler: Callable | None = None


def _hz(x):
    return np.asarray(x) / (2 * np.pi)


def _fmt(x: float, spec: str = ".6g") -> str:
    return format(float(x), spec)


def _excitation(q: Question, name: str, opt: str | None = None) -> float | None:
    if opt and q.opts.get(opt) is not None:
        return q.opts[opt]
    return q.excitation.get(name)


# ------------------------------------------------------------------------------------------ natural frequencies
def natural_frequencies(q: Question) -> QuestionResult:
    lin = q.model.linear
    with q.log.step("evaluate M, K0 and solve K0 phi = omega^2 M phi", "numeric, generalised symmetric eigenproblem"):
        if q.model.inverted:  # gravity flips sign: the hanging system has stiffness -K0 (a vibration does not enter K0)
            lam = lin.eigenvalues(q.values)
            if np.any(lam >= 0):
                raise q.fail(
                    "the model is not a statically unstable inverted chain; set inverted = false",
                    "set inverted = false",
                )
            omega = np.sort(np.sqrt(-lam))
            Phi = None
        else:
            omega, Phi = lin.modes(q.values)
    hz = _hz(omega)
    lines = []
    if q.model.inverted:
        lines.append("Frequencies of the same chain hanging (the inverted equilibrium is statically unstable).")
    ref = q.opts.get("reference_hz")
    if ref is None and q.opts.get("reference_rad_s") is not None:
        ref = [w / (2 * np.pi) for w in q.opts["reference_rad_s"]]
    headers = ["mode", "omega, rad/s", "f, Hz"]
    if ref is not None:
        if len(ref) != len(omega):
            raise q.fail(
                f"reference_hz has {len(ref)} values, the model has {len(omega)} modes",
                f"give {len(omega)} values",
                "reference_hz",
            )
        headers += ["source, Hz", "difference"]
    if Phi is not None:
        headers.append("mass-normalised shape")
    rows = []
    for i in range(len(omega)):
        row = [str(i + 1), _fmt(omega[i], ".6f"), _fmt(hz[i], ".6f")]
        if ref is not None:
            row += [_fmt(ref[i]), f"{(hz[i] - ref[i]) / ref[i]:+.3%}"]
        if Phi is not None:
            row.append("(" + ", ".join(f"{c + 0.0:+.6g}" for c in Phi[:, i]) + ")")
        rows.append(tuple(row))
    data: dict[str, Any] = {"omega_rad_s": omega.tolist(), "frequency_hz": hz.tolist()}
    if Phi is not None:
        data["modes"] = Phi.tolist()
    if len(omega) >= 2:
        r = float((omega[0] / omega[-1]) ** 2)
        data["ratio"] = r
        text = f"squared frequency ratio r = (p1/p{len(omega)})^2 = {r:.6f}"
        if q.opts.get("reference_ratio") is not None:
            text += f" (source: {q.opts['reference_ratio']:g})"
        lines.append(text)
    if q.opts.get("reference"):
        lines.append(f"source values: {q.opts['reference']}")
    if q.opts.get("note"):
        lines.append(f"note: {q.opts['note']}")
    return QuestionResult(
        "natural_frequencies",
        "Natural frequencies and modes",
        tuple(lines),
        (Table(tuple(headers), tuple(rows)),),
        data=data,
    )


# ------------------------------------------------------------------------------------------ matrices, equations
def _num_matrix(m: np.ndarray) -> str:
    return "[" + "; ".join(", ".join(f"{x:.6g}" for x in row) for row in np.atleast_2d(m)) + "]"


def linear_matrices(q: Question) -> QuestionResult:
    import sympy as sp

    lin = q.model.linear
    lines = [f"M = {sp.latex(lin.M)}", f"D = {sp.latex(lin.D)}", f"K = {sp.latex(lin.K)}"]
    data: dict[str, Any] = {"latex": {"M": sp.latex(lin.M), "D": sp.latex(lin.D), "K": sp.latex(lin.K)}}
    if q.values or not lin.parameters:
        skip = set(q.model.excitation_symbols.values()) if getattr(q.model, "excitation_symbols", None) else set()
        needed = {s.name for s in (lin.M.free_symbols | lin.D.free_symbols | lin.K0.free_symbols)} - skip
        if needed <= set(q.values):
            with q.log.step("evaluate M, D, K0 numerically"):
                M, D, K0 = lin.matrices(q.values)
            lines += [
                "",
                "at the given parameters (SI):",
                f"M = {_num_matrix(M)}",
                f"D = {_num_matrix(D)}",
                f"K0 = {_num_matrix(K0)}",
            ]
            data["numeric"] = {"M": M.tolist(), "D": D.tolist(), "K0": K0.tolist()}
    math = tuple((i, sp.Symbol(name), m) for i, (name, m) in enumerate((("M", lin.M), ("D", lin.D), ("K", lin.K))))
    title = "Linearized model M q'' + D q' + K q = f (LaTeX)"
    return QuestionResult("linear_matrices", title, tuple(lines), data=data, math=math)


def equations_of_motion(q: Question) -> QuestionResult:
    import sympy as sp

    M, F = q.model.equations
    system = q.model.system
    names = {}
    for c, v, acc in zip(system.coordinates, system.velocities, system.accelerations, strict=True):
        names[v] = rf"\dot{{{sp.latex(c)}}}"
        names[acc] = rf"\ddot{{{sp.latex(c)}}}"
    lhs = sp.MatMul(M, sp.Matrix(system.accelerations), evaluate=False)
    latex = f"{sp.latex(lhs, symbol_names=names)} = {sp.latex(F, symbol_names=names)}"
    return QuestionResult(
        "equations_of_motion",
        "Nonlinear equations of motion M(q, t) q'' = F(q, q', t) (LaTeX)",
        (latex,),
        data={"latex": latex, "mass_matrix": str(M), "forcing": str(F)},
        math=tuple((0, sum(M[i, j] * a for j, a in enumerate(system.accelerations)), F[i]) for i in range(len(F))),
    )


# ------------------------------------------------------------------------------------------ stability
def _needs_vibrating_inverted(q: Question) -> None:
    if not (getattr(q.model, "inverted", False) and getattr(q.model, "vibrating", False)):
        raise q.fail(
            f"a {q.kind} question needs an inverted chain on a vibrating pivot, the system is: {q.model.describe}",
            'set inverted = true and pivot = "vertical" in [system]',
        )


def stability(q: Question) -> QuestionResult:
    _needs_vibrating_inverted(q)
    from ...periodic import stability_region

    q.model.periodic  # noqa: B018 - K0, K1 (logged); stability_region reuses the linear model
    with q.log.step("stability region from M, K0, K1", f"method {q.opts['method']}"):
        reg = stability_region(q.model.linear, q.values, method=q.opts["method"])
    p1 = reg.natural_frequencies
    lines = [
        "Natural frequencies of the hanging chain: " + ", ".join(f"{w:.6g} rad/s ({w / 2 / np.pi:.6g} Hz)" for w in p1),
        "ratios r_i = (p1/p_i)^2: " + ", ".join(f"{r:.6g}" for r in reg.ratios),
    ]
    data: dict[str, Any] = {"natural_frequencies_rad_s": p1.tolist(), "ratios": list(reg.ratios), "method": reg.method}
    p = _excitation(q, "frequency", "frequency")
    a = q.excitation.get("amplitude")
    point = None
    rows = []
    if p is not None:
        with q.log.step("amplitude interval at the pivot frequency"):
            amin, amax = (float(x) for x in reg.amplitude_bounds(p))
        data.update({"frequency_rad_s": p, "amplitude_min": amin, "amplitude_max": amax})
        rows.append(("pivot frequency p", f"{p:.6g} rad/s = {p / 2 / np.pi:.6g} Hz"))
        if np.isnan(amin):
            rows.append(("stable amplitudes", "none at this frequency"))
        else:
            rows.append(("stable amplitudes", f"{amin * 1e3:.6g} mm < a < {amax * 1e3:.6g} mm"))
        if a is not None:
            stable = bool(reg.is_stable(p, a))
            a1, q1 = (float(x) for x in reg.first_tone(p, a))
            point = (a1, q1)
            data.update({"amplitude": a, "stable": stable, "first_tone": [a1, q1]})
            rows.append(
                (
                    "pivot amplitude a",
                    f"{a * 1e3:.6g} mm -> {'STABLE' if stable else 'unstable'} (a1 = {a1:.4g}, q1 = {q1:.4g})",
                )
            )
    tables = [Table(("quantity", "value"), tuple(rows))] if rows else []
    if q.opts.get("frequencies"):
        ps = np.array(q.opts["frequencies"])
        with q.log.step("amplitude intervals over the pivot frequencies", f"{ps.size} frequencies"):
            lo, hi = reg.amplitude_bounds(ps)
        tables.append(
            Table(
                ("p, Hz", "a_min, mm", "a_max, mm"),
                tuple(
                    (f"{x / 2 / np.pi:.6g}", f"{u * 1e3:.6g}", f"{v * 1e3:.6g}")
                    for x, u, v in zip(ps, lo, hi, strict=True)
                ),
                "Stable pivot amplitudes a_min < a < a_max (nan: none)",
            )
        )
        data["range"] = {"frequency_rad_s": ps.tolist(), "amplitude_min": lo.tolist(), "amplitude_max": hi.tolist()}
    tables = tuple(tables)
    figures = ()
    if q.opts["figure"]:
        qmax = max(1.2 * reg.ratios[-1], 1.3 * point[1] if point else 0.0)
        figures = (
            Figure(
                f"{q.stem}-ince-strutt.png",
                "Modified Ince–Strutt diagram (Gribkov & Khokhlov 2015, Fig. 3)",
                "modified_ince_strutt",
                {"ratios": list(reg.ratios), "point": point, "q_max": qmax},
            ),
        )
        lines.append(f"figure: {figures[0].filename} (modified Ince–Strutt diagram, first-tone axes)")
    return QuestionResult(
        "stability_region",
        "Stability of the inverted chain on the vibrating pivot",
        tuple(lines),
        tables,
        figures,
        data,
    )


def floquet(q: Question) -> QuestionResult:
    _needs_vibrating_inverted(q)
    import sympy as sp

    from ...periodic import monodromy

    _, K1s, _ = q.model.periodic
    lin = q.model.linear
    args = sorted(K1s.free_symbols, key=lambda s: s.name)
    K1f = sp.lambdify(args, K1s, "numpy")
    with q.log.step("evaluate M, D, K0 numerically"):
        M, D, K0 = lin.matrices(q.values)
    n = M.shape[0]
    Minv = np.linalg.inv(M)
    Z = np.zeros((n, n))
    A0 = np.block([[Z, np.eye(n)], [-Minv @ K0, -Minv @ D]])
    rows, data_rows = [], []
    npts = len(q.opts["frequencies"]) * len(q.opts["amplitudes"])
    with q.log.step("monodromy matrices on the grid", f"{npts} points, one pivot period each"):
        for p in q.opts["frequencies"]:
            for a in q.opts["amplitudes"]:
                vals = {**q.values, "a": a, "p": p}
                K1 = np.array(K1f(*(vals[s.name] for s in args)), dtype=float)
                A1 = np.block([[Z, Z], [-Minv @ K1, Z]])
                res = monodromy(_AFun(A0, A1, p), 2 * np.pi / p)
                rho = float(np.max(np.abs(res.floquet_multipliers)))
                rows.append((f"{p / 2 / np.pi:.6g}", f"{a * 1e3:.6g}", f"{rho:.8f}", res.stability))
                data_rows.append(
                    {"frequency_rad_s": p, "amplitude": a, "max_abs_multiplier": rho, "stability": res.stability}
                )
    table = Table(
        ("p, Hz", "a, mm", "max |rho|", "verdict"),
        tuple(rows),
        "Floquet multipliers of the linearized 2N-dimensional system",
    )
    return QuestionResult(
        "floquet",
        "Floquet multipliers on a grid",
        ("monodromy of x' = A(t) x, x = (q, q'), integrated over one pivot period",),
        (table,),
        data={"grid": data_rows},
    )


class _AFun:
    """A(t) = A0 + A1 cos(p t) (picklable, no closure)."""

    def __init__(self, A0: np.ndarray, A1: np.ndarray, p: float) -> None:
        self.A0, self.A1, self.p = A0, A1, p

    def __call__(self, t: float) -> np.ndarray:
        return self.A0 + self.A1 * np.cos(self.p * t)


# ------------------------------------------------------------------------------------------ sweep
def sweep_frequencies(q: Question) -> QuestionResult:
    name = q.opts["parameter"]
    valid = q.model.parameter_names()
    if name not in valid:
        from .._errors import closest

        raise q.fail(
            f"unknown parameter '{name}'.{closest(name, valid)} Valid parameters: {', '.join(valid)}",
            "name one of the model's parameters",
            "parameter",
        )
    dim = q.model.dimension(name)
    vals = np.array(q.ctx.quantities(q.opts["values"], q.key("values"), dim), dtype=float)
    if q.opts["of"] == "amplitude_bounds":
        return _sweep_bounds(q, name, vals)
    lin = q.model.linear
    with q.log.step(f"natural frequencies over {name}", f"{vals.size} values, vectorised"):
        lam = lin.eigenvalues({**q.values, name: vals})
        omega = np.sqrt(np.abs(lam)) if q.model.inverted else lin.natural_frequencies({**q.values, name: vals})
        omega = np.sort(omega, axis=-1)
    hz = _hz(omega)
    rows = tuple((f"{v:.6g}", *(f"{h:.6f}" for h in row)) for v, row in zip(vals, hz, strict=True))
    headers = (f"{name} (SI)", *(f"f{i + 1}, Hz" for i in range(hz.shape[1])))
    lines = ("frequencies of the hanging chain",) if q.model.inverted else ()
    return QuestionResult(
        "sweep",
        f"Natural frequencies against {name}",
        lines,
        (Table(headers, rows),),
        data={"parameter": name, "values": vals.tolist(), "frequency_hz": hz.tolist()},
    )


def _sweep_bounds(q: Question, name: str, vals: np.ndarray) -> QuestionResult:
    _needs_vibrating_inverted(q)
    from ...periodic import stability_region

    p = q.excitation.get("frequency")
    if p is None:
        raise q.fail("an amplitude_bounds sweep needs the pivot frequency", "add [excitation] frequency = ...", "of")
    lin = q.model.linear
    lo, hi = [], []
    with q.log.step(f"stable amplitude interval over {name}", f"{vals.size} stability regions at p = {p:.6g} rad/s"):
        for v in vals:
            a_min, a_max = stability_region(lin, {**q.values, name: float(v)}).amplitude_bounds(p)
            lo.append(float(a_min))
            hi.append(float(a_max))
    rows = tuple((f"{v:.6g}", f"{a * 1e3:.6g}", f"{b * 1e3:.6g}") for v, a, b in zip(vals, lo, hi, strict=True))
    return QuestionResult(
        "sweep",
        f"Stable pivot amplitudes against {name} at {p / 2 / np.pi:.6g} Hz",
        (),
        (Table((f"{name} (SI)", "a_min, mm", "a_max, mm"), rows),),
        data={"parameter": name, "values": vals.tolist(), "amplitude_min": lo, "amplitude_max": hi},
    )
