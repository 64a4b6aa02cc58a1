"""The dialect data tables: consistent rows, the seeds' numbers, codes and functions.

The spot checks quote the seed manuals: seed 000 (GSK980TDi §3.28.1 system-variable tables,
§3.28.2 ``G65 Hm``) and seed 003 (FANUC-0i thesis, chapter 4 "系统变量"). docs/semantics.md §3
"Expressions" lists the functions and operators, §7 "GSK macro A form" the H codes.
"""

from __future__ import annotations

import itertools
import re
import string

import pytest

from cncmacro.dialects import DIALECTS, fanuc_data, functions_data, get_dialect, gsk980tdi_data
from cncmacro.dialects.dialect import last_address_key
from cncmacro.dialects.tables import (
    FUNCTION,
    FUNCTION_KINDS,
    MODAL_GROUPS,
    OPERATOR,
    SOURCES,
    STATEMENT,
    CodeDoc,
    SystemVariable,
)

DIALECT_DATA = {"fanuc": fanuc_data, "gsk980tdi": gsk980tdi_data}
AXES = ("X", "Y", "Z", "4th", "5th", "6th")
CJK = re.compile(r"[\u4e00-\u9fff]")
ACCESS = {"r", "w", "rw"}
GROUPS = {"signals", "tool", "work", "alarm", "time", "control", "counters", "modal", "position"}
PARAMS = {
    "timer": {"ms", "s", "h", "ms/2147483648"},  # the last: whole ms, back to 0 at 2^31 (FANUC #3001)
    "position": {"end", "machine", "current", "skip", "skip_programmed", "tool", "servo", "handle"},
    "code": set("FSTMDHBNOP"),
}
PLACEHOLDERS = {"axis", "index", "diameter"}  # diameter: a lathe's X only (describe.py)


def rows(dialect: str) -> tuple[SystemVariable, ...]:
    return DIALECT_DATA[dialect].SYSTEM_VARIABLES


def profile_rows(profile: str) -> tuple[SystemVariable, ...]:
    """Every row a profile answers with: the checks below hold for every profile the registry
    lists, so a new control is checked without a line here."""
    return get_dialect(profile).system_variables()


def find(dialect: str, number: int) -> SystemVariable | None:
    hits = [row for row in rows(dialect) if number in row]
    assert len(hits) <= 1, f"{dialect} #{number} is in {len(hits)} rows"
    return hits[0] if hits else None


def row(dialect: str, number: int) -> SystemVariable:
    found = find(dialect, number)
    assert found is not None, f"{dialect} #{number} is missing"
    return found


def text(dialect: str, number: int, lang: str = "en") -> str:
    """The hover text of one number, placeholders filled in."""
    r = row(dialect, number)
    k = number - r.first
    axis = AXES[k] if k < len(AXES) else "?"
    return getattr(r, lang).format(axis=axis, index=k + 1)


def alias_target(dialect: str, number: int) -> int:
    r = row(dialect, number)
    assert r.source == "alias"
    return int(r.param) + number - r.first


# ---------------------------------------------------------------------------------------------
# every row


@pytest.mark.parametrize("dialect", DIALECTS)
def test_rows_do_not_overlap(dialect):
    ordered = sorted(profile_rows(dialect), key=lambda r: r.first)
    for before, after in itertools.pairwise(ordered):
        assert before.last < after.first, f"#{before.first}-#{before.last} overlaps #{after.first}-#{after.last}"


