"""Code actions: split a G65/G66 block with words before the call, clamp an out-of-range L,
write out a macro word written shortened (``WH`` → ``WHILE``), write Haas's conditional
``[cond] M99 P n`` as ``IF [cond] GOTO n`` where the profile does not read it
(``conditional_m99.py``), and name the profile a file was written for (``profile-suggestion``:
its dialect comment, or the machine file's ``base``; for a lathe program under ``fanuc-30i``, the
machine file's ``lathe = true``, which no comment can say).

docs/semantics.md §5: only N may precede G65/G66 in its block (``machine/block_rules.py``, whose
``BEFORE_CALL`` problem is the ``g65-nc-words`` finding). The split is offered exactly where that
rule finds the problem, and moves the words it names (with the label and a block delete) to a
block of their own just before the call, so they run first as before (FANUC sets modal G codes
there and then calls; elsewhere the block is alarm 127). Any other letter after the call is an
argument (``M5.`` is M → #13) and stays. An O word in the block gets no split: on a line of its
own it would start a program. L must be 1..9999; the clamp writes the nearest allowed count. An
abbreviated macro word (docs/semantics.md §1) is replaced by the whole word. Each is offered for
the blocks in the requested range (in a range of thousands of lines, those of the findings sent
with the question: ``lines_looked_at``), and carries the matching diagnostics (``g65-nc-words``,
``repeat-count-range``, ``keyword-abbreviation`` or ``dialect-feature``) when the client sent them.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from lsprotocol import types

from ..analysis.checks.profile_suggestion import CODE, suggestion_target
from ..analysis.indexes.call_sites import call_site
from ..library.files import SkippedFileError, read_bytes
from ..library.machine_file import MACHINE_FILE_NAME, MAX_MACHINE_FILE_BYTES, CallCode, MachineSettings
from ..machine.block_rules import BEFORE_CALL, validate_block
from ..machine.calls import MAX_REPEAT, recognise_call
from ..syntax.nodes import Number
from .conditional_m99 import if_goto_rewrite
from .cursor import doc_range
from .documents import OpenDocument
from .positions import Encoding
from .texts import t

if TYPE_CHECKING:
    from .server import CncMacroServer

MAX_LINES_LOOKED_AT = 2_000  # a longer range is looked at only on the lines of its findings (``lines_looked_at``)


def split_edit(
    doc: OpenDocument, line: int, encoding: Encoding, calls: Mapping[str, CallCode] | None
) -> tuple[types.TextEdit, str, str] | None:
    """(edit, the words moved as written, the call's name) of the split of ``line`` where the
    words before its G65/G66 may not be there (``block_rules.BEFORE_CALL``), else None;
    ``calls`` are the machine file's call codes."""
    block = doc.block(line)
    if block is None or not block.words or block.statements:
        return None
    call = recognise_call(block.words, doc.dialect, calls)
    if call is None or call.kind not in ("G65", "G66"):
        return None
    problems = validate_block(block, doc.dialect, calls, call=call)
    moved = next((p.words for p in problems if p.rule == BEFORE_CALL), ())
    if not moved:
        return None
    text = doc.line(line)
    cut = sorted([(w.start, w.end) for w in moved] + ([block.label_span] if block.label_span else []))
    first = " ".join(text[s:e] for s, e in cut)
    if block.block_delete is not None:  # both blocks are skipped where the one was
        first = f"{text[: cut[0][0]].strip()} {first}"
    rest, pos = [], 0
    for s, e in cut:
        rest.append(text[pos:s])
        pos = e
    rest.append(text[pos:])
    indent = text[: len(text) - len(text.lstrip())]
    second = re.sub(r"[ \t]{2,}", " ", "".join(rest).strip())
    edit = types.TextEdit(doc_range(doc, line, 0, len(text), encoding), f"{indent}{first}\n{indent}{second}")
    return edit, " ".join(text[w.start : w.end] for w in moved), call.kind


def clamp_edit(doc: OpenDocument, line: int, encoding: Encoding) -> tuple[types.TextEdit, int] | None:
    block = doc.block(line)
    if block is None or call_site(block, doc.dialect) is None:
        return None
    for w in block.words:
        if w.letter == "L" and isinstance(w.value, Number):
            n = w.value.value
            if n < 1 or n > MAX_REPEAT:
                value = 1 if n < 1 else MAX_REPEAT
                return types.TextEdit(doc_range(doc, line, w.start, w.end, encoding), f"L{value}"), value
    return None


def expand_edits(doc: OpenDocument, line: int, encoding: Encoding) -> list[tuple[types.TextEdit, str, str]]:
    """(edit, written text, whole word) for each macro word written shortened on ``line``."""
    block = doc.block(line)
    if block is None:
        return []
    return [(types.TextEdit(doc_range(doc, line, a.start, a.end, encoding), a.word), a.text, a.word)
            for a in block.abbreviations]  # fmt: skip


def lines_looked_at(r: types.Range, findings: Mapping[int, object], count: int) -> Sequence[int]:
    """The lines of ``r`` whose blocks are looked at for a fix: every one of a range up to
    ``MAX_LINES_LOOKED_AT`` lines, else those of the findings sent with the question (``findings``,
    by line). The editor asks for the range of a finding it shows: hovering one that spans a
    million-line file (``not-executed``) would have every block of it looked at, for seconds
    in which the server answers nothing."""
    last = min(r.end.line, count - 1)
    if last - r.start.line < MAX_LINES_LOOKED_AT:
        return range(r.start.line, last + 1)
    return sorted(line for line in findings if r.start.line <= line <= last)


def register(server: CncMacroServer) -> None:
    @server.feature(
        types.TEXT_DOCUMENT_CODE_ACTION, types.CodeActionOptions(code_action_kinds=[types.CodeActionKind.QuickFix])
    )
    def code_action(ls: CncMacroServer, params: types.CodeActionParams) -> list[types.CodeAction] | None:
        doc = ls.documents.get(params.text_document.uri)
        if doc is None:  # not open: the empty answer (documents.py)
            return None
        encoding = ls.documents.encoding
        out: list[types.CodeAction] = []
        calls = ls.documents.calls_for(doc.path)
        by_line: dict[int, list[types.Diagnostic]] = {}
        for d in params.context.diagnostics:
            by_line.setdefault(d.range.start.line, []).append(d)
        for line in lines_looked_at(params.range, by_line, len(doc.lines)):
            diags = by_line.get(line, [])
            split = split_edit(doc, line, encoding, calls)
            if split is not None:
                edit, words, name = split
                out.append(_action(doc, t("fix_split", ls.locale, words=words, name=name), edit, diags, "g65-nc-words"))
            clamp = clamp_edit(doc, line, encoding)
            if clamp is not None:
                out.append(
                    _action(doc, t("fix_clamp", ls.locale, value=clamp[1]), clamp[0], diags, "repeat-count-range")
                )
            for expand, text, word in expand_edits(doc, line, encoding):
                start = expand.range.start.character
                mine = [d for d in diags if d.range.start.character == start]
                code = "keyword-abbreviation" if doc.dialect.keyword_abbreviations else "dialect-feature"
                out.append(_action(doc, t("fix_expand", ls.locale, text=text, word=word), expand, mine, code))
            block = doc.block(line)
            rewrite = if_goto_rewrite(block, doc.line(line), doc.dialect) if block and block.statements else None
            if rewrite is not None:  # [cond] M99 P n where the profile has no such jump
                start, end, new = rewrite
                edit = types.TextEdit(doc_range(doc, line, start, end, encoding), new)
                out.append(_action(doc, t("fix_if_goto", ls.locale, text=new), edit, diags, "dialect-feature"))
        out.extend(profile_actions(ls, doc, params.context.diagnostics))
        return out


def profile_actions(ls: CncMacroServer, doc: OpenDocument, diags: Sequence[types.Diagnostic]) -> list[types.CodeAction]:
    """For a ``profile-suggestion``: write the file's dialect comment, or the machine file's
    ``base`` (created beside the workspace's first folder when there is none)."""
    asked = [d for d in diags if d.code == CODE]
    if not asked:
        return []
    other = suggestion_target(doc.parsed.program, doc.dialect, ls.documents.machine(doc) or MachineSettings())
    if other is None:
        return []
    encoding = ls.documents.encoding
    # the profile's own lathe form (fanuc-30i's): no comment names it, only the machine file's ``lathe = true``
    variant = other.lathe and other.name == doc.dialect.name
    out = []
    if not variant:
        at = 1 if doc.lines and doc.lines[0].strip().startswith("%") else 0
        comment = types.TextEdit(doc_range(doc, at, 0, 0, encoding), f"(cncmacro: dialect={other.name})\n")
        out.append(_action(doc, t("fix_comment", ls.locale, title=other.title, name=other.name), comment, asked, CODE))
    machine = doc.machine_file
    if machine is None and ls.roots:
        machine = Path(ls.roots[0]) / MACHINE_FILE_NAME
    if machine is not None:
        title = (
            t("fix_machine_lathe", ls.locale, title=other.title)
            if variant
            else t("fix_machine", ls.locale, name=other.name)
        )
        out.append(types.CodeAction(
            title=title, kind=types.CodeActionKind.QuickFix,
            diagnostics=asked, edit=machine_file_edit(machine, other.name, encoding, lathe=variant),
        ))  # fmt: skip
    return out


def machine_file_edit(path: Path, name: str, encoding: Encoding, *, lathe: bool = False) -> types.WorkspaceEdit:
    """``base = "name"`` in the machine file at ``path``: the ``base`` or ``dialect`` line
    replaced, else written first; the file is created when it does not exist. With ``lathe``,
    ``lathe = true`` is written after it, in place of a ``lathe`` line before the first table."""
    uri = path.as_uri()
    line = f'base = "{name}"' + ("\nlathe = true" if lathe else "")
    start = types.Range(types.Position(0, 0), types.Position(0, 0))
    if not path.is_file():
        return types.WorkspaceEdit(document_changes=[
            types.CreateFile(uri=uri, options=types.CreateFileOptions(ignore_if_exists=True)),
            types.TextDocumentEdit(types.OptionalVersionedTextDocumentIdentifier(uri=uri, version=None),
                                   [types.TextEdit(start, line + "\n")]),
        ])  # fmt: skip
    try:
        lines = read_bytes(path, MAX_MACHINE_FILE_BYTES).decode("utf-8").split("\n")
    except (OSError, SkippedFileError, UnicodeDecodeError):
        lines = []
    edits: list[types.TextEdit] = []
    for k, text in enumerate(lines):
        if re.match(r"\s*\[", text):  # keys after a table header belong to it: write before it
            break
        if lathe and re.match(r"\s*lathe\s*=", text):  # the old lathe line goes
            edits.append(types.TextEdit(types.Range(types.Position(k, 0), types.Position(k + 1, 0)), ""))
    for k, text in enumerate(lines):
        if re.match(r"\s*(base|dialect)\s*=", text):
            edits.append(types.TextEdit(encoding.range(k, text, 0, len(text)), line))
            break
        if re.match(r"\s*\[", text):
            edits.append(types.TextEdit(types.Range(types.Position(k, 0), types.Position(k, 0)), line + "\n"))
            break
    else:
        edits.append(types.TextEdit(types.Range(types.Position(0, 0), types.Position(0, 0)), line + "\n"))
    return types.WorkspaceEdit(changes={uri: edits})


def _action(
    doc: OpenDocument, title: str, edit: types.TextEdit, diags: list[types.Diagnostic], code: str
) -> types.CodeAction:
    return types.CodeAction(
        title=title,
        kind=types.CodeActionKind.QuickFix,
        diagnostics=[d for d in diags if d.code == code] or None,
        edit=types.WorkspaceEdit(changes={doc.uri: [edit]}),
        is_preferred=True,
    )
