"""The local subprogram call ``M97 P n L k`` of Haas controls, behind the switch
``Dialect.local_subprogram_code`` (docs/semantics.md §5 "M97 local subprogram call"), run on the
interpreter.

Each rule runs twice: on the ``haas`` profile, and on ``fanuc`` with only the switch turned on
(``running.haas_switched``), so that the rule is seen apart from the rest of the profile. Plain
``fanuc`` (FANUC 0i), where M97 is an M code like any other, must keep doing what it did before.
"""

from __future__ import annotations

import pytest

from cncmacro.dialects import Dialect, get_dialect
from running import alarm, final, haas_switched, lines, run

PROFILES = {"haas": get_dialect("haas"), "fanuc+M97": haas_switched()}


@pytest.fixture(params=list(PROFILES))
def haas(request: pytest.FixtureRequest) -> Dialect:
    """The ``haas`` profile, then ``fanuc`` with the M97 switch on."""
    return PROFILES[request.param]


# a main program that calls its own N1000 block range and records the order things ran in
LOCAL_CALL = lines(
    "O0011",
    "#100=1",
    "M97 P1000",
    "#101=#100",  # runs after the local subprogram returned: #100 is 2 by then
    "M30",
    "N1000 #100=#100+1",
    "G90 G01 X5. F100",
    "M99",
)

# ---------------------------------------------------------------------------------------------
# §5 M97 local subprogram call


def test_5_m97_runs_from_its_n_label_to_m99_and_returns_after_the_call(haas: Dialect) -> None:
    m = run(LOCAL_CALL, haas)
    assert m.status == "completed", m.alarm
    v = m.variables()
    assert v[100] == 2 and v[101] == 2
    # the move inside the local subprogram is drawn like any other
    assert [(mv.line, mv.end[0]) for mv in m.planner.moves] == [(6, 5.0)]


def test_5_m97_l3_runs_the_local_subprogram_three_times(haas: Dialect) -> None:
    v = final(lines("#100=0", "M97 P50 L3", "#101=#100", "M30", "N50 #100=#100+1", "M99"), haas)
    assert v[100] == 3 and v[101] == 3


def test_5_m97_l_from_a_variable_and_an_expression_p(haas: Dialect) -> None:
    v = final(lines("#100=0", "#1=2", "#2=25", "M97 P[#2*2] L#1", "M30", "N50 #100=#100+1", "M99"), haas)
    assert v[100] == 2


def test_5_m97_shares_the_callers_locals(haas: Dialect) -> None:
    v = final(lines("#1=7", "M97 P10", "#101=#1", "M30", "N10 #100=#1", "#1=8", "M99"), haas)
    assert v[100] == 7 and v[101] == 8


def test_5_m97_levels_count_against_the_subprogram_nesting_limit(haas: Dialect) -> None:
    def chain(depth: int) -> str:
        body = ["M97 P1", "M30"]
        for k in range(1, depth + 1):
            body += [f"N{k} M97 P{k + 1}" if k < depth else f"N{k} #100=1", "M99"]
        return lines(*body)

    assert haas.subprogram_levels == 10
    assert final(chain(10), haas)[100] == 1
    assert alarm(chain(11), haas) == (77, 21)  # the M97 that would open an 11th level


def test_5_m97_and_m98_levels_count_together(haas: Dialect) -> None:
    def program(local_levels: int) -> str:
        chain = [x for k in range(1, local_levels) for x in (f"N{k} M97 P{k + 1}", "M99")]
        return lines("M98 P100", "M30", "O0100", "M97 P1", "M99", *chain, f"N{local_levels} #100=1", "M99")

    assert final(program(9), haas)[100] == 1  # 1 M98 level and 9 M97 levels: 10
    assert alarm(program(10), haas)[0] == 77  # one more


def test_5_m97_to_a_missing_n_is_alarm_128_at_the_call(haas: Dialect) -> None:
    m = run(lines("O0011", "#100=1", "M97 P99", "M30", "N1000 M99"), haas)
    assert m.status == "alarm" and m.alarm is not None
    assert (m.alarm.number, m.alarm.line + 1) == (128, 3)
    assert str(m.alarm.message) == "M97 P99: N99 not found in O0011"
    assert m.alarm.message.zh == "M97 P99：O0011 中未找到 N99"  # type: ignore[attr-defined]


def test_5_m97_without_p_is_alarm_128(haas: Dialect) -> None:
    assert alarm(lines("M97", "M30"), haas) == (128, 1)


def test_5_m97_looks_only_in_the_program_that_calls(haas: Dialect) -> None:
    # N5 is in O0100, the program M98 called; M97 in O0100 finds it, the main program's M97 does not
    program = lines("M98 P100", "M97 P5", "M30", "O0100", "M97 P5", "M99", "N5 #100=1", "M99")
    assert alarm(program, haas) == (128, 2)
    assert final(lines("M98 P100", "M30", "O0100", "M97 P5", "M99", "N5 #100=1", "M99"), haas)[100] == 1


def test_5_m99_p_in_a_local_subprogram_returns_to_that_label_after_the_call(haas: Dialect) -> None:
    v = final(lines("M97 P1000", "#101=1", "N20 #102=1", "M30", "N1000 M99 P20"), haas)
    assert 101 not in v and v[102] == 1


def test_5_m97_is_a_plain_m_code_where_the_switch_is_off(haas: Dialect) -> None:
    assert final(LOCAL_CALL, haas)[101] == 2  # the switch: M97 jumps
    m = run(LOCAL_CALL, "fanuc")
    assert m.status == "completed", m.alarm
    v = m.variables()
    assert v[100] == 1 and v[101] == 1  # no jump: the run ends at M30 before N1000
    assert m.planner.moves == []