@pytest.mark.parametrize("dialect", DIALECTS)
def test_every_row_is_well_formed(dialect):
    for r in profile_rows(dialect):
        where = f"{dialect} #{r.first}-#{r.last}"
        assert 1000 <= r.first <= r.last, where
        assert r.access in ACCESS, where
        assert r.group in GROUPS, where
        assert r.source in SOURCES, where
        if r.source == "modal":
            assert r.param in MODAL_GROUPS, where
        elif r.source == "code":  # a code the planner keeps, or a letter's last value (Haas #4124 X)
            kept = {last_address_key(letter) for letter in get_dialect(dialect).last_address_letters}
            assert r.param in PARAMS["code"] | kept, where
        elif r.source in PARAMS:
            assert r.param in PARAMS[r.source], where
        elif r.source == "alias":
            assert r.param.isdigit(), where
        elif r.source == "bits":  # the single-bit signal rows the word is made of
            first, count = (int(x) for x in r.param.split(":"))
            assert count in (16, 32) and r.first == r.last, where
            bits = [get_dialect(dialect).system_variable(first + i) for i in range(count)]
            assert all(b is not None and b.first == b.last and b.group == "signals" for b in bits), where
        else:
            assert r.param == "", where
        assert r.unit in {"", "mm", "s", "ms", "h"}, where
        assert r.en.strip() and r.zh.strip(), where
        assert CJK.search(r.zh), f"{where}: zh has no Chinese"
        assert not CJK.search(r.en), f"{where}: en has Chinese"


@pytest.mark.parametrize("dialect", DIALECTS)
def test_placeholders_are_only_axis_index_and_diameter(dialect):
    for r in profile_rows(dialect):
        for desc in (r.en, r.zh):
            names = {name for _, name, _, _ in string.Formatter().parse(desc) if name is not None}
            assert names <= PLACEHOLDERS, f"#{r.first}: {desc!r}"
            if "axis" in names:
                assert r.last - r.first < len(AXES), f"#{r.first}: {{axis}} in a row longer than the axes"
        if r.first != r.last:
            # a range names its numbers apart, or every number would read the same on hover
            assert "{" in r.en and "{" in r.zh, f"#{r.first}-#{r.last} has no placeholder"


@pytest.mark.parametrize("dialect", DIALECTS)
def test_read_only_sources_are_read_only(dialect):
    for r in profile_rows(dialect):
        if r.source in {"modal", "code", "position", "constant", "main"}:
            assert r.access == "r", f"#{r.first}"
        if r.source in {"alarm", "stop"}:
            assert r.access == "w", f"#{r.first}"


@pytest.mark.parametrize("dialect", DIALECTS)
def test_aliases_point_at_stored_variables_of_the_same_access(dialect):
    for r in profile_rows(dialect):
        if r.source != "alias":
            continue
        for number in (r.first, r.last):
            target = get_dialect(dialect).system_variable(int(r.param) + number - r.first)
            assert target is not None and target.source == "store", f"#{number} -> {target}"
            # the same access, or a writable name of a value readable only under its own number
            # (GSK980TDi #2501 writes the X workpiece shift, which #5201 reads: §3.28.1, docs/semantics.md §10.1)
            assert target.access == r.access or (r.access, target.access) == ("rw", "r"), f"#{number}"
            assert target.group == r.group, f"#{number}"


# ---------------------------------------------------------------------------------------------
# seed 003 chapter 4: FANUC 0i


