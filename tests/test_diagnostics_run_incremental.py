"""docs/design.md "How the analysis stays incremental": after random edits, the incremental
analysis equals an analysis from scratch (diagnostics and the values shown per line)."""

from __future__ import annotations

from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from cncmacro.analysis.runs import run_checks, unreached
from cncmacro.analysis.workspace import WorkspaceAnalysis
from cncmacro.library.machine_file import MachineSettings

MAIN = [
    "O0001",
    "#1=0",
    "#2=3",
    "WHILE[#1 LT #2] DO1",
    "G01 X#1 Y1. F100.",
    "G65 P9001 X#1",
    "#1=#1+1",
    "END1",
    "IF[#2 GT 5] GOTO 20",
    "#5=10/#2",
    "N20 G00 X0 Y0",
    "M30",
]
MACRO = ["O9001", "#100=#24+#25", "G01 X#24", "M99"]
POOL = [
    "#2=0", "#2=7", "#1=#1+2", "G01 X5. Y6.", "", "(NOTE)", "#3000=1(STOP)", "GOTO 20", "N20 #9=1",
    "#6=SQRT[#2-4]", "G65 P9001 Y#2", "#7=#24", "M99", "WHILE[#3 LT 2] DO2", "#3=#3+1", "END2", "N30",
]  # fmt: skip

edit = st.tuples(
    st.sampled_from(["replace", "insert", "delete", "type", "enter", "join", "paste"]),
    st.sampled_from(["MAIN.nc", "O9001.nc"]),
    st.integers(0, 20),
    st.sampled_from(POOL),
)


def snapshot(ws: WorkspaceAnalysis, path: str) -> tuple[object, object]:
    result = ws.analyze(path)
    assert result is not None
    diags = sorted(
        (Path(d.file).name, d.line, d.column, d.end_line, d.end_column, d.severity, d.code, d.message,
         tuple((Path(r.file).name, r.line) for r in d.related))
        for ds in result.diagnostics.values() for d in ds
    )  # fmt: skip
    # an unknown value (NaN: a kept common, docs/semantics.md §2) equals no other, so it is compared by name
    values = {(Path(f).name, line): [(n, "unknown" if x is not None and x != x else x) for n, x in v]
              for f, lines in result.values.items() for line, v in lines.items()}  # fmt: skip
    # the cycle time (analysis/runs/cycle_lenses.py): elapsed per line, totals per program and tool change,
    # rounded where a converged run's sums may differ from a fresh run's in the last bits
    timing = {
        (Path(f).name, kind, line): tuple(round(x, 6) for x in value)
        for f, t in result.timing.items()
        for kind, rows in (
            ("elapsed", {line: (seconds,) for line, seconds in t.elapsed.items()}),
            ("program", {line: (v.seconds, v.cut, v.rapid) for line, v in t.programs.items()}),
            ("tool", {line: (v.seconds, v.cut, v.rapid) for line, (_, v) in t.tools.items()}),
        )
        for line, value in rows.items()
    }
    return diags, (values, timing)


