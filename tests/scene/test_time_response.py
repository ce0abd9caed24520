"""The time_response question and the HTML report: data against hand-written equations, files written, and the
report rendered in a real browser (headless Chromium) shows mathematics, not TeX source."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import time
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from symosc.cli import main
from symosc.scene import SceneError, loads

SCENE = """
title = "Double pendulum released from rest"
[system]
model = "n_link_pendulum"
n = 2
[parameters]
m1 = "1 kg"
m2 = "700 g"
l1 = "1 m"
l2 = "80 cm"
g = 9.81
[[questions]]
kind = "equations_of_motion"
[[questions]]
kind = "time_response"
initial = { phi1 = 0.3, phi2 = -0.2 }
duration = "5 s"
outputs = ["phi1", "phi2", "energy"]
rtol = 1e-11
atol = 1e-12
points = 51
"""


def _double(t, y, m1=1.0, m2=0.7, l1=1.0, l2=0.8, g=9.81):
    """The hanging double point pendulum, written out by hand."""
    p1, p2, w1, w2 = y
    c, s = np.cos(p1 - p2), np.sin(p1 - p2)
    M = np.array([[(m1 + m2) * l1**2, m2 * l1 * l2 * c], [m2 * l1 * l2 * c, m2 * l2**2]])
    F = [
        -m2 * l1 * l2 * s * w2**2 - (m1 + m2) * g * l1 * np.sin(p1),
        m2 * l1 * l2 * s * w1**2 - m2 * g * l2 * np.sin(p2),
    ]
    return np.concatenate([[w1, w2], np.linalg.solve(M, F)])


@pytest.fixture(scope="module")
def result():
    return loads(SCENE).run()


def test_time_response_follows_the_hand_written_equations(result):
    d = result["time_response"].data
    t = np.array(d["t"])
    ref = solve_ivp(_double, (0, 5), [0.3, -0.2, 0, 0], t_eval=t, method="DOP853", rtol=1e-12, atol=1e-13).y
    np.testing.assert_allclose(d["outputs"]["phi1"], ref[0], atol=1e-7)
    np.testing.assert_allclose(d["outputs"]["phi2"], ref[1], atol=1e-7)
    e = np.array(d["outputs"]["energy"])
    assert d["energy_drift"] < 1e-9 and np.ptp(e) < 1e-8 * abs(e[0])
    assert d["final_state"]["phi1"] == pytest.approx(ref[0, -1], abs=1e-7)


def test_time_response_refusals():
    base = SCENE.split("[[questions]]")[0]
    with pytest.raises(SceneError, match="duration"):
        loads(base + '[[questions]]\nkind = "time_response"\ninitial = { phi1 = 0.1 }\n')
    with pytest.raises(SceneError, match="phi3"):
        loads(base + '[[questions]]\nkind = "time_response"\ninitial = { phi3 = 0.1 }\nduration = 1\n').run()
    with pytest.raises(SceneError, match="outputs"):
        loads(base + '[[questions]]\nkind = "time_response"\nduration = 1\noutputs = ["x"]\n').run()


def test_cli_writes_html_plot_data_and_animation(tmp_path, capsys):
    """``symosc run FILE --format html``: report, results.json, the time-response figure and the GIF."""
    from PIL import Image

    scene = tmp_path / "released.toml"
    scene.write_text(SCENE.replace("points = 51", "points = 51\nanimate = true\nspeed = 2"))
    assert main(["run", str(scene), "-o", str(tmp_path / "out"), "--format", "html"]) == 0
    out = tmp_path / "out"
    assert (out / "released-motion-2.png").stat().st_size > 0
    with Image.open(out / "released-motion-2.gif") as im:
        assert im.n_frames == 63  # 5 s at 25 frames/s, played twice as fast: 62.5 -> 63 frames
    data = json.loads((out / "results.json").read_text())
    assert data["questions"][1]["kind"] == "time_response"
    page = (out / "report.html").read_text()
    assert "<math" in page and "data:image/gif;base64," in page and "$" not in page
    assert "700 g" in page  # parameters echoed as the file wrote them
    assert "m2 = 700 g" in capsys.readouterr().out


#: a file that .ci/run writes (apt-get's exit status) when the Chromium it installs alongside the tests is ready
PENDING_INSTALL = os.environ.get("SYMOSC_CHROMIUM_INSTALL")


def _chromium() -> str | None:
    """Chromium's path; waits for an installation that .ci/run started in the background (at most 15 minutes)."""
    found = shutil.which("chromium") or shutil.which("chromium-browser")
    if found is None and PENDING_INSTALL:
        deadline = time.monotonic() + 900
        while not os.path.exists(PENDING_INSTALL) and time.monotonic() < deadline:
            time.sleep(1)
        found = shutil.which("chromium") or shutil.which("chromium-browser")
    return found


