"""The alarms of a lathe's cycles (docs/semantics.md §10.5): what a control refuses in a cycle
block's words and in a finishing shape. One rule each, in pure functions both sides call:
``block_findings`` (a cycle block's words) and ``shape_findings`` (a G70–G73 shape as points),
which the static check (analysis/checks/lathe_cycle_checks.py) calls for literal words and the
run for every cycle block (``check_cycle_block``, ``check_shape``).

A finding is ``sure`` where the profile's manual documents the alarm (the run stops with it, the
checker says error); otherwise it is a warning (the run notes it and goes on): a real control
runs real shop programs, and where its check can be switched off (the monotone shape: FANUC's
parameters, GSK's K1) or is not documented, a program is not called wrong. The machine file's
``shape_monotone_check = true`` says the machine checks the shape: then a shape that is not
monotone is sure. The profile's data: ``dialects/lathe_cycle_rules.py``.
"""

from __future__ import annotations

from collections.abc import Collection, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

from ..bilingual import Detail, detail
from ..dialects import alarms as A
from ..dialects import lathe_cycle_rules as K
from .alarms import MacroAlarm

if TYPE_CHECKING:
    from ..dialects.lathe_cycle_rules import LatheCycleRules
    from .lathe_cycles import ShapeReading
    from .planner import Planner

MONOTONE = "monotone"
POCKETS = "pockets"
PAST_START = "past-start"
SHAPE_CODES = frozenset({70.0, 71.0, 72.0, 73.0})
GROOVE_CODES = frozenset({74.0, 75.0})
_TOL = 1e-6
# a shape as points: where it starts (x diameter, z) and each move's (mode, x, z) end
Point = tuple[float, float]
Step = tuple[float, float, float]


@dataclass(frozen=True, slots=True)
class CycleFinding:
    """What a control says of a cycle: its alarm (None where none is documented), the finding's
    kind, the word it is about (for the static check's mark; None for the block), the message,
    and whether it is sure (a sure finding always has its alarm)."""

    alarm: int | None
    kind: str
    letter: str | None
    message: Detail
    sure: bool


def _finding(rules: LatheCycleRules, alarm: int, kind: str, letter: str | None, en: str, zh: str) -> CycleFinding:
    return CycleFinding(alarm, kind, letter, detail(en, zh), kind in rules.surely)


def is_second_block(g: float, words: Collection[str]) -> bool:
    """Whether a block of lathe cycle ``g`` runs the cycle rather than setting its parameters:
    G70 always; G71–G73 with P or Q; G74–G76 with an end point (X, Z, U or W)."""
    if g == 70.0:
        return True
    if g in SHAPE_CODES:
        return "P" in words or "Q" in words
    return any(a in words for a in ("X", "Z", "U", "W"))