@pytest.mark.parametrize(
    ("number", "access", "source", "param"),
    [
        (1000, "r", "store", ""),
        (1015, "r", "store", ""),
        (1032, "r", "bits", "1000:16"),  # the sum of #[1000+i] x 2^i
        (1100, "rw", "store", ""),
        (1115, "rw", "store", ""),
        (1132, "rw", "bits", "1100:16"),  # bit i is #[1100+i]
        (1133, "rw", "store", ""),
        (10001, "rw", "store", ""),
        (11400, "rw", "store", ""),
        (12001, "rw", "store", ""),
        (13400, "rw", "store", ""),
        (2001, "rw", "alias", "10001"),
        (2201, "rw", "alias", "11001"),
        (3000, "w", "alarm", ""),
        (3006, "w", "stop", ""),
        (3001, "rw", "timer", "ms/2147483648"),
        (3002, "rw", "timer", "h"),
        (3011, "r", "date", ""),
        (3012, "r", "time", ""),
        (3003, "rw", "store", ""),
        (3004, "rw", "store", ""),
        (3901, "rw", "store", ""),
        (3902, "rw", "store", ""),
        (4001, "r", "modal", "motion"),
        (4002, "r", "modal", "plane"),
        (4003, "r", "modal", "distance"),
        (4005, "r", "modal", "feed"),
        (4009, "r", "modal", "canned"),
        (4010, "r", "modal", "return"),
        (4012, "r", "modal", "macro"),
        (4013, "r", "modal", "spindle"),
        (4014, "r", "modal", "wcs"),
        (4017, "r", "modal", "polar"),
        (4022, "r", "modal", "mirror"),
        (4018, "r", "store", ""),
        (4021, "r", "store", ""),
        (4102, "r", "code", "B"),
        (4107, "r", "code", "D"),
        (4111, "r", "code", "H"),
        (4114, "r", "code", "N"),
        (4115, "r", "code", "O"),
        (4120, "r", "code", "T"),
        (4130, "r", "code", "P"),
        (5001, "r", "position", "end"),
        (5024, "r", "position", "machine"),
        (5041, "r", "position", "current"),
        (5064, "r", "position", "skip"),
        (5081, "r", "position", "tool"),
        (5104, "r", "position", "servo"),
        (5121, "r", "position", "handle"),
        (5124, "r", "position", "handle"),
        (5201, "rw", "store", ""),
        (5324, "rw", "store", ""),
        (7001, "rw", "store", ""),
        (7944, "rw", "store", ""),
        (2500, "rw", "alias", "5201"),
        (2806, "rw", "alias", "5324"),
    ],
)
def test_fanuc_spot_checks(number, access, source, param):
    r = row("fanuc", number)
    assert (r.access, r.source, r.param) == (access, source, param)


@pytest.mark.parametrize(
    "number",
    [1016, 1031, 1116, 1134, 2401, 2499, 2507, 3008, 3101, 4000, 4023, 4101, 4131, 4201, 5005, 5125, 5205, 5325, 7005,
     7945, 10401, 14001, 100001],
)  # fmt: skip
def test_fanuc_numbers_that_do_not_exist(number):
    assert find("fanuc", number) is None


def covered(dialect: str) -> set[int]:
    return {number for r in rows(dialect) for number in range(r.first, r.last + 1)}


def spans(*pairs: tuple[int, int]) -> set[int]:
    return {number for first, last in pairs for number in range(first, last + 1)}


def test_fanuc_covers_exactly_chapter_4_and_the_handle_interruption():
    expected = spans((1000, 1015), (1032, 1032), (1100, 1115), (1132, 1133))  # §4.1, MIF = 0
    expected |= spans((10001, 10400), (11001, 11400), (12001, 12400), (13001, 13400), (2001, 2400))  # §4.2
    expected |= {3000, 3006, 3001, 3002, 3011, 3012, 3003, 3004, 3901, 3902}  # §4.3-§4.7
    expected |= {3005, 3007}  # settings and mirror image: the 0i's macro chapter has them, the seed leaves them out
    expected |= spans((4001, 4022)) | {4102, 4107, 4109, 4111, 4113, 4114, 4115, 4119, 4120, 4130}  # §4.8
    expected |= spans(*((first, first + 3) for first in range(5001, 5102, 20)))  # §4.9
    expected |= spans((5121, 5124))  # manual handle interruption: a 0i has it, the seed leaves it out
    expected |= spans(*((first, first + 3) for first in range(5201, 5322, 20)))  # §4.10
    expected |= spans(*((first, first + 3) for first in range(7001, 7942, 20)))
    expected |= spans((2500, 2506), (2600, 2606), (2700, 2706), (2800, 2806))
    assert covered("fanuc") == expected, sorted(covered("fanuc") ^ expected)[:20]


def test_fanuc_readings_in_the_programmer_s_terms():
    assert "T code" in text("fanuc", 4120)
    assert "X" in text("fanuc", 5001) and "end" in text("fanuc", 5001)
    assert "4th" in text("fanuc", 5004)
    assert "P48" in text("fanuc", 7944) and "4th" in text("fanuc", 7944)
    assert "P1" in text("fanuc", 7001) and "X" in text("fanuc", 7001)
    assert "H200" in text("fanuc", 2200) and "H1:" in text("fanuc", 11001)
    assert "G56" in text("fanuc", 2503) and "X" in text("fanuc", 2503)
    assert "3000" in text("fanuc", 3000) and "3000" in text("fanuc", 3000, "zh")
    assert "G98" in text("fanuc", 4010)
    assert row("fanuc", 4018).default is None