def fresh(tmp: Path, texts: dict[str, str]) -> WorkspaceAnalysis:
    ws = WorkspaceAnalysis(settings=MachineSettings(date=20261122, time=80000), max_blocks=400)
    for name, text in texts.items():
        ws.open(str(tmp / name), text, 0)
    return ws


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(edits=st.lists(edit, min_size=1, max_size=6), analyse_between=st.booleans())
def test_incremental_analysis_equals_analysis_from_scratch(tmp_path, monkeypatch, edits, analyse_between):
    monkeypatch.setattr(run_checks, "CHUNK", 7)  # many checkpoints in small programs
    monkeypatch.setattr(unreached, "_WHOLE_FILE_SHARE", 0)  # not-executed ranges kept, never scanned whole
    texts = {"MAIN.nc": "\n".join(MAIN), "O9001.nc": "\n".join(MACRO)}
    ws = fresh(tmp_path, texts)
    main = str(tmp_path / "MAIN.nc")
    snapshot(ws, main)
    for version, (kind, name, at, line) in enumerate(edits, start=1):
        path = str(tmp_path / name)
        doc = ws.document(path)
        assert doc is not None
        n = len(doc.lines)
        at = min(at, n - 1)
        if kind == "replace":
            ws.change(path, at, 0, at, len(doc.lines[at]), line, version)
        elif kind == "insert":
            ws.change(path, at, 0, at, 0, line + "\n", version)
        elif kind == "delete" and n > 1:
            ws.change(path, at, 0, at + 1, 0, "", version)
        elif kind == "type":
            col = len(doc.lines[at]) // 2
            ws.change(path, at, col, at, col, "1", version)
        elif kind == "enter":  # at the end of the line, or splitting it
            col = len(doc.lines[at]) if len(line) % 2 else len(doc.lines[at]) // 2
            ws.change(path, at, col, at, col, "\n", version)
        elif kind == "join" and at + 1 < n:
            ws.change(path, at, len(doc.lines[at]), at + 1, 0, "", version)
        elif kind == "paste":  # two lines over the end of one and the start of the next
            ws.change(path, at, 0, min(at + 1, n - 1), 0, line + "\n#8=8\n", version)
        if analyse_between:
            snapshot(ws, main)
    got = snapshot(ws, main)
    final = {name: ws.document(str(tmp_path / name)).text for name in texts}  # type: ignore[union-attr]
    assert got == snapshot(fresh(tmp_path, final), main)


SKIPPING = [
    "O0001", "#1=0", "IF[#1 EQ 0] GOTO 10", "G01 X1.", "", "G01 X2.", "N10 M98 P0002", "WHILE[#1 LT 2] DO1",
    "#1=#1+1", "IF[#1 GT 5] GOTO 30", "G01 Y1.", "END1", "GOTO 40", "N30 G01 Z1.", "(NOTE)", "G01 Z2.",
    "N40 M30", "O0002", "IF[#1 GE 0] GOTO 60", "G01 X9.", "N60 M99",
]  # fmt: skip
# The edits include starting and stopping the call of O0002: a program a run enters for the
# first time gets its skipped blocks reported, one it no longer enters loses them.
SKIP_POOL = ["#1=1", "#1=7", "", "G01 X5.", "(NOTE)", "GOTO 40", "IF[#1 EQ 1] GOTO 30", "/G01 X3.", "%", "M30",
             "M98 P0002", "N10 G00 X0"]  # fmt: skip


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(edits=st.lists(st.tuples(st.integers(1, 20), st.sampled_from(SKIP_POOL), st.booleans()), min_size=1,
                      max_size=8))  # fmt: skip
def test_not_executed_ranges_after_edits_equal_ranges_from_scratch(tmp_path, monkeypatch, edits):
    """docs/semantics.md §4 (control flow decides what runs): the blocks that jumps and loops skip
    are reported as not executed, and after any typing (lines replaced in place, so that the
    ranges are kept and updated around the changed lines) exactly as a fresh analysis would."""
    monkeypatch.setattr(run_checks, "CHUNK", 5)
    monkeypatch.setattr(unreached, "_WHOLE_FILE_SHARE", 0)
    ws = fresh(tmp_path, {"MAIN.nc": "\n".join(SKIPPING)})
    main = str(tmp_path / "MAIN.nc")
    first = snapshot(ws, main)[0]
    assert any(d[6] == "not-executed" for d in first)  # type: ignore[union-attr]
    for version, (at, line, analyse) in enumerate(edits, start=1):
        doc = ws.document(main)
        assert doc is not None
        at = min(at, len(doc.lines) - 1)
        ws.change(main, at, 0, at, len(doc.lines[at]), line, version)
        if analyse:
            snapshot(ws, main)
    final = ws.document(main).text  # type: ignore[union-attr]
    assert snapshot(ws, main) == snapshot(fresh(tmp_path, {"MAIN.nc": final}), main)


def test_result_carries_the_version_it_came_from(tmp_path):
    ws = fresh(tmp_path, {"MAIN.nc": "\n".join(MAIN), "O9001.nc": "\n".join(MACRO)})
    main = str(tmp_path / "MAIN.nc")
    ws.change(main, 1, 0, 1, 4, "#1=1", 7)
    result = ws.analyze(main)
    assert result is not None and result.version == 7


