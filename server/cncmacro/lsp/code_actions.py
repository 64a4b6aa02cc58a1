"""Code actions: split a G65/G66 block that also holds NC words, clamp an out-of-range L, and
write out a macro word written shortened (``WH`` → ``WHILE``).

docs/semantics.md §5: only N may precede G65/G66 and no other G or M code or O word may share its
block; the split moves those words (with the label) to a block of their own just before the
call, so they run first as before. L must be 1..9999; the clamp writes the nearest allowed
count. An abbreviated macro word (docs/semantics.md §1) is replaced by the whole word. Each is
offered for the blocks in the requested range, and carries the matching diagnostics
(``g65-nc-words``, ``repeat-count-range``, ``keyword-abbreviation`` or ``dialect-feature``)
when the client sent them.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from lsprotocol import types

from ..machine.calls import MAX_REPEAT
from ..syntax.nodes import Number, Word
from .call_sites import call_site
from .cursor import doc_range
from .documents import OpenDocument

if TYPE_CHECKING:
    from .server import CncMacroServer

_TITLES = {
    "split": ("Split: move the NC words to a block before the G65", "拆分：把NC代码移到G65之前的单独程序段"),
    "clamp": ("Clamp the repeat count to {value}", "把重复次数改为{value}"),
    "expand": ("Write {word} in full", "把{text}写全为{word}"),
}


def _title(key: str, locale: str, **kw: object) -> str:
    en, zh = _TITLES[key]
    return (zh if locale.lower().startswith("zh") else en).format(**kw)


def nc_words(doc: OpenDocument, line: int) -> list[Word]:
    """The words that may not share the block with its G65/G66."""
    block = doc.block(line)
    if block is None:
        return []
    site = call_site(block, doc.dialect)
    if site is None or site.kind == "M98":
        return []
    out = []
    after = False
    for w in block.words:
        if w is site.code:
            after = True
            continue
        if not after or (w.letter in ("G", "M", "O")):
            out.append(w)
    return out


def split_edit(doc: OpenDocument, line: int, utf16: bool) -> types.TextEdit | None:
    words = nc_words(doc, line)
    if not words:
        return None
    block = doc.block(line)
    assert block is not None
    text = doc.line(line)
    cut = sorted([(w.start, w.end) for w in words] + ([block.label_span] if block.label_span else []))
    first = " ".join(text[s:e] for s, e in cut)
    rest, pos = [], 0
    for s, e in cut:
        rest.append(text[pos:s])
        pos = e
    rest.append(text[pos:])
    indent = text[: len(text) - len(text.lstrip())]
    second = re.sub(r"[ \t]{2,}", " ", "".join(rest).strip())
    return types.TextEdit(doc_range(doc, line, 0, len(text), utf16), f"{indent}{first}\n{indent}{second}")


def clamp_edit(doc: OpenDocument, line: int, utf16: bool) -> tuple[types.TextEdit, int] | None:
    block = doc.block(line)
    if block is None or call_site(block, doc.dialect) is None:
        return None
    for w in block.words:
        if w.letter == "L" and isinstance(w.value, Number):
            n = w.value.value
            if n < 1 or n > MAX_REPEAT:
                value = 1 if n < 1 else MAX_REPEAT
                return types.TextEdit(doc_range(doc, line, w.start, w.end, utf16), f"L{value}"), value
    return None


def expand_edits(doc: OpenDocument, line: int, utf16: bool) -> list[tuple[types.TextEdit, str, str]]:
    """(edit, written text, whole word) for each macro word written shortened on ``line``."""
    block = doc.block(line)
    if block is None:
        return []
    return [(types.TextEdit(doc_range(doc, line, a.start, a.end, utf16), a.word), a.text, a.word)
            for a in block.abbreviations]  # fmt: skip


def register(server: CncMacroServer) -> None:
    @server.feature(
        types.TEXT_DOCUMENT_CODE_ACTION, types.CodeActionOptions(code_action_kinds=[types.CodeActionKind.QuickFix])
    )
    def code_action(ls: CncMacroServer, params: types.CodeActionParams) -> list[types.CodeAction]:
        doc = ls.documents.get(params.text_document.uri)
        utf16 = ls.documents.utf16
        out: list[types.CodeAction] = []
        r = params.range
        for line in range(r.start.line, min(r.end.line, len(doc.lines) - 1) + 1):
            diags = [d for d in params.context.diagnostics if d.range.start.line == line]
            edit = split_edit(doc, line, utf16)
            if edit is not None:
                out.append(_action(doc, _title("split", ls.locale), edit, diags, "g65-nc-words"))
            clamp = clamp_edit(doc, line, utf16)
            if clamp is not None:
                out.append(
                    _action(doc, _title("clamp", ls.locale, value=clamp[1]), clamp[0], diags, "repeat-count-range")
                )
            for expand, text, word in expand_edits(doc, line, utf16):
                start = expand.range.start.character
                mine = [d for d in diags if d.range.start.character == start]
                code = "keyword-abbreviation" if doc.dialect.keyword_abbreviations else "dialect-feature"
                out.append(_action(doc, _title("expand", ls.locale, text=text, word=word), expand, mine, code))
        return out


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
