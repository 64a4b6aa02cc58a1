"""The analysis is bounded in blocks, time and memory whatever the program does: a run stops
at its block budget, at its wall-clock limit and when it has recorded too many messages, each
time with a ``run-limit`` diagnostic that says which limit it was; and its checkpoints stay
few (a ``#3006`` pause in a loop used to add one per pass)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from cncmacro.analysis.runs import run_checks
from cncmacro.analysis.workspace import WorkspaceAnalysis


def analysed(tmp_path: Path, text: str, **limits: float) -> tuple[WorkspaceAnalysis, list[tuple[str, str]]]:
    path = str(tmp_path / "O0001.nc")
    ws = WorkspaceAnalysis(max_blocks=int(limits.pop("max_blocks", 1_000_000)))
    for name, value in limits.items():
        setattr(ws, name, value)
    ws.open(path, text, 1)
    result = ws.analyze(path)
    assert result is not None
    return ws, [(d.code, d.message) for d in result.diagnostics[path] if d.code != "not-executed"]


def test_an_endless_loop_stops_at_the_wall_clock_limit_with_run_limit(tmp_path: Path) -> None:
    ws, found = analysed(tmp_path, "O0001\nN1 #100=#100+1\nGOTO1\nM30\n", max_blocks=10**12, max_seconds=0.3)
    [(code, message)] = found
    assert code == "run-limit" and "time limit" in message
    [run] = ws.runs.values()
    assert run.machine.blocks < 10**12


def test_a_run_that_prints_without_end_stops_at_its_record_limit(tmp_path: Path) -> None:
    text = "O0001\nWHILE[1 EQ 1]DO1\nDPRNT[X#100[53]]\n#100=#100+1\nEND1\nM30\n"
    ws, found = analysed(tmp_path, text, max_records=2_000)
    [(code, message)] = found
    assert code == "run-limit" and "memory limit" in message and "2000" in message
    [run] = ws.runs.values()
    assert len(run.machine.notes) <= 2_000 + run_checks.CHUNK  # checked between chunks


def test_a_pause_in_a_loop_adds_no_checkpoint_of_its_own(tmp_path: Path) -> None:
    # #100 counts the passes: a loop that changes nothing is found endless long before the budget
    text = "O0001\nWHILE[1 EQ 1]DO1\n#3006=1(CHECK)\n#100=#100+1\nEND1\nM30\n"
    ws, found = analysed(tmp_path, text, max_blocks=200_000)
    assert [code for code, _ in found] == ["run-limit"]
    [run] = ws.runs.values()
    assert run.machine.blocks == 200_000
    assert len(run.checkpoints) <= 200_000 // run_checks.CHUNK + 1  # was one per pause: 50,000


def test_a_long_run_keeps_at_most_max_checkpoints(tmp_path: Path) -> None:
    ws, found = analysed(tmp_path, "O0001\nN1 #100=#100+1\nGOTO1\nM30\n", max_blocks=3_000_000)
    assert [code for code, _ in found] == ["run-limit"]
    [run] = ws.runs.values()
    assert len(run.checkpoints) <= run_checks.MAX_CHECKPOINTS
    blocks = [c.blocks for c in run.checkpoints]
    assert blocks == sorted(blocks) and blocks[0] == 0


def test_an_edit_after_thinned_checkpoints_still_gives_the_right_result(tmp_path: Path) -> None:
    path = str(tmp_path / "O0001.nc")
    ws = WorkspaceAnalysis(max_blocks=3_000_000)
    ws.open(path, "O0001\n#1=0\nWHILE[#1 LT 700000]DO1\n#1=#1+1\nEND1\n#2=1/[#1-700000]\nM30\n", 1)
    first = ws.analyze(path)  # 2.1 million blocks: the checkpoints were thinned
    assert first is not None and [d.code for d in first.diagnostics[path]][:1] == ["division-by-zero"]
    [run] = ws.runs.values()
    assert run.interval > run_checks.CHUNK
    ws.change(path, 5, 0, 5, 100, "#2=1/[#1-699999]", 2)
    second = ws.analyze(path)
    assert second is not None and [d.code for d in second.diagnostics[path]] == []  # 1/1 now


def test_a_run_stopped_as_a_macro_runs_off_its_end_is_reported_on_its_last_line(tmp_path: Path) -> None:
    """Found by the fuzzer: a budget that ran out just as a called program ran past its last
    line (no M99) put ``run-limit`` on the line after the end of the file."""
    text = "O0001\nG65 P2 L9999\nM30\nO0002\n#100=#100+1"
    for budget in (2, 4, 6):
        ws, _ = analysed(tmp_path, text, max_blocks=budget)
        [run] = ws.runs.values()
        assert run.machine.frames[-1].pc == 5  # the place after the last line
        path = str(tmp_path / "O0001.nc")
        result = ws.analyze(path)
        assert result is not None
        [limit] = [d for d in result.diagnostics[path] if d.code == "run-limit"]
        assert (limit.line, limit.end_line) == (4, 4)


def _endless_programs(count: int, then: str = "") -> str:
    out = ["%"]
    for k in range(count):
        out += [f"O{1000 + k}", "WHILE[#100 EQ #0]DO1", "#1=#1+1", "END1", "M30"]  # main programs: #1 starts vacant
    out += [then, "%"] if then else ["%"]
    return "\n".join(out) + "\n"


def test_a_file_of_many_endless_programs_is_analysed_within_the_file_budget(tmp_path: Path) -> None:
    """A file of 100 programs that each loop for ever took 100 runs of a full budget to check;
    the runs of one file now share FILE_BUDGETS budgets, and the programs left out are named."""
    ws, found = analysed(tmp_path, _endless_programs(100), max_blocks=2_000)
    limits = [message for code, message in found if code == "run-limit" and "stopped here" in message]
    left_out = [message for code, message in found if code == "run-limit" and "was not run" in message]
    assert len(limits) == run_checks.FILE_BUDGETS
    assert len(left_out) == 100 - run_checks.FILE_BUDGETS
    assert left_out[0].startswith(f"O{1000 + run_checks.FILE_BUDGETS} was not run")
    assert sum(run.machine.blocks for run in ws.runs.values()) <= run_checks.FILE_BUDGETS * 2_000


def test_a_program_after_an_endless_one_in_the_same_file_is_still_run(tmp_path: Path) -> None:
    text = _endless_programs(1, then="O2000\n#3000=7(SECOND PROGRAM REACHED)\nM99")
    _, found = analysed(tmp_path, text, max_blocks=2_000)
    assert [code for code, _ in found] == ["run-limit", "macro-alarm"]
    assert "SECOND PROGRAM REACHED" in found[1][1]


def test_the_file_budget_follows_edits_that_end_an_endless_program(tmp_path: Path) -> None:
    """Once the first program ends, the program that was left out runs; the result is the one a
    fresh analysis gives."""
    path = str(tmp_path / "O0001.nc")
    text = _endless_programs(run_checks.FILE_BUDGETS + 1)
    ws = WorkspaceAnalysis(max_blocks=2_000)
    ws.open(path, text, 1)
    before = ws.analyze(path)
    assert before is not None and any("was not run" in d.message for d in before.diagnostics[path])
    ws.change(path, 2, 0, 2, len("WHILE[#100 EQ #0]DO1"), "WHILE[#1 LT 3]DO1", 2)
    after = ws.analyze(path)
    assert after is not None
    assert not any("was not run" in d.message for d in after.diagnostics[path])
    fresh = WorkspaceAnalysis(max_blocks=2_000)
    fresh.open(path, text.replace("WHILE[#100 EQ #0]DO1", "WHILE[#1 LT 3]DO1", 1), 2)
    again = fresh.analyze(path)
    assert again is not None
    assert after.diagnostics[path] == again.diagnostics[path]


def test_check_of_a_file_of_endless_programs_names_those_it_did_not_run(tmp_path: Path) -> None:
    f = tmp_path / "many.nc"
    f.write_text(_endless_programs(30), encoding="utf-8")
    r = subprocess.run([sys.executable, "-m", "cncmacro", "check", "--max-blocks", "20000", str(f)],
                       capture_output=True, text=True, timeout=120)  # fmt: skip
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    assert len([x for x in lines if "stopped here after 20000 blocks" in x]) == run_checks.FILE_BUDGETS
    assert len([x for x in lines if "was not run" in x]) == 30 - run_checks.FILE_BUDGETS
    first_left_out = run_checks.FILE_BUDGETS
    assert f"{f}:{5 * first_left_out + 2}:1: information: O{1000 + first_left_out} was not run" in r.stdout


# each program counts to 10**8 before it ends: far beyond any time limit of these tests
_COUNTS_LONG = "O{n:04d}\n#1=0\nWHILE[#1 LT 1]DO1\n#2=#2+1\nIF[#2 GT 100000000]THEN#1=1\nEND1\nM30\n"


def test_the_programs_of_one_file_share_one_runs_time_whatever_max_blocks_says(tmp_path: Path) -> None:
    # three long programs in one file, a budget raised to 10**12 blocks: the file's analysis
    # takes the time of one run (0.4 s here, 30 s by default), not three, and says why
    text = "%\n" + "".join(_COUNTS_LONG.format(n=n) for n in (1, 2, 3)) + "%\n"
    ws, found = analysed(tmp_path, text, max_blocks=10**12, max_seconds=0.4)
    assert sum(run.elapsed for run in ws.runs.values()) < 0.4 + 0.3  # one chunk past the limit at most
    messages = [message for code, message in found if code == "run-limit"]
    assert any("time limit" in m for m in messages)
    assert [m.split(" ")[0] for m in messages if "was not run" in m] == ["O0002", "O0003"]
    assert all("0.4 s" in m for m in messages if "was not run" in m)