def test_a_cancelled_analysis_returns_none_and_a_later_one_completes(tmp_path, monkeypatch):
    monkeypatch.setattr(run_checks, "CHUNK", 7)
    ws = fresh(tmp_path, {"MAIN.nc": "\n".join(MAIN), "O9001.nc": "\n".join(MACRO)})
    main = str(tmp_path / "MAIN.nc")
    assert ws.analyze(main, should_cancel=lambda: True) is None
    result = ws.analyze(main)
    assert result is not None
    assert not any(d.code == "division-by-zero" for ds in result.diagnostics.values() for d in ds)


def test_values_written_on_a_line_are_kept_for_the_editor(tmp_path):
    ws = fresh(tmp_path, {"MAIN.nc": "O0001\n#1=2\n#3=#1*4\nM30\n"})
    result = ws.analyze(str(tmp_path / "MAIN.nc"))
    assert result is not None
    assert result.values[str(tmp_path / "MAIN.nc")] == {1: [(1, 2.0)], 2: [(3, 8.0)]}


LONG = ["O0001", "#1=0", *[f"G01 X{k}. Y1. F100." for k in range(60)], "WHILE[#1 LT 30] DO1", "#1=#1+1",
        "G01 X#1", "END1", *[f"#{100 + k}=#1+{k}" for k in range(20)], "M30"]  # fmt: skip


def test_4_control_flow_enter_late_in_a_main_program_resumes_the_run(tmp_path, monkeypatch):
    """A line added after the loop, which runs late, keeps the run before it: the run is not
    started again, and the result equals an analysis from scratch."""
    monkeypatch.setattr(run_checks, "CHUNK", 10)
    ws = fresh(tmp_path, {"MAIN.nc": "\n".join(LONG)})
    main = str(tmp_path / "MAIN.nc")
    snapshot(ws, main)
    restarts = []
    original = run_checks.EntryRun.restart
    monkeypatch.setattr(run_checks.EntryRun, "restart", lambda self: (restarts.append(1), original(self))[1])
    at = len(LONG) - 5
    ws.change(main, at, len(LONG[at]), at, len(LONG[at]), "\n#150=1/[#1-30]", 1)  # Enter, then a new line
    got = snapshot(ws, main)
    assert restarts == []
    assert ("MAIN.nc", at + 1, "division-by-zero") in [(d[0], d[1], d[6]) for d in got[0]]
    assert got == snapshot(fresh(tmp_path, {"MAIN.nc": ws.document(main).text}), main)  # type: ignore[union-attr]


# ---------------------------------------------------------------- converging with the earlier run
# After an edit the resumed run takes over the rest of the run before it as soon as the machine
# state is the same again and the edited lines do not run any more (run_convergence.py).

STRAIGHT = ["O0001", "#1=5", *[f"G01 X{k}. Y{k % 7}. F100." for k in range(300)], "#2=#1*2", "M30"]
LOOPED = ["O0001", "#1=0", "#5=0", "WHILE[#1 LT 40] DO1", "G01 X#1 Y2.", "#5=#5+1", "#1=#1+1", "END1",
          *[f"G01 X{k}. Y1." for k in range(60)], "#6=10/[#5-40]", "M30"]  # fmt: skip
CALLED_TWICE = ["O0001", "G65 P9002 A1.", *[f"G01 X{k}. Y1." for k in range(60)], "G65 P9002 A2.",
                *[f"G01 X{k}. Y2." for k in range(60)], "#7=1/[#100-2]", "M30"]  # fmt: skip
MACRO_TWICE = ["O9002", "#100=#1", "G01 X#1 Y3.", "M99"]
CLOCK = ["O0001", "#3001=0", *[f"G01 X{k}. Y1. F100." for k in range(60)], "#8=#3001",
         *[f"G01 X{k}. Y2. F100." for k in range(60)], "IF[#8 GT 1000000] THEN #9=1/0", "M30"]  # fmt: skip
INDIRECT = ["O0001", "#3001=0", "#20=3001", *[f"G01 X{k}. Y1. F100." for k in range(60)], "#8=#[#20]",
            *[f"G01 X{k}. Y2. F100." for k in range(60)], "IF[#8 GT 1000000] THEN #9=1/0", "M30"]  # fmt: skip
