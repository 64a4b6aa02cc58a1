"""Editing that must never change what a program does, proved on every program of the corpus
(tests/corpus), the examples and the programs written for it (tests/editing_programs: blocks with
several N words, of which only the first is the label): each file is formatted (both spacings, comments aligned or not)
or has its sequence numbers renumbered, added or removed, and every program is run before and
after the edit; the runs end the same way (status, alarm and its line), with the same final
variables, output and toolpath."""

from __future__ import annotations

import contextlib
import io
import json
import shutil
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from cncmacro.analysis.editing.sequence_numbers import (
    SequencePlan,
    add_sequence_numbers,
    remove_unused_sequence_numbers,
    renumber,
)
from cncmacro.cli.main import main
from cncmacro.dialects import get_dialect
from cncmacro.library.dialect_choice import dialect_from_text
from cncmacro.syntax.block_parser import parse_block
from cncmacro.syntax.formatting import COMPACT, SPACED, FormatOptions, format_lines
from cncmacro.syntax.program import build_program

ROOT = Path(__file__).resolve().parent.parent
TREES = [ROOT / "tests" / "corpus", ROOT / "examples", ROOT / "tests" / "editing_programs"]


def _copy(to: Path) -> list[Path]:
    """The corpus and the examples copied under ``to`` (programs and machine files only)."""
    files = []
    for tree in TREES:
        for p in sorted(tree.rglob("*")):
            if p.is_file() and (p.suffix.lower() in (".nc", ".cnc") or p.name == ".cncmacro.toml"):
                target = to / tree.name / p.relative_to(tree)
                target.parent.mkdir(parents=True, exist_ok=True)
                shutil.copyfile(p, target)
                if p.name != ".cncmacro.toml":
                    files.append(target)
    return files


def _run(path: Path, root: Path) -> dict[str, Any]:
    out = io.StringIO()
    argv = ["run", "--no-save", "--json", "--max-blocks", "200000"]
    machine = path.parent / ".cncmacro.toml"
    if machine.exists():
        argv += ["--machine", str(machine)]
    with contextlib.redirect_stdout(out):
        status = main([*argv, str(path)])
    result = json.loads(out.getvalue().replace(json.dumps(str(root))[1:-1], "ROOT"))
    return {"exit": status, **{k: v for k, v in result.items() if k != "messages"}}


@pytest.fixture(scope="module")
def runs_before(tmp_path_factory: pytest.TempPathFactory) -> list[dict[str, Any]]:
    """How every program of the unedited copy runs: the same for every edit, so run once."""
    before = tmp_path_factory.mktemp("before")
    return [_run(p, before) for p in _copy(before)]


def _same_runs(tmp: Path, runs_before: list[dict[str, Any]], edit: Callable[[Path, list[str]], list[str]]) -> int:
    """Run every program after ``edit`` (which gives a file's new lines) and compare with how it
    ran before; the number of files the edit changed."""
    after = tmp / "after"
    edited = _copy(after)
    changed = 0
    for p in edited:
        data = p.read_bytes()
        encoding = "utf-8"
        try:
            text = data.decode(encoding)
        except UnicodeDecodeError:
            encoding = "gb18030"  # a GSK program written on the control
            text = data.decode(encoding)
        lines = text.split("\n")
        new = edit(p, lines)
        if new != lines:
            changed += 1
            p.write_bytes("\n".join(new).encode(encoding))
    for was, b in zip(runs_before, edited, strict=True):
        assert was == _run(b, after), f"{b.relative_to(after)} runs differently after the edit"
    return changed


def _dialect(p: Path, lines: list[str]) -> str:
    machine = p.parent / ".cncmacro.toml"
    base = None
    if machine.exists():
        for row in machine.read_text(encoding="utf-8").splitlines():
            if row.strip().startswith("base"):
                base = row.split("=", 1)[1].strip().strip('"')
    return dialect_from_text(lines) or base or "fanuc-0i"


@pytest.mark.parametrize(
    "options",
    [FormatOptions(s, a) for s in (SPACED, COMPACT) for a in (False, True)],
    ids=["spaced", "spaced-aligned", "compact", "compact-aligned"],
)
def test_formatting_changes_no_run_and_formatting_again_changes_nothing(
    tmp_path: Path, runs_before: list[dict[str, Any]], options: FormatOptions
):
    def edit(p: Path, lines: list[str]) -> list[str]:
        program = build_program([parse_block(x) for x in lines])
        new = format_lines(lines, 0, len(lines) - 1, options, program.read_end)
        out = [new.get(i, x) for i, x in enumerate(lines)]
        assert not format_lines(out, 0, len(out) - 1, options, program.read_end), f"{p.name}: formatted twice"
        return out

    assert _same_runs(tmp_path, runs_before, edit) > 20


def _applied(lines: list[str], plan: SequencePlan) -> list[str]:
    assert plan.error is None and not plan.blockers
    out = list(lines)
    for c in sorted(plan.changes, key=lambda c: (c.line, -c.start)):
        out[c.line] = out[c.line][: c.start] + c.text + out[c.line][c.end :]
    return out


@pytest.mark.parametrize("how", ["renumber", "add", "remove"])
def test_sequence_number_edits_change_no_run(tmp_path: Path, runs_before: list[dict[str, Any]], how: str):
    def edit(p: Path, lines: list[str]) -> list[str]:
        program = build_program([parse_block(x) for x in lines])
        dialect = get_dialect(_dialect(p, lines))
        if how == "renumber":
            plan = renumber(program, dialect, step=10, keep_computed=True)
        elif how == "add":
            plan = add_sequence_numbers(program, dialect, step=5, keep_computed=True)
        else:
            plan = remove_unused_sequence_numbers(program, dialect, keep_computed=True)
        return _applied(lines, plan)

    assert _same_runs(tmp_path, runs_before, edit) > 5