def block_findings(
    rules: LatheCycleRules,
    g: float,
    words: dict[str, float],
    first: dict[str, float] | None,
    travel: dict[str, float | None] | None = None,
    unknown: frozenset[str] = frozenset(),
) -> list[CycleFinding]:
    """What the control refuses in a block of cycle ``g`` whose (known) ``words`` are given by
    letter (U and W as written); ``first`` is the cycle's first block in force (None: unknown),
    ``travel`` the end point's distance from the start along X (diameter) and Z, where known,
    ``unknown`` the letters the block has whose values are not known (the static check's)."""
    out: list[CycleFinding] = []
    present = unknown | frozenset(words)
    second = is_second_block(g, present)
    c = f"G{g:g}"
    if g in SHAPE_CODES:
        if second:
            for letter in ("P", "Q"):
                if letter not in present:
                    out.append(_finding(rules, A.CYCLE_P_Q_MISSING, K.P_Q_MISSING, None,
                                        f"{c}: no {letter} (the {'first' if letter == 'P' else 'last'} block of the "
                                        "shape); the block that runs the cycle needs both P and Q",
                                        f"{c}：没有 {letter}（形状程序的{'首' if letter == 'P' else '末'}段）；"
                                        "执行循环的程序段必须同时指定 P 和 Q"))  # fmt: skip
        elif g in (71.0, 72.0):
            letter = "U" if g == 71.0 else "W"
            v = words.get(letter)
            if v is not None and v <= 0:
                out.append(_finding(rules, A.CYCLE_BAD_VALUE, K.DEPTH, letter,
                                    f"{c}: the depth of cut {letter}{v:g} is not above zero",
                                    f"{c}：切削深度 {letter}{v:g} 不大于零"))  # fmt: skip
        elif g == 73.0:
            v = words.get("R")
            if v is not None and v <= 0:
                out.append(_finding(rules, A.REPEAT_COUNT, K.REPEAT, "R",
                                    f"G73: the number of passes R{v:g} is not above zero",
                                    f"G73：切削次数 R{v:g} 不大于零"))  # fmt: skip
        return out
    if g in GROOVE_CODES and second:
        for letter, axis, haas in (("P", "X", "I"), ("Q", "Z", "K")):
            v = words.get(letter)
            if v is None:
                moved = abs((travel or {}).get(axis) or 0.0)
                given = {letter, haas} & (set(words) | unknown)  # Haas's one-block G74/G75 steps by I and K
                if moved > _TOL and not given:  # GSK §3.23.5: "0＜Δi", no default given
                    out.append(_finding(rules, A.GROOVE_END_POINT, K.GROOVE_STEP_MISSING, None,
                                        f"{c}: the end point is {moved:g} away along {axis} but the step {letter} "
                                        f"is left out: the manuals give it no default; the run cuts at the start's "
                                        f"{axis} and then at the end point's",
                                        f"{c}：终点沿 {axis} 相距 {moved:g}，但省略了移动量 {letter}："
                                        f"说明书未给出其默认值；本次运行先在起点的 {axis} 处切削，"
                                        f"再在终点的 {axis} 处切削"))  # fmt: skip
                continue
            if v < 0:
                out.append(_finding(rules, A.GROOVE_AMOUNT, K.GROOVE_AMOUNT, letter,
                                    f"{c}: the step {letter}{v:g} is negative (it is written without a sign)",
                                    f"{c}：移动量 {letter}{v:g} 为负值（应不带符号）"))  # fmt: skip
            elif v == 0 and travel is not None and abs(travel.get(axis) or 0.0) > _TOL:
                out.append(_finding(rules, A.GROOVE_END_POINT, K.GROOVE_END, letter,
                                    f"{c}: the step {letter}0 along {axis} never reaches the end point, "
                                    f"{abs(travel[axis] or 0.0):g} away along {axis}",
                                    f"{c}：沿 {axis} 的移动量 {letter}0 永远到达不了终点（沿 {axis} 相距 "
                                    f"{abs(travel[axis] or 0.0):g}）"))  # fmt: skip
        v = words.get("R")
        if v is not None and v < 0:
            out.append(_finding(rules, A.GROOVE_RELIEF, K.GROOVE_RELIEF, "R",
                                f"{c}: the relief R{v:g} at the end of the cut is negative",
                                f"{c}：切削终点的退刀量 R{v:g} 为负值"))  # fmt: skip
        return out
    if g == 76.0:
        if not second:
            p = words.get("P")
            if p is not None and rules.tool_angles is not None and p >= 0:
                angle = float(round(p) % 100)
                if angle not in rules.tool_angles:
                    shown = ", ".join(f"{a:g}" for a in sorted(rules.tool_angles, reverse=True))
                    out.append(_finding(rules, A.TOOL_ANGLE, K.TOOL_ANGLE, "P",
                                        f"G76: the tool angle {angle:g}° (the last two digits of P) is not one of "
                                        f"{shown}",
                                        f"G76：刀尖角度 {angle:g}°（P 的末两位）不是 {shown} 之一"))  # fmt: skip
            return out
        if "K" in present or "D" in present:
            return out  # the one-block form of FANUC 15 (K the height, D the first depth): not judged
        k, d = words.get("P"), words.get("Q")
        for letter, v, what, what_zh in (("P", k, "thread height", "螺纹牙高"),
                                         ("Q", d, "first depth of cut", "第一次切深")):  # fmt: skip
            if v is None and letter not in unknown:
                out.append(_finding(rules, A.THREAD_DEPTH, K.THREAD_DEPTH, None,
                                    f"G76: no {letter} (the {what}) in the block that cuts the thread",
                                    f"G76：切削螺纹的程序段中没有 {letter}（{what_zh}）"))  # fmt: skip
            elif v is not None and v <= 0:
                out.append(_finding(rules, A.THREAD_DEPTH, K.THREAD_DEPTH, letter,
                                    f"G76: the {what} {letter}{v:g} is not above zero",
                                    f"G76：{what_zh} {letter}{v:g} 不大于零"))  # fmt: skip
        least = None if first is None else first.get("Q")
        # both in the same unit: least input increments (whole numbers) or mm (a decimal point)
        same_unit = least is not None and k is not None and (least == int(least)) == (k == int(k))
        if least is not None and k is not None and same_unit and k > 0 and least > k:
            out.append(_finding(rules, A.THREAD_MIN_DEPTH, K.THREAD_MIN_DEPTH, "P",
                                f"G76: the minimum depth of cut Q{least:g} of the first block is larger than the "
                                f"thread height P{k:g}",
                                f"G76：第一段的最小切深 Q{least:g} 大于螺纹牙高 P{k:g}"))  # fmt: skip
    return out