SKIPPED = ["O0001", "#1=1", "IF[#1 EQ 1] GOTO 10", *[f"G01 X{k}. Y3." for k in range(20)], "N10 #2=1",
           *[f"G01 X{k}. Y1." for k in range(60)], "#3=#2/[#1-1]", "M30"]  # fmt: skip
# a CAM program with a sequence number every tenth line and a jump over some of them
LABELLED = ["O0001", "#1=1", "IF[#1 EQ 1] GOTO 40",
            *[f"N{k} G01 X{k}. Y1." if k % 10 == 0 else f"G01 X{k}. Y2." for k in range(1, 150)],
            "#3=#1/[#1-1]", "M30"]  # fmt: skip
PROGRAMS = {"STRAIGHT": STRAIGHT, "LOOPED": LOOPED, "CALLED_TWICE": CALLED_TWICE, "CLOCK": CLOCK,
            "INDIRECT": INDIRECT, "SKIPPED": SKIPPED, "LABELLED": LABELLED}  # fmt: skip
# the label lines are typed into too, keeping their label, also while unfinished (``X1-2.``)
EDITS = ["G01 X1. Y1.", "G01 X9000. Y1.", "#1=7", "#1=1", "#1=0", "#5=3", "#100=2", "#100=#1+1", "",
         "G65 P9002 A3.", "#2=0", "G01 X2. Y2. F5.", "IF[#1 EQ 1] GOTO 10", "#20=1", "#3001=500",
         "N10 #2=2", "N40 G01 X1-2.", "N40 G01 X12. Y1.", "N10 G01 X5. Y5."]  # fmt: skip


def _open_program(tmp: Path, name: str, lines: list[str]) -> tuple[WorkspaceAnalysis, str]:
    texts = {"MAIN.nc": "\n".join(lines), "O9002.nc": "\n".join(MACRO_TWICE)}
    ws = WorkspaceAnalysis(settings=MachineSettings(date=20261122, time=80000), max_blocks=2000)
    for file, text in texts.items():
        (tmp / file).write_text(text)  # on disk too, where G65 looks for the macro (the editor's text wins)
        ws.open(str(tmp / file), text, 0)
    return ws, str(tmp / "MAIN.nc")


def _same_as_from_scratch(tmp: Path, ws: WorkspaceAnalysis, main: str) -> None:
    got = snapshot(ws, main)
    texts = {name: ws.document(str(tmp / name)).text for name in ("MAIN.nc", "O9002.nc")}  # type: ignore[union-attr]
    scratch = WorkspaceAnalysis(settings=MachineSettings(date=20261122, time=80000), max_blocks=2000)
    for file, text in texts.items():
        scratch.open(str(tmp / file), text, 0)
    assert got == snapshot(scratch, main)


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(name=st.sampled_from(sorted(PROGRAMS)), edits=st.lists(st.tuples(st.integers(1, 200), st.sampled_from(EDITS),
       st.booleans()), min_size=1, max_size=4), chunk=st.sampled_from([5, 7, 16]))  # fmt: skip
def test_4_control_flow_converging_runs_equal_runs_from_scratch(tmp_path, monkeypatch, name, edits, chunk):
    """Line edits in programs where the resumed run converges with the earlier one (a straight
    line, a loop, a macro called twice) and where it must not (the edited line runs again, the
    program reads the clock, directly or through indirection): the result is always the same
    as an analysis from scratch."""
    monkeypatch.setattr(run_checks, "CHUNK", chunk)
    ws, main = _open_program(tmp_path, name, PROGRAMS[name])
    snapshot(ws, main)
    for version, (at, text, in_macro) in enumerate(edits, start=1):
        path = str(tmp_path / "O9002.nc") if in_macro and name == "CALLED_TWICE" else main
        doc = ws.document(path)
        assert doc is not None
        at = min(at, len(doc.lines) - 2)
        ws.change(path, at, 0, at, len(doc.lines[at]), text, version)
        _same_as_from_scratch(tmp_path, ws, main)


