"""SPICE-like netlists: R, L, C, coupled inductors, independent sources and port terminals, read without evaluation.

A netlist is text a user may have received from someone else, so nothing in it is evaluated: each line is split
into whitespace-separated tokens and every token is checked against a small explicit grammar (element and node
names are ASCII identifiers, values are numbers with SPICE's scale suffixes or parameter names).  No ``eval``,
``sympify`` or ``parse_expr`` ever sees the text; sizes are bounded (characters, lines, digits, exponents).

Grammar (one element per line, case-insensitive keywords, ``*`` comment lines, ``;`` inline comments, ``+``
continuation lines)::

    R<name> <node> <node> <value>          resistor            (ohm)
    L<name> <node> <node> <value>          inductor            (henry)
    C<name> <node> <node> <value>          capacitor           (farad)
    K<name> L<name> L<name> <value>        coupling 0 < k <= 1 of two inductors (M = k sqrt(L1 L2))
    V<name> <node+> <node-> [DC|AC] <value>   independent voltage source (Laplace image of its voltage)
    I<name> <node+> <node-> [DC|AC] <value>   independent current source (flows from node+ to node- inside)
    P<name> <node+> <node->                two-port terminal pair: the first P line is the input, the second
                                           the output (lcapy's convention)
    .param <name>=<value> ...              numeric values for parameter names
    .title <text>     .end

Values: ``[+-]digits[.digits][e[+-]digits]`` with an optional scale suffix ``T G MEG K M(milli) U µ N P F(femto)
MIL`` and optional unit letters that are ignored (``10uF``, ``4.7k``, ``1meg``; as in SPICE, ``1F`` is a femtofarad),
or a parameter name (an identifier, optionally in braces: ``{Rload}``), which becomes a positive SymPy symbol.
Nodes ``0``, ``gnd`` and ``GND`` are the ground.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any

import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError, ParameterError
from .._util import P
from ._nodal import Netlist, admittance_matrix, chain_from_netlist
from .fourpoles import FourPole

__all__ = ["Circuit", "CircuitElement", "parse_netlist"]

#: limits on what a netlist may contain (beyond them: ParameterError, before any work is done)
MAX_CHARACTERS = 1_000_000
MAX_LINES = 20_000
MAX_LINE_LENGTH = 4096
MAX_ELEMENTS = 2_000
MAX_NAME_LENGTH = 64
MAX_DIGITS = 60
MAX_EXPONENT = 300

_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*\Z")
_NODE = re.compile(r"[A-Za-z0-9_]+\Z")
_PARAMETER = re.compile(r"\{?([A-Za-z][A-Za-z0-9_]*)\}?\Z")
_NUMBER = re.compile(
    r"(?P<sign>[+-]?)(?P<mantissa>\d+\.?\d*|\.\d+)(?:[eE](?P<exponent>[+-]?\d+))?"
    r"(?P<suffix>meg|mil|[tgkmunpfµ])?(?P<unit>[a-zΩµ]*)\Z",
    re.IGNORECASE | re.ASCII,
)
_SCALE = {
    "t": sp.Integer(10) ** 12,
    "g": sp.Integer(10) ** 9,
    "meg": sp.Integer(10) ** 6,
    "k": sp.Integer(10) ** 3,
    "m": sp.Rational(1, 10**3),
    "u": sp.Rational(1, 10**6),
    "µ": sp.Rational(1, 10**6),
    "n": sp.Rational(1, 10**9),
    "p": sp.Rational(1, 10**12),
    "f": sp.Rational(1, 10**15),
    "mil": sp.Rational(254, 10**7),
}
_GROUND = {"0", "gnd"}
_KINDS = {"R": 4, "L": 4, "C": 4, "K": 4, "V": (4, 5), "I": (4, 5), "P": 3}


@dataclass(frozen=True)
class CircuitElement(SymPyPrintable):
    """One line of a netlist.

    Attributes
    ----------
    name : str
        The element name as written (``R1``, ``Vin``, ``P2``).
    kind : str
        ``"R"``, ``"L"``, ``"C"``, ``"K"``, ``"V"``, ``"I"`` or ``"P"``.
    nodes : tuple of str
        The two nodes (ground is ``"0"``); for ``K`` the names of the two coupled inductors.
    value : Expr
        The value (exact ``Rational`` or a positive ``Symbol``); ``None`` for a port.
    """

    name: str
    kind: str
    nodes: tuple
    value: Any = None

    def __repr__(self) -> str:
        value = "" if self.value is None else f" {self.value}"
        return f"{self.name} {' '.join(self.nodes)}{value}"


@dataclass(frozen=True)
class Circuit(SymPyPrintable):
    """A network read from a netlist (:func:`parse_netlist`): its elements, sources and ports.

    Attributes
    ----------
    elements : tuple of CircuitElement
        Every element in netlist order.
    title : str
        The ``.title`` (empty when there is none).
    parameters : dict
        The ``.param`` values (name -> exact number), already substituted into the element values.
    p : Symbol
        The operator variable of the impedances (``p = i omega`` in the steady state).
    """

    elements: tuple
    title: str = ""
    parameters: dict = field(default_factory=dict)
    p: sp.Symbol = P

    def __repr__(self) -> str:
        kinds = {}
        for e in self.elements:
            kinds[e.kind] = kinds.get(e.kind, 0) + 1
        counts = ", ".join(f"{n} {k}" for k, n in kinds.items())
        title = f"{self.title!r}: " if self.title else ""
        return f"Circuit({title}{counts}; nodes {', '.join(self.nodes)})"

    @property
    def ports(self) -> tuple[CircuitElement, ...]:
        """The port terminal pairs (``P`` lines) in netlist order."""
        return tuple(e for e in self.elements if e.kind == "P")

    @property
    def nodes(self) -> tuple[str, ...]:
        """Every node, ground (``"0"``) first when present."""
        seen: dict[str, None] = {}
        for e in self.elements:
            if e.kind != "K":
                for n in e.nodes:
                    seen.setdefault(n, None)
        return tuple(sorted(seen, key=lambda n: (n != "0", list(seen).index(n))))

    def _netlist(self, terminals: tuple, short_sources: bool = True) -> Netlist:
        """The passive branches; with ``short_sources`` the sources are zeroed (voltage sources shorted, current
        sources open)."""
        merge = _shorted_nodes(self.elements, {frozenset(e.nodes) for e in self.ports}) if short_sources else {}
        node = lambda n: merge.get(n, n)  # noqa: E731
        p = self.p
        inductors = {e.name.upper(): e for e in self.elements if e.kind == "L"}
        coupled: dict[str, tuple] = {}
        for e in self.elements:
            if e.kind == "K":
                a, b = (inductors[n.upper()] for n in e.nodes)
                if e.value == 1:
                    raise ModelError(
                        f"{e.name}: perfectly coupled inductors (k = 1) have no branch admittance, which nodal "
                        "analysis needs; use k < 1, or an ideal transformer section (symosc.networks.transformer)"
                    )
                if a.name in coupled or b.name in coupled:
                    raise ModelError(f"{e.name}: an inductor coupled twice is not supported ({a.name}, {b.name})")
                M = e.value * sp.sqrt(a.value * b.value)
                branch = (
                    ((node(a.nodes[0]), node(a.nodes[1])), (node(b.nodes[0]), node(b.nodes[1]))),
                    sp.Matrix([[p * a.value, p * M], [p * M, p * b.value]]),
                )
                coupled[a.name] = coupled[b.name] = branch
        branches = []
        for e in self.elements:
            if e.kind in ("R", "L", "C") and e.name not in coupled:
                Z = {"R": e.value, "L": p * e.value, "C": 1 / (p * e.value)}[e.kind]
                branches.append((((node(e.nodes[0]), node(e.nodes[1])),), sp.Matrix([[Z]])))
        branches += list({id(b): b for b in coupled.values()}.values())
        return Netlist(tuple(branches), tuple(node(n) for n in terminals))

    def four_pole(self) -> FourPole:
        """The four-pole between the first port (input) and the second (output), sources set to zero.

        Independent sources are zeroed (voltage sources shorted, current sources opened), except a voltage source
        across a port's own terminals, which drives that port and is removed.

        Examples
        --------
        >>> from symosc.networks import parse_netlist
        >>> circuit = parse_netlist('''
        ... * L section: series inductor, shunt capacitor
        ... P1 in 0
        ... L1 in out 10m
        ... C1 out 0 1u
        ... P2 out 0
        ... ''')
        >>> circuit.four_pole().chain
        Matrix([
        [p**2/100000000 + 1, p/100],
        [         p/1000000,     1]])

        See Also
        --------
        impedance, symosc.networks.FourPole
        """
        ports = self.ports
        if len(ports) != 2:
            raise ModelError(f"a four-pole needs two ports (P lines); the netlist has {len(ports)}")
        net = self._netlist((*ports[0].nodes, *ports[1].nodes))
        chain = chain_from_netlist(net)
        return FourPole(chain, self.p, net, name=self.title or "netlist")

    def impedance(self, port: int | str = 0) -> sp.Expr:
        """Driving-point impedance ``Z(p)`` at a port (the others open, sources set to zero as in :meth:`four_pole`).

        Parameters
        ----------
        port : int or str
            Index of the port among the ``P`` lines, or its name.
        """
        ports = self.ports
        if not ports:
            raise ModelError("the netlist has no port (P line)")
        names = [e.name.upper() for e in ports]
        idx = names.index(port.upper()) if isinstance(port, str) and port.upper() in names else port
        if not isinstance(idx, int) or not 0 <= idx < len(ports):
            raise ParameterError(f"port must be an index below {len(ports)} or one of {names}, got {port!r}")
        plus, minus = ports[idx].nodes
        net = self._netlist((plus, minus, plus, minus))
        if net.terminals[0] == net.terminals[1]:
            raise ModelError(f"port {ports[idx].name} is shorted by a voltage source (set to zero for the impedance)")
        nodes, Y = admittance_matrix(net)
        index = {n: i for i, n in enumerate(nodes)}
        a, b = index[net.terminals[0]], index[net.terminals[1]]
        keep = [i for i in range(len(nodes)) if i != b]  # the port's minus terminal is the reference
        rhs = sp.zeros(len(nodes), 1)
        rhs[a] = 1
        try:
            V = Y.extract(keep, keep).LUsolve(rhs.extract(keep, [0]))
        except (ValueError, ZeroDivisionError) as exc:
            raise ModelError("the network seen from the port has floating parts (a singular nodal matrix)") from exc
        return sp.cancel(V[keep.index(a)])

    def node_voltages(self) -> dict[str, sp.Expr]:
        """Node voltages ``V(p)`` (Laplace images, ground = 0) driven by the independent sources, by modified
        nodal analysis; ports are open."""
        nodes = [n for n in self.nodes if n != "0"]
        index = {n: i for i, n in enumerate(nodes)}
        order, Ybr = admittance_matrix(self._netlist((), short_sources=False))
        Y = sp.zeros(len(nodes), len(nodes))
        for i, ni in enumerate(order):
            for j, nj in enumerate(order):
                if ni in index and nj in index:
                    Y[index[ni], index[nj]] += Ybr[i, j]
        vsrc = [e for e in self.elements if e.kind == "V"]
        A = sp.zeros(len(nodes) + len(vsrc), len(nodes) + len(vsrc))
        A[: len(nodes), : len(nodes)] = Y
        rhs = sp.zeros(len(nodes) + len(vsrc), 1)
        for e in self.elements:
            if e.kind == "I":  # current e.value from node+ to node- through the source: leaves node+
                for n, sign in zip(e.nodes, (-1, 1), strict=True):
                    if n in index:
                        rhs[index[n]] += sign * e.value
        for k, e in enumerate(vsrc):
            row = len(nodes) + k
            for n, sign in zip(e.nodes, (1, -1), strict=True):
                if n in index:
                    A[row, index[n]] = sign
                    A[index[n], row] = sign
            rhs[row] = e.value
        try:
            x = A.LUsolve(rhs)
        except (ValueError, ZeroDivisionError) as exc:
            raise ModelError("the circuit has floating parts or a loop of voltage sources (singular MNA)") from exc
        return {"0": sp.S.Zero, **{n: sp.cancel(x[i]) for n, i in index.items()}}


def _shorted_nodes(elements: tuple, ports: set) -> dict[str, str]:
    """Node merges of the voltage sources (shorted when the sources are set to zero); a source across a port's
    terminals is the port's drive and is removed instead."""
    parent: dict[str, str] = {}

    def find(n: str) -> str:
        while parent.get(n, n) != n:
            n = parent[n]
        return n

    for e in elements:
        if e.kind == "V" and frozenset(e.nodes) not in ports:
            a, b = find(e.nodes[0]), find(e.nodes[1])
            if a != b:
                keep, drop = (a, b) if a == "0" or b != "0" else (b, a)
                parent[drop] = keep
    return {n: find(n) for n in parent}


