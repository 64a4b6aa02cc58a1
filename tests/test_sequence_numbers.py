"""Editing sequence numbers (docs/editor.md "Sequence numbers"): renumbering, adding and removing
N labels keeps every jump landing where it landed, which each test proves by running the program
before and after the edit; a jump whose label is computed refuses the edit, naming its line."""

from __future__ import annotations

from cncmacro.analysis.editing.sequence_numbers import (
    OutsideJump,
    SequencePlan,
    add_sequence_numbers,
    remove_unused_sequence_numbers,
    renumber,
)
from cncmacro.dialects import get_dialect
from cncmacro.syntax.block_parser import parse_block
from cncmacro.syntax.program import build_program
from running import final, lines


def _program(text: str):
    return build_program([parse_block(line) for line in text.split("\n")])


def _apply(text: str, plan: SequencePlan) -> str:
    assert plan.error is None and not plan.blockers, (plan.error, plan.blockers)
    rows = text.split("\n")
    for c in sorted(plan.changes, key=lambda c: (c.line, -c.start)):
        row = rows[c.line]
        rows[c.line] = row[: c.start] + c.text + row[c.end :]
    return "\n".join(rows)


def _renumbered(text: str, dialect: str = "fanuc", **kw: object) -> str:
    d = get_dialect(dialect)
    return _apply(text, renumber(_program(text), d, **kw))  # type: ignore[arg-type]


LOOPING = lines(
    "O1000",
    "#1=0",
    "N3 #1=#1+1",
    "IF [#1 LT 3] GOTO 3",
    "GOTO 7",
    "#2=99",
    "N7 #3=#1*2",
    "M30",
)


def test_renumbering_rewrites_every_goto_and_keeps_the_run():
    after = _renumbered(LOOPING, step=10)
    assert "N10 #1=#1+1" in after and "IF [#1 LT 3] GOTO 10" in after
    assert "GOTO 20" in after and "N20 #3=#1*2" in after
    assert final(after) == final(LOOPING)


def test_renumbering_follows_the_label_a_jump_lands_on_among_duplicates():
    # GOTO 5 searches forward first: the first jumps to line 4's N5, the second to line 6's.
    text = lines("O1000", "#1=0", "GOTO 5", "N5 #1=#1+1", "GOTO 6", "N6 GOTO 5", "N5 #1=#1+10", "M30")
    after = _renumbered(text, step=10)
    assert after.splitlines()[2] == "GOTO 10"
    assert after.splitlines()[5] == "N20 GOTO 30"
    assert final(after) == final(text)


def test_renumbering_a_selection_skips_numbers_the_other_labels_use():
    text = lines("O1000", "N10 #1=1", "N3 #2=2", "N4 GOTO 3", "N30 M30")
    after = _renumbered(text, step=10, lines=range(2, 4))
    assert after.splitlines()[1:5] == ["N10 #1=1", "N20 #2=2", "N40 GOTO 20", "N30 M30"]


def test_new_numbers_do_not_make_a_missing_label_appear():
    # GOTO 20 finds no N20 (alarm 128): no label may become N20.
    text = lines("O1000", "N1 #1=1", "N2 IF [#1 EQ 2] GOTO 20", "M30")
    after = _renumbered(text, step=10)
    assert after.splitlines()[1:3] == ["N10 #1=1", "N30 IF [#1 EQ 2] GOTO 20"]


def test_m99_p_m98_q_and_h_codes_are_rewritten():
    text = lines(
        "O1000",
        "M98 P3000 Q8",
        "M98 P2000",
        "#1=1",
        "N5 #2=5",
        "M30",
        "O2000",
        "#3=#3+1",
        "M99 P5",
        "O3000",
        "#5=1",
        "N8 #4=8",
        "M99",
    )
    after = _renumbered(text, step=10)
    assert "M98 P3000 Q10" in after and "M99 P10" in after and "N10 #2=5" in after
    assert final(after) == final(text)
    gsk = lines("O1000", "#100=0", "N7 #100=#100+1", "G65 H84 P7 Q#100 R3", "M30")
    after = _renumbered(gsk, "gsk980tdi", step=10)
    assert "G65 H84 P10 Q#100 R3" in after
    assert final(after, "gsk980tdi") == final(gsk, "gsk980tdi")