def _edit(ws: WorkspaceAnalysis, main: str, line: int, text: str, version: int) -> None:
    doc = ws.document(main)
    assert doc is not None
    ws.change(main, line, 0, line, len(doc.lines[line]), text, version)


def _run_of(ws: WorkspaceAnalysis) -> run_checks.EntryRun:
    return next(iter(ws.runs.values()))


def test_4_control_flow_an_edit_near_the_start_of_a_long_program_runs_little_again(tmp_path, monkeypatch):
    """A coordinate typed near the start of a long straight program: the resumed run converges
    at its next checkpoint and takes the rest over (a few chunks run again, not the program)."""
    monkeypatch.setattr(run_checks, "CHUNK", 10)
    ws, main = _open_program(tmp_path, "STRAIGHT", STRAIGHT)
    snapshot(ws, main)
    total = _run_of(ws).machine.blocks
    _edit(ws, main, 3, "G01 X77. Y2. F100.", 1)
    _same_as_from_scratch(tmp_path, ws, main)
    run = _run_of(ws)
    assert run.machine.blocks == total and run.rerun_blocks <= 20 < total
    _edit(ws, main, 250, "G01 X78. Y2. F100.", 2)  # later edits still resume and converge
    _same_as_from_scratch(tmp_path, ws, main)
    assert _run_of(ws).rerun_blocks <= 20


def test_4_control_flow_a_skipped_range_shifts_the_steps_of_the_converged_run(tmp_path, monkeypatch):
    """An edit that makes the run skip 20 lines converges 20 blocks earlier: the block count
    of the run and of a finding after it are shifted, and a later edit still resumes right."""
    monkeypatch.setattr(run_checks, "CHUNK", 10)
    lines = ["O0001", "#1=0", "IF[#1 EQ 1] GOTO 10", *[f"G01 X{k}. Y3." for k in range(20)], "N10 #2=1",
             *[f"G01 X{k}. Y1." for k in range(60)], "#3=#2/#1", "M30"]  # fmt: skip
    ws, main = _open_program(tmp_path, "SKIPPED", lines)
    snapshot(ws, main)
    before = _run_of(ws).machine.blocks
    _edit(ws, main, 2, "GOTO 10", 1)
    _same_as_from_scratch(tmp_path, ws, main)
    run = _run_of(ws)
    assert run.machine.blocks == before - 20 and run.rerun_blocks < 60
    assert any(d[6] == "division-by-zero" for d in snapshot(ws, main)[0])
    _edit(ws, main, 70, "G01 X1. Y9.", 2)
    _same_as_from_scratch(tmp_path, ws, main)


def test_4_control_flow_an_edited_line_inside_a_loop_runs_the_loop_again(tmp_path, monkeypatch):
    """The edited line runs on every pass of the loop: the earlier run is not taken over while
    the loop runs, and the changed count shows in a finding after the loop."""
    monkeypatch.setattr(run_checks, "CHUNK", 10)
    ws, main = _open_program(tmp_path, "LOOPED", LOOPED)
    assert any(d[6] == "division-by-zero" for d in snapshot(ws, main)[0])  # #5 is 40 after the loop
    _edit(ws, main, 5, "#5=#5+2", 1)
    _same_as_from_scratch(tmp_path, ws, main)
    assert not any(d[6] == "division-by-zero" for d in snapshot(ws, main)[0])
    _edit(ws, main, 5, "#5=#5+1", 2)
    _same_as_from_scratch(tmp_path, ws, main)
    assert any(d[6] == "division-by-zero" for d in snapshot(ws, main)[0])
    assert _run_of(ws).rerun_blocks >= 4 * 40


def test_5_calls_a_macro_called_twice_is_run_again_for_the_second_call(tmp_path, monkeypatch):
    """An edit in a macro that the program calls twice changes what the second call leaves
    behind: converging after the first call must not hide the second one's new value."""
    monkeypatch.setattr(run_checks, "CHUNK", 10)
    ws, main = _open_program(tmp_path, "CALLED_TWICE", CALLED_TWICE)
    assert any(d[6] == "division-by-zero" for d in snapshot(ws, main)[0])
    macro = str(tmp_path / "O9002.nc")
    ws.change(macro, 1, 0, 1, len("#100=#1"), "#100=#1+1", 1)
    _same_as_from_scratch(tmp_path, ws, main)
    assert not any(d[6] == "division-by-zero" for d in snapshot(ws, main)[0])