def _value(token: str, where: str, params: dict, p: sp.Symbol) -> sp.Expr:
    """A value token: number with scale suffix (exact) or a parameter name (a positive Symbol)."""
    m = _NUMBER.match(token)
    if m:
        mantissa = m["mantissa"]
        if len(mantissa.replace(".", "")) > MAX_DIGITS:
            raise ParameterError(f"{where}: {token[:40]!r}... has more than {MAX_DIGITS} digits")
        exponent = int(m["exponent"] or 0) if len(m["exponent"] or "") <= 6 else MAX_EXPONENT + 1
        if abs(exponent) > MAX_EXPONENT:
            raise ParameterError(f"{where}: the exponent of {token[:40]!r} is beyond +-{MAX_EXPONENT}")
        value = sp.Rational(mantissa) * sp.Integer(10) ** exponent
        if m["suffix"]:
            value *= _SCALE[m["suffix"].lower()]
        return -value if m["sign"] == "-" else value
    m = _PARAMETER.match(token)
    if m and (token.startswith("{") == token.endswith("}")):
        name = m[1]
        if len(name) > MAX_NAME_LENGTH:
            raise ParameterError(f"{where}: parameter name longer than {MAX_NAME_LENGTH} characters")
        if name in params:
            return params[name]
        if name == p.name:
            raise ParameterError(f"{where}: {name!r} is the operator variable; choose another parameter name")
        return sp.Symbol(name, positive=True)
    raise ParameterError(
        f"{where}: {token[:40]!r} is neither a number (digits, optional exponent and scale suffix such as 4.7k, "
        "10u, 1meg) nor a parameter name (an identifier)"
    )


