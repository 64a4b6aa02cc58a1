"""The language server's clean-up of its heap waits for quiet in proportion to what it will cost:
the full collection of a million-line file's working set holds the interpreter for over a
second, so it waits until the editor has sent nothing for several seconds, while a small
workspace's clean-up still comes after half a second."""

from __future__ import annotations

import pytest

from cncmacro.lsp import collector
from cncmacro.lsp.collector import QUIET_SECONDS, Collector


@pytest.mark.parametrize(("resident_mb", "at_least", "at_most"), [(50, QUIET_SECONDS, QUIET_SECONDS), (640, 3.0, 6.0)])
def test_the_quiet_wanted_before_a_clean_up_grows_with_the_heap(
    monkeypatch: pytest.MonkeyPatch, resident_mb: int, at_least: float, at_most: float
) -> None:
    monkeypatch.setattr(collector, "resident_bytes", lambda: resident_mb << 20)
    assert at_least <= Collector().quiet_seconds() <= at_most


def test_without_a_reading_of_memory_the_quiet_is_the_short_one(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(collector, "resident_bytes", lambda: None)
    assert Collector().quiet_seconds() == QUIET_SECONDS


def test_a_workspace_index_is_working_set_not_garbage(monkeypatch: pytest.MonkeyPatch) -> None:
    """A folder holding a 100k-line program grows the server by about 100 MB as it is indexed:
    counted as growth, it made a clean-up urgent, which held up the first file's diagnostics
    for a collection that freed nothing. Once indexed, the growth counts from there."""
    resident = [60 << 20]
    monkeypatch.setattr(collector, "resident_bytes", lambda: resident[0])
    c = Collector()
    resident[0] = 180 << 20  # the index of the folder's programs
    assert c.urgent()
    c.indexed()
    assert not c.due() and not c.urgent()
    resident[0] = 300 << 20  # what edits left since grew it again
    assert c.due()


def test_an_index_does_not_hide_a_closed_document(monkeypatch: pytest.MonkeyPatch) -> None:
    resident = [60 << 20]
    monkeypatch.setattr(collector, "resident_bytes", lambda: resident[0])
    c = Collector()
    c.closed()  # its working set is garbage now
    c.indexed()
    assert c.due()