def test_8_machine_a_program_that_reads_the_clock_does_not_converge_on_other_times(tmp_path, monkeypatch):
    """A faster feed near the start changes the time that ``#3001`` reads later (directly, or
    through ``#[#20]``): the rest of the earlier run is not taken over with the old time."""
    monkeypatch.setattr(run_checks, "CHUNK", 10)
    for name in ("CLOCK", "INDIRECT"):
        lines = PROGRAMS[name]
        ws, main = _open_program(tmp_path, name, lines)
        assert not any(d[6] == "division-by-zero" for d in snapshot(ws, main)[0])
        at = lines.index("G01 X0. Y1. F100.")
        _edit(ws, main, at, "G01 X0. Y1. F0.001", 1)  # one very slow move: the timer passes 1000 s
        _same_as_from_scratch(tmp_path, ws, main)
        assert any(d[6] == "division-by-zero" for d in snapshot(ws, main)[0]), name


def test_8_machine_a_program_that_never_reads_the_clock_converges_on_other_times(tmp_path, monkeypatch):
    """The same slow move in a program that never reads the clock converges all the same."""
    monkeypatch.setattr(run_checks, "CHUNK", 10)
    ws, main = _open_program(tmp_path, "STRAIGHT", STRAIGHT)
    snapshot(ws, main)
    _edit(ws, main, 3, "G01 X0. Y1. F0.001", 1)
    _same_as_from_scratch(tmp_path, ws, main)
    assert _run_of(ws).rerun_blocks <= 20


def test_4_control_flow_typing_into_a_label_line_resumes_the_run(tmp_path, monkeypatch):
    """A digit typed into the coordinates of ``N40 G01 X40. Y1.`` leaves the program's labels as
    they were: the run resumes and converges instead of starting again, also while the line
    does not parse (``X1-40.``: the run stops there with the syntax alarm, the GOTO still lands
    on N40)."""
    monkeypatch.setattr(run_checks, "CHUNK", 10)
    ws, main = _open_program(tmp_path, "LABELLED", LABELLED)
    snapshot(ws, main)
    total = _run_of(ws).machine.blocks
    restarts = []
    original = run_checks.EntryRun.restart
    monkeypatch.setattr(run_checks.EntryRun, "restart", lambda self: (restarts.append(1), original(self))[1])
    n100 = LABELLED.index("N100 G01 X100. Y1.")
    _edit(ws, main, n100, "N100 G01 X1100. Y1.", 1)
    snapshot(ws, main)
    assert restarts == [] and _run_of(ws).rerun_blocks <= 30 < total
    _same_as_from_scratch(tmp_path, ws, main)
    n40 = LABELLED.index("N40 G01 X40. Y1.")
    _edit(ws, main, n40, "N40 G01 X1-40. Y1.", 2)
    restarts.clear()
    got = snapshot(ws, main)[0]
    assert restarts == []
    assert [(d[1], d[6]) for d in got if d[5] == "error"] == [(n40, "syntax")]  # not "no N40" at the GOTO
    _same_as_from_scratch(tmp_path, ws, main)


def test_4_control_flow_cross_line_findings_follow_the_edits_that_change_them(tmp_path):
    """The label and call checks are kept while only coordinates are typed, and found again
    when a jump, a label or a file on disk changes."""
    # the subprogram is O8002, outside the 9000 series a FANUC control keeps in its memory
    lines = ["O0001", "#1=1", "IF[#1 EQ 1] GOTO 30", "G01 X1. Y1.", "N30 G01 X2. Y2.", "M98 P8002", "M30"]
    ws, main = _open_program(tmp_path, "MAIN", lines)
    sub = tmp_path / "O8002.nc"
    sub.write_text("O8002\nG01 X3. Y3.\nM99", encoding="utf-8")
    ws.file_changed(str(sub))

    def undefined() -> list[tuple[int, str]]:
        return [(d[1], d[6]) for d in snapshot(ws, main)[0] if d[6] in ("undefined-label", "program-not-found")]

    assert undefined() == []
    _edit(ws, main, 3, "G01 X5. Y1.", 1)
    assert undefined() == []
    _edit(ws, main, 2, "IF[#1 EQ 1] GOTO 31", 2)  # the jump changed
    assert undefined() == [(2, "undefined-label")]
    _edit(ws, main, 3, "G01 X6. Y1.", 3)  # typing elsewhere keeps it
    assert undefined() == [(2, "undefined-label")]
    _edit(ws, main, 4, "N31 G01 X2. Y2.", 4)  # the label changed
    assert undefined() == []
    sub.unlink()
    ws.file_changed(str(sub))  # the called program is gone from the folder
    assert undefined() == [(5, "program-not-found")]


