"""Completion: system variables (with their descriptions) after ``#``, N labels after ``GOTO``,
the profile's G or M codes (with what each does) after a ``G`` or ``M`` that starts a word,
programs after the ``P`` of a call (the file's own last), G65/G66 argument letters with the
locals they fill (those the called macro reads first), the
letters of a cycle block not yet written with what each means there (``G71 `` after a first
block offers P, Q, U, W, F; ``ide/cycle_words.py``), and the keywords and functions of the
dialect. Everything offered comes from the dialect tables, the parser's labels and the workspace
index."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from lsprotocol import types

from ..analysis.indexes.call_sites import CallSite, call_site
from ..bilingual import pick
from ..dialects import describe, tables
from ..dialects.dialect import ARGUMENTS_I
from ..ide.cycle_words import cycle_signature
from ..ide.signature_help import locals_read
from .cursor import Cursor, cursor_at
from .cycle_lenses import program_inch
from .texts import t

if TYPE_CHECKING:
    from .server import CncMacroServer

EXPAND_RANGE = 8  # a table row covering more numbers than this is offered by its first number
_HASH = re.compile(r"#(\d*)$")
_GOTO = re.compile(r"GOTO\s*(\d*)$", re.I)
_P = re.compile(r"P(\[?)([\w\u4e00-\u9fff]*)$", re.I)
_NEW_WORD = re.compile(r"(?:\s|(?<=[\s\d.])[A-Za-z])$")  # the cursor starts a word (or its letter)
_CODE = re.compile(r"(?:^|(?<=[\s\d.\]]))([GM])[\d.]*$", re.I)  # a G or M word begun at a word start
_CALL = re.compile(r"\b(G0*65|G0*66|M0*98)\b|(G0*65|G0*66|M0*98)(?=\s*P)", re.I)


def register(server: CncMacroServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_COMPLETION, types.CompletionOptions(trigger_characters=["#", " ", "["]))
    def completion(ls: CncMacroServer, params: types.CompletionParams) -> types.CompletionList | None:
        cur = cursor_at(ls, params.text_document.uri, params.position)
        if cur is None:
            return None
        return types.CompletionList(is_incomplete=False, items=complete(ls, cur))


def complete(ls: CncMacroServer, cur: Cursor) -> list[types.CompletionItem]:
    before = cur.text[: cur.column]
    m = _HASH.search(before)
    if m:
        return system_variable_items(ls, cur, cur.column - len(m.group(0)))
    m = _GOTO.search(before)
    if m:
        return label_items(cur)
    in_call = _CALL.search(before.upper()) is not None
    m = _P.search(before)
    if m and in_call and (m.start() == 0 or not before[m.start() - 1].isalpha()):
        return program_items(ls, cur, bool(m.group(1)), cur.column - len(m.group(2)))
    items: list[types.CompletionItem] = []
    code = None if in_call else _CODE.search(before)
    if in_call:
        items += argument_items(ls, cur)
    elif code is not None and "(" not in before[before.rfind(")") + 1 :]:  # not inside a comment
        items += code_items(ls, cur, code.group(1).upper(), code.start(1))
    elif _NEW_WORD.search(before):
        items += cycle_letter_items(ls, cur)
    items += keyword_items(ls, cur)
    return items


def system_variable_items(ls: CncMacroServer, cur: Cursor, start: int) -> list[types.CompletionItem]:
    dialect = cur.doc.dialect
    loc = ls.locale
    out: list[types.CompletionItem] = []
    inch = program_inch(ls, cur)
    for row in dialect.system_variables():
        last = row.last if row.last - row.first < EXPAND_RANGE else row.first
        for n in range(row.first, last + 1):
            doc = describe.describe_system_variable(dialect, n, loc)
            if doc is None:
                continue
            detail = f"{t(doc.access, loc)}" + (f", {describe.unit_text(doc.unit, inch, loc)}" if doc.unit else "")
            out.append(
                types.CompletionItem(
                    label=f"#{n}",
                    kind=types.CompletionItemKind.Variable,
                    detail=detail,
                    documentation=types.MarkupContent(kind=types.MarkupKind.Markdown, value=doc.text),
                    filter_text=f"#{n}",
                    sort_text=f"{n:08d}",
                    text_edit=types.TextEdit(cur.range(start, cur.column), f"#{n}"),
                )
            )
    return out


def label_items(cur: Cursor) -> list[types.CompletionItem]:
    program = cur.doc.parsed.program
    unit = program.unit_at(cur.line)
    out = []
    for n, lines in sorted(program.labels.items()):
        inside = [x for x in lines if x in unit]
        if not inside:
            continue
        out.append(
            types.CompletionItem(
                label=str(n),
                kind=types.CompletionItemKind.Reference,
                detail=f"N{n}: " + ", ".join(str(x + 1) for x in inside),
                sort_text=f"{n:08d}",
            )
        )
    return out


def code_items(ls: CncMacroServer, cur: Cursor, letter: str, start: int) -> list[types.CompletionItem]:
    """The profile's G or M codes (``letter``), each with what it does as its hover says it
    (the dialect's code table, the machine file's codes first), in the table's order."""
    loc = ls.locale
    dialect = cur.doc.dialect
    rows = dialect.g_codes() if letter == "G" else dialect.m_codes()
    edit = cur.range(start, cur.column)
    out = []
    seen = set()
    for k, row in enumerate(rows):
        if row.code in seen:
            continue
        seen.add(row.code)
        text = pick(loc, row.en, row.zh)
        group = f"{t('modal', loc)}: {row.group}" if row.group else t("one_shot", loc)
        out.append(
            types.CompletionItem(
                label=row.code,
                kind=types.CompletionItemKind.Keyword,
                detail=text,
                documentation=types.MarkupContent(
                    kind=types.MarkupKind.Markdown, value=f"**{row.code}** — {text}\n\n{group} · *{dialect.title}*"
                ),
                filter_text=row.code,
                sort_text=f"!{k:04d}",
                text_edit=types.TextEdit(edit, row.code),
            )
        )
    return out


