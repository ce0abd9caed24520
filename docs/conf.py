"""Sphinx configuration: Markdown guides (MyST), notebooks with their stored outputs, numpydoc API reference.

Build: ``python -m sphinx -W -j 1 -b html docs docs/_build/html`` (the API pages are generated on every build from
the ``__all__`` of every public module, discovered by walking the package, so every public object is listed).
"""

from __future__ import annotations

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
templates_path = ["_templates"]
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


sys.path.insert(0, str(Path(__file__).parent))
from _api_pages import write_api_pages  # noqa: E402 - the discovery of the public API and its pages


def _write_api_pages() -> None:
    """One page per public module (discovered by walking the package) with every name of its ``__all__``."""
    write_api_pages(Path(__file__).parent / "api")


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