# ---------------------------------------------------------------- generated programs
# CAM-like programs as the benchmarks generate them, small: absolute moves that set every axis,
# #1xx arithmetic, forward jumps to sequence numbers, short loops, macro calls and clock reads
# (directly or through indirection). Coordinates typed anywhere, and other lines replaced.

GEN_MACRO = ["O9003", "#101=#101+#1", "G01 X#1 Y3. Z-1. F300.", "M99"]
GEN_MACRO_CLOCK = ["O9003", "#101=#101+#1", "G01 X#1 Y3. Z-1. F300.", "#142=#3002", "M99"]


@st.composite
def generated_program(draw: st.DrawFn) -> tuple[list[str], list[str]]:
    """A main program and the macro it calls; a program that reads the clock, directly or
    through indirection, or none (the clock is compared only when one of them may read it)."""
    clocked = draw(st.booleans())
    lines = ["O0001", "G90 G17 G21", "T1 M06", "#100=2.5", "#101=1", *(["#3001=0", "#20=3001"] if clocked else [])]
    kinds = ["move", "move", "move", "calc", "loop", "call", "jump", *(["clock", "indirect"] if clocked else [])]
    segments = draw(st.integers(2, 8))
    for label in range(1, segments + 1):
        for kind in draw(st.lists(st.sampled_from(kinds), min_size=2, max_size=10)):
            x, y, z = draw(st.integers(0, 50)), draw(st.integers(-50, 50)), draw(st.integers(-20, 5))
            feed = draw(st.sampled_from([300, 800, 1500]))
            if kind == "move":
                lines.append(f"G01 X{x}.{draw(st.integers(0, 9))} Y{y}. Z{z}. F{feed}")
            elif kind == "calc":
                lines.append(f"#10{draw(st.integers(0, 3))}=#100*{draw(st.integers(1, 5))}+SIN[#101]")
            elif kind == "loop":
                lines += ["#130=0", f"WHILE[#130 LT {draw(st.integers(1, 4))}] DO1", f"G01 X#130 Y{y}. Z{z}. F{feed}",
                          "#130=#130+1", "END1"]  # fmt: skip
            elif kind == "call":
                lines.append(f"G65 P9003 A{draw(st.integers(1, 3))}.")
            elif kind == "clock":
                lines += ["#140=#3001", "IF[#140 GT 60000] THEN #141=1/0"]
            elif kind == "indirect":
                lines.append("#143=#[#20]")
            else:
                lines.append(f"IF[#10{draw(st.integers(0, 3))} GT {draw(st.integers(0, 20))}] GOTO {label}")
        lines.append(f"N{label} G01 X0. Y0. Z5. F{feed}")
    end = ["#144=#3001"] if clocked else []  # the time at the end: a clock the runs disagree on shows
    return [*lines, *end, "G00 Z50.", "M30"], GEN_MACRO_CLOCK if clocked and draw(st.booleans()) else GEN_MACRO


GEN_LINES = ["G01 X7. Y7. Z1. F800", "G01 X1. Y1. Z1. F0.001", "#100=30", "#101=0", "#3001=500", "#20=3002", "",
             "G65 P9003 A9.", "#150=#3001", "T2 M06", "G04 P1500"]  # fmt: skip