def test_fanuc_tool_offset_aliases():
    # seed 003 §4.2: #2001 is H1 wear (#10001), #2201 is H1 geometry (#11001)
    assert alias_target("fanuc", 2001) == 10001
    assert alias_target("fanuc", 2200) == 10200
    assert alias_target("fanuc", 2201) == 11001
    assert alias_target("fanuc", 2400) == 11200


def test_fanuc_work_offset_aliases():
    # seed 003 §4.10: #2500-#2506 axis 1 (external, G54..G59), #2600.. axis 2, ... (#5303 in the seed is #5203)
    for axis in range(4):
        for i in range(7):
            assert alias_target("fanuc", 2500 + 100 * axis + i) == 5201 + 20 * i + axis
    assert alias_target("fanuc", 2503) == 5261
    assert alias_target("fanuc", 2700) == 5203


def test_fanuc_g54_1_p1_to_p48():
    for p in range(1, 49):
        first = 7001 + 20 * (p - 1)
        r = row("fanuc", first)
        assert (r.first, r.last) == (first, first + 3)
        assert re.search(rf"G54\.1 P{p}(?!\d)", r.en) and re.search(rf"G54\.1 P{p}(?!\d)", r.zh), r.en
        assert find("fanuc", first + 4) is None and find("fanuc", first - 1) is None


def test_fanuc_modal_rows_cover_groups_1_to_22():
    numbers = [r.first for r in rows("fanuc") if r.group == "modal" and 4001 <= r.first <= 4022]
    assert numbers == list(range(4001, 4023))
    named = {r.param for r in rows("fanuc") if r.source == "modal"}
    assert named == set(MODAL_GROUPS)


# ---------------------------------------------------------------------------------------------
# seed 000 §3.28.1: GSK980TDi


@pytest.mark.parametrize(
    ("number", "access", "source", "param"),
    [
        (1000, "r", "store", ""),
        (1015, "r", "store", ""),
        (1032, "r", "bits", "1000:16"),  # G54/G55: #1000-#1015
        (1034, "r", "store", ""),
        (1100, "r", "store", ""),
        (1134, "r", "store", ""),
        (2001, "rw", "store", ""),
        (2032, "rw", "store", ""),
        (2332, "rw", "store", ""),
        (2482, "rw", "store", ""),
        (2932, "rw", "store", ""),
        (2501, "rw", "alias", "5201"),  # the work coordinate shift is the external offset (§10.1)
        (2502, "rw", "alias", "5203"),
        (3901, "rw", "store", ""),
        (3902, "rw", "store", ""),
        (3000, "w", "alarm", ""),
        (3001, "r", "timer", "s"),
        (3002, "rw", "timer", "s"),
        (3011, "rw", "date", ""),
        (3012, "rw", "time", ""),
        (4001, "r", "modal", "motion"),
        (4002, "r", "modal", "spindle"),
        (4005, "r", "modal", "feed"),
        (4006, "r", "modal", "units"),
        (4007, "r", "modal", "cutter"),
        (4012, "r", "modal", "macro"),
        (4014, "r", "modal", "wcs"),
        (4016, "r", "modal", "plane"),
        (4109, "r", "code", "F"),
        (4113, "r", "code", "M"),
        (4114, "r", "code", "N"),
        (4115, "r", "code", "O"),
        (4119, "r", "code", "S"),
        (4120, "r", "code", "T"),
        (5001, "r", "position", "end"),
        (5005, "r", "position", "end"),
        (5025, "r", "position", "machine"),
        (5045, "r", "position", "current"),
        (5121, "r", "position", "handle"),
        (5125, "r", "position", "handle"),
        (5201, "r", "store", ""),
        (5325, "r", "store", ""),
    ],
)
def test_gsk_spot_checks(number, access, source, param):
    r = row("gsk980tdi", number)
    assert (r.access, r.source, r.param) == (access, source, param)