def test_haas_m97_p_is_rewritten():
    text = lines("O1000", "M97 P4", "M30", "N4 #1=4", "M99")
    after = _renumbered(text, "haas", step=10)
    assert "M97 P10" in after and "N10 #1=4" in after
    assert final(after, "haas") == final(text, "haas")


def test_haas_conditional_m99_p_is_rewritten_as_a_goto():
    # docs/semantics.md §4: [cond] M99 P n lands as GOTO n does
    text = lines("O1000", "#1=0", "N4 #1=#1+1", "N8 [#1 LT 3] M99 P4", "M30")
    after = _renumbered(text, "haas", step=10)
    assert "N10 #1=#1+1" in after and "N20 [#1 LT 3] M99 P10" in after
    assert final(after, "haas") == final(text, "haas") == {1: 3}


def test_a_computed_goto_refuses_and_names_its_line():
    text = lines("O1000", "#1=20", "GOTO #1", "N20 #2=1", "M30")
    plan = renumber(_program(text), get_dialect("fanuc"), step=10)
    assert not plan.changes and len(plan.blockers) == 1
    assert plan.blockers[0].line == 2 and "line 3" in plan.blockers[0].message
    kept = renumber(_program(text), get_dialect("fanuc"), step=10, keep_computed=True)
    assert not kept.changes and kept.kept == [3]


def test_a_gsk_h_code_jump_whose_p_is_a_variable_refuses_and_names_its_line():
    # G65 H81 P#1 Q#100 R5 jumps to the N label whose number #1 holds when #100 equals 5.
    text = lines("O1000", "#1=20", "#100=5", "G65 H81 P#1 Q#100 R5", "#2=1", "N20 #3=3", "M30")
    assert 2 not in final(text, "gsk980tdi") and final(text, "gsk980tdi")[3] == 3
    plan = renumber(_program(text), get_dialect("gsk980tdi"), step=10)
    assert not plan.changes and [b.line for b in plan.blockers] == [3]
    assert "line 4" in plan.blockers[0].message and "computed" in plan.blockers[0].message
    kept = renumber(_program(text), get_dialect("gsk980tdi"), step=10, keep_computed=True)
    assert not kept.changes and kept.kept == [5]


def test_a_computed_goto_in_another_program_does_not_refuse():
    text = lines("O1000", "N5 M98 P2000", "M30", "O2000", "#1=20", "GOTO [#1+10]", "N30 M99")
    plan = renumber(_program(text), get_dialect("fanuc"), step=10, lines=range(0, 3))
    assert not plan.blockers and [c.text for c in plan.changes] == ["N10"]
    chinese = renumber(_program(text), get_dialect("fanuc"), step=10, locale="zh-CN")
    assert "第 6 行" in chinese.blockers[0].message


def test_labels_jumps_of_other_files_land_on_are_kept():
    text = lines("O1000", "N5 #1=1", "N6 #2=2", "M30")
    plan = renumber(_program(text), get_dialect("fanuc"), step=10, outside=[OutsideJump(0, 6, "O2000:3")])
    assert _apply(text, plan).splitlines()[1:3] == ["N10 #1=1", "N6 #2=2"]


def test_adding_sequence_numbers_numbers_every_block_that_runs():
    text = lines("O1000 (T)", "(A COMMENT)", "#1=1", "N20 #2=2", "G0 X1.", "", "M30", "%")
    plan = add_sequence_numbers(_program(text), get_dialect("fanuc"), step=10)
    after = _apply(text, plan)
    assert after.splitlines()[:7] == ["O1000 (T)", "(A COMMENT)", "N10 #1=1", "N20 #2=2", "N30 G0 X1.", "", "N40 M30"]
    assert final(after) == final(text)


