"""Sphinx configuration: Markdown guides (MyST), notebooks with their stored outputs, numpydoc API reference.

Build: ``python -m sphinx -W -j 1 -b html docs docs/_build/html`` (the API pages are generated from the
subpackages' ``__all__`` on every build, so every public object is listed).
"""

from __future__ import annotations

import importlib
import sys
import warnings
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import symosc  # noqa: E402

# numpydoc reads the docstring of sympy.Symbol (for symosc.t), which has a section it does not know.
warnings.filterwarnings("ignore", message="Unknown section", category=UserWarning)

project = "symosc"
author = "symosc contributors"
release = symosc.__version__
extensions = ["myst_nb", "sphinx.ext.autodoc", "sphinx.ext.autosummary", "numpydoc", "sphinx.ext.mathjax"]
source_suffix = {".rst": "restructuredtext", ".md": "myst-nb", ".ipynb": "myst-nb"}
exclude_patterns = ["_build", "**/.ipynb_checkpoints"]
nb_execution_mode = "off"  # render the outputs stored in the notebooks; the test suite executes them
myst_heading_anchors = 3
myst_enable_extensions = ["dollarmath"]
autosummary_generate = True
autodoc_typehints = "none"
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_validation_checks: set[str] = set()
numpydoc_xref_param_type = False
suppress_warnings = ["myst.header", "myst.xref_missing", "autosummary.import_cycle"]
html_theme = "alabaster"
html_static_path: list[str] = []
# the ~500 generated API pages link up/previous/next instead of repeating the whole site's navigation tree in their
# sidebars (rendering that tree on every page took about a quarter of the build time)
html_sidebars = {"api/generated/*": ["relations.html", "searchbox.html"]}


def _subpackages() -> list[str]:
    return [f"symosc.{n}" for n in symosc._installed_subpackages() if n != "cli"]


def _write_api_pages() -> None:
    """One page per subpackage with an autosummary of every name in its ``__all__``."""
    api = Path(__file__).parent / "api"
    api.mkdir(exist_ok=True)
    for stale in (api / "generated").glob("*.rst"):  # pages of names no longer public are rebuilt, not kept
        stale.unlink()
    mods = ["symosc", *_subpackages()]
    index = ["API reference", "=============", "", "Every public object, generated from the docstrings.", ""]
    index += [".. toctree::", "   :maxdepth: 1", ""] + [f"   {m}" for m in mods]
    (api / "index.rst").write_text("\n".join(index) + "\n")
    for modname in mods:
        mod = importlib.import_module(modname)
        names = [n for n in getattr(mod, "__all__", ()) if not isinstance(getattr(mod, n), type(sys))]
        lines = [f"``{modname}``", "=" * (len(modname) + 4), "", f".. automodule:: {modname}", "   :no-members:", ""]
        lines += [f".. currentmodule:: {modname}", "", ".. autosummary::", "   :toctree: generated", ""]
        lines += [f"   {n}" for n in names]
        (api / f"{modname}.rst").write_text("\n".join(lines) + "\n")


_write_api_pages()


def _compile_numpydoc_template_once() -> None:
    """numpydoc (1.x) builds a new Jinja environment and compiles its docstring template for every docstring (about
    a tenth of this site's build time); the template is the same for all of them, so it is compiled once."""
    import numpydoc.docscrape_sphinx as docscrape_sphinx

    base, compiled = docscrape_sphinx.SandboxedEnvironment, {}

    class OneTemplateEnvironment(base):
        def get_template(self, name, *args, **kwargs):
            if name not in compiled:
                compiled[name] = super().get_template(name, *args, **kwargs)
            return compiled[name]

    docscrape_sphinx.SandboxedEnvironment = OneTemplateEnvironment


_compile_numpydoc_template_once()
