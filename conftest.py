"""Test configuration shared by the whole suite."""

import os

# Small dense linear algebra (SVDs, eigenproblems) runs many times slower when OpenBLAS starts its own
# threads on top of pytest-xdist's workers on a 2-core machine; one BLAS thread per worker is fastest here.
for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import matplotlib  # noqa: E402

matplotlib.use("Agg")


import pytest  # noqa: E402


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