def _logical_lines(text: str) -> list[tuple[int, str]]:
    lines: list[tuple[int, str]] = []
    raw = text.replace("\r\n", "\n").replace("\r", "\n").split("\n")
    if len(raw) > MAX_LINES:
        raise ParameterError(f"text: the netlist has more than {MAX_LINES} lines")
    for number, line in enumerate(raw, start=1):
        line = line.split(";", 1)[0].strip()
        if not line or line.startswith("*"):
            continue
        if line.startswith("+"):
            if not lines:
                raise ParameterError(f"text, line {number}: a continuation line ('+') with nothing to continue")
            first, prev = lines[-1]
            line = prev + " " + line[1:].strip()
            lines[-1] = (first, line)
        else:
            lines.append((number, line))
        if len(lines[-1][1]) > MAX_LINE_LENGTH:
            raise ParameterError(f"text, line {lines[-1][0]}: longer than {MAX_LINE_LENGTH} characters")
    return lines


def _parameters(tokens: list[str], where: str, params: dict, p: sp.Symbol) -> None:
    joined = " ".join(tokens).replace(" =", "=").replace("= ", "=")
    for item in joined.split():
        name, sep, value = item.partition("=")
        if not sep or not _NAME.match(name) or len(name) > MAX_NAME_LENGTH:
            raise ParameterError(f"{where}: .param takes name=value pairs, got {item[:40]!r}")
        v = _value(value, where, params, p)
        if v.free_symbols:
            raise ParameterError(f"{where}: .param {name} must be a number, got {value[:40]!r}")
        params[name] = v


