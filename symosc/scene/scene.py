"""Scenes: a TOML file describing a system, its parameters, excitation and the questions to answer."""

from __future__ import annotations

import os
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .._printing import SymPyPrintable
from ..errors import ParameterError
from . import _html
from ._errors import SceneError, closest
from ._log import DerivationLog
from ._models import build_model
from ._parse import Ctx
from ._questions import mathieu as fq
from ._questions import mechanical as mq
from ._questions import other as oq
from ._questions import time_response as tr
from ._questions.continuation import SPEC as _CONTINUATION
from ._questions.mechanical import Question, QuestionSpec
from ._result import SceneResult

__all__ = ["QUESTIONS", "Scene", "load", "loads"]

TOP_KEYS = ("title", "source", "description", "system", "parameters", "excitation", "questions")
EXCITATION_KEYS = ("amplitude", "frequency")


def _int(ctx, v, k):
    return ctx.integer(v, k)


def _ints0(ctx, v, k):
    if isinstance(v, int) and not isinstance(v, bool):
        v = [v]
    if not isinstance(v, list) or not v:
        raise ctx.error(k, f"expected a list of integers >= 0, got {v!r}", "write n = [0, 1, 2]")
    return [ctx.integer(x, k, minimum=0) for x in v]


def _bool(ctx, v, k):
    return ctx.boolean(v, k)


def _str(ctx, v, k):
    return ctx.string(v, k)


def _floats(ctx, v, k):
    return [float(x) for x in ctx.quantities(v, k, "dimensionless")]


def _any(ctx, v, k):
    return v


def _choice(*choices):
    def parse(ctx, v, k):
        return ctx.choice(v, k, list(choices))

    return parse


def _freq(ctx, v, k):
    return ctx.quantity(v, k, "angular frequency", positive=True)


def _freqs(ctx, v, k):
    return ctx.quantities(v, k, "angular frequency", positive=True)


def _lengths(ctx, v, k):
    return ctx.quantities(v, k, "length", positive=True)


def _span(ctx, v, k):
    return ctx.span(v, k, "angular frequency")


def _times(ctx, v, k):
    return ctx.quantities(v, k, "time")


_REF = {
    "reference_hz": (_floats, None),
    "reference_rad_s": (_floats, None),
    "reference_ratio": (lambda c, v, k: _floats(c, v, k)[0], None),
    "reference": (_str, ""),
    "note": (_str, ""),
}
_MECH = ("mechanical",)
_LIN = ("mechanical", "linear")
_NL = ("weakly_nonlinear",)

