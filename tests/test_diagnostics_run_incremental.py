"""DESIGN.md "How the analysis stays incremental": after random edits, the incremental
analysis equals an analysis from scratch (diagnostics and the values shown per line)."""

from __future__ import annotations

from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from cncmacro.analysis import run_checks
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
    values = {(Path(f).name, line): v for f, lines in result.values.items() for line, v in lines.items()}
    return diags, values


def fresh(tmp: Path, texts: dict[str, str]) -> WorkspaceAnalysis:
    ws = WorkspaceAnalysis(settings=MachineSettings(date=20261122, time=80000), max_blocks=400)
    for name, text in texts.items():
        ws.open(str(tmp / name), text, 0)
    return ws


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(edits=st.lists(edit, min_size=1, max_size=6), analyse_between=st.booleans())
def test_incremental_analysis_equals_analysis_from_scratch(tmp_path, monkeypatch, edits, analyse_between):
    monkeypatch.setattr(run_checks, "CHUNK", 7)  # many checkpoints in small programs
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