@validated
def parse_netlist(text: str, *, p: sp.Symbol = P) -> Circuit:
    """Read a SPICE-like netlist (R, L, C, K, V, I, P lines) into a :class:`Circuit`, evaluating nothing.

    Parameters
    ----------
    text : str
        The netlist (the grammar is in :mod:`symosc.networks.ports.netlist`): one element per line, ``*`` comments,
        ``;`` inline comments, ``+`` continuations, ``.param name=value``, ``.title``, ``.end``.
    p : Symbol
        The operator variable of the impedances (``p = i omega``).

    Returns
    -------
    Circuit
        Elements with exact values (``10k`` is ``10000``, ``4.7u`` is ``47/10000000``); names in values become
        positive symbols.

    Raises
    ------
    ParameterError
        A token outside the grammar (named with its line), an unsupported element or directive (subcircuits,
        includes, controlled sources, semiconductors), a repeated element name, a non-positive R, L, C or a
        coupling outside ``(0, 1]``, a netlist beyond the size limits.

    Examples
    --------
    >>> circuit = parse_netlist('''
    ... .title RC low-pass
    ... V1 in 0 AC 1
    ... R1 in out 1k
    ... C1 out 0 {C}
    ... ''')
    >>> circuit.node_voltages()["out"]
    1/(1000*C*p + 1)

    See Also
    --------
    Circuit.four_pole, Circuit.impedance, FourPole
    """
    if not isinstance(text, str):
        raise ParameterError(f"text must be the netlist as a string, got {type(text).__name__}")
    if len(text) > MAX_CHARACTERS:
        raise ParameterError(f"text: the netlist is longer than {MAX_CHARACTERS} characters")
    if not isinstance(p, sp.Symbol):
        raise ParameterError(f"p must be a SymPy Symbol, got {type(p).__name__}")
    params: dict[str, sp.Expr] = {}
    elements: list[CircuitElement] = []
    names: set[str] = set()
    title = ""
    for number, line in _logical_lines(text):
        where = f"text, line {number}"
        tokens = line.split()
        head = tokens[0]
        if head.startswith("."):
            directive = head.lower()
            if directive == ".end":
                break
            if directive == ".title":
                title = " ".join(tokens[1:])[:200]
            elif directive == ".param":
                _parameters(tokens[1:], where, params, p)
            else:
                raise ParameterError(
                    f"{where}: the directive {head[:20]!r} is not supported (only .title, .param and .end; "
                    "subcircuits, includes and analyses are not read)"
                )
            continue
        elements.append(_element(tokens, where, params, p, names))
        if len(elements) > MAX_ELEMENTS:
            raise ParameterError(f"text: the netlist has more than {MAX_ELEMENTS} elements")
    _check_couplings(elements)
    return Circuit(tuple(elements), title, dict(params), p)