def _monotone_alarm(axis: str) -> int:
    """The alarm of a shape that is not monotone along ``axis``: PS0064 for the plane's first
    axis (Z in the lathe's ZX plane), PS0329 for its second (X), by FANUC's alarm list."""
    return A.SHAPE_NOT_MONOTONE if axis == "Z" else A.SHAPE_NOT_MONOTONE_X


def check_on(rules: LatheCycleRules, words: dict[str, float], machine_checks: bool) -> bool:
    """Whether the control checks that a G71/G72 shape is monotone: the machine file says so,
    or the profile's check word is 1 in the cycle block (GSK980TDi: K1)."""
    if machine_checks:
        return True
    return rules.check_word is not None and words.get(rules.check_word) == 1.0


def _turns(values: Sequence[float]) -> tuple[int, int | None]:
    """How many times a sequence changes direction, and the index of the first value after
    the first change (None: monotone)."""
    sign = 0
    turns = 0
    at: int | None = None
    for i in range(1, len(values)):
        d = values[i] - values[i - 1]
        if abs(d) <= _TOL:
            continue
        s = 1 if d > 0 else -1
        if sign and s != sign:
            turns += 1
            if at is None:
                at = i
        sign = s
    return turns, at


def shape_findings(
    rules: LatheCycleRules,
    g: float,
    words: dict[str, float],
    start: Point | None,
    steps: Sequence[Step],
    type_two: bool,
    machine_checks: bool,
) -> list[CycleFinding]:
    """What the control refuses in the shape of cycle ``g`` (block ``words``): ``start`` is the
    start point (X a diameter, Z; None where not known: then only the first move is judged,
    and ``steps`` may hold only it), ``steps`` each move of the shape as (mode, x, z) where it
    ends, ``type_two`` whether its first block names both axes (a type II shape)."""
    out: list[CycleFinding] = []
    if not steps:
        return out
    c = f"G{g:g}"
    if steps[0][0] in (2.0, 3.0):  # an arc (another mode in force, G32 or G90, is left alone)
        out.append(_finding(rules, A.SHAPE_FIRST_BLOCK, K.FIRST_BLOCK, None,
                            f"{c}: the first move of the shape is G{steps[0][0]:02g}, not G00 or G01",
                            f"{c}：形状程序的第一个移动是 G{steps[0][0]:02g}，不是 G00 或 G01"))  # fmt: skip
    if g not in (71.0, 72.0) or start is None:
        return out
    xs = [start[0], *(s[1] for s in steps)]
    zs = [start[1], *(s[2] for s in steps)]
    along, across = (zs, xs) if g == 71.0 else (xs, zs)
    along_name, across_name = ("Z", "X") if g == 71.0 else ("X", "Z")
    sure = check_on(rules, words, machine_checks)
    switch = f"{rules.check_word}1 in the cycle block" if rules.check_word else "its parameter"
    switch_zh = f"循环程序段中的 {rules.check_word}1" if rules.check_word else "其参数"
    if machine_checks:
        how, how_zh = "the machine file says the machine checks it", "机床文件说明机床检查此项"
    elif sure:
        how, how_zh = f"{switch} turns the check on", f"{switch_zh}打开了检查"
    else:
        how = f"a warning: the control checks it only where {switch} or the machine file says so"
        how_zh = f"警告：系统只在{switch_zh}或机床文件打开检查时才检查此项"
    turns, at = _turns(along[1:])
    if at is not None:
        out.append(CycleFinding(_monotone_alarm(along_name), MONOTONE, None,
                                detail(f"{c}: the shape turns back along {along_name} at its move {at + 1}; "
                                       f"{along_name} must only increase or only decrease ({how})",
                                       f"{c}：形状在第 {at + 1} 个移动处沿 {along_name} 折返；"
                                       f"{along_name} 必须单调增加或单调减少（{how_zh}）"),
                                sure))  # fmt: skip
    turns, at = _turns(across[1:])
    if not type_two and at is not None:
        out.append(CycleFinding(_monotone_alarm(across_name), MONOTONE, None,
                                detail(f"{c}: the type I shape turns back along {across_name} at its move {at + 1}; "
                                       f"a pocket needs type II (name both axes in its first block) ({how})",
                                       f"{c}：I 型形状在第 {at + 1} 个移动处沿 {across_name} 折返；"
                                       f"有凹槽时须用 II 型（首段同时指定两轴）（{how_zh}）"),
                                sure))  # fmt: skip
    pockets = (turns + 1) // 2
    if type_two and pockets > rules.pockets:
        out.append(CycleFinding(None, POCKETS, None,
                                detail(f"{c}: the type II shape has {pockets} pockets, more than the {rules.pockets} "
                                       "the control takes",
                                       f"{c}：II 型形状有 {pockets} 个凹槽，超过系统允许的 {rules.pockets} 个"),
                                False))  # fmt: skip
    base = across[0]
    inward = across[1] - base
    if abs(inward) > _TOL:
        beyond = [i for i, v in enumerate(across[1:]) if (v - base) * inward < -_TOL]
        if beyond:
            out.append(CycleFinding(A.SHAPE_PAST_START, PAST_START, None,
                                    detail(f"{c}: the shape goes past the start point along {across_name} at its move "
                                           f"{beyond[0] + 1} (a warning: a control with the check on stops there)",
                                           f"{c}：形状在第 {beyond[0] + 1} 个移动处沿 {across_name} 超出了循环起点"
                                           "（警告：系统打开该检查时在此停止）"),
                                    False))  # fmt: skip
    return out


