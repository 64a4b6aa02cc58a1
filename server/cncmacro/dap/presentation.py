"""How the debugger shows a stopped machine: stack frames, scopes and variables.

One stack frame per program level, innermost first, named like ``O9100 (G65, level 1)`` (the
macro level whose locals it has) or ``O2100 (M98, level 1's locals)``, ``O2000 (M98, main's
locals)`` for a subprogram, which runs in its caller's locals; a call repeated by its L says
which pass runs (``O2100 (M98, main's locals, pass 2 of 2)``).
Each frame has up to six scopes: its locals ``#1–#33`` (``#24 (X)`` where a caller passed the
argument letter), the volatile commons, the persistent ``#500–#999`` (a kind of common the
control lacks has no scope), and the system variables of the dialect's tables grouped as
position, modal state and offsets. A scope of more than ``GROUP`` commons opens on one row per
hundred numbers (``#500–#599``, a Haas's ``#10000–#10099``), its value the first numbers that
hold one, and each row opens on its variables. A variables reference encodes the frame, the
scope and the hundred, so it stays valid for as long as the machine stays stopped. Vacant
shows as ``<vacant>`` (``<空>`` in a Chinese locale), and the interpreter's alarm details and
notes are shown in Chinese there too (``detail_text``).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..bilingual import in_language, is_chinese, pick
from ..dialects import describe
from ..dialects.tables import SystemVariable
from ..machine import Machine, MacroAlarm
from ..machine.frames import Frame
from ..planner.numbers import shown_value

LOCALS, COMMON, PERSISTENT, POSITION, MODAL, OFFSETS = range(6)
SCOPES_PER_FRAME = 8
GROUP = 100  # a scope of more commons than this opens on one row per hundred numbers
GROUPS_PER_SCOPE = 1024  # references: 0 the scope itself, k its k-th hundred
PREVIEW = 3  # the numbers with a value a hundred's row names
_NUMBER_NAME = re.compile(r"^\s*#\s*(\d+)(?:\s|$)")  # ``#24 (X)``; never ``#1e400`` or ``#1.5``
# the external and G54–G59 offsets, 20 numbers each up to G59's #5321–#5340, whatever the number
# of axes (not the additional systems G54.1 P / G154 P)
WORK_OFFSETS = (2500, 5340)


def vacant_text(locale: str | None) -> str:
    return shown_value(None, locale)


def detail_text(text: str, locale: str | None) -> str:
    """An alarm's detail or a note in the client's language (the program's own texts as written)."""
    return in_language(text, is_chinese(locale))


def show(value: float | None, locale: str | None) -> str:
    """A value for the variables pane, the hover and the console."""
    return shown_value(value, locale)


def is_vacant_text(text: str) -> bool:
    return text.strip() in ("", "<vacant>", "<空>", "vacant", "空")


def variable_number(name: str) -> int | None:
    """The number in a variable's shown name (``#24 (X)`` is 24)."""
    m = _NUMBER_NAME.match(name)
    return int(m.group(1)) if m else None


def frame_name(frames: list[Frame], level: int) -> str:
    f = frames[level]
    if level == 0:
        return f"{f.name} (main)"
    if f.end_line >= 0:  # a lathe cycle's finishing shape
        return (
            f"{f.name} ({f.kind} shape N{f.found.file.program.blocks[f.start_pc].label}–"
            f"N{f.found.file.program.blocks[f.end_line].label})"
        )
    # a call repeated by its L (M98 P2100 L2, G65 P9001 L3) says which pass runs
    passes = f", pass {f.passes - f.repeats} of {f.passes}" if f.passes > 1 else ""
    if f.locals is frames[level - 1].locals:  # a subprogram (M98, M97) runs in its caller's locals
        owner = "main's" if f.macro_level == 0 else f"level {f.macro_level}'s"
        return f"{f.name} ({f.kind}, {owner} locals{passes})"
    return f"{f.name} ({f.kind}, level {f.macro_level}{passes})"


def stack_frames(machine: Machine) -> list[dict[str, Any]]:
    """DAP stack frames, innermost first; a frame's id is its level + 1."""
    out = []
    for level in range(len(machine.frames) - 1, -1, -1):
        f = machine.frames[level]
        line = min(f.pc, max(0, len(f.found.file.lines) - 1))
        source: dict[str, Any] = {"name": Path(f.file).name, "path": f.file}
        if f.found.file.on_control:  # kept on the control: no file to show
            source = {"name": f.file, "presentationHint": "deemphasize"}
        out.append({
            "id": level + 1, "name": frame_name(machine.frames, level), "line": line + 1, "column": 1,
            "source": source,
        })  # fmt: skip
    return out


def reference(level: int, scope: int, group: int = 0) -> int:
    """The variables reference of a frame's scope (``group`` 0) or of its ``group``-th hundred (from 1)."""
    return (level * SCOPES_PER_FRAME + scope) * GROUPS_PER_SCOPE + group + 1


def decode_reference(ref: int) -> tuple[int, int, int]:
    """(level, scope, group) of a variables reference; group 0 is the whole scope."""
    place, group = divmod(ref - 1, GROUPS_PER_SCOPE)
    return place // SCOPES_PER_FRAME, place % SCOPES_PER_FRAME, group


def scopes(machine: Machine, level: int, locale: str | None) -> list[dict[str, Any]]:
    volatile = ", ".join(r.text().replace("-", "–") for r in machine.kinds.volatile)
    kept = ", ".join(r.text().replace("-", "–") for r in machine.kinds.persistent)
    names = {
        LOCALS: pick(locale, "Locals", "局部变量"),
        COMMON: pick(locale, f"Common {volatile}", f"公共变量 {volatile}"),
        PERSISTENT: pick(locale, f"Persistent {kept}", f"保持型变量 {kept}"),
        POSITION: pick(locale, "Position", "位置"),
        MODAL: pick(locale, "Modal", "模态"),
        OFFSETS: pick(locale, "Offsets", "偏置"),
    }
    out = []
    for scope, name in names.items():
        if (scope == COMMON and not volatile) or (scope == PERSISTENT and not kept):
            continue  # a control without such commons (every common of a Haas is kept): no empty scope
        entry: dict[str, Any] = {"name": name, "variablesReference": reference(level, scope), "expensive": False}
        if scope == LOCALS:
            entry["presentationHint"] = "locals"
        elif scope >= POSITION:
            entry["presentationHint"] = "registers"
        out.append(entry)
    return out


@dataclass(frozen=True, slots=True)
class Shown:
    """One variable as a row of the variables pane."""

    number: int
    name: str
    value: float | None
    detail: str = ""


def letters_for(machine: Machine, level: int) -> dict[int, str]:
    """Argument letters for a level's locals: a subprogram (M98) shares its macro's locals."""
    frames = machine.frames
    for k in range(level, -1, -1):
        if frames[k].locals is not frames[level].locals:
            break
        if frames[k].letters:
            return frames[k].letters
    return {}


def hundreds(machine: Machine, scope: int) -> list[tuple[int, int]]:
    """The rows a Common or Persistent scope of more than ``GROUP`` variables opens on: its
    ranges cut at each hundred (``#100–#199``, ``#200–#299``, ...; ``#500–#531`` stays whole),
    first and last number of each. Empty for a smaller scope, which shows its variables at once."""
    if scope not in (COMMON, PERSISTENT):
        return []
    ranges = machine.kinds.volatile if scope == COMMON else machine.kinds.persistent
    if sum(r.last - r.first + 1 for r in ranges) <= GROUP:
        return []
    out = []
    for r in ranges:
        first = r.first
        while first <= r.last:
            last = min(r.last, (first // GROUP + 1) * GROUP - 1)
            out.append((first, last))
            first = last + 1
    return out


def children(machine: Machine, level: int, scope: int, group: int, locale: str | None) -> list[dict[str, Any]]:
    """What a variables reference opens on: a scope's variables, or its hundreds' rows and
    then, for one of those (``group`` from 1), the variables of that hundred."""
    cut = hundreds(machine, scope)
    if not cut:
        return [variable_json(r, locale) for r in rows(machine, level, scope, locale)]
    if group == 0:
        return [_hundred_json(machine, level, scope, k, span, locale) for k, span in enumerate(cut, 1)]
    first, last = cut[group - 1]
    return [variable_json(Shown(n, f"#{n}", machine.read(n)), locale) for n in range(first, last + 1)]


def has_group(machine: Machine, scope: int, group: int) -> bool:
    """Whether ``group`` names the scope itself (0) or one of its hundreds."""
    return group == 0 or group <= len(hundreds(machine, scope))


def _hundred_json(
    machine: Machine, level: int, scope: int, k: int, span: tuple[int, int], locale: str | None
) -> dict[str, Any]:
    """A hundred's row: ``#500–#599``, valued with its first numbers that hold a value."""
    first, last = span
    held = [(n, v) for n in range(first, last + 1) if (v := machine.read(n)) is not None]
    value = ", ".join(f"#{n} = {show(v, locale)}" for n, v in held[:PREVIEW])
    if len(held) > PREVIEW:
        value += ", …"
    return {
        "name": f"#{first}–#{last}", "value": value or pick(locale, "all vacant", "全部为空"),
        "variablesReference": reference(level, scope, k), "namedVariables": last - first + 1,
        "presentationHint": {"kind": "virtual"},
    }  # fmt: skip


def rows(machine: Machine, level: int, scope: int, locale: str | None) -> list[Shown]:
    if scope == LOCALS:
        local = machine.frames[level].locals
        letters = letters_for(machine, level)
        return [Shown(n, f"#{n} ({letters[n]})" if n in letters else f"#{n}", local[n]) for n in range(1, 34)]
    if scope in (COMMON, PERSISTENT):
        ranges = machine.kinds.volatile if scope == COMMON else machine.kinds.persistent
        return [Shown(n, f"#{n}", machine.read(n)) for r in ranges for n in range(r.first, r.last + 1)]
    return _system_rows(machine, scope, locale)


def _system_rows(machine: Machine, scope: int, locale: str | None) -> list[Shown]:
    out = []
    for row in machine.dialect.system_variables():
        if not _in_scope(row, scope):
            continue
        for n in range(row.first, row.last + 1):
            try:
                value = machine.read_system(n)
            except MacroAlarm:
                continue
            if row.group == "tool" and not value and n not in machine.written_system | machine.preset_system:
                continue  # hundreds of tool offsets: only those that hold something
            detail = _describe(row, n, machine, locale)
            short = detail if len(detail) <= 48 else detail[:47] + "…"
            out.append(Shown(n, f"#{n} ({short})", value, detail))
    return out


def _in_scope(row: SystemVariable, scope: int) -> bool:
    if scope == POSITION:
        return row.group == "position"
    if scope == MODAL:
        return row.group == "modal"
    if scope == OFFSETS:
        if row.group == "tool":
            return row.source == "store"
        return (
            row.group == "work"
            and row.first >= WORK_OFFSETS[0]
            and row.last <= WORK_OFFSETS[1]
            and (row.source == "store")
        )
    return False


def _describe(row: SystemVariable, n: int, machine: Machine, locale: str | None) -> str:
    """The row's text for ``#n`` as hover fills it (``describe``), up to its first ``;``."""
    doc = describe.describe_system_variable(machine.dialect, n, locale)
    text = doc.text if doc is not None else pick(locale, row.en, row.zh)
    return text.split(";")[0]


def variable_json(shown: Shown, locale: str | None) -> dict[str, Any]:
    out: dict[str, Any] = {
        "name": shown.name, "value": show(shown.value, locale), "variablesReference": 0,
        "evaluateName": f"#{shown.number}",
    }  # fmt: skip
    if shown.detail:
        out["type"] = shown.detail
    return out