GEN_EDITS = st.one_of(
    st.tuples(st.just("digit"), st.sampled_from(["1", "9", "0"])),  # typed after the X of a move
    st.tuples(st.just("line"), st.sampled_from(GEN_LINES)),
)


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(program=generated_program(), edits=st.lists(st.tuples(st.integers(1, 80), GEN_EDITS, st.booleans()), min_size=1,
       max_size=4), chunk=st.sampled_from([5, 7, 16]))  # fmt: skip
def test_4_control_flow_generated_programs_after_edits_equal_runs_from_scratch(tmp_path, monkeypatch, program, edits,
                                                                              chunk):  # fmt: skip
    """Coordinates typed and lines replaced in generated CAM programs with loops, calls and
    clock reads, in the program or in the macro it calls: whether the resumed run converges
    or not, the result is the same as an analysis from scratch."""
    monkeypatch.setattr(run_checks, "CHUNK", chunk)
    ws = WorkspaceAnalysis(settings=MachineSettings(date=20261122, time=80000), max_blocks=2000)
    lines, macro = program
    texts = {"MAIN.nc": "\n".join(lines), "O9003.nc": "\n".join(macro)}
    for file, text in texts.items():
        (tmp_path / file).write_text(text)
        ws.open(str(tmp_path / file), text, 0)
    main = str(tmp_path / "MAIN.nc")
    snapshot(ws, main)
    for version, (at, (how, text), in_macro) in enumerate(edits, start=1):
        path = str(tmp_path / "O9003.nc") if in_macro and how == "digit" else main
        doc = ws.document(path)
        assert doc is not None
        if how == "digit":  # into a coordinate of a move (the distance, and so the time, changes)
            moves = [k for k, line in enumerate(doc.lines) if "X" in line]
            if not moves:  # the edits before replaced every move
                continue
            at = moves[at % len(moves)]
            col = doc.lines[at].index("X") + 1
            ws.change(path, at, col, at, col, text, version)
        else:
            at = 1 + at % (len(doc.lines) - 2)
            ws.change(path, at, 0, at, len(doc.lines[at]), text, version)
        got = snapshot(ws, main)
        scratch = WorkspaceAnalysis(settings=MachineSettings(date=20261122, time=80000), max_blocks=2000)
        for file in texts:
            scratch.open(str(tmp_path / file), ws.document(str(tmp_path / file)).text, 0)  # type: ignore[union-attr]
        assert got == snapshot(scratch, main)


def _grooving_parts(parts: int) -> list[str]:
    """A lathe program of ``parts`` grooving cycles: each G75 block makes about 220 passes (from
    X40+k to X20 in pecks of 1.5 mm of radius: 7 pecks, 13 columns 2.5 mm apart from Z2 to Z-28)."""
    lines = ["O0001 (cncmacro: dialect=fanuc-0i-lathe)", "G50 S2500", "G99 G18"]
    for k in range(parts):
        lines += ["T0101", "G97 S800 M03", f"G00 X{40 + k}. Z2.", "G75 R0.5", "G75 X20. Z-28. P1500 Q2500 F0.08",
                  "G00 X100. Z100."]  # fmt: skip
    return [*lines, "M30"]


def test_4_control_flow_an_edit_in_a_program_of_lathe_cycles_runs_little_again(tmp_path, monkeypatch):
    """A chunk of 64 blocks of grooving cycles is about 2,200 passes of work: the checkpoints
    come every 4 blocks instead (64 / 16, the least interval), so a diameter typed in the 20th
    part runs a few blocks again, not the 64 to 128 of two chunks, and the result is the same
    as an analysis from scratch."""
    monkeypatch.setattr(run_checks, "CHUNK", 64)
    lines = _grooving_parts(40)
    ws, main = _open_program(tmp_path, "GROOVING", lines)
    snapshot(ws, main)
    run = _run_of(ws)
    total = run.machine.blocks
    assert run.interval == 4 and total == 2 + 6 * 40 + 1  # the O line is not a block
    edited = 3 + 6 * 20 + 2  # the G00 of the 21st part
    assert lines[edited] == "G00 X60. Z2."
    _edit(ws, main, edited, "G00 X61.5 Z2.", 1)
    _same_as_from_scratch(tmp_path, ws, main)
    run = _run_of(ws)
    assert run.machine.blocks == total and run.rerun_blocks <= 12