# ---------------------------------------------------------------- at run time
def _report(p: Planner, found: list[CycleFinding], subject: str, line: int | None = None) -> None:
    """Stop with the first sure finding; note the others (warnings), together, on ``line`` (the
    block running when None), and go on. ``subject`` is the diagnostic's (``cycle-block`` or
    ``cycle-shape``, analysis/codes.py)."""
    for f in found:
        if f.sure and f.alarm is not None:
            raise MacroAlarm(f.alarm, f.message, subject)
    if found:  # one note: the analysis shows one finding of a code per line
        en = "; ".join(str(f.message) for f in found)
        zh = "；".join(f.message.zh for f in found)
        p.host.note("cycle", detail(en, zh), line, subject)


def check_cycle_block(p: Planner, g: float, words: dict[str, float], line: int | None = None) -> None:
    """Refuse a block of lathe cycle ``g`` on ``line`` whose ``words`` (U and W by letter) the
    control alarms on; the first block's parameters are in ``p.cycle_params``."""
    rules = p.dialect.cycle_rules
    if rules is None:
        return
    travel: dict[str, float | None] = {}
    for axis, inc in (("X", "U"), ("Z", "W")):
        i = p.axis_index.get(axis)
        if i is None:
            continue
        if axis in words:
            travel[axis] = words[axis] - p.pos[i]
        else:
            travel[axis] = words.get(inc, 0.0)
    _report(p, block_findings(rules, g, words, p.cycle_params.get(g), travel), "cycle-block", line)


def check_shape(p: Planner, shape: ShapeReading) -> None:
    """Refuse a finishing shape, read in full, that the control alarms on."""
    rules = p.dialect.cycle_rules
    if rules is None:
        return
    xi, zi = p.axis_index["X"], p.axis_index["Z"]
    steps = [(mode, end[xi], end[zi]) for mode, _, end, _ in shape.segments]
    named = shape.first_axes or frozenset()
    type_two = xi in named and zi in named
    found = shape_findings(rules, shape.code, shape.words, (shape.start[xi], shape.start[zi]), steps, type_two,
                           p.settings.shape_monotone_check)  # fmt: skip
    _report(p, found, "cycle-shape")