def program_items(ls: CncMacroServer, cur: Cursor, bracket: bool, start: int) -> list[types.CompletionItem]:
    """The workspace's programs, those of other files first (the file's own, a call of itself,
    last)."""
    out: list[types.CompletionItem] = []
    seen = set()
    for p in sorted(ls.index.programs(), key=lambda p: p.path == cur.doc.path):
        if bracket:
            if p.number is not None and not p.first:
                continue
            text = p.name if p.number is None else p.path.rsplit("/", 1)[-1].rsplit(".", 1)[0]
        else:
            if p.number is None:
                continue
            text = str(p.number)
        if text in seen:
            continue
        seen.add(text)
        own = p.path == cur.doc.path
        out.append(
            types.CompletionItem(
                label=text,
                kind=types.CompletionItemKind.Module,
                detail=f"{p.name} {p.title or ''}".strip(),
                sort_text=("~" if own else "") + f"{len(out):05d}",
                text_edit=types.TextEdit(cur.range(start, cur.column), text),
            )
        )
    return out


def argument_items(ls: CncMacroServer, cur: Cursor) -> list[types.CompletionItem]:
    loc = ls.locale
    site = call_site(cur.block, cur.doc.dialect)
    reads: set[int] = set()  # the arguments the called macro reads: first, and preselected
    if site is not None and (site.number is not None or site.name is not None):
        reads = ls_reads(ls, cur, site)
    out = []
    for letter, n in ARGUMENTS_I.items():
        read = n in reads
        out.append(
            types.CompletionItem(
                label=letter,
                kind=types.CompletionItemKind.Field,
                detail=f"{t('fills', loc)} #{n}",
                sort_text=("!" if read else "") + f"0{n:02d}",
                preselect=True if read else None,
            )
        )
    out.sort(key=lambda item: item.sort_text or "")  # the ones it reads first, in the list too
    return out


def cycle_letter_items(ls: CncMacroServer, cur: Cursor) -> list[types.CompletionItem]:
    """The letters of the cycle block being typed that it does not have yet, in the manual's
    order, each with what it means in this block."""
    cycle = cycle_signature(cur.doc, cur.line, cur.column)
    if cycle is None:
        return []
    name = pick(ls.locale, *cycle.form.name)
    out = []
    for k, w in enumerate(cycle.form.words):
        if w.letter in cycle.given:
            continue
        out.append(
            types.CompletionItem(
                label=w.letter,
                kind=types.CompletionItemKind.Field,
                detail=f"{cycle.code} {name}: {w.piece}" if name else f"{cycle.code}: {w.piece}",
                documentation=pick(ls.locale, w.en, w.zh),
                sort_text=f"!{k:02d}",
            )
        )
    return out


def ls_reads(ls: CncMacroServer, cur: Cursor, site: CallSite) -> set[int]:
    found = ls.index.find_program(cur.doc, site.number, site.name)
    return set(locals_read(found)) if found is not None else set()


# a row's kind in the dialect's function table -> the completion item's kind
_ITEM_KIND = {
    tables.FUNCTION: types.CompletionItemKind.Function,
    tables.OPERATOR: types.CompletionItemKind.Operator,
    tables.STATEMENT: types.CompletionItemKind.Keyword,
}


def keyword_items(ls: CncMacroServer, cur: Cursor) -> list[types.CompletionItem]:
    """The names of the dialect's function table, each as its row's ``kind`` says; a name written
    with brackets (``SIN[a]``) is inserted with them, the cursor between."""
    out = []
    seen = set()
    for f in cur.doc.dialect.functions():
        if f.name in seen:
            continue
        seen.add(f.name)
        bracketed = f.kind == tables.FUNCTION and f.signature.startswith(f.name + "[")
        out.append(
            types.CompletionItem(
                label=f.name,
                kind=_ITEM_KIND[f.kind],
                detail=f.signature,
                documentation=pick(ls.locale, f.en, f.zh),
                insert_text=f"{f.name}[$1]" if bracketed else None,
                insert_text_format=types.InsertTextFormat.Snippet if bracketed else None,
            )
        )
    return out
