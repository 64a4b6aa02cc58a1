"""A run's status is a ``RunStatus`` member that reads as its text everywhere (docs/design.md:
``cncmacro run --json`` writes ``"status": "completed"``, the debugger ``status: completed``)."""

from __future__ import annotations

import json

import pytest

from cncmacro.machine import RunStatus
from running import lines, run

TEXTS = ["ready", "running", "paused", "completed", "alarm", "limit", "stopped"]


def test_the_statuses_are_the_seven_texts() -> None:
    assert [s.value for s in RunStatus] == TEXTS


@pytest.mark.parametrize("status", list(RunStatus))
def test_a_status_is_its_text_in_str_format_json_and_as_a_key(status: RunStatus) -> None:
    text = status.value
    assert str(status) == f"{status}" == "%s" % status == format(status, "") == text  # noqa: UP031
    assert f"{status:>10}" == f"{text:>10}"
    assert json.dumps({"status": status}) == json.dumps({"status": text})
    assert json.dumps({status: 1}) == json.dumps({text: 1})
    assert status == text and hash(status) == hash(text)
    assert {text: 1}[status] == 1 and {status: 1}[text] == 1


def test_a_run_returns_a_status() -> None:
    m = run(lines("#1=1", "M30"))
    assert m.status is RunStatus.COMPLETED
    assert m.result().status == "completed"
