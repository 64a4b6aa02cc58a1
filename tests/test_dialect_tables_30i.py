"""The FANUC 30i table (``dialects/profiles/fanuc_30i.py``): names that resolve, the 0i rows it
reuses, what sets it apart (the checks every profile's rows pass are in test_dialect_tables.py).

docs/profiles.md "fanuc-30i: sources and decisions" says where each row comes from; the checks
here hold the table to its own rules: every row and name is described in English and Chinese,
no two rows share a number, every number a name stands for has a row, aliases point at stored
variables, and where the 30i reads a number the way the 0i does the row is the 0i's.
"""

from __future__ import annotations

import math
import re

import pytest

from cncmacro.dialects import fanuc_data, functions_data, get_dialect
from cncmacro.dialects.profiles import fanuc_30i as data
from cncmacro.dialects.tables import SystemVariable

CJK = re.compile(r"[\u4e00-\u9fff]")
GROUPS = {"signals", "tool", "work", "alarm", "time", "control", "counters", "modal", "position"}
PARAMS = {
    "timer": {"ms", "s", "h"},
    "position": {"end", "machine", "current", "skip", "tool", "servo", "handle"},
    "code": set("FSTMDHBNOP"),
}
ROWS = data.SYSTEM_VARIABLES
DIALECT = get_dialect("fanuc-30i")


def row(number: int) -> SystemVariable:
    hits = [r for r in ROWS if number in r]
    assert len(hits) == 1, f"#{number} is in {len(hits)} rows"
    return hits[0]


def test_30i_reuses_the_0i_rows_where_the_30i_reads_a_number_alike() -> None:
    for number in (3000, 3001, 3006, 3011, 3901, 4001, 4120, 5001, 5061, 5121, 5221, 7001, 7944, 2001, 2500):
        assert row(number) == next(r for r in fanuc_data.SYSTEM_VARIABLES if number in r), f"#{number}"


def test_30i_constants_pi_e_and_vacant_are_read_only() -> None:
    assert (row(3101).source, row(3101).access, row(3101).default) == ("constant", "r", math.pi)
    assert (row(3102).source, row(3102).access, row(3102).default) == ("constant", "r", math.e)
    assert (row(3100).source, row(3100).access, row(3100).default) == ("constant", "r", None)


def test_30i_has_32_interface_signals_each_way_and_999_offsets() -> None:
    assert row(1031).access == "r" and row(1131).access == "rw" and row(1035).access == "r"
    assert "UI031" in row(1031).en and "UO300" in row(1135).en
    assert (row(10999).first, row(10999).last) == (10001, 10999) and row(13999).first == 13001


def test_30i_modal_rows_of_the_executing_block_mirror_those_of_the_previous_block() -> None:
    for number in (*range(4001, 4031), 4102, 4107, 4109, 4111, 4113, 4114, 4115, 4119, 4120, 4130):
        before, now = row(number), row(number + data.EXECUTING)
        assert (before.source, before.param, before.default) == (now.source, now.param, now.default), number
        assert "executed" in now.en and "执行" in now.zh, number
    assert row(4000).source == "main"


def test_30i_long_numbers_repeat_positions_and_g54_1_offsets() -> None:
    for first, base in data._EXTENDED_POSITIONS:
        assert (row(first).source, row(first).param) == (row(base).source, row(base).param), first
    for p in (1, 48):
        long = row(14001 + 20 * (p - 1))
        assert (long.source, long.param) == ("alias", str(7001 + 20 * (p - 1))) and f"P{p};" in long.en


NAMES = data.SYSTEM_VARIABLE_NAMES


def test_30i_names_are_unique_bilingual_and_resolve_to_rows() -> None:
    assert len({n.name for n in NAMES}) == len(NAMES)
    for n in NAMES:
        assert re.fullmatch(r"[A-Z][A-Z0-9]*", n.name), n.name
        assert n.en.strip() and CJK.search(n.zh) and not CJK.search(n.en), n.name
        for number in range(n.first, n.last + 1):
            assert DIALECT.system_variable(number) is not None, f"#_{n.name} -> #{number}"


@pytest.mark.parametrize(
    ("name", "first"),
    [("UI", 1000), ("UO", 1100), ("OFSHW", 10001), ("ALM", 3000), ("MSGSTP", 3006), ("DATE", 3011),
     ("TIME", 3012), ("PI", 3101), ("E", 3102), ("BUFG", 4001), ("ACTG", 4201), ("BUFT", 4120), ("ACTT", 4320),
     ("ABSIO", 5001), ("ABSMT", 5021), ("ABSOT", 5041), ("ABSKP", 5061), ("WZG54", 5221), ("WZG59", 5321)],
)  # fmt: skip
def test_30i_name_spot_checks(name: str, first: int) -> None:
    found = DIALECT.variable_name(name)
    assert found is not None and found.first == first


def test_names_and_extra_functions_belong_to_the_30i_only() -> None:
    for other in ("fanuc", "gsk980tdi"):
        d = get_dialect(other)
        assert not d.variable_names and d.system_variable_names() == () and d.variable_name("ABSIO") is None
        assert not {"POW", "ADP", "PRM"} & {f.name for f in d.functions()}
        assert "ATAN[a,b]" not in {f.signature for f in d.functions()}
    signatures = {f.signature for f in DIALECT.functions()}
    assert {"POW[a,b]", "ADP[a]", "PRM[n]", "PRM[n,axis]", "PRM[n]/[bit]", "ATAN[a,b]", "ATAN[a]/[b]"} <= signatures


def test_extra_functions_are_documented_in_both_languages() -> None:
    for f in functions_data.EXTRA_FUNCTIONS:
        assert f.name in f.signature and f.en.strip() and CJK.search(f.zh), f.signature
    assert "POW[2,3] = 8" in next(f.en for f in functions_data.EXTRA_FUNCTIONS if f.name == "POW")


def test_30i_m98_reads_p_as_the_program_and_counts_in_l() -> None:
    m98 = next(c for c in data.M_CODES if c.code == "M98")
    assert "8 digits" in m98.en and "L only" in m98.en and "只能用L" in m98.zh
    assert data.G_CODES == fanuc_data.G_CODES
