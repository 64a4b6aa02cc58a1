"""docs/semantics.md §4 (control flow) as the analysis finds it: a run that comes back to the same
place with every variable, position and frame unchanged can never end (the interpreter is
deterministic), so it stops there with a ``run-limit`` finding that says so, long before the
block budget; a loop that changes anything, or reads the clock, runs on as the control would."""

from __future__ import annotations

from pathlib import Path

from analysis_helpers import analyse_files as analyse
from cncmacro.analysis.diagnostics import Diagnostic

ENDLESS = "an endless loop"


def limits(diags: list[Diagnostic]) -> list[tuple[str, int, str]]:
    """(file name, 1-based line, message) of each ``run-limit`` and ``endless-loop`` finding."""
    return [(Path(d.file).name, d.line + 1, d.message) for d in diags if d.code in ("run-limit", "endless-loop")]


def endless_at(tmp_path: Path, files: dict[str, str], **kw: object) -> tuple[str, int]:
    [(name, line, message)] = limits(analyse(tmp_path, files, **kw))
    assert message.startswith(ENDLESS) and f"line {line} comes back" in message and "unchanged" in message
    return name, line


def test_4_control_flow_a_goto_to_its_own_line_is_an_endless_loop(tmp_path):
    assert endless_at(tmp_path, {"O0001.nc": "O0001\nN1 GOTO1\nM30\n"}) == ("O0001.nc", 2)


def test_4_control_flow_an_if_goto_whose_condition_never_changes_is_an_endless_loop(tmp_path):
    text = "O0001\n#100=7.584\nG01 X10. F100.\nN348 IF [#100 LE 59.8] GOTO 348\nM30\n"
    assert endless_at(tmp_path, {"O0001.nc": text}) == ("O0001.nc", 4)
    assert limits(analyse(tmp_path, {"O0001.nc": text.replace("GOTO 348", "GOTO 349\nN349")})) == []


def test_4_control_flow_a_while_loop_that_changes_nothing_is_an_endless_loop(tmp_path):
    text = "O0001\n#1=1\nWHILE[#1 LT 2]DO1\n#2=5\nG00 X#2\nEND1\nM30\n"
    assert endless_at(tmp_path, {"O0001.nc": text}) == ("O0001.nc", 6)
    assert endless_at(tmp_path, {"O0001.nc": "O0001\nDO1\nEND1\nM30\n"}) == ("O0001.nc", 3)


def test_5_calls_an_m99_p_back_to_the_call_is_an_endless_loop(tmp_path):
    files = {"MAIN.nc": "O0001\n#1=3\nN10 M98 P100\nM30\n", "O0100.nc": "O0100\n#2=#1\nM99 P10\n"}
    name, line = endless_at(tmp_path, files)
    assert (name, line) in {("MAIN.nc", 3), ("O0100.nc", 2)}


def test_4_control_flow_a_loop_that_counts_to_its_end_is_no_endless_loop(tmp_path):
    text = "O0001\n#1=0\nN1 #1=#1+1\nIF[#1 LT 5000] GOTO1\nM30\n"
    assert limits(analyse(tmp_path, {"O0001.nc": text})) == []
    text = "O0001\n#1=0\nWHILE[#1 LT 5000]DO1\n#1=#1+1\nEND1\nM30\n"
    assert limits(analyse(tmp_path, {"O0001.nc": text})) == []


def test_4_control_flow_a_loop_that_waits_on_the_clock_is_no_endless_loop(tmp_path):
    """Only the clock changes from one pass to the next, and the program reads it (#3001)."""
    text = "O0001\n#3001=0\nN1 G04 X0.01\nIF[#3001 LT 5000] GOTO1\n#1=1\nM30\n"
    assert limits(analyse(tmp_path, {"O0001.nc": text})) == []
    unread = "O0001\n#1=0\nN1 G04 X0.01\nIF[#1 LT 5000] GOTO1\nM30\n"
    assert endless_at(tmp_path, {"O0001.nc": unread}) == ("O0001.nc", 4)


