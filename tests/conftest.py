"""Hypothesis profiles for the property tests, and the order in which the tests are handed out.

With ``CI`` set (the CI run and ``.ci/run``), every property test replays the same pseudo-random examples
(``derandomize=True``, no example database): the result of a run depends on the code, not on the draw.  Without
it (a developer's run) each run draws new examples, so the properties keep being explored; a failure prints the
``@reproduce_failure`` blob that replays it.  No deadline: the tests never assert on wall-clock time.  A test's own
``@settings`` (example counts, health checks) apply on top of either profile.

The tests marked ``slow`` come first: pytest-xdist deals the first quarter of the tests to the workers in turn and
the rest to whichever worker is free, so long tests at the front run side by side from the start instead of leaving
one worker alone at the end of the run.  The tests marked ``browser`` come last: .ci/run installs Chromium while the
other tests run.
"""

import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, database=None, deadline=None, print_blob=True)
settings.register_profile("explore", deadline=None, print_blob=True)
settings.load_profile("ci" if os.environ.get("CI") else "explore")


def pytest_collection_modifyitems(config, items):
    """Tests marked ``slow`` first and ``browser`` last; the order is otherwise the collection order."""
    items.sort(
        key=lambda item: 0 if item.get_closest_marker("slow") else 2 if item.get_closest_marker("browser") else 1
    )