#: question kind -> specification (model categories it applies to, options, handler)
QUESTIONS: dict[str, QuestionSpec] = {
    s.kind: s
    for s in (
        QuestionSpec(
            "natural_frequencies",
            "natural frequencies and mass-normalised modes",
            _LIN,
            dict(_REF),
            mq.natural_frequencies,
        ),
        QuestionSpec(
            "linear_matrices", "M, D, K of the linearized model (LaTeX and numbers)", _LIN, {}, mq.linear_matrices
        ),
        QuestionSpec(
            "equations_of_motion", "nonlinear equations M(q) q'' = F (LaTeX)", _MECH, {}, mq.equations_of_motion
        ),
        QuestionSpec(
            "stability_region",
            "stability of an inverted chain on a vibrating pivot",
            _MECH,
            {
                "method": (
                    _choice("modified-ince-strutt", "floquet", "otterbein", "acheson", "chelomei"),
                    "modified-ince-strutt",
                ),
                "frequency": (_freq, None),
                "frequencies": (_freqs, None),
                "figure": (_bool, True),
            },
            mq.stability,
        ),
        QuestionSpec(
            "floquet",
            "Floquet multipliers on a grid of pivot frequencies and amplitudes",
            _MECH,
            {"frequencies": (_freqs, None), "amplitudes": (_lengths, None)},
            mq.floquet,
        ),
        QuestionSpec(
            "sweep",
            "natural frequencies over a range of one parameter",
            _LIN,
            {
                "parameter": (_str, None),
                "values": (_any, None),
                "of": (_choice("natural_frequencies", "amplitude_bounds"), "natural_frequencies"),
            },
            mq.sweep_frequencies,
        ),
        QuestionSpec(
            "mathieu_values",
            "Mathieu characteristic values a_n(q) or b_n(q)",
            ("mathieu",),
            {"characteristic": (_choice("a", "b"), "a"), "n": (_ints0, None), "q": (_floats, None)},
            oq.mathieu_values,
        ),
        QuestionSpec(
            "ince_strutt",
            "the classic Ince–Strutt diagram (figure)",
            ("mathieu",),
            {"orders": (_int, 3), "q_max": (lambda c, v, k: _floats(c, v, k)[0], 8.0)},
            oq.ince_strutt,
        ),
        fq.SPEC,
        QuestionSpec(
            "limit_cycle",
            "Poincaré series of a limit cycle with its validation",
            _NL,
            {"order": (_int, None), "validate_eps": (_floats, None)},
            oq.limit_cycle,
        ),
        QuestionSpec(
            "lindstedt",
            "Lindstedt frequency series of a conservative oscillator",
            _NL,
            {
                "order": (_int, None),
                "validate_eps": (_floats, None),
                "amplitude": (lambda c, v, k: _floats(c, v, k)[0], None),
            },
            oq.lindstedt_series,
        ),
        QuestionSpec(
            "resonance_curve",
            "resonance (frequency-response) curve by averaging",
            ("forced_oscillator",),
            {"frequency_range": (_span, None), "points": (_int, 400)},
            oq.resonance_curve,
        ),
        QuestionSpec(
            "operational_solution",
            "solution of f(D) y = e(D) x(t) by the Carson transform",
            ("operator_ode",),
            {"times": (_times, None)},
            oq.operational_solution,
        ),
        QuestionSpec(
            "identify",
            "modal identification of a CSV record (Belyakov 2005)",
            None,
            {
                "record": (_str, None),
                "dt": (lambda c, v, k: c.quantity(v, k, "time", positive=True), None),
                "n_modes": (_int, None),
                "method": (_choice("matrix_pencil", "esprit", "prony", "era"), "matrix_pencil"),
                "refine": (_bool, False),
                "force": (_floats, None),
                "positions": (_floats, None),
                "product_of_inertia": (_choice("tensor", "dissertation"), "tensor"),
            },
            oq.identify,
        ),
        _CONTINUATION,
        QuestionSpec(
            "time_response",
            "simulated motion from an initial state (plot, data, GIF)",
            _LIN,
            tr.OPTIONS,
            tr.time_response,
        ),
    )
}

_REQUIRED = {
    "floquet": ("frequencies", "amplitudes"),
    "sweep": ("parameter", "values"),
    "mathieu_values": ("n", "q"),
    "mathieu_functions": ("n", "q"),
    "limit_cycle": ("order",),
    "lindstedt": ("order",),
    "resonance_curve": ("frequency_range",),
    "identify": ("record", "n_modes"),
    "continuation": ("range",),
    "time_response": ("duration",),
}


