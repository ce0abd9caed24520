"""Bad-input walk over the whole public API: only symosc errors (or results) may come out, nothing hangs.

The walk (``tests/edges/_api_walk.py``) discovers every function and class in the ``__all__`` of symosc and of
every subpackage at run time, so subpackages added later are covered.  Each required argument gets one of None,
nan, inf, -1, 0, "abc", 1.5 and a 1x3 array (all the same first, then three fixed mixtures); a call with only nan
(or only inf) arguments must not return a result; each call has a 20 s SIGALRM cap and every pass runs in a
subprocess with an overall cap.  Every symosc error a function call provokes must also be explicit: its message
names an argument of the function and states an expectation (what the argument must be, or what to do), and the
expectation is more than a pointer to ``help()``.  The constructors of the public classes, the command line (exit
code 1 or 2, one error line, never a traceback) and malformed scene texts are walked too.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import symosc
from symosc.errors import ParameterError

WALK = Path(__file__).with_name("_api_walk.py")


def _walk(passes: str, cwd: Path) -> list[dict]:
    env = {**os.environ, "PYTHONPATH": str(Path(symosc.__file__).parents[1])}
    proc = subprocess.run(  # in a scratch folder: bad paths such as "abc" may be written as files
        [sys.executable, str(WALK), "20", "3", passes],
        capture_output=True,
        text=True,
        timeout=600,
        env=env,
        check=False,
        cwd=cwd,
    )
    assert proc.returncode == 0, proc.stderr[-3000:]
    return [json.loads(line) for line in proc.stdout.splitlines() if line.strip()]


def test_public_api_bad_input_walk(tmp_path):
    problems = _walk("functions", tmp_path)
    assert problems == [], "\n".join(f"{p['function']}: {p.get('detail', p)}" for p in problems)


def test_constructors_command_line_and_scene_texts_walk(tmp_path):
    problems = _walk("classes,cli,scenes", tmp_path)
    assert problems == [], "\n".join(f"{p['function']}: {p.get('detail', p)}" for p in problems)


def test_the_walk_reports_silent_results_and_generic_errors(capsys):
    """The walk's own check can fail: a function that returns for nan, one that leaks a ValueError and one whose
    symosc error names no argument are each reported; a function that refuses nan explicitly is not."""
    sys.path.insert(0, str(WALK.parent))
    try:
        import _api_walk as walk
    finally:
        sys.path.remove(str(WALK.parent))

    def doubles(x: float) -> float:
        return 2 * x

    def leaks(x: float, y: float) -> float:
        return float("abc") if x != x else 0.0

    def vague(x: float) -> float:
        raise ParameterError("something went wrong")

    def refuses(x: float) -> float:
        raise ParameterError(f"x must be a finite number, got {x!r}")

    for fn in (doubles, leaks, vague, refuses):
        walk._walk_one(f"toy.{fn.__name__}", fn, 5, 3, check_messages=True, nonfinite=True)
    reports = [json.loads(line) for line in capsys.readouterr().out.splitlines()]
    kinds = {(r["function"], r["kind"]) for r in reports}
    assert ("toy.doubles", "accepts nan") in kinds and ("toy.doubles", "accepts inf") in kinds
    assert ("toy.leaks", "builtins.ValueError") in kinds
    assert ("toy.vague", "vague ParameterError (names no argument)") in kinds
    assert not any(r["function"] == "toy.refuses" for r in reports)


def test_guard_names_the_argument():
    """The boundary guard's message names the offending argument; a valid call is unchanged."""
    from symosc.operational import heaviside_expand, pairwise_root_sum_product

    with pytest.raises(ParameterError, match=r"heaviside_expand\(\): .*argument 'p' .* got the number 1.5; expected: "):
        heaviside_expand(1.5, 1.5)
    with pytest.raises(
        ParameterError, match=r"must not be None; argument 'p' of pairwise_root_sum_product\(\) got None; expected"
    ):
        pairwise_root_sum_product(None, None)
    import sympy as sp

    p, t = sp.symbols("p t")
    assert heaviside_expand(p / (p + 1), p, t) == sp.exp(-t)


def test_guard_keeps_genuine_bugs_visible():
    """A generic exception from a call with only ordinary arguments is not relabelled as bad input."""
    from symosc._validate import validated as guard

    def f(x: float) -> float:
        return [1.0][int(x)]

    g = guard(f)
    assert g(0.0) == 1.0
    with pytest.raises(IndexError):
        g(3.0)
    with pytest.raises(ParameterError, match=r"argument 'x' of f\(\) got the non-finite number nan; expected: float"):
        g(float("nan"))


def test_message_states_the_expectation_from_the_docstring():
    """The guard's message quotes the numpydoc "Parameters" entry (type and first sentence) of the argument."""
    from symosc._validate import validated as guard

    def links(n: int, *, kind: str = "point") -> int:
        """Toy.

        Parameters
        ----------
        n : int
            Number of links (n >= 1). Further text is not quoted.
        kind : {"point", "rigid"}
            Link model.

        Returns
        -------
        int
        """
        return list(range(3))[n]

    g = guard(links)
    with pytest.raises(ParameterError) as info:
        g(-7)
    assert "argument 'n' of links() got the negative number -7; expected: int — Number of links (n >= 1)" in str(
        info.value
    )
    assert "Further" not in str(info.value)
    with pytest.raises(
        ParameterError, match=r"argument 'kind' of links\(\) got None; expected: \{\"point\", \"rigid\"\}"
    ):
        g(1, kind=None)
    assert g(2) == 2