@pytest.mark.parametrize(
    "number",
    [
        1016,
        1035,
        1116,
        1135,
        2000,
        2033,
        2433,
        2450,
        2483,
        2503,
        2733,
        2933,
        3003,
        3006,
        4003,
        4107,
        4130,
        5006,
        5061,
        5081,
        5126,
        5206,
        5326,
        7001,
    ],
)
def test_gsk_numbers_that_do_not_exist(number):
    assert find("gsk980tdi", number) is None


def test_gsk_covers_exactly_the_tables_of_3_28_1():
    expected = spans((1000, 1015), (1032, 1034), (1100, 1115), (1132, 1134))  # 1)
    expected |= spans(*((first, first + 31) for first in (2001, 2101, 2201, 2301, 2401, 2451, 2701, 2801, 2901)))
    expected |= {3901, 3902, 2501, 2502, 3000, 3001, 3002, 3011, 3012}  # 3)-7)
    expected |= {4001, 4002, 4005, 4006, 4007, 4012, 4014, 4016, 4109, 4113, 4114, 4115, 4119, 4120}  # 8)
    expected |= spans((5001, 5005), (5021, 5025), (5041, 5045), (5121, 5125))  # 9), 10)
    expected |= spans(*((first, first + 4) for first in range(5201, 5322, 20)))  # 11)
    assert covered("gsk980tdi") == expected, sorted(covered("gsk980tdi") ^ expected)[:20]


def test_gsk_readings_in_the_programmer_s_terms():
    assert "X wear" in text("gsk980tdi", 2032) and "32" in text("gsk980tdi", 2032)
    assert "X geometry" in text("gsk980tdi", 2701) and "1" in text("gsk980tdi", 2701)
    assert "Z wear" in text("gsk980tdi", 2101)
    assert "nose" in text("gsk980tdi", 2301) and "假想刀尖" in text("gsk980tdi", 2301, "zh")
    assert "Y geometry" in text("gsk980tdi", 2482) and "32" in text("gsk980tdi", 2482)
    assert "5900" in text("gsk980tdi", 3000) and "5999" in text("gsk980tdi", 3000)
    assert "G99" in text("gsk980tdi", 4005) and "revolution" in text("gsk980tdi", 4005)
    assert "5th" in text("gsk980tdi", 5125) and "5th" in text("gsk980tdi", 5005)
    assert "G59" in text("gsk980tdi", 5321) and "X" in text("gsk980tdi", 5321)


def test_gsk_tool_offset_columns():
    # seed 000 §3.28.1 2): offset numbers 1..32 in nine columns
    for first in (2001, 2101, 2201, 2301, 2401, 2451, 2701, 2801, 2901):
        r = row("gsk980tdi", first)
        assert (r.first, r.last, r.access, r.group) == (first, first + 31, "rw", "tool")


# ---------------------------------------------------------------------------------------------
# G and M codes


@pytest.mark.parametrize("dialect", DIALECTS)
@pytest.mark.parametrize("table", ["G_CODES", "M_CODES"])
def test_codes_are_unique_and_well_formed(dialect, table):
    """Every profile the registry lists, a new one included, has its G and M codes documented
    once each, in English and in Chinese."""
    d = get_dialect(dialect)
    codes: tuple[CodeDoc, ...] = d.g_codes() if table == "G_CODES" else d.m_codes()
    assert codes, f"{dialect} documents no {table}"
    names = [c.code for c in codes]
    assert len(names) == len(set(names)), [n for n in names if names.count(n) > 1]
    for c in codes:
        assert re.fullmatch(table[0] + r"\d{2,3}(\.\d)?", c.code), c.code
        assert c.group == "" or c.group in MODAL_GROUPS, c.code
        assert c.en.strip() and CJK.search(c.zh) and not CJK.search(c.en), c.code
        if table == "M_CODES":
            assert c.group == "", c.code