def test_removing_unused_sequence_numbers_keeps_the_jumped_to_ones():
    after = _apply(LOOPING, remove_unused_sequence_numbers(_program(LOOPING), get_dialect("fanuc")))
    assert after == LOOPING
    text = lines("O1000", "N1 #1=1", "N2 GOTO 4", "N3 #2=2", "N4 M30")
    after = _apply(text, remove_unused_sequence_numbers(_program(text), get_dialect("fanuc")))
    assert after.splitlines()[1:5] == ["#1=1", "GOTO 4", "#2=2", "N4 M30"]
    assert final(after) == final(text)


def test_m98_q_into_a_program_named_by_a_variable_refuses():
    text = lines("O1000", "#1=1000", "M98 P#1 Q10", "M30", "N10 #2=1", "M99")
    plan = renumber(_program(text), get_dialect("fanuc"), step=5)
    assert [b.line for b in plan.blockers] == [2]


def test_an_m99_p_whose_callers_labels_would_part_ways_refuses():
    # O2000 returns to N5 of both O1000 and O3000: renumbering O1000 alone would split them.
    text = lines("O1000", "M98 P2000", "N5 M30", "O2000", "M99 P5", "O3000", "#1=1", "M98 P2000", "N5 M99")
    plan = renumber(_program(text), get_dialect("fanuc"), step=10, lines=range(0, 3), keep_computed=True)
    assert [(b.line, b.keepable) for b in plan.blockers] == [(4, False)] and not plan.changes
    whole = _renumbered(text, step=10)  # both become N10: the return follows them
    assert whole.splitlines()[4] == "M99 P10" and whole.splitlines()[8] == "N10 M99"


def test_an_m99_p_of_a_lone_program_keeps_its_label():
    # Run as a main program, M99 P5 jumps to its own N5; called from elsewhere, to the caller's N5.
    text = lines("O2000", "N3 #1=#1+1", "N5 #2=2", "M99 P5")
    assert _renumbered(text, step=10).splitlines()[1:4] == ["N10 #1=#1+1", "N5 #2=2", "M99 P5"]
    computed = lines("O2000", "N3 #1=#1+1", "M99 P#1")
    assert [b.line for b in renumber(_program(computed), get_dialect("fanuc"), step=10).blockers] == [2]


LATHE_SHAPE = lines(
    "O0001",
    "G00 X40. Z2.",
    "G71 U2. R0.5",
    "N5 G71 P10 Q20 U0.4 W0.1 F0.2",
    "N10 G00 X30.",
    "G01 Z-20. F0.1",
    "N20 X40.",
    "#100=#5001",
    "G70 P10 Q20",
    "#101=#5001",
    "M30",
)


def test_the_labels_of_a_lathe_cycles_shape_are_kept_and_renumbered_with_its_p_and_q() -> None:
    # G71/G70 P10 Q20 name the shape N10..N20: removing unused labels keeps them (only N5 goes);
    # renumbering rewrites P and Q with them, and the run is the same.
    d = get_dialect("gsk980tdi")
    removed = _apply(LATHE_SHAPE, remove_unused_sequence_numbers(_program(LATHE_SHAPE), d))
    assert "N10 G00 X30." in removed and "N20 X40." in removed and "N5 " not in removed
    renumbered = _renumbered(LATHE_SHAPE, "gsk980tdi", step=100)
    assert "G71 P200 Q300" in renumbered and "G70 P200 Q300" in renumbered
    assert "N200 G00 X30." in renumbered and "N300 X40." in renumbered
    for text in (removed, renumbered):
        assert final(text, "gsk980tdi") == final(LATHE_SHAPE, "gsk980tdi")
