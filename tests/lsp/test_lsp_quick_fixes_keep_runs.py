"""Every quick fix the language server offers changes what a program does only as its title
says, on every example program (examples/) and every corpus program (tests/corpus/**), and on
programs written to need each kind of fix (tests/lsp/workspace_quick_fixes/): each
program is opened in the server, every code action it offers for the whole text (with the
diagnostics published for it, as an editor sends them) is applied on its own, and the program is
run with ``cncmacro run --json`` before and after, as ``test_editing_keeps_runs.py`` runs them.
The lines of the file in the run afterwards are mapped back to the lines they were (an edit
replaces some lines by others: a split makes one line two, a dialect comment adds one).

What "only as its title says" means, per kind of fix:

- "Split: move W to a block before the G65" (or G66): the words W, with the label and a block
  delete, stand on a line of their own above the call, whose line keeps everything else (its
  arguments among them). The run afterwards is the run before, but for the count of blocks run
  (the new block is one more each time it runs); where the run before stopped at the split
  block with an alarm (alarm 127: a control that allows only N before the call), the run
  afterwards agrees with it up to that block (every move and line of output) and goes on.
- "Clamp the repeat count to n", "Write W in full", "Write it as IF [..] GOTO n": one line is
  rewritten in place. The run afterwards is the run before; where the run before stopped at that
  line with an alarm (a count out of range, a form the profile does not read), it agrees with it
  up to there and goes on.
- "Read this file as P: add (cncmacro: dialect=P)" and 'Set base = "P" in .cncmacro.toml': the
  run afterwards is the program's run read as P, all else of its machine file kept: the run of
  the file without a dialect comment, with its machine file without ``base``, under
  ``--dialect P``. With the comment the file alone is read as P: the other programs of its folder
  stay in the profile each is read in there, and a call finds only a program of its own profile
  (docs/editor.md, "Where a call finds its program"), so the run under ``--dialect`` looks for the
  programs it calls in a copy of the folder's programs, each marked with the profile it is read
  in there.

Messages (notes such as a clamped count's) are left out, as in ``test_editing_keeps_runs.py``.
"""

from __future__ import annotations

import asyncio
import contextlib
import difflib
import io
import json
import re
import shutil
from collections import Counter
from pathlib import Path
from typing import Any

import pytest
import pytest_lsp
from lsprotocol import types
from pygls.uris import to_fs_path
from pytest_lsp import LanguageClient

from cncmacro.cli.main import main
from cncmacro.library.machine_file import MACHINE_FILE_NAME, find_machine_file, load_machine_file
from cncmacro.library.profiles import file_profile

from .lsp_session import close_file, config, diagnostics_for, open_file, start

pytestmark = pytest.mark.asyncio(loop_scope="module")

REPO = Path(__file__).resolve().parents[2]
# the corpus, the examples, and programs written to need each kind of fix (the corpus and the
# examples need few: they are clean programs)
TREES = [REPO / "tests" / "corpus", REPO / "examples", Path(__file__).resolve().parent / "workspace_quick_fixes"]
_DIALECT_COMMENT = re.compile(r"\(\s*cncmacro\s*:\s*dialect\s*=[^)]*\)", re.I)
_BASE_LINE = re.compile(r"^\s*(base|dialect)\s*=.*$", re.M)


@pytest_lsp.fixture(config=config(), scope="module")
async def client(lsp_client: LanguageClient, tmp_path_factory: pytest.TempPathFactory):  # type: ignore[no-untyped-def]
    """A server on a copy of ``TREES`` (programs and machine files)."""
    root = tmp_path_factory.mktemp("quick_fixes")
    for tree in TREES:
        for p in sorted(tree.rglob("*")):
            if p.is_file() and (p.suffix.lower() in (".nc", ".cnc") or p.name == MACHINE_FILE_NAME):
                target = root / tree.name / p.relative_to(tree)
                target.parent.mkdir(parents=True, exist_ok=True)
                shutil.copyfile(p, target)
    lsp_client.root = root  # type: ignore[attr-defined]
    await start(lsp_client, root, "en")
    yield
    await lsp_client.shutdown_session()


def _decoded(path: Path) -> tuple[str, str]:
    data = path.read_bytes()
    try:
        return data.decode("utf-8"), "utf-8"
    except UnicodeDecodeError:
        return data.decode("gb18030"), "gb18030"  # a GSK program written on the control


