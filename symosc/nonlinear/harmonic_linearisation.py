"""The old import path of :mod:`symosc.nonlinear.harmonic_linearization` (the same module object).

Kept from before the project settled on American spelling; the module's British-spelled names warn once.
"""

import importlib
import sys

sys.modules[__name__] = importlib.import_module("symosc.nonlinear.harmonic_linearization")
