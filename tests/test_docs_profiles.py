"""The pages that list the control profiles list the registry's (``dialects/registry.py``):
a profile added or renamed must show in the README's table, docs/profiles.md's table and the
editor page's setting, or a user reads of a profile that is not there."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from cncmacro.dialects import DIALECTS

ROOT = Path(__file__).resolve().parents[1]


def _table_names(page: str) -> list[str]:
    """The profile names that start the rows of a page's table of profiles."""
    text = (ROOT / page).read_text(encoding="utf-8")
    return re.findall(r"^\| `([a-z0-9-]+)`", text, re.M)


@pytest.mark.parametrize("page", ["README.md", "docs/profiles.md"])
def test_the_profile_tables_list_every_profile_of_the_registry(page: str) -> None:
    assert sorted(_table_names(page)) == sorted(DIALECTS)


def test_the_editor_page_names_every_profile_for_the_dialect_setting() -> None:
    text = (ROOT / "docs/editor.md").read_text(encoding="utf-8")
    line = re.search(r"`cncMacro\.dialect` \(a profile: ([^,]*),", text)
    assert line is not None, "docs/editor.md no longer describes the cncMacro.dialect setting"
    assert sorted(re.findall(r"`([a-z0-9-]+)`", line.group(1))) == sorted(DIALECTS)