def _element(tokens: list[str], where: str, params: dict, p: sp.Symbol, names: set) -> CircuitElement:
    name = tokens[0]
    if not _NAME.match(name) or len(name) > MAX_NAME_LENGTH:
        raise ParameterError(f"{where}: {name[:40]!r} is not an element name (a letter, then letters, digits, _)")
    kind = name[0].upper()
    if kind not in _KINDS:
        raise ParameterError(
            f"{where}: element {name!r}: only R, L, C, K (coupling), V, I (independent sources) and P (ports) "
            "are supported"
        )
    if name.upper() in names:
        raise ParameterError(f"{where}: the element name {name!r} is used twice")
    names.add(name.upper())
    counts = _KINDS[kind] if isinstance(_KINDS[kind], tuple) else (_KINDS[kind],)
    if len(tokens) not in counts:
        raise ParameterError(f"{where}: {name} takes {' or '.join(map(str, counts))} fields, got {len(tokens)}")
    if kind == "K":
        coils = tuple(tokens[1:3])
        for c in coils:
            if not _NAME.match(c) or c[0].upper() != "L":
                raise ParameterError(f"{where}: {name} couples two inductors (L names), got {c[:40]!r}")
        k = _value(tokens[3], where, params, p)
        if k.is_number and not 0 < k <= 1:
            raise ParameterError(f"{where}: the coupling {name} must lie in (0, 1], got {k}")
        return CircuitElement(name, kind, coils, k)
    nodes = []
    for n in tokens[1:3]:
        if not _NODE.match(n) or len(n) > MAX_NAME_LENGTH:
            raise ParameterError(f"{where}: {n[:40]!r} is not a node name (letters, digits, _)")
        nodes.append("0" if n.lower() in _GROUND else n)
    if kind == "P":
        return CircuitElement(name, kind, tuple(nodes))
    fields = tokens[3:]
    if kind in ("V", "I") and len(fields) == 2:
        if fields[0].upper() not in ("DC", "AC"):
            raise ParameterError(f"{where}: {name}: expected DC or AC before the value, got {fields[0][:20]!r}")
        fields = fields[1:]
    value = _value(fields[0], where, params, p)
    if kind in ("R", "L", "C") and value.is_number and not value > 0:
        raise ParameterError(f"{where}: {name} must be positive, got {value}")
    if kind in ("R", "L", "C") and nodes[0] == nodes[1]:
        raise ParameterError(f"{where}: {name} connects node {nodes[0]} to itself")
    return CircuitElement(name, kind, tuple(nodes), value)


def _check_couplings(elements: list[CircuitElement]) -> None:
    inductors = {e.name.upper() for e in elements if e.kind == "L"}
    for e in elements:
        if e.kind == "K":
            missing = [c for c in e.nodes if c.upper() not in inductors]
            if missing:
                raise ParameterError(f"text: {e.name} couples {missing}, which are not inductors of the netlist")
            if e.nodes[0].upper() == e.nodes[1].upper():
                raise ParameterError(f"text: {e.name} couples an inductor with itself")
