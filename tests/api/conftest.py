"""Fixtures of the API-wide tests."""

from __future__ import annotations

import pytest

from .public import example_instances


@pytest.fixture(scope="session")
def examples():
    """One instance of each public class, from the documented examples (:func:`tests.api.public.example_instances`).

    Running those examples takes seconds; as a session fixture it is built once, and pytest-xdist keeps every test
    that uses it on one worker (``conftest.py`` at the root of the repository)."""
    return example_instances()
