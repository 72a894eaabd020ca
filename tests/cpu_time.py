"""Opt-in pytest plugin: the CPU seconds each test used, summed over the run.

``pytest -p cpu_time`` (and ``CPU_TIME_JSON=FILE`` to keep every test's figure) (from the checkout, with ``tests`` on the path as pytest puts it) ends with
the CPU seconds of every test's setup, call and teardown: this process's and those of the
processes it started and waited for (compilers, ``derive`` commands, process pools), summed over
the run and listed for the costliest tests and files. With pytest-xdist each worker measures its
own tests and the controller adds them up.

The sum is what the suite costs whatever else the machine runs: on a machine shared with other
work, ``--durations`` shows wall-clock times stretched by the load, while the CPU seconds stay
put; divided by the number of cores it bounds ``make test``'s wall time from below on an idle
machine (collection and the workers' start come on top).
"""
from __future__ import annotations

import collections
import json
import os
import resource

import pytest

_TOP = 25


def _cpu() -> float:
    own, kids = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + kids.ru_utime + kids.ru_stime


def _measured(phase: str):
    @pytest.hookimpl(hookwrapper=True)
    def hook(item):
        start = _cpu()
        yield
        item.user_properties.append((f"cpu_{phase}", _cpu() - start))
    return hook


pytest_runtest_setup = _measured("setup")
pytest_runtest_call = _measured("call")
pytest_runtest_teardown = _measured("teardown")

_by_test: collections.Counter = collections.Counter()


def pytest_runtest_logreport(report):
    for key, value in report.user_properties:
        if key == f"cpu_{report.when}":
            _by_test[report.nodeid] += value


def pytest_terminal_summary(terminalreporter):
    if not _by_test:
        return
    by_file: collections.Counter = collections.Counter()
    for nodeid, seconds in _by_test.items():
        by_file[nodeid.split("::")[0]] += seconds
    if os.environ.get("CPU_TIME_JSON"):
        with open(os.environ["CPU_TIME_JSON"], "w") as out:
            json.dump(dict(_by_test), out, indent=0)
    write = terminalreporter.write_line
    terminalreporter.section("CPU seconds")
    write(f"{sum(_by_test.values()):.1f} s of CPU in {len(_by_test)} tests")
    write(f"-- the {_TOP} costliest tests")
    for nodeid, seconds in _by_test.most_common(_TOP):
        write(f"{seconds:7.2f}  {nodeid}")
    write(f"-- the {_TOP} costliest files")
    for name, seconds in by_file.most_common(_TOP):
        write(f"{seconds:7.2f}  {name}")
