"""A line of literal words that a program repeats word for word (a lathe program's cycle and
shape blocks, part after part) is compiled once for the file (``CompiledFile.plain_words``).
Each place it is written still goes on to its own next line, keeps its own sequence number and
starts from where the tool is there."""

from __future__ import annotations

from running import lines, run


def test_a_line_repeated_word_for_word_goes_on_to_the_line_after_each_place_it_is_written() -> None:
    # M05 is not a plain motion line, so every M05 below is the one compiled block; after each
    # the run must go on below that M05 (a blank line and a comment are passed over), and a
    # labelled M05 sets its own sequence number
    m = run(
        lines(
            "O0001",
            "#1=0",
            "M05",
            "#1=#1+1",
            "(a comment line)",
            "",
            "M05",
            "",
            "#1=#1+10",
            "N30 M05",
            "#1=#1+100",
            "N40 M05",
            "#2=#4114",
            "#1=#1+1000",
            "M30",
        )
    )
    assert m.status == "completed", m.alarm
    assert m.variables()[1] == 1111.0
    assert m.variables()[2] == 40.0


def test_a_repeated_single_cycle_block_cuts_from_where_the_tool_is_each_time() -> None:
    # G90 X30. Z-20.: rapid to X30 at the start's Z, cut to Z-20, cut out to the start's X,
    # rapid back to the start, from (X40, Z2) the first time and from (X50, Z5) the second
    m = run(
        lines(
            "O0001",
            "G99 G97 S500 M03",
            "G00 X40. Z2.",
            "G90 X30. Z-20. F0.2",
            "G00 X50. Z5.",
            "G90 X30. Z-20. F0.2",
            "M30",
        ),
        "fanuc-0i-lathe",
    )
    assert m.status == "completed", m.alarm
    cycles = [mv for mv in m.planner.moves if mv.legs is not None]
    assert [mv.line for mv in cycles] == [3, 5]
    first, second = ([(leg.rapid, leg.end[:2]) for leg in mv.legs or ()] for mv in cycles)
    assert first == [(True, (30.0, 2.0)), (False, (30.0, -20.0)), (False, (40.0, -20.0)), (True, (40.0, 2.0))]
    assert second == [(True, (30.0, 5.0)), (False, (30.0, -20.0)), (False, (50.0, -20.0)), (True, (50.0, 5.0))]
