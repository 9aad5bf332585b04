"""Test configuration: hypothesis runs derandomised (same examples every run, so CI is
reproducible); set HYPOTHESIS_PROFILE=explore to search new examples locally."""

import os
import sys

import pytest
from hypothesis import settings

settings.register_profile("default", derandomize=True, database=None)
settings.register_profile("explore", max_examples=500, database=None)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "default"))


_SHOWN = 0  # hostile.SUMMARY lines already attached to a report


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    """Attach the hostile corpus's new summary lines to the test's report, so that they reach the
    terminal from a pytest-xdist worker too (reports carry user_properties to the controller)."""
    global _SHOWN
    report = (yield).get_result()
    lines = getattr(sys.modules.get("hostile"), "SUMMARY", [])
    if report.when == "call" and len(lines) > _SHOWN:
        report.user_properties.extend(("hostile_summary", ln) for ln in lines[_SHOWN:])
        _SHOWN = len(lines)


def pytest_terminal_summary(terminalreporter):
    """The hostile corpus's summary lines (tests/test_hostile.py), shown whatever the capture and
    however many workers: "N hostile inputs: 0 tracebacks, 0 hangs, 0 silent results"."""
    for reports in terminalreporter.stats.values():
        for report in reports:
            for name, line in getattr(report, "user_properties", ()):
                if name == "hostile_summary":
                    terminalreporter.write_line(line)


def pytest_collection_modifyitems(items):
    """The long cases (marked ``slow``) first: on several workers they then run beside the rest
    instead of ending the run alone. The sort is stable, so the order is the same in every
    worker, as pytest-xdist requires."""
    items.sort(key=lambda item: item.get_closest_marker("slow") is None)


@pytest.fixture(scope="session")
def validator():
    """A real JSON Schema validator (the ``jsonschema`` package) of ``govopt schema``'s schema,
    itself checked against draft-07."""
    jsonschema = pytest.importorskip("jsonschema")
    from govopt.spec_schema import schema

    found = schema()
    jsonschema.Draft7Validator.check_schema(found)
    return jsonschema.Draft7Validator(found)