@dataclass
class Scene(SymPyPrintable):
    """A validated scene: run it with :meth:`run`.

    Attributes
    ----------
    path : str
        The scene file (or ``"<string>"``).
    title, source : str
        Free text from the file.
    model : object or None
        The lazy model (nothing is derived before :meth:`run`, except what validation needs).
    values : dict
        Parameter values in SI units.
    excitation : dict
        ``amplitude`` / ``frequency`` in SI units (frequencies in rad/s).
    questions : list of (kind, options)
        The validated questions in file order: each ``kind`` (a key of :data:`QUESTIONS`) with its options.
    log : DerivationLog
        The steps derived so far for this scene (filled by validation and by :meth:`run`).
    _ctx : object
        Internal: the scene's text and name, used to locate keys in error messages and to pickle the scene.

    See Also
    --------
    load : read a scene file.
    """

    path: str
    title: str
    source: str
    model: Any = field(repr=False)
    values: dict
    excitation: dict
    questions: list
    log: DerivationLog = field(repr=False)
    _ctx: Ctx = field(repr=False)

    def __reduce__(self) -> tuple:
        """Pickled as its text and parameter values: the lazy model is rebuilt (derivations are redone on use)."""
        return (_rebuild_scene, (self._ctx.text, self.path, dict(self.values)))

    def run(self) -> SceneResult:
        """Answer every question; returns a :class:`SceneResult` (report, tables, figures, data, log).

        Errors are raised as :class:`SceneError` naming the question; nothing is written by ``run``.  The log
        covers everything derived for this scene so far: a second ``run`` reuses the derivations of the first
        and adds only the steps it ran.
        """
        from ..errors import SymoscError

        results = []
        base = Path(self.path).parent if self.path != "<string>" else Path.cwd()
        stem = Path(self.path).stem if self.path != "<string>" else "scene"
        for i, (kind, opts) in enumerate(self.questions):
            q = Question(i, kind, self.model, self.values, self.excitation, opts, self._ctx, base, stem, self.log)
            try:
                results.append(QUESTIONS[kind].handler(q))
            except SceneError:
                raise
            except SymoscError as exc:
                raise q.fail(f"{kind} failed: {exc}", "check the parameters and options of this question") from exc
        return SceneResult(
            title=self.title,
            source=self.source,
            system=getattr(self.model, "describe", "") if self.model is not None else "",
            parameters=dict(self.values),
            results=tuple(results),
            log=tuple(self.log.entries),
            parameter_text=_html.parameter_text(self),
        )


#: the largest scene file read (a scene is a page of TOML; a CSV record is referenced, not embedded)
MAX_SCENE_BYTES = 1_000_000


def load(path: str | os.PathLike) -> Scene:
    """Read and validate a scene file (TOML).

    Parameters
    ----------
    path : str or PathLike
        The ``.toml`` file.

    Returns
    -------
    Scene

    Raises
    ------
    SceneError
        One paragraph naming the file, the key (and its line), what was expected and the fix.

    Examples
    --------
    >>> from symosc.scene import loads
    >>> scene = loads('''
    ... [system]
    ... model = "n_link_pendulum"
    ... n = 1
    ... [parameters]
    ... m1 = "1 kg"
    ... l1 = "981 cm"
    ... g = 9.81
    ... [[questions]]
    ... kind = "natural_frequencies"
    ... ''')
    >>> result = scene.run()
    >>> result.to_json()["questions"][0]["omega_rad_s"]
    [1.0]
    >>> result.to_json()["derivation_log"][1]["step"]
    'linearize at q = 0'

    See Also
    --------
    Scene.run : answer the questions.
    """
    if not isinstance(path, str | os.PathLike):
        raise ParameterError(f"path must be a str or os.PathLike naming a scene file, got {path!r}")
    p = Path(path)
    try:
        if p.stat().st_size > MAX_SCENE_BYTES:
            raise SceneError(
                str(p),
                "",
                f"the file has {p.stat().st_size:,} bytes; a scene file has at most {MAX_SCENE_BYTES:,}",
                fix="check that this is a scene file",
            )
        data = p.read_bytes()
    except OSError as exc:
        raise SceneError(
            str(p), "", f"cannot read the scene file ({exc.strerror or exc})", fix="check the path"
        ) from None
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise SceneError(
            str(p),
            "",
            f"the file is not UTF-8 text (byte {exc.start}: {exc.reason})",
            fix="save the scene file as UTF-8 (TOML files are UTF-8)",
        ) from None
    return loads(text, name=str(p))


def _rebuild_scene(text: str, path: str, values: dict) -> Scene:
    scene = loads(text, name=path)
    scene.values = values
    return scene


