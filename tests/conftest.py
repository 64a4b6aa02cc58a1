"""Shared helpers for the tests: parse a line and look at its block; and the property tests'
settings: the same examples on every run (``derandomize``), so that a red test is a change in
the code, never a new random draw. ``HYPOTHESIS_PROFILE=explore`` draws new examples, with the
example database, to look for failures on purpose."""

from __future__ import annotations

import os
import shutil
import sys
from pathlib import Path

import pytest
from hypothesis import settings

# no deadline: an example's time is not what the tests judge (a busy machine's garbage collection or
# a parallel job made a pure-logic example take 0.6 s, failing a run on time alone)
settings.register_profile("repeatable", derandomize=True, database=None, deadline=None)
settings.register_profile("explore")
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "repeatable"))
# the command line reads its language from the environment (cli/locale_option.py): the tests
# expect English unless they ask for Chinese, on any developer's machine
for _name in ("LC_ALL", "LC_MESSAGES", "LANG"):
    if os.environ.get(_name, "").lower().startswith("zh"):
        os.environ[_name] = "C.UTF-8"

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "benchmarks"))  # the CAM program generator

from cncmacro.syntax import Block, parse_block  # noqa: E402
from cncmacro.syntax.nodes import Problem  # noqa: E402


def block(text: str) -> Block:
    """The block of one line; it must parse without an error."""
    b = parse_block(text)
    errors = [p for p in b.problems if p.severity == "error"]
    assert not errors, f"{text!r}: {errors}"
    return b


def error(text: str) -> Problem:
    """The (first) syntax error of a line that must not parse."""
    b = parse_block(text)
    errors = [p for p in b.problems if p.severity == "error"]
    assert errors, f"{text!r} parsed without error: {b}"
    return errors[0]


@pytest.fixture()
def examples(tmp_path: Path) -> Path:
    """A copy of the bundled examples to run them in (a run may write beside them)."""
    target = tmp_path / "examples"
    shutil.copytree(ROOT / "examples", target)
    return target