FANUC_G = (
    "G00 G01 G02 G03 G04 G09 G10 G11 G15 G16 G17 G18 G19 G20 G21 G27 G28 G30 G31 G40 G41 G42 G43 G44 G49 "
    "G50 G51 G50.1 G51.1 G52 G53 G54 G55 G56 G57 G58 G59 G54.1 G61 G63 G64 G65 G66 G67 G68 G69 G73 G74 G76 "
    "G80 G81 G82 G83 G84 G85 G86 G87 G88 G89 G90 G91 G92 G94 G95 G96 G97 G98 G99"
).split()
FANUC_M = "M00 M01 M02 M03 M04 M05 M06 M08 M09 M19 M30 M98 M99 M198".split()
GSK_G = (
    "G00 G01 G02 G03 G04 G05 G07.1 G10 G17 G18 G19 G20 G21 G28 G30 G31 G32 G33 G34 G40 G41 G42 G50 "
    "G54 G55 G56 G57 G58 G59 G65 G66 G67 G70 G71 G72 G73 G74 G75 G76 G80 G83 G84 G87 G88 G90 G92 G94 "
    "G96 G97 G98 G99"
).split()
GSK_M = "M00 M01 M02 M03 M04 M05 M08 M09 M10 M11 M30 M32 M33 M98 M99 M198".split()


@pytest.mark.parametrize(
    ("dialect", "table", "wanted"),
    [
        ("fanuc", "G_CODES", FANUC_G),
        ("fanuc", "M_CODES", FANUC_M),
        ("gsk980tdi", "G_CODES", GSK_G),
        ("gsk980tdi", "M_CODES", GSK_M),
    ],
)
def test_codes_present(dialect, table, wanted):
    have = {c.code for c in getattr(DIALECT_DATA[dialect], table)}
    assert set(wanted) <= have, sorted(set(wanted) - have)


def code(dialect: str, name: str) -> CodeDoc:
    return next(c for c in DIALECT_DATA[dialect].G_CODES + DIALECT_DATA[dialect].M_CODES if c.code == name)


def test_code_groups_match_the_modal_tables():
    assert code("fanuc", "G98").group == "return" and code("fanuc", "G95").group == "feed"
    assert code("fanuc", "G65").group == "" and code("fanuc", "G66").group == "macro"
    assert code("fanuc", "G51.1").group == "mirror" and code("fanuc", "G54.1").group == "wcs"
    assert code("fanuc", "G16").group == "polar" and code("fanuc", "G83").group == "canned"
    # on the lathe G98/G99 are the feed mode and G90/G92/G94 cycles of group 01 (seed 000 #4001, #4005)
    assert code("gsk980tdi", "G98").group == "feed" and "minute" in code("gsk980tdi", "G98").en
    assert code("gsk980tdi", "G99").group == "feed" and "revolution" in code("gsk980tdi", "G99").en
    for name in ("G90", "G92", "G94", "G32", "G05", "G84", "G88", "G80"):
        assert code("gsk980tdi", name).group == "motion", name
    assert code("gsk980tdi", "G71").group == ""


# ---------------------------------------------------------------------------------------------
# functions (docs/semantics.md §3 "Expressions") and the GSK H codes (§7 "GSK macro A form")

SECTION_3 = "SIN COS TAN ASIN ACOS ATAN SQRT ABS LN EXP ROUND FIX FUP BIN BCD AND OR XOR MOD EQ NE GT GE LT LE".split()
STATEMENTS = "IF GOTO THEN WHILE DO END POPEN PCLOS DPRNT BPRNT".split()


def test_every_function_has_a_doc():
    names = {f.name for f in functions_data.FUNCTIONS}
    assert set(SECTION_3 + STATEMENTS) <= names, sorted(set(SECTION_3 + STATEMENTS) - names)
    signatures = [(f.name, f.signature) for f in functions_data.FUNCTIONS]
    assert len(signatures) == len(set(signatures))
    for f in functions_data.FUNCTIONS:
        assert f.name in f.signature, f.name
        assert f.en.strip() and CJK.search(f.zh), f.name