def test_4_control_flow_a_counting_endless_loop_still_stops_at_the_block_budget(tmp_path):
    [(_, _, message)] = limits(analyse(tmp_path, {"O0001.nc": "O0001\nN1 #1=#1+1\nGOTO1\nM30\n"}, max_blocks=5000))
    assert "after 5000 blocks" in message and not message.startswith(ENDLESS)


def test_4_control_flow_an_endless_loop_is_found_in_chinese_too(tmp_path):
    [(_, line, message)] = limits(analyse(tmp_path, {"O0001.nc": "O0001\nN1 GOTO1\nM30\n"}, locale="zh-cn"))
    assert line == 2 and message.startswith("死循环：第 2 行")


def test_4_control_flow_an_edit_before_an_endless_loop_finds_it_again_as_from_scratch(tmp_path):
    """The incremental analysis takes the rest of the run over from before the edit (docs/design.md
    "How the analysis stays incremental"), the endless loop included."""
    from cncmacro.analysis.workspace import WorkspaceAnalysis
    from cncmacro.library.machine_file import MachineSettings

    lines = ["O0001", "#6=0", "#5=1", "#5=0", "WHILE[#1 LT 3000]DO1", "#1=#1+1", "END1", "#100=7.5+#5",
             "N348 IF [#100 LE 59.8] GOTO 348", "M30"]  # fmt: skip
    path = str(tmp_path / "O0001.nc")

    def found(ws: WorkspaceAnalysis) -> list[tuple[int, str, str]]:
        result = ws.analyze(path)
        assert result is not None
        return sorted((d.line, d.code, d.message) for ds in result.diagnostics.values() for d in ds)

    ws = WorkspaceAnalysis(settings=MachineSettings(date=20261122, time=80000))
    ws.open(path, "\n".join(lines), 1)
    assert [(line, code) for line, code, _ in found(ws)] == [(8, "endless-loop"), (9, "not-executed")]
    ws.change(path, 2, 3, 2, 4, "2", 2)
    lines[2] = "#5=2"
    again = found(ws)
    scratch = WorkspaceAnalysis(settings=MachineSettings(date=20261122, time=80000))
    scratch.open(path, "\n".join(lines), 1)
    assert again == found(scratch) and again[0][2].startswith(ENDLESS)
    [run] = ws.runs.values()
    assert run.rerun_blocks < 5000  # the loops were not run again to their end


def test_5_calls_a_haas_main_programs_loop_back_by_m99_p_is_a_production_loop_not_reported(tmp_path):
    """Haas branches to N10 at a main program's M99 P10 for ever: a warm-up that changes nothing,
    or a part loop that counts its parts, is the shop's production loop, reported by nothing."""
    warm_up = "O01000\nG00 X0 Y0\nN10 G01 X10. F100.\nG01 X0\nN50 M99 P10\nM30\n"
    counted = "O01000\n#100=0\nN10 #100=#100+1\nG00 X#100\nN50 M99 P10\nM30\n"
    for text in (warm_up, counted):
        diags = analyse(tmp_path, {"O01000.nc": text}, "haas", max_blocks=20_000)
        assert [(d.code, d.message) for d in diags if d.severity != "hint"] == []
    # the same warm-up closed by GOTO 10 is still the endless loop it is
    goto = warm_up.replace("M99 P10", "GOTO 10")
    assert endless_at(tmp_path, {"O01000.nc": goto}, dialect="haas") == ("O01000.nc", 5)


def test_4_control_flow_a_wait_on_the_timer_is_no_loop_the_control_never_leaves(tmp_path):
    # #3001 counts milliseconds on the control, so the wait ends after 3 s there; the simulated
    # clock does not run while no block moves, so the run cannot leave it, and says only that
    text = "O0001\n#3001=0\nN10 IF [#3001 LT 3000] GOTO 10\nG00 X10.\nM30\n"
    [(name, line, message)] = limits(analyse(tmp_path, {"O0001.nc": text}))
    assert (name, line) == ("O0001.nc", 3)
    assert not message.startswith(ENDLESS) and "never leave" not in message
    assert "the control leaves it when what the machine changes (a timer, an input signal) ends it" in message
