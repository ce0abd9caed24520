"""Export symbolic models as source code in other languages.

:func:`export` writes a system's mass matrix, forcing, right-hand side (with ``M q'' = F`` solved inside) and
analytic Jacobian -- or plain expressions -- as a self-contained C (with a header), Python (NumPy), Julia,
Fortran 95 or Octave/MATLAB file.  The expressions are CSE'd and printed by SymPy's code printers.
"""

from ._export import LANGUAGES, export

__all__ = ["LANGUAGES", "export"]