@pytest.mark.parametrize("dialect", DIALECTS)
def test_every_function_row_has_the_kind_its_signature_writes(dialect):
    """A row's ``kind`` is how the editor colours and completes the name: every row of the
    profile's function table and of the GSK H codes has one, the rows of one name agree on it, and
    the signature writes the word so: a function with its name first, an operator between two
    operands."""
    table = (*get_dialect(dialect).functions(), *functions_data.GSK_H_CODES)
    kinds: dict[str, set[str]] = {}
    for f in table:
        assert f.kind in FUNCTION_KINDS, (f.name, f.kind)
        kinds.setdefault(f.name, set()).add(f.kind)
        if f.kind == FUNCTION:
            assert f.signature == f.name or f.signature.startswith(f"{f.name}["), f.signature
        elif f.kind == OPERATOR:
            assert re.fullmatch(rf"\[?\w+ {f.name} \w+\]?", f.signature), f.signature
    assert {name: k for name, k in kinds.items() if len(k) > 1} == {}
    shown = {name: k.pop() for name, k in kinds.items() if name in ("SIN", "POPEN", "AND", "GT", "IF", "THEN", "H80")}
    assert shown == {"SIN": FUNCTION, "POPEN": FUNCTION, "AND": OPERATOR, "GT": OPERATOR, "IF": STATEMENT,
                     "THEN": STATEMENT, "H80": STATEMENT}  # fmt: skip


def test_both_atan_forms():
    atan = {f.signature: f for f in functions_data.FUNCTIONS if f.name == "ATAN"}
    assert set(atan) == {"ATAN[a]/[b]", "ATAN[a]"}
    assert "360" in atan["ATAN[a]/[b]"].en and "90" in atan["ATAN[a]"].en


def test_3_gsk_random_numbers_are_its_functions_only():
    # GSK980TDi §3.29.1: "#i = RAND[#j]", "#i = SRAND[#j，#k]" (note 10: "不包括 0"); hover and
    # completion read these rows, in both languages
    gsk = {f.signature: f for f in get_dialect("gsk980tdi").functions() if f.name in ("RAND", "SRAND")}
    assert set(gsk) == {"RAND[a]", "SRAND[a,b]"}
    assert "never 0" in gsk["RAND[a]"].en and "不包括0" in gsk["RAND[a]"].zh
    assert all(f.kind == FUNCTION and CJK.search(f.zh) for f in gsk.values())
    assert not {f.name for f in get_dialect("fanuc").functions()} & {"RAND", "SRAND"}


def test_fix_and_fup_examples_match_section_3():
    docs = {f.name: f for f in functions_data.FUNCTIONS}
    assert "FIX[-1.7] = -1" in docs["FIX"].en
    assert "FUP[-1.2] = -2" in docs["FUP"].en
    assert "ROUND[2.5] = 3" in docs["ROUND"].en


H_CODES = (
    "H01 H02 H03 H04 H05 H11 H12 H13 H21 H22 H23 H24 H25 H26 H27 H31 H32 H33 H34 H80".split()
    + [f"H8{i}" for i in range(1, 7)]
    + ["H99"]
)


def test_gsk_h_codes():
    docs = {f.name: f for f in functions_data.GSK_H_CODES}
    assert list(docs) == H_CODES
    for name, f in docs.items():
        assert f.signature.startswith(f"G65 {name} P"), name
        assert CJK.search(f.zh), name
    assert docs["H80"].signature == "G65 H80 Pn" and docs["H99"].signature == "G65 H99 Pn"
    assert docs["H02"].signature == "G65 H02 P#i Q#j R#k"
    assert "#i = #j + #k" in docs["H02"].en
    assert "TRUNC" in docs["H23"].en
    assert "#i = #i × #j ÷ #k" in docs["H26"].en
    assert "5900" in docs["H99"].en and "5915" in docs["H99"].en
    for name, sign in zip(("H81", "H82", "H83", "H84", "H85", "H86"), "=≠><≥≤", strict=True):
        assert f"#j {sign} #k" in docs[name].en, name