def _run(path: Path, *extra: str) -> dict[str, Any]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        status = main(["run", "--no-save", "--json", "--max-blocks", "200000", *extra, str(path)])
    if not out.getvalue():  # the run did not start (its setup refused): what it said
        return {"exit": status, "refused": err.getvalue()}
    result = json.loads(out.getvalue())
    return {"exit": status, **{k: v for k, v in result.items() if k != "messages"}}


def _column(line: str, utf16: int) -> int:
    """A client's UTF-16 column as a code-point index of ``line``."""
    units = 0
    for k, ch in enumerate(line):
        if units >= utf16:
            return k
        units += 2 if ord(ch) > 0xFFFF else 1
    return len(line)


def _applied(text: str, edits: list[types.TextEdit]) -> str:
    lines = text.split("\n")
    for e in sorted(edits, key=lambda e: (e.range.start.line, e.range.start.character), reverse=True):
        s, t = e.range.start, e.range.end
        while len(lines) <= t.line:
            lines.append("")
        head = lines[s.line][: _column(lines[s.line], s.character)]
        tail = lines[t.line][_column(lines[t.line], t.character) :]
        lines[s.line : t.line + 1] = (head + e.new_text + tail).split("\n")
    return "\n".join(lines)


def _edits(action: types.CodeAction) -> dict[str, tuple[list[types.TextEdit], bool]]:
    """URI -> (its edits, whether the file is created) of ``action``'s workspace edit."""
    edit = action.edit
    assert edit is not None, action.title
    out: dict[str, tuple[list[types.TextEdit], bool]] = {}
    for uri, edits in (edit.changes or {}).items():
        out[uri] = (list(edits), False)
    created = set()
    for change in edit.document_changes or []:
        if isinstance(change, types.CreateFile):
            created.add(change.uri)
        elif isinstance(change, types.TextDocumentEdit):
            items = [e for e in change.edits if isinstance(e, types.TextEdit)]
            out[change.text_document.uri] = (items, change.text_document.uri in created)
    return out


def _line_map(before: list[str], after: list[str]) -> list[int | None]:
    """For each line after the edit, the line it was (a line of a replaced range: the range's
    first; an added line next to nothing: None)."""
    out: list[int | None] = [None] * len(after)
    for tag, i1, i2, j1, j2 in difflib.SequenceMatcher(None, before, after, autojunk=False).get_opcodes():
        for j in range(j1, j2):
            out[j] = i1 + (j - j1) if tag == "equal" else (i1 if i2 > i1 else None)
    return out


def _mapped(result: dict[str, Any], path: Path, lines: list[int | None]) -> dict[str, Any]:
    """``result`` with the (1-based) lines of ``path`` given as the lines they were."""

    def back(where: dict[str, Any]) -> dict[str, Any]:
        if Path(where["file"]) != path:
            return where
        was = lines[where["line"] - 1]
        return {**where, "line": None if was is None else was + 1}

    if "refused" in result:
        return result
    out = {**result, "moves": [back(m) for m in result["moves"]]}
    if result["alarm"] is not None:
        alarm = back(result["alarm"])
        out["alarm"] = {**alarm, "chain": [back(c) for c in alarm["chain"]]}
    return out


def _stopped_on(result: dict[str, Any], path: Path, lines: range) -> bool:
    """Whether the run stopped with an alarm on one of ``lines`` (0-based) of ``path``."""
    alarm = result.get("alarm")
    return alarm is not None and Path(alarm["file"]) == path and alarm["line"] - 1 in lines


def _read_as(path: Path, text: str, encoding: str, profile: str, tmp: Path, alone: bool) -> dict[str, Any]:
    """The run of the program ``text`` at ``path`` read as ``profile``, all else of its machine
    kept; ``alone``: the file alone is (its comment), its folder's other programs kept in theirs."""
    bare = tmp / path.name
    bare.write_bytes(_DIALECT_COMMENT.sub(lambda m: " " * len(m.group(0)), text).encode(encoding))
    machine = find_machine_file(path)
    settings = machine.read_text("utf-8") if machine is not None else ""
    (tmp / MACHINE_FILE_NAME).write_text(_BASE_LINE.sub("", settings), "utf-8")
    folder = _marked_folder(path, tmp / "marked") if alone else path.parent
    found = _run(bare, "--machine", str(tmp / MACHINE_FILE_NAME), "--dialect", profile, "--path", str(folder))
    shown = json.dumps(found).replace(json.dumps(str(bare))[1:-1], json.dumps(str(path))[1:-1])
    return json.loads(shown.replace(json.dumps(str(folder))[1:-1], json.dumps(str(path.parent))[1:-1]))