def loads(text: str, *, name: str = "<string>", overrides: Mapping[str, Any] | None = None) -> Scene:
    """Validate a scene given as TOML text (``name`` is used in error messages); see :func:`load`.

    ``overrides`` replaces parameter values (``{"m1": 0.002}``) before validation, as ``symosc double-pendulum
    --set`` does.

    Parameters
    ----------
    text : str
        The scene as TOML text (tables ``[system]``, ``[parameters]``, ``[excitation]``, ``[[questions]]``).
    name : str
        Name of the scene in error messages and the default title (a file name, or ``"<string>"``).
    overrides : mapping of str to number or str, optional
        Parameter values replacing those of ``[parameters]`` before validation, keyed by parameter name; numbers
        in SI units or strings with units such as ``"200 N/m"``.

    Returns
    -------
    Scene

    Raises
    ------
    SceneError
        One paragraph naming the key (and its line), what was expected and the fix.

    Examples
    --------
    >>> text = '[system]\\nmodel = "lagrangian"\\ncoordinates = ["x"]\\nT = "m*x_dot**2/2"\\nV = "k*x**2/2"\\n'
    >>> text += '[parameters]\\nm = "2 kg"\\nk = "50 N/m"\\n[[questions]]\\nkind = "natural_frequencies"\\n'
    >>> [round(w, 12) for w in loads(text).run()["natural_frequencies"].data["omega_rad_s"]]
    [5.0]
    >>> [round(w, 12) for w in loads(text, overrides={"k": "200 N/m"}).run()["natural_frequencies"].data["omega_rad_s"]]
    [10.0]

    See Also
    --------
    load : the same from a file.
    """
    ctx = Ctx(name, text)
    if not isinstance(text, str):
        raise SceneError(name, "", f"expected the scene as text (str), got {type(text).__name__}", fix="pass a str")
    if len(text) > MAX_SCENE_BYTES:
        raise SceneError(name, "", f"the text has {len(text):,} characters; a scene has at most {MAX_SCENE_BYTES:,}")
    try:
        data = tomllib.loads(text)
    except (tomllib.TOMLDecodeError, RecursionError) as exc:
        raise SceneError(name, "", f"not valid TOML: {exc}", fix="see https://toml.io for the syntax") from None
    ctx.check_keys(data, TOP_KEYS, "")
    log = DerivationLog()
    title = ctx.string(data.get("title", Path(name).stem), "title")
    source = ctx.string(data.get("source", ""), "source")
    model = None
    if "system" in data:
        model = build_model(ctx, ctx.table(data["system"], "system"), log)
    params = dict(ctx.table(data.get("parameters", {}), "parameters"))
    if overrides:
        params.update(overrides)
    values = _parameters(ctx, model, params)
    excitation = _excitation(ctx, model, ctx.table(data.get("excitation", {}), "excitation"))
    questions = _questions(ctx, model, data.get("questions"))
    return Scene(name, title, source, model, values, excitation, questions, log, ctx)


def _parameters(ctx: Ctx, model: Any, params: Mapping[str, Any]) -> dict[str, float]:
    if model is None:
        if params:
            raise ctx.error(
                "parameters",
                "parameters given but the scene has no [system]",
                "add a [system] table or remove [parameters]",
            )
        return {}
    valid = model.parameter_names()
    for k in params:
        if k not in valid:
            exc = getattr(model, "excitation_symbols", None) or {}
            hint = ""
            for ek, sym in exc.items():
                if sym == k:
                    hint = f" ('{k}' is set by [excitation] {ek})"
            raise ctx.error(
                f"parameters.{k}",
                f"'{k}' is not a parameter of the {model.describe}{hint}.{closest(k, valid)} "
                f"Valid parameters: {', '.join(valid) or 'none'}",
                f"remove '{k}' or rename it",
            )
    required = getattr(model, "required", None)
    required = valid if required is None else required
    missing = [k for k in required if k not in params]
    if missing:
        raise ctx.error(
            "parameters",
            f"missing parameter(s) {', '.join(missing)} of the {model.describe}",
            f"add {missing[0]} = <value> under [parameters]",
        )
    values = {
        k: ctx.quantity(params[k], f"parameters.{k}", model.dimension(k), positive=model.positive(k))
        for k in valid
        if k in params
    }
    check = getattr(model, "check_units", None)
    if check is not None:  # a user Lagrangian: the units the file gives against their places in T, V, R, forces
        from ._units import UnitError, parse_quantity_unit

        given = {}
        for k in values:
            unit = parse_quantity_unit(params[k])
            if unit is not None:
                given[k] = (params[k], unit)
        try:
            check(given)
        except UnitError as exc:
            key = f"parameters.{exc.parameter}" if exc.parameter else "parameters"
            raise ctx.error(key, str(exc), "give the unit its place implies, or fix T, V, R or the forces") from None
    return values


