"""docs/semantics.md §4 "Control flow": Haas's conditional jump ``[cond] M99 P n`` (Haas mill
operator's manual 96-8000, macros, docs/profiles.md [H1]), behind ``Dialect.conditional_m99``.

On ``haas`` it is ``IF [cond] GOTO n`` written another way: the jump lands on Nn of the program
that runs it (searching forward, then from its start, as GOTO does) when the condition holds, and
the block does nothing when it does not; the checks see its P as a jump target. Elsewhere it is a
``dialect-feature`` error and the run stops there with alarm 114.
"""

from __future__ import annotations

import pytest

from cncmacro.analysis.indexes.sites import jump_sites
from cncmacro.dialects import get_dialect
from cncmacro.lsp.conditional_m99 import if_goto_rewrite
from cncmacro.syntax.block_parser import parse_block
from cncmacro.syntax.nodes import If, Number, Var, Word
from conftest import block, error
from running import alarm, final, lines, run
from static_helpers import at, check, coded

HAAS = "haas"

# the manual's own line, in a loop that counts #100 up to 10
COUNT_TO_10 = lines(
    "O01000",
    "#100=0",
    "#101=0",
    "N10 #100=#100+1",
    "N50 [#100 LT 10] M99 P10",
    "#101=1",  # reached once, when the condition no longer holds
    "M30",
)


# ---------------------------------------------------------------------------------------------
# reading the form


def test_4_control_flow_conditional_m99_reads_as_if_goto_with_the_p_as_target() -> None:
    b = block("N50 [#100 LT 10] M99 P10")
    [s] = b.statements
    assert isinstance(s, If) and s.then is None and s.m99 is not None
    assert isinstance(s.goto, Number) and s.goto.value == 10
    assert b.label == 50 and b.words == ()  # M99 and P belong to the jump, not to an NC block
    m99, p = s.m99
    assert (m99.letter, p.letter, p.value) == ("M", "P", s.goto)
    assert isinstance(block("[#1 EQ #0]M99P#5").statements[0].goto, Var)  # spaces are insignificant


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("[#1 LT 2] M99", "the conditional M99 needs P n after it"),
        ("[#1 LT 2] M99 Q5", "the conditional M99 needs P n after it"),
        ("[#1 LT 2] G01 X5.", "a condition in brackets starts a block only in the conditional jump"),
        ("[#1] M99 P10", "the condition needs a comparison"),
    ],
)
def test_4_control_flow_conditional_m99_malformed_says_what_the_form_needs(text: str, said: str) -> None:
    problem = error(text)
    assert said in problem.message and "expected a variable name" not in problem.message


def test_4_control_flow_conditional_m99_p_is_a_goto_jump_site() -> None:
    [site] = jump_sites(block("N50 [#100 LT 10] M99 P10"), get_dialect("haas"))
    assert (site.label, site.kind, site.start, site.end) == (10, "GOTO", 22, 24)


# ---------------------------------------------------------------------------------------------
# running it on haas


def test_4_control_flow_haas_conditional_m99_jumps_while_the_condition_holds() -> None:
    assert final(COUNT_TO_10, HAAS) == {100: 10, 101: 1}


def test_4_control_flow_haas_conditional_m99_does_nothing_when_the_condition_fails() -> None:
    text = lines("O01000", "#100=20", "N10 #102=#102+1", "[#100 LT 10] M99 P10", "#101=1", "M30")
    assert final(text, HAAS) == {100: 20, 101: 1, 102: 1}


def test_4_control_flow_haas_conditional_m99_in_a_subprogram_neither_returns_nor_leaves_it() -> None:
    # false: the M99 does not return, the subprogram goes on; true: the jump stays in the
    # subprogram ("it does not return control to the calling program", [H1])
    text = lines(
        "O01000",
        "M98 P200",
        "#111=#110",
        "M30",
        "O00200",
        "[#1 GT 0] M99 P5",  # #1 is vacant: 0 in GT, the condition fails
        "#112=7",
        "N1 #110=#110+1",
        "[#110 LT 3] M99 P1",
        "N5 M99",
    )
    assert final(text, HAAS) == {110: 3, 111: 3, 112: 7}


def test_4_control_flow_haas_conditional_m99_p_from_a_variable_or_an_expression() -> None:
    text = lines("#5=10", "#100=0", "N10 #100=#100+1", "[#100 LT 3] M99 P#5", "N20 [#100 LT 5] M99 P[#5/2+5]", "M30")
    assert final(text, HAAS)[100] == 5


