"""Hover: what the thing under the cursor is, in the client's language and the file's dialect.

System variables (also by their FANUC 30i names ``[#_ABSIO[1]]``, with the number a name stands
for), G/M codes, functions and the GSK ``G65 Hm`` commands are described from the dialect
tables; a macro word written shortened (``WH``) shows the whole word; a local
shows the argument letters that fill it (``machine.calls``); a common shows where it is
written; an N label shows the jumps to it; the ``M99`` of Haas's ``[cond] M99 P n`` says it is
a conditional jump; a letter of a cycle block says what it means in that block (a lathe's G71
first block or second, ``ide/cycle_words.py``), and the cycle's G code which block it is; an O
program (or the P of a call) shows its title and file, or, for a program kept on the control that
the profile documents (Haas's probing macros), what it does, the arguments it reads (those the
call gives marked) and what it writes; ``&&`` and ``||`` the word they stand for (AND, OR) and
whether the file's control reads them so. Only the block under the cursor is parsed; the places come
from each file's site index (``analysis/indexes/site_index.py``), in time proportional to how many
there are.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from lsprotocol import types

from ..analysis.indexes.call_sites import call_site
from ..analysis.indexes.return_labels import callers, return_landings, returns_onto
from ..analysis.indexes.sites import label_jumps, word_at
from ..bilingual import in_language, is_chinese, listed, pick
from ..dialects import describe
from ..dialects.alarms import FORMAT, VARIABLE_NUMBER
from ..dialects.cycle_words import CycleForm
from ..dialects.functions_data import GSK_H_CODES
from ..dialects.tables import MODAL_GROUP_NAMES
from ..ide.address_words import address_hover
from ..ide.cycle_words import cycle_form_of, cycle_word_at
from ..machine.alarms import MacroAlarm
from ..machine.calls import argument_targets, letters_for_local
from ..machine.jump_words import RETURN_LABEL
from ..machine.variables import named_number
from ..syntax.nodes import (
    LOGICAL_SYMBOLS,
    Abbreviation,
    Binary,
    Bracket,
    CornerWord,
    FunctionCall,
    NamedVar,
    Number,
    Unary,
    Var,
    Word,
)
from ..syntax.walk import nodes_at
from .conditional_m99 import conditional_m99_hover
from .cursor import Cursor, cursor_at
from .cycle_lenses import elapsed_text, program_inch
from .program_docs import doc_lines
from .site_steps import index_soon
from .texts import t

if TYPE_CHECKING:
    from ..dialects.dialect import Dialect
    from .server import CncMacroServer

MAX_PLACES = 8
_H_CODES = {h.name: h for h in GSK_H_CODES}  # the GSK ``G65 Hm`` macro commands


def register(server: CncMacroServer) -> None:
    @server.feature(types.TEXT_DOCUMENT_HOVER)
    def hover(ls: CncMacroServer, params: types.HoverParams) -> types.Hover | None:
        cur = cursor_at(ls, params.text_document.uri, params.position)
        if cur is None:
            return None
        found = hover_text(ls, cur)
        elapsed = elapsed_text(ls, cur.doc, params.position.line)  # the cycle time (cycle_lenses.py)
        if found is None:
            if elapsed is None:
                return None
            return types.Hover(contents=types.MarkupContent(kind=types.MarkupKind.Markdown, value=elapsed))
        text, start, end = found
        if elapsed is not None:
            text = f"{text}\n\n---\n\n{elapsed}"
        return types.Hover(
            contents=types.MarkupContent(kind=types.MarkupKind.Markdown, value=text), range=cur.range(start, end)
        )


def hover_text(ls: CncMacroServer, cur: Cursor) -> tuple[str, int, int] | None:
    """The Markdown for the cursor and the range it describes."""
    b, col = cur.block, cur.column
    if b.label_span is not None and b.label_span[0] <= col <= b.label_span[1] and b.label is not None:
        return label_hover(ls, cur, b.label), *b.label_span
    if b.program_span is not None and b.program_span[0] <= col <= b.program_span[1] and b.program is not None:
        return program_hover(ls, cur, b.program, None), *b.program_span
    for j in cur.doc.sites.jumps_of(b):
        if j.start <= col <= j.end:
            if j.kind == RETURN_LABEL:
                return return_hover(ls, cur, j.label), j.start, j.end
            return label_hover(ls, cur, j.label), j.start, j.end
    for a in b.abbreviations:
        if a.start <= col <= a.end:
            return abbreviation_hover(ls, cur, a), a.start, a.end
    if b.statements:
        m99 = conditional_m99_hover(b, col, cur.doc.dialect, ls.locale)  # [cond] M99 P n (Haas)
        if m99 is not None:
            return m99
    path = nodes_at(b, col)
    for node in reversed(path):
        if isinstance(node, Var):
            return variable_hover(ls, cur, node.number), node.start, node.end
        if isinstance(node, NamedVar):
            return named_hover(ls, cur, node), node.start, node.end
        if isinstance(node, FunctionCall) and col <= node.start + len(node.name):
            text = function_hover(ls, cur, node.name)
            if text:
                return text, node.start, node.start + len(node.name)
        if isinstance(node, Word):
            text = word_hover(ls, cur, node)
            if text:
                return text, node.start, node.end
        if isinstance(node, CornerWord):
            return corner_hover(ls, cur, node), node.start, node.end
        if isinstance(node, Binary) and node.op in LOGICAL_SYMBOLS:
            symbol = _symbol_at(cur.text, col, node.op)
            if symbol is not None:
                text = symbol_hover(ls, cur, node.op)
                if text:
                    return text, *symbol
    w = word_at(cur.text, col)
    if w is not None:
        text = function_hover(ls, cur, w[0])
        if text:
            return text, w[1], w[2]
    return None


# ---------------------------------------------------------------- variables
def variable_hover(ls: CncMacroServer, cur: Cursor, number: int) -> str:
    loc = ls.locale
    dialect = cur.doc.dialect
    kind = describe.variable_class(number, cur.doc.dialect)
    head = f"**#{number}** — {t(kind, loc)}"
    lines = [head]
    if kind == describe.SYSTEM:
        doc = describe.describe_system_variable(dialect, number, loc)
        if doc is None:
            said = dialect.alarm_said(VARIABLE_NUMBER)
            lines = [f"**#{number}** — {t('undefined', loc, alarm=pick(loc, said, said.zh))}"]
        else:
            lines.append("")
            lines.append(doc.text)
            lines.append("")
            facts = [f"{t('access', loc)}: {t(doc.access, loc)}"]
            if doc.unit:
                facts.append(f"{t('unit', loc)}: {describe.unit_text(doc.unit, program_inch(ls, cur), loc)}")
            if doc.axis:
                facts.append(f"{t('axis', loc)}: {doc.axis}")
            lines.append(" · ".join(facts))
            lines.append("")
            lines.append(f"*{dialect.shown_title(loc)}*")
    elif kind == describe.LOCAL:
        spec1, spec2 = letters_for_local(number)
        lines.append("")
        if spec1 or spec2:
            lines.append(f"{t('filled_by', loc)}:")
            if spec1:
                lines.append(f"- {t('spec1', loc)}: **{spec1}**")
            if spec2:
                lines.append(f"- {t('spec2', loc)}: **{spec2}**")
        else:
            lines.append(t("no_argument", loc))
    elif kind in (describe.COMMON, describe.PERSISTENT):
        axis = next((a for a, n in dialect.skip_commons if n == number), None)
        if axis is not None:  # GSK980TDi #995–#999: where G31 stopped (Dialect.skip_commons)
            code = f"G{min(dialect.skip_codes):g}"
            lines += ["", t("skip_common", loc, code=code, axis=axis)]
        shared = dialect.shared_common(number)
        if shared is not None:
            lines += ["", t("part_system_shared" if shared else "part_system_own", loc)]
        places, pending = write_places(ls, cur, number)
        shown = [f"{Path(path).name}:{line + 1}" for path, line in places[:MAX_PLACES]]
        if places or not pending:
            lines += _places(t("written_at", loc), shown, len(places), t("not_written", loc), loc)
        if pending:
            names = ", ".join(Path(path).name for path in pending)
            lines += ["", f"{t('written_at', loc)}: {t('being_found', loc, files=names)}"]
    return "\n".join(lines)


def named_hover(ls: CncMacroServer, cur: Cursor, node: NamedVar) -> str:
    """``[#_NAME[n]]``: the number it stands for and that variable's description; with a
    subscript known only when the block runs, the numbers the name covers."""
    loc = ls.locale
    dialect = cur.doc.dialect
    head = f"**{node.text}**"
    if not dialect.variable_names:
        said = dialect.alarm_said(FORMAT)
        return f"{head} — {t('no_names', loc, alarm=pick(loc, said, said.zh))}\n\n*{dialect.shown_title(loc)}*"
    row = dialect.variable_name(node.name)
    subscript = _literal(node.index.inner) if node.index is not None else None
    if row is not None and node.index is not None and subscript is None:
        text = pick(loc, row.en, row.zh)
        return f"**{node.text}[n]** = #{row.first} … #{row.last} (n = 1 … {row.count}) — {t('name', loc)}\n\n{text}"
    try:
        number = named_number(dialect, node.name, subscript, node.index is not None)
    except MacroAlarm as alarm:
        shown_no = dialect.shown_alarm(alarm.number)
        tail = f" ({shown_no})" if shown_no is not None else ""
        return f"{head} — {in_language(alarm.message, is_chinese(loc))}{tail}"
    shown = f"{node.text}[{subscript:g}]" if node.index is not None and subscript is not None else node.text
    return f"**{shown}** = **#{number}**\n\n" + variable_hover(ls, cur, number)


def _literal(node: object) -> float | None:
    """The value of a literal number (possibly bracketed or signed), else None."""
    while isinstance(node, Bracket):
        node = node.inner
    if isinstance(node, Number):
        return node.value
    if isinstance(node, Unary) and isinstance(node.operand, Number):
        return -node.operand.value if node.op == "-" else node.operand.value
    return None


def _bulleted(entries: list[str], loc: str, total: int | None = None) -> list[str]:
    """At most ``MAX_PLACES`` entries as a Markdown list, then how many more there are (of
    ``total`` places, when only the first entries were formatted)."""
    total = len(entries) if total is None else total
    out = [f"- {e}" for e in entries[:MAX_PLACES]]
    if total > MAX_PLACES:
        out.append(f"- … (+{total - MAX_PLACES} {t('more', loc)})")
    return out


def _places(heading: str, entries: list[str], total: int, none: str, loc: str) -> list[str]:
    """A paragraph of places: ``heading:`` and the first ``entries`` of ``total`` as a list, or
    ``none`` when there are none."""
    if not total:
        return ["", none]
    return ["", f"{heading}:", *_bulleted(entries, loc, total)]


def write_places(ls: CncMacroServer, cur: Cursor, number: int) -> tuple[list[tuple[str, int]], list[str]]:
    """Every (file, line) of the cursor's machine that assigns ``#number`` (from each file's map
    of the lines that write each variable; a file of another control is another machine:
    ``WorkspaceIndex.machine_sites``), and the files whose map is not made yet (a huge file
    being read, or indexed in steps: ``site_steps.py``)."""
    places: list[tuple[str, int]] = []
    pending: list[str] = []
    for f in ls.index.machine_sites(cur.doc.path, cur.doc.dialect):
        if not f.sites.ready:
            index_soon(f.sites)
            pending.append(f.path)
            continue
        places += [(f.path, i) for i in f.sites.writes(number)]
    return places, pending


# ---------------------------------------------------------------- labels and programs
def label_hover(ls: CncMacroServer, cur: Cursor, label: int) -> str:
    loc = ls.locale
    program = cur.doc.parsed.program
    unit = program.unit_at(cur.line)
    defined = program.label_lines(label, unit)
    lines = [f"**N{label}** — {t('label', loc)}"]
    if defined:
        lines.append("")
        lines.append(", ".join(f"{t('line', loc)} {x + 1}" for x in defined))
    else:
        lines.append("")
        lines.append(f"N{label}: {t('not_found', loc)}")
    if not cur.doc.sites.ready:  # a huge file not indexed yet: its jumps are still being found
        index_soon(cur.doc.sites)
        found = t("being_found", loc, files=Path(cur.doc.path).name)
        return "\n".join([*lines, "", f"{t('jumps', loc)}: {found}"])
    jumps = [(i, j.kind) for i, j in label_jumps(cur.doc, unit.start, unit.end, label)]
    if any(kind == RETURN_LABEL for _, kind in jumps) and callers(ls.index, cur.doc, unit):
        jumps = [(i, kind) for i, kind in jumps if kind != RETURN_LABEL]  # called: its M99 P returns to the caller
    shown = [f"{t('line', loc)} {i + 1} ({kind})" for i, kind in jumps[:MAX_PLACES]]
    for r in (r for at in defined for r in returns_onto(ls.index, cur.doc, at, label)):  # the callees' M99 P
        where = "" if r.file.path == cur.doc.path else f"{Path(r.file.path).name}, "
        shown.append(f"{where}{t('line', loc)} {r.line + 1} ({RETURN_LABEL} P{label})")
        jumps.append((r.line, RETURN_LABEL))
    lines += _places(t("jumps", loc), shown, len(jumps), t("no_jumps", loc), loc)
    return "\n".join(lines)


def return_hover(ls: CncMacroServer, cur: Cursor, label: int) -> str:
    """The ``n`` of ``M99 P n``: the ``Nn`` of each caller it returns to
    (``analysis/indexes/return_labels.py``), a main program's own, or that the callers are unknown."""
    loc = ls.locale
    program = cur.doc.parsed.program
    unit = program.unit_at(cur.line)
    name = f"O{unit.number:04d}" if unit.number is not None else Path(cur.doc.path).name
    lines = [f"**N{label}** — {t('label', loc)}", ""]
    found = return_landings(ls.index, cur.doc, cur.line, label)
    if found.main:
        lines.append(t("main_return", loc, name=name, label=label))
        lines.append("")
        lines.append(f"N{label}: {t('not_found', loc)}" if found.own is None else f"{t('line', loc)} {found.own + 1}")
        return "\n".join(lines)
    if not found.landings:
        lines.append(t("callers_unknown", loc, name=name, label=label))
        return "\n".join(lines)
    shown = []
    for landing in found.landings:
        c = landing.caller
        where = f"{c.name} ({Path(c.file.path).name})"
        said = (
            f"{where}: N{label} {t('not_found', loc)}"
            if landing.line is None
            else (f"{where}, {t('line', loc)} {landing.line + 1}")
        )
        if said not in shown:  # several calls of one caller that land alike: once
            shown.append(said)
    return "\n".join([*lines, t("returns_to", loc, label=label) + ":", *_bulleted(shown, loc)])


