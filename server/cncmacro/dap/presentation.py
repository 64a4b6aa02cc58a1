"""How the debugger shows a stopped machine: stack frames, scopes and variables.

One stack frame per program level, innermost first, named like ``O9100 (G65, level 1)`` (the
macro level whose locals it has) or ``O2100 (M98, level 1's locals)``, ``O2000 (M98, main's
locals)`` for a subprogram, which runs in its caller's locals.
Each frame has up to six scopes: its locals ``#1–#33`` (``#24 (X)`` where a caller passed the
argument letter), the volatile commons, the persistent ``#500–#999`` (a kind of common the
control lacks has no scope), and the system variables of the dialect's tables grouped as
position, modal state and offsets. A variables
reference encodes the frame and the scope, so it stays valid for as long as the machine
stays stopped. Vacant shows as ``<vacant>`` (``<空>`` in a Chinese locale), and the
interpreter's alarm details and notes are shown in Chinese there too (``detail_text``).
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
    if f.locals is frames[level - 1].locals:  # a subprogram (M98, M97) runs in its caller's locals
        owner = "main's" if f.macro_level == 0 else f"level {f.macro_level}'s"
        return f"{f.name} ({f.kind}, {owner} locals)"
    return f"{f.name} ({f.kind}, level {f.macro_level})"


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


def reference(level: int, scope: int) -> int:
    return level * SCOPES_PER_FRAME + scope + 1


def decode_reference(ref: int) -> tuple[int, int]:
    """(level, scope) of a variables reference."""
    return (ref - 1) // SCOPES_PER_FRAME, (ref - 1) % SCOPES_PER_FRAME


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