def test_4_control_flow_haas_conditional_m99_to_a_missing_label_is_alarm_128() -> None:
    text = lines("O01000", "#100=1", "[#100 LT 10] M99 P20", "M30")
    m = run(text, HAAS)
    assert m.status == "alarm" and m.alarm is not None
    assert (m.alarm.number, m.alarm.line + 1, str(m.alarm.message)) == (128, 3, "N20 not found in O1000")
    [d] = check(text, HAAS)
    assert (d.code, *at(d)) == ("undefined-label", 3, 18, 20, "error")
    assert d.message.startswith("M99 P20: there is no N20")


def test_4_control_flow_haas_conditional_m99_to_a_vacant_p_is_alarm_128() -> None:
    m = run(lines("[1 LT 2] M99 P#1", "M30"), HAAS)
    assert m.alarm is not None and (m.alarm.number, str(m.alarm.message)) == (
        128,
        "M99 P to a vacant sequence number",
    )
    assert alarm(lines("[1 LT 2] M99 P100000", "M30"), HAAS) == (128, 1)


def test_4_control_flow_haas_conditional_m99_into_a_loop_is_refused_as_a_goto_is() -> None:
    text = lines("#1=0", "[#1 EQ 0] M99 P10", "WHILE [#1 LT 3] DO1", "N10 #1=#1+1", "END1", "M30")
    m = run(text, HAAS)
    assert m.alarm is not None and (m.alarm.number, m.alarm.line + 1) == (126, 2)
    assert str(m.alarm.message) == "M99 P10 jumps into a WHILE/DO loop from outside it"
    assert [d.code for d in check(text, HAAS)] == ["jump-into-loop"]


def test_4_control_flow_haas_conditional_m99_checks_clean() -> None:
    assert check(COUNT_TO_10, HAAS) == []


def test_4_control_flow_haas_conditional_m99_with_nc_words_is_alarm_127() -> None:
    text = lines("[1 LT 2] M99 P1 X5.", "N1 M30")
    assert [d.code for d in check(text, HAAS)] == ["nc-and-macro"]
    assert alarm(text, HAAS) == (127, 1)


# ---------------------------------------------------------------------------------------------
# the other profiles refuse it


@pytest.mark.parametrize(
    ("profile", "title"), [("fanuc-0i", "FANUC 0i"), ("fanuc-30i", "FANUC 30i"), ("gsk980tdi", "GSK")]
)
def test_4_control_flow_conditional_m99_is_a_dialect_feature_and_alarm_114_elsewhere(profile: str, title: str) -> None:
    errors = [d for d in check(COUNT_TO_10, profile) if d.severity == "error"]
    assert [(d.code, *at(d)) for d in errors] == [("dialect-feature", 5, 4, 24, "error")]
    message = errors[0].message
    assert message.startswith("[cond] M99 P n is Haas's conditional jump (the same as IF [cond] GOTO n)")
    assert title in message and "stops at this block with alarm 114" in message
    assert alarm(COUNT_TO_10, profile) == (114, 5)


def test_4_control_flow_conditional_m99_refused_is_said_in_chinese() -> None:
    [d] = coded(check(COUNT_TO_10, "fanuc-0i", locale="zh-CN"), "dialect-feature")
    assert "哈斯系统的条件跳转" in d.message and "报警 114" in d.message


def test_4_control_flow_conditional_m99_refused_elsewhere_still_has_its_label_checked() -> None:
    text = lines("O1000", "#100=1", "[#100 LT 10] M99 P20", "M30")
    assert sorted(d.code for d in check(text, "fanuc-0i")) == ["dialect-feature", "undefined-label"]


def test_4_control_flow_conditional_m99_written_as_if_goto_runs_the_same_elsewhere() -> None:
    # the quick fix the editor offers where the profile has no conditional M99
    rows = COUNT_TO_10.split("\n")
    jump = rows[4]
    assert if_goto_rewrite(parse_block(jump), jump, get_dialect(HAAS)) is None  # haas reads it: nothing to fix
    start, end, new = if_goto_rewrite(parse_block(jump), jump, get_dialect("fanuc-0i")) or (0, 0, "")
    assert new == "IF [#100 LT 10] GOTO 10"
    rows[4] = rows[4][:start] + new + rows[4][end:]
    rewritten = "\n".join(rows)
    assert rows[4] == "N50 IF [#100 LT 10] GOTO 10" and check(rewritten, "fanuc-0i") == []
    assert final(rewritten, "fanuc-0i") == final(COUNT_TO_10, HAAS)


def test_4_control_flow_an_m99_word_alone_is_still_an_m99() -> None:
    b = block("N50 M99 P10")
    assert b.statements == () and [w.letter for w in b.words] == ["M", "P"]
    assert isinstance(b.words[0], Word)
