"""Hover on an address that is no cycle word and no G/M code but means something by the block it
is in: a T word (a lathe's tool and offset, T0101; a mill's tool number), the H of G43/G44 (the
tool length offset and the variables it reads), the L of M98 (the repeat count) and the P of G04
(the dwell, in the profile's unit: ``Timing.dwell_p_unit``, ``dwell_p_point_seconds``). The
splitting of a lathe's T is the planner's (``planner/tool_offsets.py``), the numbers the
profile's; the words are written here, in English and Chinese (``lsp/hover.py`` shows them).
"""

from __future__ import annotations

from ..bilingual import pick
from ..dialects.dialect import Dialect
from ..planner.tool_offsets import lathe_offset_number, station_number
from ..syntax.nodes import Block, Number, Word

_TEXTS: dict[str, tuple[str, str]] = {
    "tool_mill": (
        "Tool number: the tool the next M06 puts in the spindle (T1 M06 changes to tool 1)",
        "刀具号：下一个M06装入主轴的刀具（T1 M06换1号刀）",
    ),
    "tool_lathe": (
        "the turret indexes to the tool and its offset shifts the path (geometry + wear)",
        "刀架转到该刀位，其刀补（形状+磨损）偏移刀具轨迹",
    ),
    "tool_and_offset": ("Tool {tool}, offset {offset}", "刀具号 {tool}，刀补号 {offset}"),
    "offset_cancel": ("offset 0 cancels the tool offset (the turret stays)", "刀补号为0时取消刀补（刀架不转位）"),
    "length_offset": (
        "Tool length offset number: G43 adds (G44 subtracts) offset H's geometry + wear, {places}, to Z",
        "刀具长度补偿号：G43在Z向加上（G44减去）H号刀补的形状+磨损值，{places}",
    ),
    "repeat_count": (
        "Repeat count: the subprogram runs L times (1 when left out)",
        "重复次数：子程序执行L次（省略时为1次）",
    ),
    "dwell": ("Dwell time, {unit}", "暂停时间，{unit}"),
    "dwell_ms": ("in milliseconds (P1000 = 1 s)", "单位为毫秒（P1000 = 1秒）"),
    "dwell_unit": ("in units of {seconds:g} s", "单位为 {seconds:g} 秒"),
    "dwell_point_seconds": ("with a decimal point in seconds (P1. = 1 s)", "带小数点时单位为秒（P1. = 1秒）"),
}


def t(key: str, locale: str | None, **values: object) -> str:
    """The text ``key`` in the language of ``locale``, its ``{name}`` places filled from ``values``."""
    return pick(locale, *_TEXTS[key]).format(**values)


def _codes(block: Block, letter: str) -> set[float]:
    return {w.value.value for w in block.words if w.letter == letter and isinstance(w.value, Number)}


def _dwell_unit(dialect: Dialect, loc: str | None) -> str:
    """The unit of G04's P on this profile: milliseconds or seconds, and what a decimal point does."""
    unit = dialect.timing.dwell_p_unit
    text = t("dwell_ms", loc) if unit == 0.001 else t("dwell_unit", loc, seconds=unit)
    if dialect.timing.dwell_p_point_seconds:
        text += pick(loc, "; ", "；") + t("dwell_point_seconds", loc)
    return text


def address_hover(dialect: Dialect, block: Block, word: Word, loc: str | None) -> str | None:
    """The Markdown for ``word`` of ``block``, or None where its letter means nothing of its own here."""
    letter = word.letter
    value = word.value.value if isinstance(word.value, Number) else None
    title = f"*{dialect.shown_title(loc)}*"
    if letter == "T":
        if not dialect.lathe:
            return f"**T** — {t('tool_mill', loc)}\n\n{title}"
        text = t("tool_lathe", loc)
        if value is not None:
            offset = lathe_offset_number(value)
            said = t("tool_and_offset", loc, tool=station_number(value), offset=offset)
            text = f"{said}{pick(loc, '; ', '；')}{t('offset_cancel', loc) if offset == 0 else text}"
        return f"**T** — {text}\n\n{title}"
    if letter == "H" and _codes(block, "G") & {43.0, 44.0} and not dialect.lathe:
        geometry, wear = dialect.tool_offset_bases[:2]
        n = int(value) if value is not None else None
        places = f"#{geometry + n} + #{wear + n}" if n else f"#{geometry}+n + #{wear}+n"
        return f"**H** — {t('length_offset', loc, places=places)}\n\n{title}"
    if letter == "L" and 98.0 in _codes(block, "M"):
        return f"**L** — {t('repeat_count', loc)}\n\n{title}"
    if letter == "P" and 4.0 in _codes(block, "G"):
        return f"**P** — {t('dwell', loc, unit=_dwell_unit(dialect, loc))}\n\n{title}"
    return None