def program_hover(
    ls: CncMacroServer, cur: Cursor, number: int | None, name: str | None, given: tuple[Word, ...] = ()
) -> str:
    """An O program or the program a call names (``given``: the call's argument words)."""
    loc = ls.locale
    found = ls.index.find_program(cur.doc, number, name)
    shown = f"O{number:04d}" if number is not None else f"[{name}]"
    dialect = cur.doc.dialect
    if found is None and number is not None and dialect.on_control(number):
        kept = dialect.programs_on_control
        ranges = ", ".join(f"O{a:04d}" if a == b else f"O{a:04d}–O{b:04d}" for a, b in kept)
        said = t("on_control", loc, title=dialect.shown_title(loc), ranges=ranges)
        doc = dialect.program_doc(number)
        if doc is not None:  # the maker documents it: what it does, reads and writes, then where it lives
            lines = doc_lines(doc, loc, {w.letter for w in given})
            return "\n".join([*lines, "", f"{t('program', loc)}: {said}"])
        return f"**{shown}** — {t('program', loc)}: {said}"
    if found is None:
        return f"**{shown}** — {t('program', loc)}: {t('not_found', loc)}"
    lines = [f"**{found.label}**" + (f" ({found.unit.title})" if found.unit.title else "")]
    lines.append("")
    lines.append(f"{t('file', loc)}: {Path(found.file.path).name}, {t('line', loc)} {found.unit.start + 1}")
    return "\n".join(lines)