def test_message_falls_back_to_the_type_hint():
    from symosc._validate import validated as guard

    def f(count: int) -> float:
        return 1.0 / count

    with pytest.raises(ParameterError, match=r"argument 'count' of f\(\) got zero; expected: int"):
        guard(f)(0)


def test_vague_error_from_inside_is_completed():
    """A symosc error raised deep inside that names no argument gets the argument and its expectation added (from
    the docstring, else from a documented example); the class is kept."""
    from symosc._validate import validated as guard
    from symosc.errors import ModelError

    def resonance(stiffness, mass):
        """Toy.

        Examples
        --------
        >>> resonance(4.0, 1.0)
        2.0
        """
        if stiffness != stiffness:
            raise ModelError("the spring is undefined")
        return (stiffness / mass) ** 0.5

    g = guard(resonance)
    with pytest.raises(ModelError) as info:
        g(float("nan"), 1.0)
    text = str(info.value)
    assert text.startswith("resonance(): argument 'stiffness' of resonance() got the non-finite number nan; expected: ")
    assert "a value like 4.0 (as in the documented example resonance(...))" in text
    assert text.endswith("the spring is undefined")
    assert g(4.0, 1.0) == 2.0


def test_message_from_a_real_function_names_argument_and_expectation():
    """relay_regulator_cycles checks its own arguments; the pendulum's n names its range and the alternative."""
    from symosc.models import n_link_pendulum
    from symosc.nonlinear import relay_regulator_cycles

    with pytest.raises(ParameterError, match=r"dead_zone must be >= 0"):
        relay_regulator_cycles(0.1, 1.0, 1.0, 1.0, dead_zone=-1.0)
    with pytest.raises(ParameterError, match=r"n must be a positive integer"):
        n_link_pendulum(-1)


#: string parameters that are free text (a name for generated code), not a choice among values
FREE_TEXT = {("symosc.codegen.export", "name"), ("symosc.scene.loads", "name")}


def _probe(mode: str, cwd: Path) -> list[list[str]]:
    script = WALK.with_name("_example_probe.py")
    env = {**os.environ, "PYTHONPATH": str(Path(symosc.__file__).parents[1])}
    proc = subprocess.run(  # in a scratch folder: bad paths such as "abc" may be written as files
        [sys.executable, str(script), mode], capture_output=True, text=True, timeout=900, env=env, check=False, cwd=cwd
    )
    assert proc.returncode == 0, proc.stderr[-3000:]
    return [json.loads(line) for line in proc.stdout.splitlines() if line.strip()]


def test_misspelt_options_get_the_closest_valid_value(tmp_path):
    """Every string option of every public function with a documented example: the example called again with the
    option misspelt (default + "x") raises a symosc error that names the option and the closest valid value."""
    checked = [r for r in _probe("options", tmp_path) if ": " in r[1]]
    assert len(checked) >= 25  # the probe reached the options (not just "no example")
    bad = [r for r in checked if not r[1].endswith(": ok") and (r[0], r[1].split(":")[0]) not in FREE_TEXT]
    assert bad == [], "\n".join(map(str, bad))


@pytest.mark.slow
def test_bad_numeric_options_are_refused_explicitly(tmp_path):
    """Every numeric keyword of every public function with a documented example set to -1, nan, inf, "abc" (and 1.5
    for integers): the call returns, or raises a symosc error that names an argument and states an expectation;
    never a generic exception, never a hang (20 s cap per call).  Tolerances, limits and seeds used to hang or
    return nonsense (``rtol=nan`` integrated forever, ``tol=-1`` ran to the iteration cap)."""
    checked = [r for r in _probe("numbers", tmp_path) if ": " in r[1]]
    assert len(checked) >= 400
    bad = [r for r in checked if not (r[1].endswith(": ok") or r[1].endswith(": ACCEPTED"))]
    assert bad == [], "\n".join(map(str, bad))


def test_model_errors_about_the_model_are_not_decorated():
    """A ModelError that only mentions an argument's name ("f(A) is not defined") describes the model: the guard
    must not append what the (valid) arguments must be; one caused by a bad value (nan) still says it."""
    import sympy as sp

    from symosc.algebra import matrix_function
    from symosc.errors import ModelError
    from symosc.operational import heaviside_expand, inverse_carson

    with pytest.raises(ModelError) as info:
        matrix_function(sp.Matrix([[0, 1], [0, 0]]), sp.sqrt)
    assert str(info.value).endswith("f(A) is not defined") and "must be" not in str(info.value)
    p, t = sp.symbols("p t")
    with pytest.raises(ModelError) as info:
        inverse_carson(p**2 / (p + 1), p, t)
    assert "must be" not in str(info.value) and "improper Carson image" in str(info.value)
    with pytest.raises((ModelError, ParameterError)) as info:
        heaviside_expand(float("nan"), float("nan"))
    assert "nan" in str(info.value) and ("must be" in str(info.value) or "expected" in str(info.value))