def _marked_folder(path: Path, marked: Path) -> Path:
    """A copy of the other programs of ``path``'s folder, each with the dialect comment of the
    profile it is read in there (its own comment, else the folder's: ``file_profile``), added at
    the end of its first line so that no line moves."""
    shutil.rmtree(marked, ignore_errors=True)
    marked.mkdir()
    machine = find_machine_file(path)
    settings = load_machine_file(machine) if machine is not None else None
    for other in path.parent.iterdir():
        if other == path or not other.is_file() or other.suffix.lower() not in (".nc", ".cnc"):
            continue
        text, encoding = _decoded(other)
        name = file_profile(text, settings).name
        first, sep, rest = text.partition("\n")
        cr = "\r" if first.endswith("\r") else ""
        marked_text = f"{first.removesuffix(cr)} (cncmacro: dialect={name}){cr}{sep}{rest}"
        (marked / other.name).write_bytes(marked_text.encode(encoding))
    return marked


def _expect_same(title: str, path: Path, before: dict[str, Any], after: dict[str, Any], changed: range) -> None:
    if _stopped_on(before, path, changed):  # the fix lets the run past the block it stopped at
        assert after["moves"][: len(before["moves"])] == before["moves"], title
        assert after["output"][: len(before["output"])] == before["output"], title
        return
    assert after == before, title


async def test_every_quick_fix_changes_a_run_only_as_its_title_says(client: LanguageClient, tmp_path: Path) -> None:
    root: Path = client.root  # type: ignore[attr-defined]
    programs = sorted(p for p in root.rglob("*") if p.is_file() and p.suffix.lower() in (".nc", ".cnc"))
    assert len(programs) > 90
    offered: Counter[str] = Counter()
    for path in programs:
        text, encoding = _decoded(path)
        uri = open_file(client, path, text)
        try:
            found = await asyncio.wait_for(diagnostics_for(client, uri, 1), 60)
        except TimeoutError:
            raise AssertionError(f"no diagnostics for {path}") from None
        rows = text.split("\n")
        actions = await client.text_document_code_action_async(
            types.CodeActionParams(
                types.TextDocumentIdentifier(uri),
                types.Range(types.Position(0, 0), types.Position(len(rows) - 1, len(rows[-1]))),
                types.CodeActionContext(diagnostics=list(found.diagnostics)),
            )
        )
        close_file(client, uri)
        before = None
        for action in actions or []:
            assert isinstance(action, types.CodeAction) and action.kind == types.CodeActionKind.QuickFix
            kind = action.title.split(":")[0].split(" ")[0]
            offered[kind] += 1
            before = before or _run(path)
            saved: dict[Path, bytes | None] = {}
            try:
                new_rows = rows
                for edit_uri, (edits, created) in _edits(action).items():
                    target = Path(to_fs_path(edit_uri) or edit_uri)
                    saved[target] = None if created or not target.exists() else target.read_bytes()
                    if target == path:
                        new_text = _applied(text, edits)
                        new_rows = new_text.split("\n")
                        target.write_bytes(new_text.encode(encoding))
                    else:
                        old = "" if saved[target] is None else (saved[target] or b"").decode("utf-8")
                        target.write_text(_applied(old, edits), "utf-8")
                lines = _line_map(rows, new_rows)
                after = _mapped(_run(path), path, lines)
                # the lines the fix rewrote (a line it only added is none of them)
                edited = {was for k, was in enumerate(lines) if was is not None and rows[was] != new_rows[k]}
                changed = range(min(edited), max(edited) + 1) if edited else range(0)
                if action.title.startswith("Split:"):
                    words = action.title.split("move ", 1)[1].split(" to a block before")[0]
                    first = new_rows[min(edited)]
                    assert words in first and "G65" not in first and "G66" not in first, (path, first)
                    _expect_same(action.title, path, {**before, "blocks": 0}, {**after, "blocks": 0}, changed)
                elif action.title.startswith(("Read this file as", "Set base")):
                    profile = re.findall(r'dialect=([\w-]+)\)|base = "([\w-]+)"', action.title)[0]
                    alone = action.title.startswith("Read this file as")
                    read_as = _read_as(path, text, encoding, profile[0] or profile[1], tmp_path, alone)
                    assert after == read_as, (path, action.title)
                else:
                    _expect_same(action.title, path, before, after, changed)
            finally:
                for target, data in saved.items():
                    if data is None:
                        target.unlink(missing_ok=True)
                    else:
                        target.write_bytes(data)
                path.write_bytes(text.encode(encoding))
    assert set(offered) == {"Split", "Clamp", "Write", "Read", "Set"}, offered  # every kind was tried