# ---------------------------------------------------------------- words and functions
def word_hover(ls: CncMacroServer, cur: Cursor, word: Word) -> str | None:
    loc = ls.locale
    dialect = cur.doc.dialect
    site = call_site(cur.block, dialect)
    if site is not None and word is site.target:
        return program_hover(ls, cur, site.number, site.name, site.arguments)
    if site is not None and word in site.arguments:
        targets = argument_targets([w.letter for w in site.arguments])
        k = next(i for i, w in enumerate(site.arguments) if w is word)
        if targets[k] is not None:
            return f"**{word.letter}** → **#{targets[k]}** ({t('fills', loc)} #{targets[k]})"
    if word.letter == "H" and dialect.h_codes and isinstance(word.value, Number) and _is_g65(cur.block.words):
        h = _H_CODES.get(f"H{int(word.value.value):02d}")
        if h is not None:
            return f"```\n{h.signature}\n```\n{pick(loc, h.en, h.zh)}\n\n*{dialect.shown_title(loc)}*"
    cycle = cycle_word_at(dialect, cur.block, word.start)
    if cycle is not None:  # a letter of a cycle block: what it means in this block
        name = pick(loc, *cycle.form.name)
        head = f"**{cycle.code}**" + (f" {name}" if name else "")
        meaning = f"**{cycle.word.piece}**: {pick(loc, cycle.word.en, cycle.word.zh)}"
        return f"{head} — {meaning}\n\n{_form_line(cycle.code, cycle.form, loc)} · *{dialect.shown_title(loc)}*"
    said = address_hover(dialect, cur.block, word, loc)  # T, G43's H, M98's L, G04's P
    if said is not None:
        return said
    if word.letter in ("G", "M") and isinstance(word.value, Number):
        doc = describe.code_doc(dialect, word.letter, word.value.value)
        if doc is not None:
            names = MODAL_GROUP_NAMES.get(doc.group, (doc.group, doc.group))
            group = f"{t('modal', loc)}: {pick(loc, *names)}" if doc.group else t("one_shot", loc)
            text = f"**{doc.code}** — {pick(loc, doc.en, doc.zh)}\n\n{group} · *{dialect.shown_title(loc)}*"
            form = cycle_form_of(dialect, cur.block) if word.letter == "G" else None
            if form is not None and form[0] == doc.code:  # a cycle's code: the block it writes
                text += f"\n\n{t('this_block', loc)}: {_form_line(form[0], form[1], loc)}"
            if word.letter == "G" and word.value.value in dialect.skip_codes:
                text += _skip_lines(dialect, loc)
            return text
    return None


