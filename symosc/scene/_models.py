"""The systems a scene can name: catalogue models and a Lagrangian given by its energies.

Each model derives lazily and records every derivation step in the scene's :class:`DerivationLog`, so that a
question takes only what it needs (a frequency question never forms the nonlinear equations of motion).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import sympy as sp

from ._log import DerivationLog
from ._parse import Ctx, parse_sympy
from ._units import check_lagrangian_units

__all__ = ["MODELS", "ModelSpec", "build_model"]


# ------------------------------------------------------------------------------------------------ mechanical
def _pendulum_dimension(name: str) -> str:
    if name == "g":
        return "acceleration"
    if name.startswith("I"):
        return "moment of inertia"
    if name.startswith("m"):
        return "mass"
    return "length"  # l1.., lc1..


class MechanicalModel:
    """A Lagrangian system built on first use; linearization, K(t) split and equations of motion on demand."""

    category = "mechanical"

    def __init__(
        self,
        log: DerivationLog,
        make: Callable[[], Any],
        describe: str,
        *,
        dimension: Callable[[str], str | None] = lambda name: None,
        excitation: Mapping[str, str] | None = None,
        inverted: bool = False,
        vibrating: bool = False,
    ) -> None:
        self.log, self._make, self.describe = log, make, describe
        self._dimension = dimension
        self.excitation_symbols = dict(excitation or {})  # excitation key -> parameter name (amplitude -> a)
        self.inverted, self.vibrating = inverted, vibrating

    @cached_property
    def system(self):
        with self.log.step("build the Lagrangian system", "T, V (the first model also imports the catalogue)"):
            return self._make()

    @cached_property
    def linear(self):
        with self.log.step("linearize at q = 0", "M, D, K from the energies (no nonlinear equations)"):
            return self.system.linearize()

    @cached_property
    def periodic(self):
        with self.log.step("split K(t) = K0 + K1 cos(p t)", "stiffness harmonics of the linear model"):
            return self.linear.periodic_stiffness()

    @cached_property
    def equations(self):
        with self.log.step("derive the nonlinear equations of motion", "M(q, t) q'' = F(q, q', t)"):
            return self.system.mass_matrix, self.system.forcing

    # -------------------------------------------------------------- parameters
    def parameter_names(self) -> list[str]:
        skip = set(self.excitation_symbols.values())
        return [s.name for s in self.system.parameters if s.name not in skip]

    def dimension(self, name: str) -> str | None:
        return self._dimension(name)

    def positive(self, name: str) -> bool:
        """Parameters of pendulums and of Lagrangians read from a file are positive symbols."""
        return True


def _n_link_pendulum(ctx: Ctx, opts: Mapping[str, Any], log: DerivationLog) -> MechanicalModel:
    n = ctx.integer(opts.get("n", 1), "system.n")
    links = ctx.choice(opts.get("links", "point"), "system.links", ["point", "rigid"])
    inverted = ctx.boolean(opts.get("inverted", False), "system.inverted")
    pivot = ctx.choice(opts.get("pivot", "fixed"), "system.pivot", ["fixed", "vertical"])

    def make():
        from ..models import n_link_pendulum

        return n_link_pendulum(n, links=links, inverted=inverted, pivot=pivot)

    state = "inverted" if inverted else "hanging"
    how = "vibrating pivot y = a cos(p t)" if pivot == "vertical" else "fixed pivot"
    return MechanicalModel(
        log,
        make,
        f"{n}-link pendulum ({links} links), {state}, {how}",
        dimension=_pendulum_dimension,
        excitation={"amplitude": "a", "frequency": "p"} if pivot == "vertical" else {},
        inverted=inverted,
        vibrating=pivot == "vertical",
    )


def _lagrangian(ctx: Ctx, opts: Mapping[str, Any], log: DerivationLog) -> MechanicalModel:
    from ..symbols import dot, t

    coords = ctx.require(opts, "coordinates", "system", '["x", "phi"]')
    if not isinstance(coords, list) or not coords or not all(isinstance(c, str) and c.isidentifier() for c in coords):
        raise ctx.error(
            "system.coordinates",
            f"expected a list of coordinate names, got {coords!r}",
            'write coordinates = ["x", "phi"]',
        )
    qs = [sp.Symbol(c, real=True) for c in coords]
    names: dict[str, Any] = {"t": t}
    for q in qs:
        names[q.name] = q
        names[f"{q.name}_dot"] = dot(q)
    functions = {"dot": dot}
    T = parse_sympy(ctx, ctx.require(opts, "T", "system", '"m*x_dot**2/2"'), "system.T", names, functions)
    V = parse_sympy(ctx, ctx.require(opts, "V", "system", '"k*x**2/2"'), "system.V", names, functions)
    R = parse_sympy(ctx, opts.get("R", 0), "system.R", names, functions)
    forces = opts.get("forces")
    Q = None
    if forces is not None:
        if not isinstance(forces, list) or len(forces) != len(qs):
            raise ctx.error(
                "system.forces",
                f"expected a list of {len(qs)} generalised forces (one per coordinate), got {forces!r}",
                f"write forces = {['0'] * len(qs)}",
            )
        Q = [parse_sympy(ctx, f, "system.forces", names, functions) for f in forces]
    from ..errors import ModelError
    from ..mechanics import LagrangianSystem

    try:  # build now, so that a T that is not quadratic in the velocities is reported against the file
        with log.step("build the Lagrangian system", "T, V (R, forces) parsed from the scene file"):
            system = LagrangianSystem(T, V, qs, dissipation=R, forces=Q)
    except ModelError as exc:
        raise ctx.error("system.T", str(exc), "check T, V, R and forces") from None
    vibrating = t in (T.free_symbols | V.free_symbols)
    model = MechanicalModel(log, lambda: system, f"Lagrangian system in {', '.join(coords)}", vibrating=vibrating)
    model.__dict__["system"] = system  # already built (and logged)

    def check_units(given: dict) -> None:
        by_name = {s.name: s for s in system.parameters}
        velocities = {dot(q): q for q in qs}
        check_lagrangian_units(T, V, R, Q, qs, velocities, t, {by_name[k]: v for k, v in given.items()})

    model.check_units = check_units
    return model


# ------------------------------------------------------------------------------------------------ body on springs
def _body_dimension(name: str) -> str:
    if name == "m":
        return "mass"
    if name.startswith("I"):
        return "moment of inertia"
    if name[0] in "kc":
        return "stiffness"
    return "length"  # rx, rz, Lx, Lz, x1.., z1..


class LinearOnlyModel:
    """A model known by its linear matrices only (no Lagrangian): natural frequencies, matrices, sweeps."""

    category = "linear"
    inverted = vibrating = False

    def __init__(self, log: DerivationLog, body: Any, describe: str) -> None:
        self.log, self._body, self.describe = log, body, describe
        self.excitation_symbols: dict = {}

    @cached_property
    def linear(self):
        from ..mechanics import LinearModel

        with self.log.step("M, K of the 3-DOF model", "vertical rows of the 6-DOF model (Belyakov 2005, eqs 23-26)"):
            n = self._body.M.shape[0]
            coords = tuple(sp.Symbol(c, real=True) for c in ("y", "theta_z", "theta_x"))
            return LinearModel(self._body.M, sp.zeros(n, n), self._body.K, sp.zeros(n, 1), coords)

    def parameter_names(self) -> list[str]:
        return [s.name for s in self._body.parameters]

    def dimension(self, name: str) -> str | None:
        return _body_dimension(name)

    def positive(self, name: str) -> bool:
        """Products of inertia and coordinates of the center of mass and of the springs may be negative."""
        return not (name in ("Ixy", "Ixz", "Iyz", "rx", "ry", "rz") or name[0] in "xz")


def _body_on_springs(ctx: Ctx, opts: Mapping[str, Any], log: DerivationLog) -> LinearOnlyModel:
    n = ctx.integer(opts.get("n_springs", 4), "system.n_springs", minimum=3)
    layout = opts.get("layout")
    if layout is not None:
        layout = ctx.choice(layout, "system.layout", ["rectangle", "general"])
    conv = ctx.choice(opts.get("product_of_inertia", "tensor"), "system.product_of_inertia", ["tensor", "dissertation"])
    from ..models import body_on_springs

    with log.step("build the body-on-springs model", f"{n} springs, product of inertia: {conv}"):
        body = body_on_springs(n, layout=layout, product_of_inertia=conv)
    return LinearOnlyModel(log, body, f"rigid body on {n} vertical springs (Belyakov 2005), 3-DOF linear model")


# ------------------------------------------------------------------------------------------------ other models
@dataclass
class SimpleModel:
    """A model without a mechanical derivation (Mathieu equation, weakly nonlinear oscillators, operator ODEs)."""

    category: str
    describe: str
    log: DerivationLog
    params: dict[str, str | None]  # valid parameter -> dimension
    required: tuple[str, ...] = ()
    data: dict | None = None
    excitation_symbols: dict | None = None

    def parameter_names(self) -> list[str]:
        return list(self.params)

    def dimension(self, name: str) -> str | None:
        return self.params.get(name)

    def positive(self, name: str) -> bool:
        return self.params.get(name) not in (None, "dimensionless")


def _mathieu(ctx: Ctx, opts: Mapping[str, Any], log: DerivationLog) -> SimpleModel:
    return SimpleModel("mathieu", "Mathieu equation y'' + (a - 2 q cos 2x) y = 0", log, {})


def _self_excited(f_text: str, describe: str):
    def build(ctx: Ctx, opts: Mapping[str, Any], log: DerivationLog) -> SimpleModel:
        x, v = sp.symbols("x v")
        text = opts.get("f", f_text)
        f = parse_sympy(ctx, text, "system.f", {"x": x, "v": v})
        extra = sorted(s.name for s in f.free_symbols - {x, v})
        if extra:
            raise ctx.error(
                "system.f",
                f"f may contain only x and v (numbers for everything else), found {', '.join(extra)}",
                "scale the parameters out (Bulgakov §8: x'' + x = eps f(x, x'))",
            )
        return SimpleModel(
            "weakly_nonlinear", describe.format(f=f), log, {"eps": "dimensionless"}, data={"f": f, "x": x, "v": v}
        )

    return build


def _duffing(ctx: Ctx, opts: Mapping[str, Any], log: DerivationLog) -> SimpleModel:
    params = {"w0": "angular frequency", "zeta": "dimensionless", "mu": None}
    return SimpleModel(
        "forced_oscillator",
        "Duffing oscillator x'' + 2 zeta w0 x' + w0^2 x + mu x^3 = R cos(nu t)",
        log,
        params,
        required=tuple(params),
        excitation_symbols={"amplitude": "R"},
    )


def _operator_ode(ctx: Ctx, opts: Mapping[str, Any], log: DerivationLog) -> SimpleModel:
    D = sp.Symbol("D")
    from ..symbols import t

    lhs = parse_sympy(ctx, ctx.require(opts, "operator", "system", '"D**2 + 3*D + 2"'), "system.operator", {"D": D})
    rhs = parse_sympy(ctx, opts.get("input_operator", 1), "system.input_operator", {"D": D})
    for key, e in (("system.operator", lhs), ("system.input_operator", rhs)):
        if not e.is_polynomial(D) or e.free_symbols - {D}:
            raise ctx.error(
                key, f"expected a polynomial in D with numeric coefficients, got {e}", 'write e.g. "D**2 + 3*D + 2"'
            )
    order = sp.degree(lhs, D)
    if order < 1:
        raise ctx.error(
            "system.operator", f"the operator {lhs} has no derivative (degree 0 in D)", 'write e.g. "D**2 + 3*D + 2"'
        )
    x = parse_sympy(ctx, opts.get("input", 1), "system.input", {"t": t})
    init = opts.get("initial", [0] * order)
    if (
        not isinstance(init, list)
        or len(init) != order
        or not all(isinstance(v, int | float) and not isinstance(v, bool) for v in init)
    ):
        raise ctx.error(
            "system.initial",
            f"expected {order} numbers y(0), y'(0), ... (the operator has degree {order}), got {init!r}",
            f"write initial = {[0] * order}",
        )
    return SimpleModel(
        "operator_ode",
        f"({lhs}) y = ({rhs}) x(t), x(t) = {x}, D = d/dt",
        log,
        {},
        data={"D": D, "lhs": lhs, "rhs": rhs, "input": x, "initial": [sp.nsimplify(v) for v in init]},
    )


@dataclass(frozen=True)
class ModelSpec:
    """A model name a scene may use: its options (name -> hint) and builder."""

    name: str
    summary: str
    options: dict
    build: Callable


MODELS: dict[str, ModelSpec] = {
    s.name: s
    for s in (
        ModelSpec(
            "n_link_pendulum",
            "planar N-link pendulum (Gribkov & Khokhlov 2015)",
            {
                "n": "integer >= 1",
                "links": '"point" or "rigid"',
                "inverted": "true/false",
                "pivot": '"fixed" or "vertical"',
            },
            _n_link_pendulum,
        ),
        ModelSpec(
            "lagrangian",
            "any holonomic system from T, V (R, forces) in SymPy syntax",
            {
                "coordinates": '["x", "phi"]',
                "T": '"m*x_dot**2/2"',
                "V": '"k*x**2/2"',
                "R": "Rayleigh function",
                "forces": "list, one per coordinate",
            },
            _lagrangian,
        ),
        ModelSpec(
            "body_on_springs",
            "rigid body on N vertical springs, 3-DOF (Belyakov 2005)",
            {
                "n_springs": "integer >= 3",
                "layout": '"rectangle" or "general"',
                "product_of_inertia": '"tensor" or "dissertation"',
            },
            _body_on_springs,
        ),
        ModelSpec("mathieu", "Mathieu equation y'' + (a - 2 q cos 2x) y = 0", {}, _mathieu),
        ModelSpec(
            "van_der_pol",
            "x'' + x = eps (1 - x^2) x' (Bulgakov 1954, §8)",
            {},
            _self_excited("(1 - x**2)*v", "van der Pol oscillator x'' + x = eps*({f})"),
        ),
        ModelSpec(
            "weakly_nonlinear",
            "x'' + x = eps f(x, x'), f in x and v",
            {"f": '"(1 - x**2)*v"'},
            _self_excited("", "x'' + x = eps*({f}), v = x'"),
        ),
        ModelSpec("duffing", "x'' + 2 zeta w0 x' + w0^2 x + mu x^3 = R cos(nu t)", {}, _duffing),
        ModelSpec(
            "operator_ode",
            "f(D) y = e(D) x(t), solved by the Carson transform (Bulgakov 1954, ch. 2)",
            {
                "operator": '"D**2 + 3*D + 2"',
                "input_operator": '"1"',
                "input": '"1" (a unit step)',
                "initial": "[y(0), y'(0), ...]",
            },
            _operator_ode,
        ),
    )
}


def build_model(ctx: Ctx, system: Mapping[str, Any], log: DerivationLog):
    """Validate ``[system]`` and return the lazy model."""
    from ._errors import closest

    name = system.get("model")
    if name is None:
        raise ctx.error("system", "missing required key 'model'", f"add model = one of {', '.join(MODELS)}")
    if not isinstance(name, str) or name not in MODELS:
        raise ctx.error(
            "system.model",
            f"unknown model {name!r}.{closest(str(name), MODELS)} Known models: {', '.join(MODELS)}",
            "use one of the catalogue's models",
        )
    spec = MODELS[name]
    ctx.check_keys(system, ["model", *spec.options], "system", "option")
    return spec.build(ctx, system, log)
