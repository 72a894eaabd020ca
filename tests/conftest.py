"""Hypothesis settings for the whole suite: deterministic by default, exploring on request.

* Profile ``derive`` (the default): ``derandomize=True`` (each property test draws the same
  examples on every run, derived from the test's code) and ``database=None`` (no examples are
  stored in ``.hypothesis/`` and replayed). The suite's outcome then depends on the code alone:
  a clone does not go red because an earlier run in it found (and stored) a failing example,
  and a fresh clone in CI runs exactly what the developer ran.
* The compile cache: ``.cache/derive-tests`` in the checkout (``DERIVE_CACHE``), so that the
  suite leaves nothing in the user's own cache.
* Profile ``explore``: fresh random examples, still nothing stored; a failure prints its
  ``@reproduce_failure`` blob. Selected by ``--hypothesis-seed=N`` (a reproducible exploration
  with seed N) or ``--hypothesis-profile=explore`` (a new seed each run)::

      .venv/bin/python -m pytest -p no:cacheprovider tests/test_fuzz_scene.py --hypothesis-seed=7

  A bug found this way is fixed in the code and pinned by a plain test (not by a stored seed).
"""
import os
from pathlib import Path

import pytest
from hypothesis import settings

# The suite compiles into a cache of its own inside the checkout (kept between runs, ignored by
# git), never into the user's ~/.cache/derive; a test that needs another cache sets its own.
os.environ["DERIVE_CACHE"] = str(Path(__file__).resolve().parents[1] / ".cache" / "derive-tests")

settings.register_profile("derive", database=None, derandomize=True)
settings.register_profile("explore", database=None, derandomize=False, print_blob=True)
settings.load_profile("derive")


@pytest.fixture(scope="session")
def lecture_claims():
    """The lecture's notes read and checked once per test process (``check_notes``, ~4 s),
    shared by the files that test the reader on them."""
    from pathlib import Path

    from derive.lecture import notes_check as nc

    return nc.check_notes(Path(__file__).resolve().parents[2] / "shared" / "notes" / "lecture26-rigid-body.md")


def pytest_configure(config):
    # Under derandomize a --hypothesis-seed would be ignored (the digest of the test wins):
    # asking for a seed means asking to explore, unless a profile was named explicitly.
    seed = config.getoption("hypothesis_seed", None)
    if seed is not None and config.getoption("hypothesis_profile", None) is None:
        settings.load_profile("explore")