def _excitation(ctx: Ctx, model: Any, exc: Mapping[str, Any]) -> dict[str, float]:
    ctx.check_keys(exc, EXCITATION_KEYS, "excitation")
    if not exc:
        return {}
    allowed = getattr(model, "excitation_symbols", None) or {}
    out = {}
    for k, v in exc.items():
        if k not in allowed:
            raise ctx.error(
                f"excitation.{k}",
                f"the {getattr(model, 'describe', 'scene')} has no excitation '{k}'",
                'remove it, or choose a vibrating pivot (pivot = "vertical") or a forced model',
            )
        dim = (
            "angular frequency"
            if k == "frequency"
            else ("length" if getattr(model, "category", "") == "mechanical" else None)
        )
        out[k] = ctx.quantity(v, f"excitation.{k}", dim, positive=True)
    return out


def _questions(ctx: Ctx, model: Any, qs: Any) -> list:
    if qs is None:
        raise ctx.error(
            "questions",
            "the scene asks no question",
            'add [[questions]] with kind = "natural_frequencies" (or another kind)',
        )
    if not isinstance(qs, list) or not all(isinstance(x, Mapping) for x in qs):
        raise ctx.error(
            "questions",
            "expected an array of tables ([[questions]] blocks)",
            "write each question as [[questions]] followed by kind = ...",
        )
    out = []
    for i, qd in enumerate(qs):
        where = f"questions[{i}]"
        kind = qd.get("kind")
        if kind is None:
            raise ctx.error(where, "missing required key 'kind'", f"add kind = one of {', '.join(QUESTIONS)}")
        if kind not in QUESTIONS:
            raise ctx.error(
                f"{where}.kind",
                f"unknown question kind {kind!r}.{closest(str(kind), QUESTIONS)} Known kinds: {', '.join(QUESTIONS)}",
                "use one of the known kinds",
            )
        spec = QUESTIONS[kind]
        category = getattr(model, "category", None)
        if spec.categories is not None and category not in spec.categories:
            what = getattr(model, "describe", "no [system]") if model is not None else "a scene without [system]"
            able = [k for k, s in QUESTIONS.items() if s.categories is None or category in s.categories]
            raise ctx.error(
                f"{where}.kind",
                f"the {what} cannot answer {kind!r}; it answers: {', '.join(able)}",
                "ask a question this model answers, or change [system]",
            )
        ctx.check_keys(qd, ["kind", *spec.options], where, "option")
        opts = {}
        for name, (parse, default) in spec.options.items():
            if name in qd:
                opts[name] = parse(ctx, qd[name], f"{where}.{name}")
            else:
                if name in _REQUIRED.get(kind, ()):
                    raise ctx.error(
                        where, f"{kind} needs the option '{name}'", f"add {name} = ... to this [[questions]] block"
                    )
                opts[name] = default
        vib = kind in ("stability_region", "floquet") or (kind == "sweep" and opts.get("of") == "amplitude_bounds")
        if vib and not (getattr(model, "inverted", False) and getattr(model, "vibrating", False)):
            raise ctx.error(
                f"{where}.kind" if kind != "sweep" else f"{where}.of",
                f"{kind} needs an inverted chain on a vibrating pivot, the system is: {model.describe}",
                'set inverted = true and pivot = "vertical" in [system]',
            )
        if kind == "sweep":
            valid = model.parameter_names()
            if opts["parameter"] not in valid:
                raise ctx.error(
                    f"{where}.parameter",
                    f"unknown parameter {opts['parameter']!r}.{closest(opts['parameter'], valid)} "
                    f"Valid parameters: {', '.join(valid)}",
                    "name one of the model's parameters",
                )
            ctx.quantities(opts["values"], f"{where}.values", model.dimension(opts["parameter"]))
        out.append((kind, opts))
    return out
