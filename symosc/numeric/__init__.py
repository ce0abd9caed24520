"""Compile SymPy expressions into fast numeric callables.

This subpackage is the only place in symosc that turns symbolic objects into numbers.  :func:`compile`
performs common-subexpression elimination, generates code (kept in ``.source``, which runs or compiles on its
own so it can be copied into other programs), and checks its arguments on every call.

Backends:

``"numpy"``
    Arguments may be scalars or arrays; they broadcast against each other.  For a matrix-valued
    expression of shape ``(r, c)`` the result has shape ``broadcast_shape + (r, c)`` (batch first, as
    ``numpy.linalg`` expects for stacks of matrices).  Real scalar arguments take a ``math``-module fast path.
``"mpmath"``
    Scalar arguments, evaluated in mpmath at the working precision ``dps`` given to :func:`compile`
    (or the current ``mpmath.mp.dps``).  Matrix results are ``mpmath.matrix``.
``"c"``
    C99 from SymPy's C printer, built with the system C compiler into a shared library cached on disk
    (see :func:`cache_dir`) and called through ctypes; array arguments are looped over in C.  Real values only.
``"llvm"``
    symengine's LLVM JIT (optional extra ``symosc[fast]``).  Real values only.
``"auto"``
    ``"c"`` when a compiler works, else ``"llvm"``, else ``"numpy"``; ``.backend`` says which was picked.

Division by zero and domain errors follow IEEE/NumPy semantics in every backend (``1/x`` at ``x = 0`` is
``inf``, ``sqrt(-1)`` is ``nan``); a *checked* call whose finite arguments give a non-finite result also emits a
``RuntimeWarning`` naming the function and the argument values.

Examples
--------
>>> import sympy as sp
>>> from symosc.numeric import compile
>>> g, l = sp.symbols("g l", positive=True)
>>> omega = compile(sp.sqrt(g / l), [g, l])
>>> float(omega(9.81, 9.81))
1.0
>>> omega([9.81, 39.24], 9.81).tolist()
[1.0, 2.0]
>>> omega(9.81, -1.0)
Traceback (most recent call last):
...
symosc.errors.ParameterError: l must be positive (declared positive), got -1.0
"""

from ._build import CompilerError, cache_dir
from ._core import CompiledFunction, available_backends, bind, compile, resolve

__all__ = ["CompiledFunction", "CompilerError", "available_backends", "bind", "cache_dir", "compile", "resolve"]