PROBE = """<script>
window.addEventListener("load", function () {
  var maths = Array.from(document.querySelectorAll("math"));
  var shown = maths.filter(function (m) { var r = m.getBoundingClientRect(); return r.width > 0 && r.height > 0; });
  var styled = maths.filter(function (m) { return getComputedStyle(m).display.indexOf("math") >= 0; });
  var out = document.createElement("pre");
  out.id = "probe";
  out.textContent = JSON.stringify({math: maths.length, shown: shown.length, styled: styled.length,
                                    text: document.body.innerText});
  document.body.appendChild(out);
});
</script>"""


@pytest.mark.browser
def test_report_renders_mathematics_in_a_browser(result, tmp_path):
    """Chromium lays the report out: every equation is a rendered MathML element (display: math, non-empty box) and
    the visible text holds no TeX source (no \\frac, \\sin, \\left or $)."""
    chromium = _chromium()
    if chromium is None:
        pytest.skip("needs headless Chromium (apt-get install chromium; .ci/run installs it)")
    page = tmp_path / "report.html"
    page.write_text(result.html().replace("</body>", PROBE + "</body>"), encoding="utf-8")
    flags = [
        "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
        "--disable-background-networking", "--disable-component-update", "--disable-sync",
        f"--user-data-dir={tmp_path / 'profile'}", "--virtual-time-budget=5000", "--dump-dom",
    ]  # fmt: skip
    proc = subprocess.run([chromium, *flags, page.as_uri()], capture_output=True, text=True, timeout=120)
    dom = proc.stdout
    start = dom.index('<pre id="probe">') + len('<pre id="probe">')
    import html

    probe = json.loads(html.unescape(dom[start : dom.index("</pre>", start)]))
    assert probe["math"] == 2  # one equation of motion per coordinate
    assert probe["shown"] == probe["math"] and probe["styled"] == probe["math"]
    for tex in ("\\frac", "\\sin", "\\left", "\\begin", "$"):
        assert tex not in probe["text"], tex
    # single-letter identifiers get the mathematical italic forms (MathML's math-auto text transform): the angle
    # phi is shown as U+1D711, which no text rendering of the page's source produces
    assert "\U0001d711" in probe["text"]


def test_report_fragment_for_notebooks(result):
    frag = result._repr_html_()
    assert frag.startswith("<div class='symosc-report'>") and "<!DOCTYPE" not in frag and "<html" not in frag
    doc = result.html()
    assert doc.startswith("<!DOCTYPE html>") and frag in doc


def test_parameters_keep_the_units_of_the_file():
    scene = loads(SCENE, overrides={"m1": 2.0})
    res = scene.run()
    assert res.parameter_text["m2"] == "700 g" and res.parameter_text["l2"] == "80 cm"
    assert "m1" not in res.parameter_text  # overridden: shown in SI
    assert "m1 = 2, " in res.report() and "m2 = 700 g" in res.report()


def test_examples_gribkov_shows_upright_and_falling():
    """The first example scene: at 2 mm the pendulum stays up, at 1 mm it falls (Gribkov & Khokhlov 2015)."""
    from symosc.scene import load

    res = load(Path(__file__).resolve().parents[2] / "examples" / "gribkov2015.toml").run()
    up, down = (r for r in res.results if r.kind == "time_response")
    assert max(abs(np.array(up.data["outputs"]["phi1"]))) < 0.5
    assert max(abs(np.array(down.data["outputs"]["phi1"]))) > 1.5
    assert [f.filename.endswith(".gif") for f in up.figures] == [False, True]
