"""The extra work offsets ``G154 P1``–``P99`` and ``G110``–``G129`` of Haas controls, behind the
switches ``Dialect.extra_offset_code``, ``extra_offset_aliases``, ``extra_offset_variables`` and
``extra_offset_count`` (docs/semantics.md §8 "G154 extra work offsets"), run on the interpreter.

Each rule runs twice: on the ``haas`` profile, which keeps the offsets at #14001 + 20(P−1) with
#7001… the same offsets P1–P20, and on ``fanuc`` with only the switches turned on
(``running.haas_switched``), which keeps them at FANUC's numbers (#7001…), so that the rule is
seen apart from the rest of the profile. What only the switched ``fanuc`` has (G54.1 beside
G154, the offsets moved by ``extra_offset_variables``) runs there alone. Plain ``fanuc`` (FANUC
0i), where G154 and G110 are no codes and G10 L20 takes P1–P48, must keep doing what it did
before.
"""

from __future__ import annotations

import pytest

from cncmacro.dialects import Dialect, get_dialect
from running import alarm, final, haas_switched, lines, run

HAAS = haas_switched()
PROFILES = {"haas": get_dialect("haas"), "fanuc+G154": HAAS}

# P1 X at #7001, P3 X at #7041: G54.1 P1, P3 on the FANUC table the switches are tried on, and on
# haas the other numbers of G154 P1, P3 (#14001, #14041)
OFFSETS = {7001: 5.0, 7041: 10.0}


def work_group_variable(dialect: Dialect) -> int:
    """The #4001–#4030 that reads the code of the work coordinate system's modal group: #4014 on
    FANUC (group 14), #4012 on Haas (group 12)."""
    rows = dialect.system_variables()
    return next(r.first for r in rows if r.param == "wcs" and r.source == "modal" and 4001 <= r.first <= 4030)


@pytest.fixture(params=list(PROFILES))
def haas(request: pytest.FixtureRequest) -> Dialect:
    """The ``haas`` profile, then ``fanuc`` with the G154 switches on."""
    return PROFILES[request.param]


def test_8_g154_p3_applies_the_p3_offset_to_the_machine_position(haas: Dialect) -> None:
    group = work_group_variable(haas)
    text = lines("G90 G154 P3 G00 X1.", "#100=#5021", "#101=#5041", f"#102=#{group}", "G54 X1.", "#103=#5021", "M30")
    v = final(text, haas, presets=OFFSETS)
    assert v[100] == 11 and v[101] == 1  # machine = work + offset P3
    assert v[102] == 154  # the work coordinate system's modal group reads the code
    assert v[103] == 1  # G54 (no offset set) is back to the work position


def test_8_g110_is_g154_p1_and_g129_is_g154_p20(haas: Dialect) -> None:
    one = final(lines("G90 G110 G00 X1.", "#100=#5021", "G154 P1 X1.", "#101=#5021", "M30"), haas, presets=OFFSETS)
    assert one[100] == one[101] == 6
    twenty = final(lines("G90 G129 G00 X0", "#100=#5021", "M30"), haas, presets={7381: 4.0})
    assert twenty[100] == 4


def test_8_g10_l20_writes_extra_offsets_up_to_p99_that_g154_uses(haas: Dialect) -> None:
    v = final(lines("G90 G10 L20 P99 X7.", "G154 P99 G00 X0", "#100=#5021", "M30"), haas)
    assert v[100] == 7
    assert alarm(lines("G90 G10 L20 P99 X7.", "M30"), "fanuc") == (119, 1)  # FANUC 0i: P1-P48


def test_8_g154_p_outside_1_to_99_is_alarm_119(haas: Dialect) -> None:
    assert alarm(lines("G154 P100", "M30"), haas) == (119, 1)
    assert alarm(lines("G154 P0", "M30"), haas) == (119, 1)


def test_8_g154_and_g110_are_unknown_g_codes_where_the_switch_is_off(haas: Dialect) -> None:
    assert run(lines("G90 G154 P3 G00 X1.", "G110 X1.", "M30"), haas).status == "completed"  # both known
    assert alarm(lines("G90 G154 P3 G00 X1.", "M30"), "fanuc") == (10, 1)
    assert alarm(lines("G110 X1.", "M30"), "fanuc") == (10, 1)


def test_8_g54_1_and_g154_read_the_same_offsets_where_both_exist() -> None:
    text = lines("G90 G54.1 P3 G00 X1.", "#100=#5021", "G154 P3 X1.", "#101=#5021", "M30")
    v = final(text, HAAS, presets=OFFSETS)
    assert v[100] == v[101] == 11


def test_8_the_extra_offsets_are_stored_where_extra_offset_variables_says() -> None:
    # Haas keeps G154 P1-P99 at #14001 + 20(n-1): FANUC's #7021 (G54.1 P2) is then not P2
    moved = HAAS.configured(extra_offset_variables=14001)
    text = lines("G90 G154 P2 G00 X0", "#100=#5021", "G10 L20 P2 X3.", "G154 P2 X0", "#101=#5021", "M30")
    v = final(text, moved, presets={7021: 9.0})
    assert v[100] == 0 and v[101] == 3
