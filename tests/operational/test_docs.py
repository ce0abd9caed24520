"""The examples of docs/operational.md are run as doctests (they must stay correct)."""

import doctest
import pathlib
import re

DOC = pathlib.Path(__file__).resolve().parents[2] / "docs" / "operational.md"


def test_user_guide_examples():
    text = re.sub(r"^```.*$", "", DOC.read_text(), flags=re.M)
    parser = doctest.DocTestParser()
    test = parser.get_doctest(text, {}, "operational.md", str(DOC), 0)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
    runner.run(test)
    assert runner.failures == 0 and runner.tries > 20
