"""The dialect tables say today exactly what they said when ``data/dialect_tables.json`` was frozen.

Every system-variable row (its numbers, access, group, English and Chinese text, unit, source,
default), every system variable name, every G and M code, every function and every documented
program on the control of every dialect is compared with the frozen copy, so a change to one
description (or to a row several controls share) is caught. The hover a user sees for a number
comes from the row the dialect finds for it, so every number of every frozen row must find that
row, and no other number any. After a change to the tables that is
meant, write the fixture again with ``python tests/test_dialect_tables_frozen.py`` and review
its diff.
"""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path
from typing import Any

import pytest

from cncmacro.dialects import DIALECTS, get_dialect
from cncmacro.dialects.functions_data import GSK_H_CODES

FIXTURE = Path(__file__).parent / "data" / "dialect_tables.json"
HIGHEST = 100_400  # above every system variable of every dialect


def current() -> dict[str, Any]:
    """The tables as plain data: per dialect, rows and codes in the order the dialect gives them."""
    tables: dict[str, Any] = {}
    for name in DIALECTS:
        d = get_dialect(name)
        tables[name] = {
            "system_variables": [dataclasses.asdict(r) for r in d.system_variables()],
            "system_variable_names": [dataclasses.asdict(r) for r in d.system_variable_names()],
            "g_codes": [dataclasses.asdict(c) for c in d.g_codes()],
            "m_codes": [dataclasses.asdict(c) for c in d.m_codes()],
            "functions": [dataclasses.asdict(f) for f in d.functions()],
            # arguments and results are tuples, which JSON keeps as lists
            "program_docs": json.loads(json.dumps([dataclasses.asdict(p) for p in d.program_docs()])),
        }
    tables["gsk_h_codes"] = [dataclasses.asdict(f) for f in GSK_H_CODES]
    return tables


def frozen() -> dict[str, Any]:
    return json.loads(FIXTURE.read_text(encoding="utf-8"))


@pytest.mark.parametrize("dialect", DIALECTS)
@pytest.mark.parametrize(
    "table", ["system_variables", "system_variable_names", "g_codes", "m_codes", "functions", "program_docs"]
)
def test_dialect_table_matches_the_frozen_copy(dialect: str, table: str) -> None:
    now, then = current()[dialect][table], frozen()[dialect][table]
    changed = [(a, b) for a, b in zip(now, then, strict=False) if a != b]
    assert not changed, f"{dialect} {table}: first change {changed[0][1]} -> {changed[0][0]}"
    assert len(now) == len(then), f"{dialect} {table}: {len(then)} rows frozen, {len(now)} now"


def test_gsk_h_codes_match_the_frozen_copy() -> None:
    assert current()["gsk_h_codes"] == frozen()["gsk_h_codes"]


@pytest.mark.parametrize("dialect", DIALECTS)
def test_every_number_finds_its_frozen_row(dialect: str) -> None:
    d = get_dialect(dialect)
    owner: dict[int, dict[str, Any]] = {}
    for row in frozen()[dialect]["system_variables"]:
        for n in range(row["first"], row["last"] + 1):
            owner[n] = row
    for n in range(HIGHEST):
        found = d.system_variable(n)
        assert (dataclasses.asdict(found) if found else None) == owner.get(n), f"{dialect} #{n}"


if __name__ == "__main__":
    text = json.dumps(current(), ensure_ascii=False, indent=1)
    FIXTURE.write_text(text + "\n", encoding="utf-8")
    print(f"wrote {FIXTURE} ({len(text.encode()):,} bytes)")