def _skip_lines(dialect: Dialect, loc: str | None) -> str:
    """What a skip (G31) leaves where the program reads it, on a control that stores it in
    commons (``Dialect.skip_commons``: GSK980TDi #995–#999), and its feed clamp."""
    out = ""
    if dialect.skip_commons:
        places = listed(loc, [f"#{n} ({axis})" for axis, n in dialect.skip_commons])
        out += f"\n\n{t('skip_stores', loc, places=places)}"
    if dialect.skip_feed_clamp is not None:
        out += f"{pick(loc, '; ', '；')}{t('skip_clamp', loc, feed=dialect.skip_feed_clamp)}" if out else ""
    return out


def _form_line(code: str, form: CycleForm, loc: str | None) -> str:
    """A cycle block's form and, for a two-block cycle, which block it is: ``G71 U(Δd) R(e)``
    (first block)."""
    name = pick(loc, *form.name)
    return f"`{form.text(code)}`" + (f" ({name})" if name else "")


def corner_hover(ls: CncMacroServer, cur: Cursor, corner: CornerWord) -> str:
    """``,C``, ``,R`` or ``,A``: what it asks of the control and what the simulator does with it."""
    loc = ls.locale
    lines = [f"**,{corner.letter}** — {t(f'corner_{corner.letter}', loc)}", "", t("corner_run", loc)]
    dialect = cur.doc.dialect
    if not dialect.corner_words:
        lines += ["", t("corner_not_in_manual", loc, title=dialect.shown_title(loc))]
    return "\n".join(lines)


