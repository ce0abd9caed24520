"""Canonical transformations from generating functions (Bulgakov (1954), §3.13-3.14)."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import sympy as sp

from ..._printing import SymPyPrintable
from ..._validate import validated
from ...errors import ModelError
from ...symbols import t
from .hamiltonian import poisson_bracket

__all__ = ["CanonicalTransformation", "canonical_transformation", "is_canonical"]


@validated
def is_canonical(
    new_coordinates: Sequence[Any],
    new_momenta: Sequence[Any],
    coordinates: Sequence[sp.Symbol],
    momenta: Sequence[sp.Symbol],
) -> bool:
    """True when ``(Q(q, p, t), P(q, p, t))`` is canonical: ``{Q_i, Q_j} = {P_i, P_j} = 0``, ``{Q_i, P_j} = delta_ij``.

    Goldstein, Classical Mechanics, §9.5 (the fundamental Poisson brackets; equivalently a symplectic Jacobian).
    Each bracket is simplified with SymPy; a bracket SymPy cannot reduce counts as "not canonical".

    Parameters
    ----------
    new_coordinates : sequence of SymPy expressions
        The new coordinates ``Q_i(q, p, t)``, one per old coordinate.
    new_momenta : sequence of SymPy expressions
        The new momenta ``P_i(q, p, t)``, one per old coordinate.
    coordinates : sequence of Symbol
        The old canonical coordinates ``q``.
    momenta : sequence of Symbol
        The old momenta ``p``, which must be as many as the coordinates.

    Examples
    --------
    >>> import sympy as sp
    >>> q, p = sp.symbols("q p", positive=True)
    >>> is_canonical([sp.atan(q / p)], [(p**2 + q**2) / 2], [q], [p])
    True
    >>> is_canonical([q], [2 * p], [q], [p])
    False

    See Also
    --------
    canonical_transformation, poisson_bracket
    """
    Q = [sp.sympify(e) for e in new_coordinates]
    P = [sp.sympify(e) for e in new_momenta]
    n = len(coordinates)
    if not (len(Q) == len(P) == n == len(momenta)):
        raise ModelError(
            f"is_canonical needs as many new coordinates ({len(Q)}), new momenta ({len(P)}), coordinates ({n}) "
            f"and momenta ({len(momenta)})"
        )
    for i in range(n):
        for j in range(n):
            if j > i:
                for a, b in ((Q[i], Q[j]), (P[i], P[j])):
                    if sp.simplify(poisson_bracket(a, b, coordinates, momenta)) != 0:
                        return False
            if sp.simplify(poisson_bracket(Q[i], P[j], coordinates, momenta) - (1 if i == j else 0)) != 0:
                return False
    return True


@dataclass(frozen=True)
class CanonicalTransformation(SymPyPrintable):
    """A canonical transformation ``(q, p) -> (u, v)`` defined by a generating function.

    Attributes
    ----------
    generating_function : Expr
        The generating function ``S``.
    kind : int
        1: ``S(q, u, t)``; 2: ``S(q, v, t)``; 3: ``S(p, u, t)``; 4: ``S(p, v, t)``.
    coordinates, momenta : tuple of Symbol
        The old canonical variables ``q``, ``p``.
    new_coordinates, new_momenta : tuple of Symbol
        The new canonical variables ``u``, ``v``.
    relations : tuple of Eq
        The defining equations (Bulgakov (1954), eqs. (3.135)-(3.139)).
    forward : dict
        New variables in terms of ``(q, p, t)`` (empty when SymPy cannot solve the relations).
    backward : dict
        Old variables in terms of ``(u, v, t)`` (empty when SymPy cannot solve the relations).
    hamiltonian_shift : Expr
        ``dS/dt``: the new Hamiltonian is ``H' = H + dS/dt`` (eq. (3.136)).

    Examples
    --------
    >>> import sympy as sp
    >>> q, p, u, v = sp.symbols("q p u v", real=True)
    >>> canonical_transformation(q * u, [q], [p], [u], [v], kind=1).forward
    {u: p, v: -q}

    See Also
    --------
    canonical_transformation, is_canonical
    """

    generating_function: sp.Expr
    kind: int
    coordinates: tuple[sp.Symbol, ...]
    momenta: tuple[sp.Symbol, ...]
    new_coordinates: tuple[sp.Symbol, ...]
    new_momenta: tuple[sp.Symbol, ...]
    relations: tuple[sp.Eq, ...]
    forward: dict
    backward: dict
    hamiltonian_shift: sp.Expr

    def __repr__(self) -> str:
        return f"CanonicalTransformation(kind {self.kind}, S = {self.generating_function})"

    def _repr_latex_(self) -> str:
        return "$$" + r",\quad ".join(sp.latex(r) for r in self.relations) + "$$"

    def new_hamiltonian(self, H: Any) -> sp.Expr:
        """``H' = H(q(u, v), p(u, v), t) + dS/dt`` in the new variables.

        Parameters
        ----------
        H : SymPy expression
            The old Hamiltonian ``H(q, p, t)``.
        """
        if not self.backward:
            raise ModelError("the relations could not be solved for (q, p): express H in (u, v) by hand")
        return sp.sympify(H).xreplace(self.backward) + self.hamiltonian_shift.xreplace(self.backward)

    def is_canonical(self) -> bool:
        """Check the solved forward map with Poisson brackets."""
        if not self.forward:
            raise ModelError("the relations could not be solved for (u, v)")
        return is_canonical(
            [self.forward[u] for u in self.new_coordinates],
            [self.forward[v] for v in self.new_momenta],
            self.coordinates,
            self.momenta,
        )


def _solve(eqs: list[sp.Expr], unknowns: list[sp.Symbol], branch: int) -> dict | None:
    try:
        sols = sp.solve(eqs, unknowns, dict=True)
    except (NotImplementedError, ValueError):
        return None
    sols = [s for s in sols if all(u in s for u in unknowns)]
    if not sols:
        return None
    return sols[min(branch, len(sols) - 1)]


@validated
def canonical_transformation(
    S: Any,
    coordinates: Sequence[sp.Symbol],
    momenta: Sequence[sp.Symbol],
    new_coordinates: Sequence[sp.Symbol],
    new_momenta: Sequence[sp.Symbol],
    *,
    kind: int,
    branch: int = 0,
    solve: bool = True,
) -> CanonicalTransformation:
    """The canonical transformation generated by ``S`` (Bulgakov (1954), §3.14; Goldstein, §9.1).

    ===== ============ ======================================
    kind  S depends on relations
    ===== ============ ======================================
    1     q, u, t      p = dS/dq,  v = -dS/du
    2     q, v, t      p = dS/dq,  u = dS/dv
    3     p, u, t      q = -dS/dp, v = -dS/du
    4     p, v, t      q = -dS/dp, u = dS/dv
    ===== ============ ======================================

    In every case ``H' = H + dS/dt``.  The mixed second derivatives of S must form a non-singular matrix,
    otherwise :class:`ModelError` is raised (S then generates no transformation).

    Parameters
    ----------
    S : SymPy expression
        The generating function, depending only on the old and new variables its ``kind`` allows (and on ``t``
        and parameters).
    coordinates : sequence of Symbol
        The old coordinates ``q``.
    momenta : sequence of Symbol
        The old momenta ``p``, as many as the coordinates.
    new_coordinates : sequence of Symbol
        The new coordinates ``u``, as many as the coordinates.
    new_momenta : sequence of Symbol
        The new momenta ``v``, as many as the coordinates.
    kind : int
        Kind of the generating function, which must be 1, 2, 3 or 4 (the table above).
    branch : int, optional
        Index (>= 0) of the solution of the relations to keep when SymPy finds several; an index past the last
        takes the last (default 0).
    solve : bool, optional
        Whether to solve the relations for ``forward`` and ``backward`` (default True); False keeps only the
        relations (``forward``/``backward`` empty), which avoids SymPy's ``solve`` on large systems.

    Examples
    --------
    The harmonic oscillator's action-angle variables (Goldstein, Classical Mechanics, §9.3):
    ``S = (w q^2 / 2) cot u``.

    >>> import sympy as sp
    >>> q, p, u, v = sp.symbols("q p u v", positive=True)
    >>> w = sp.Symbol("omega", positive=True)
    >>> ct = canonical_transformation(w * q**2 / 2 * sp.cot(u), [q], [p], [u], [v], kind=1)
    >>> ct.relations[0]
    Eq(p, omega*q*cot(u))
    >>> ct.forward
    {u: acot(p/(omega*q)), v: (omega**2*q**2 + p**2)/(2*omega)}
    >>> ct.is_canonical()
    True
    >>> sp.simplify(ct.new_hamiltonian((p**2 + w**2 * q**2) / 2))
    omega*v

    See Also
    --------
    is_canonical, HamiltonianSystem
    """
    if kind not in (1, 2, 3, 4):
        raise ModelError(f"kind must be 1, 2, 3 or 4, got {kind!r}")
    S = sp.sympify(S)
    q, p, u, v = (tuple(x) for x in (coordinates, momenta, new_coordinates, new_momenta))
    n = len(q)
    if not (len(p) == len(u) == len(v) == n):
        raise ModelError("coordinates, momenta, new_coordinates and new_momenta must have the same length")
    old = q if kind in (1, 2) else p  # the old variables S depends on
    new = u if kind in (1, 3) else v  # the new variables S depends on
    forbidden = (set(q) | set(p) | set(u) | set(v)) - set(old) - set(new)
    bad = S.free_symbols & forbidden
    if bad:
        raise ModelError(
            f"a generating function of kind {kind} depends on "
            f"{'q' if kind in (1, 2) else 'p'} and {'u' if kind in (1, 3) else 'v'} only; "
            f"S contains {sorted(map(str, bad))}"
        )
    hess = sp.Matrix(n, n, lambda i, j: S.diff(old[i], new[j]))
    if sp.simplify(hess.det()) == 0:
        raise ModelError(
            "the mixed Hessian d^2 S / d(old) d(new) of the generating function is singular: S does not generate "
            "a canonical transformation (the relations cannot be solved for the variables)"
        )
    s_old = 1 if kind in (1, 2) else -1  # p = dS/dq (kinds 1, 2) or q = -dS/dp (kinds 3, 4)
    s_new = -1 if kind in (1, 3) else 1  # v = -dS/du (kinds 1, 3) or u = dS/dv (kinds 2, 4)
    partner_old = p if kind in (1, 2) else q  # given by dS/d(old)
    partner_new = v if kind in (1, 3) else u  # given by dS/d(new)
    rel_old = [s_old * S.diff(x) for x in old]
    rel_new = [s_new * S.diff(x) for x in new]
    relations = tuple(sp.Eq(a, b) for a, b in zip(partner_old, rel_old, strict=True)) + tuple(
        sp.Eq(a, b) for a, b in zip(partner_new, rel_new, strict=True)
    )
    forward: dict = {}
    sol = None if not solve else _solve([a - b for a, b in zip(partner_old, rel_old, strict=True)], list(new), branch)
    if sol is not None:
        forward = {x: sol[x] for x in new}
        for a, b in zip(partner_new, rel_new, strict=True):
            forward[a] = sp.simplify(b.xreplace(sol))
    backward: dict = {}
    sol = None if not solve else _solve([a - b for a, b in zip(partner_new, rel_new, strict=True)], list(old), branch)
    if sol is not None:
        backward = {x: sol[x] for x in old}
        for a, b in zip(partner_old, rel_old, strict=True):
            backward[a] = sp.simplify(b.xreplace(sol))
    return CanonicalTransformation(
        generating_function=S,
        kind=kind,
        coordinates=q,
        momenta=p,
        new_coordinates=u,
        new_momenta=v,
        relations=relations,
        forward=forward,
        backward=backward,
        hamiltonian_shift=S.diff(t),
    )
