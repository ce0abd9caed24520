"""The examples of docs/algebra.md are run as doctests, with the imports the page states at its top."""

import doctest
import pathlib
import re

import numpy as np
import sympy as sp

import symosc.algebra as algebra

DOC = pathlib.Path(__file__).resolve().parents[2] / "docs" / "algebra.md"


def test_user_guide_examples():
    text = re.sub(r"^```.*$", "", DOC.read_text(), flags=re.M)
    x, t, l = sp.symbols("x t l")
    globs = {"sp": sp, "np": np, "x": x, "t": t, "l": l, **{k: getattr(algebra, k) for k in algebra.__all__}}
    test = doctest.DocTestParser().get_doctest(text, globs, "algebra.md", str(DOC), 0)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    runner.run(test)
    assert runner.failures == 0 and runner.tries > 40