def abbreviation_hover(ls: CncMacroServer, cur: Cursor, a: Abbreviation) -> str:
    """A macro word written shortened: the whole word it stands for, then the word's own doc."""
    loc = ls.locale
    head = t("short_for", loc, text=a.text, word=a.word)
    if not cur.doc.dialect.keyword_abbreviations:
        head += f" ({t('not_here', loc)}: *{cur.doc.dialect.shown_title(loc)}*)"
    doc = function_hover(ls, cur, a.word)
    return f"{head}\n\n{doc}" if doc else head


def _is_g65(words: tuple[Word, ...] | list[Word]) -> bool:
    return any(w.letter == "G" and isinstance(w.value, Number) and w.value.value == 65 for w in words)


def _symbol_at(line: str, column: int, symbol: str) -> tuple[int, int] | None:
    """The range of ``symbol`` (``&&``, ``||``) written under ``column`` (or ending at it)."""
    for start in (column - 2, column - 1, column):
        if start >= 0 and line.startswith(symbol, start):
            return start, start + len(symbol)
    return None


def symbol_hover(ls: CncMacroServer, cur: Cursor, symbol: str) -> str | None:
    """``&&`` or ``||``: the word it stands for, described, and whether this control reads it so."""
    word = LOGICAL_SYMBOLS[symbol]
    text = function_hover(ls, cur, word)
    if text is None:
        return None
    said = t(
        "symbol_read" if cur.doc.dialect.logical_symbols else "symbol_refused", ls.locale, symbol=symbol, word=word
    )
    return f"{said}\n\n{text}"


def function_hover(ls: CncMacroServer, cur: Cursor, name: str) -> str | None:
    docs = describe.function_docs(cur.doc.dialect, name)
    if not docs:
        return None
    parts = [f"```\n{d.signature}\n```\n{pick(ls.locale, d.en, d.zh)}" for d in docs]
    return "\n\n".join(parts)
