"""Test configuration shared by the whole suite.

* One BLAS thread per process and the Agg backend for matplotlib.
* One compiled-code cache per session (``SYMOSC_CACHE_DIR``), shared by the pytest-xdist workers.
* How ``python -m pytest -n 2`` hands the tests to its workers: tests that share an expensive module- or
  session-scoped fixture stay on one worker (so it is built once), and long tests start first (so the two workers
  finish together).  ``--durations=20`` (as ``.ci/run`` passes) shows what the run spent its time on.
"""

import os
import shutil
import tempfile
from pathlib import Path

# Small dense linear algebra (SVDs, eigenproblems) runs many times slower when OpenBLAS starts its own
# threads on top of pytest-xdist's workers on a 2-core machine; one BLAS thread per worker is fastest here.
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import matplotlib  # noqa: E402

matplotlib.use("Agg")


import pytest  # noqa: E402

ROOT = Path(__file__).resolve().parent


# ------------------------------------------------------------------------------------------------ compiled code
def pytest_configure(config):
    """Point ``SYMOSC_CACHE_DIR`` at a fresh directory for this session, unless the caller chose one.

    Set in the controlling process before pytest-xdist starts its workers, so the workers inherit it and share one
    cache: a library one worker has built is loaded, not rebuilt, by the other (builds are atomic renames, see
    ``symosc.numeric._build``).  A fresh directory keeps a run independent of the user's ``~/.cache/symosc`` (and
    keeps the tests' libraries out of it); set ``SYMOSC_CACHE_DIR`` yourself to keep the builds between runs.
    """
    if not hasattr(config, "workerinput") and not os.environ.get("SYMOSC_CACHE_DIR"):
        path = tempfile.mkdtemp(prefix="symosc-test-cache-")
        os.environ["SYMOSC_CACHE_DIR"] = path
        config.stash[_SESSION_CACHE] = path
    _use_grouped_distribution(config)
    config.pluginmanager.register(_LongWorkFirst(), "symosc-long-work-first")


_SESSION_CACHE = pytest.StashKey[str]()


def pytest_unconfigure(config):
    path = config.stash.get(_SESSION_CACHE, None)
    if path is not None:
        shutil.rmtree(path, ignore_errors=True)
        if os.environ.get("SYMOSC_CACHE_DIR") == path:
            del os.environ["SYMOSC_CACHE_DIR"]


@pytest.fixture(scope="module")
def private_symosc_cache(tmp_path_factory):
    """A fresh compiled-code cache (SYMOSC_CACHE_DIR) for one test module, restored afterwards."""
    old = os.environ.get("SYMOSC_CACHE_DIR")
    os.environ["SYMOSC_CACHE_DIR"] = str(tmp_path_factory.mktemp("symosc_cache"))
    yield
    if old is None:
        os.environ.pop("SYMOSC_CACHE_DIR")
    else:
        os.environ["SYMOSC_CACHE_DIR"] = old


# ------------------------------------------------------------------------------------------------ scheduling
def _use_grouped_distribution(config) -> None:
    """``-n N`` alone distributes with ``loadgroup``: every test is its own unit of work, handed to whichever worker
    is free, except the groups formed in :func:`pytest_collection_modifyitems` (one worker each).  An explicit
    ``--dist`` is left alone."""
    if getattr(config.option, "dist", "no") != "load" or getattr(config.option, "distload", False):
        return
    given = [*config.invocation_params.args, *os.environ.get("PYTEST_ADDOPTS", "").split(), *config.getini("addopts")]
    if not any(str(a).startswith("--dist") for a in given):
        config.option.dist = "loadgroup"
        config.option.loadscopereorder = False  # keep the order set by _LongWorkFirst (not: largest group first)


def _shared_fixture_group(item) -> str | None:
    """The group of a test that uses a module-, class-, package- or session-scoped fixture defined in this
    repository (not pytest's own such as ``tmp_path_factory``): the fixture's name for session and package scope
    (every test that uses it, in any module), else the test's module."""
    info = getattr(item, "_fixtureinfo", None)
    if info is None:
        return None
    group = None
    for name in item.fixturenames:
        defs = info.name2fixturedefs.get(name)
        if not defs:
            continue
        fixturedef = defs[-1]
        scope = getattr(fixturedef.scope, "value", fixturedef.scope)
        if scope == "function":
            continue
        source = getattr(getattr(fixturedef, "func", None), "__code__", None)
        if source is None or not Path(source.co_filename).resolve().is_relative_to(ROOT):
            continue
        if scope in ("session", "package"):
            return f"fixture-{name}"
        group = item.nodeid.split("::")[0]
    return group


@pytest.hookimpl(optionalhook=True)
def pytest_configure_node(node):
    """Tell each pytest-xdist worker that the run is grouped (a worker parses the command line anew, and sees only
    ``-n``): the worker then names grouped tests as ``loadgroup`` expects."""
    if node.config.getvalue("dist") == "loadgroup":
        node.workerinput["symosc_loadgroup"] = True


def _distributed_by_group(config) -> bool:
    """True in a pytest-xdist worker of a ``loadgroup`` run (the only place where groups and order matter)."""
    workerinput = getattr(config, "workerinput", None)
    if workerinput is not None and workerinput.get("symosc_loadgroup"):
        config.option.loadgroup = True  # what xdist sets itself when --dist loadgroup is on the command line
    return bool(getattr(config.option, "loadgroup", False))


@pytest.hookimpl(tryfirst=True)
def pytest_collection_modifyitems(config, items):
    """Form the worker groups: a test that shares an expensive fixture (:func:`_shared_fixture_group`) joins that
    group; pytest-xdist's ``loadgroup`` runs a group on one worker (as it does for ``@pytest.mark.xdist_group``).
    Runs first, so that pytest-xdist sees the groups when it names the tests."""
    if not _distributed_by_group(config):
        return
    for item in items:
        if item.get_closest_marker("xdist_group") is None:
            shared = _shared_fixture_group(item)
            if shared is not None:
                item.add_marker(pytest.mark.xdist_group(shared))


class _LongWorkFirst:
    """The order in which the workers receive the units of work (a group, or a single test): units holding a test
    marked ``slow`` first, then the other groups, then everything else in collection order; so the longest work
    starts at once on both workers and the last units handed out are short ones.  Runs after every other
    ``pytest_collection_modifyitems`` (pytest's own fixture-driven ordering, ``-k``/``-m`` selection)."""

    @pytest.hookimpl(trylast=True)
    def pytest_collection_modifyitems(self, config, items):
        if not _distributed_by_group(config):
            return
        units = [_group_of(item) or item.nodeid for item in items]
        slow = {unit for unit, item in zip(units, items, strict=True) if item.get_closest_marker("slow")}

        def rank(k: int) -> int:
            return 0 if units[k] in slow else 1 if _group_of(items[k]) else 2

        items[:] = [items[k] for k in sorted(range(len(items)), key=rank)]  # stable within each rank


def _group_of(item) -> str | None:
    mark = item.get_closest_marker("xdist_group")
    if mark is None:
        return None
    return str(mark.args[0] if mark.args else mark.kwargs.get("name", "default"))
