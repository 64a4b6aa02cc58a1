"""Table rows that FANUC 0i and GSK980TDi describe alike, written once for both dialect modules.

Both controls number the code-letter modal variables (#4109 F … #4119 S) and the axis positions
(#5001…, #5021…, #5041…, one per axis) the same way and describe them in the same words, name the
work zero offsets (#5201 + 20·n, G54–G59) alike, and give many G and M codes the same meaning.
``fanuc_data`` and ``gsk980tdi_data`` take these rows and texts from here, sized to their own
number of axes, beside the rows that are theirs alone; what differs stays in their modules.
The builders of rows whose words differ by control (``modal_group_row``, ``work_coordinate_codes``,
``signal_bits``) serve the Haas and 30i profiles too, each giving its own texts; the M98 row of
the controls that read P as the whole program number (``M98_COUNT_IN_L``) and the #3000 row as
they show it (``MACRO_ALARM_SHOWN``) serve Mitsubishi's and Mazak's.
"""

from __future__ import annotations

import re

from .tables import CodeDoc, SystemVariable

# ---------------------------------------------------------------------------------------------
# system variables


def modal_example(codes: str) -> tuple[str, str]:
    """An example for a modal row's hover: the group's second code and the number it reads as."""
    found = re.findall(r"G\d+(?:\.\d)?", codes)
    code = found[1] if len(found) > 1 else found[0]
    return code, code[1:].lstrip("0") or "0"


def modal_group_row(
    number: int,
    group: int,
    group_codes: dict[int, tuple[str, str]],
    vacant: tuple[str, str],
    known: tuple[str, str],
) -> SystemVariable:
    """The modal row ``#number`` of G-code ``group``, as FANUC and Haas profiles describe it.

    ``group_codes`` maps a group the simulated machine keeps to (its name in MODAL_GROUPS, its
    codes); a group it does not keep is vacant unless the machine presets it, described by
    ``vacant`` (en, zh templates of ``{group}``). A kept group reads its code as a number,
    described by ``known`` (en, zh templates of ``{group}``, ``{codes}`` and ``{code}`` reads
    ``{value}``, the example of ``modal_example``)."""
    if group not in group_codes:
        en, zh = vacant
        return SystemVariable(
            number, number, "r", "modal", en.format(group=group), zh.format(group=group), default=None
        )
    name, codes = group_codes[group]
    code, value = modal_example(codes)
    en, zh = known
    return SystemVariable(
        number,
        number,
        "r",
        "modal",
        en.format(group=group, codes=codes, code=code, value=value),
        zh.format(group=group, codes=codes, code=code, value=value),
        source="modal",
        param=name,
    )


def signal_bits(
    first: int, count: int, access: str, kind: str, pmc: tuple[str, str], en: str, zh: str
) -> tuple[SystemVariable, ...]:
    """The FANUC interface signals #first… one bit a number, ``count`` of them: ``kind`` is
    "input" or "output", ``pmc`` the macro's name of the signals (UI, UO) and the PMC's address
    letter (G, F; byte 54 is bit 0); ``en`` and ``zh`` follow the signal's name, each with its
    punctuation."""
    kind_zh = "输入" if kind == "input" else "输出"
    return tuple(
        SystemVariable(first + bit, first + bit, access, "signals",
                       f"Interface {kind} signal {pmc[0]}{bit:03d} (PMC {pmc[1]}{54 + bit // 8}.{bit % 8}){en}",
                       f"接口{kind_zh}信号{pmc[0]}{bit:03d}（PMC {pmc[1]}{54 + bit // 8}.{bit % 8}）{zh}")
        for bit in range(count)
    )  # fmt: skip


# The code-letter rows both controls have: (number, letter, en, zh).
CODE_LETTERS: tuple[tuple[int, str, str, str], ...] = (
    (4109, "F", "F code (feedrate) in effect", "当前的F代码（进给速度）"),
    (4113, "M", "M code last commanded", "最近指令的M代码"),
    (4114, "N", "Sequence number (N) of the last numbered block", "顺序号（最近的N号）"),
    (4115, "O", "Program number (O) of the program being run", "正在运行的程序号（O号）"),
    (4119, "S", "S code (spindle speed or surface speed) in effect", "当前的S代码（主轴转速或线速度）"),
)


def code_letter_rows(rows: tuple[tuple[int, str, str, str], ...]) -> tuple[SystemVariable, ...]:
    """Read-only rows that give the last value of an address (``source="code"``), in number
    order: ``rows`` holds (number, letter, en, zh)."""
    return tuple(
        SystemVariable(number, number, "r", "modal", en, zh, source="code", param=letter)
        for number, letter, en, zh in sorted(rows)
    )


def axis_position_rows(axes: int) -> tuple[SystemVariable, ...]:
    """The block end point (#5001…), machine position (#5021…) and work position (#5041…),
    one number per axis."""
    kinds = (
        (5001, "end", "block end position, work coordinates, without tool offset; readable while the axis moves",
         "程序段终点位置（工件坐标系，不含刀具补偿，移动中可读）"),
        (5021, "machine", "current position, machine coordinates, with tool offset; not readable while moving",
         "当前位置（机床坐标系，含刀具补偿，移动中不可读）"),
        (5041, "current", "current position, work coordinates, with tool offset; not readable while moving",
         "当前位置（工件坐标系，含刀具补偿，移动中不可读）"),
    )  # fmt: skip
    return tuple(
        SystemVariable(first, first + axes - 1, "r", "position", f"{{axis}} axis {en}",
                       f"第{{index}}轴（{{axis}}）{zh}", "mm", "position", param)
        for first, param, en, zh in kinds
    )  # fmt: skip


# The work zero offsets at #5201 + 20·i: i = 0 external, 1-6 G54-G59 (en, zh).
WCS_NAMES: tuple[tuple[str, str], ...] = (
    ("external work zero offset", "外部工件零点偏移值"),
    ("G54 work zero offset", "G54工件零点偏移值"),
    ("G55 work zero offset", "G55工件零点偏移值"),
    ("G56 work zero offset", "G56工件零点偏移值"),
    ("G57 work zero offset", "G57工件零点偏移值"),
    ("G58 work zero offset", "G58工件零点偏移值"),
    ("G59 work zero offset", "G59工件零点偏移值"),
)

# ---------------------------------------------------------------------------------------------
# G and M codes


def work_coordinate_codes(axes: int, offsets_zh: str = "偏移值") -> tuple[CodeDoc, ...]:
    """G54-G59, each naming its offsets #5221… (one per axis); ``offsets_zh`` is the control's
    Chinese word for them (Haas's manual says 偏置)."""
    return tuple(
        CodeDoc(f"G{53 + n}", "wcs", f"Work coordinate system {n} (offsets #{5201 + 20 * n}-#{5200 + 20 * n + axes})",
                f"工件坐标系{n}（{offsets_zh}#{5201 + 20 * n}～#{5200 + 20 * n + axes}）")
        for n in range(1, 7)
    )  # fmt: skip


# The feed modes: G94/G95 on the FANUC mill, G98/G99 on the GSK lathe (en, zh).
FEED_PER_MINUTE: tuple[str, str] = ("Feed per minute (F in mm/min)", "每分钟进给（F单位mm/min）")
FEED_PER_REVOLUTION: tuple[str, str] = ("Feed per revolution (F in mm/rev)", "每转进给（F单位mm/r）")

# G and M codes that both controls describe alike, by code
_CODES: dict[str, CodeDoc] = {
    c.code: c
    for c in (
        CodeDoc("G00", "motion", "Rapid positioning", "快速定位"),
        CodeDoc("G01", "motion", "Linear interpolation at feedrate F", "直线插补（以进给速度F切削）"),
        CodeDoc("G17", "plane", "XY plane selection", "XY平面选择"),
        CodeDoc("G19", "plane", "YZ plane selection", "YZ平面选择"),
        CodeDoc("G20", "units", "Input in inches", "英制输入"),
        CodeDoc("G21", "units", "Input in millimetres", "公制输入"),
        CodeDoc(
            "G66",
            "macro",
            "Modal macro call: G66 P L arguments; the macro is called after every later block that moves an axis",
            "宏程序模态调用：G66 P L 自变量；之后每个有轴移动的程序段执行后调用宏程序",
        ),
        CodeDoc("G67", "macro", "Modal macro call cancel", "宏程序模态调用取消"),
        CodeDoc("G96", "spindle", "Constant surface speed control (S in m/min)", "恒线速度控制（S单位m/min）"),
        CodeDoc(
            "G97", "spindle", "Constant surface speed control cancel (S in rev/min)", "恒线速度控制取消（S单位r/min）"
        ),
        CodeDoc(
            "M01",
            "",
            "Optional stop (only when the optional stop switch is on)",
            "选择停止（仅在选择停止开关打开时有效）",
        ),
        CodeDoc("M02", "", "End of program; modal macro calls are cleared", "程序结束，清除模态宏调用"),
        CodeDoc("M03", "", "Spindle on clockwise", "主轴正转"),
        CodeDoc("M04", "", "Spindle on counterclockwise", "主轴反转"),
        CodeDoc("M05", "", "Spindle stop", "主轴停止"),
        CodeDoc(
            "M30",
            "",
            "End of program and return to its start; modal macro calls are cleared",
            "程序结束并返回程序开头，清除模态宏调用",
        ),
    )
}


def codes(*names: str) -> tuple[CodeDoc, ...]:
    """The rows of G and M codes that mean the same on both controls, in the order named."""
    return tuple(_CODES[name] for name in names)


# G92 on the FANUC mill and G50 on the GSK lathe, and M99 on both, read the same in English; the Chinese
# manuals word them differently.
SET_COORDINATES_EN: str = "Set the work coordinate system so that the current position has the given coordinates"
M99_EN: str = (
    "Return from a subprogram or macro to the block after the call (M99 Pn: to block Nn); "
    "in a main program it restarts the program"
)


# ---------------------------------------------------------------------------------------------
# M98 where P is the whole program number and only L counts (Mitsubishi M70, Mazak EIA/ISO)

M98_COUNT_IN_L = CodeDoc(
    "M98",
    "",
    "Subprogram call: M98 P(program number, up to 8 digits) L(repeat count); the count is given in L only. "
    "No new level of local variables",
    "子程序调用：M98 P（程序号，最多8位）L（重复次数）；调用次数只能用L指定。局部变量不改变级别",
)


def with_m98_count_in_l(codes: tuple[CodeDoc, ...]) -> tuple[CodeDoc, ...]:
    """``codes`` with their M98 row replaced by ``M98_COUNT_IN_L``."""
    return tuple(M98_COUNT_IN_L if c.code == "M98" else c for c in codes)


# #3000 as Mitsubishi M70 and Mazak show it: the control's macro alarm with the message

MACRO_ALARM_SHOWN = SystemVariable(
    3000,
    3000,
    "w",
    "alarm",
    "Macro alarm: #3000=n (message) stops the program with the control's macro alarm and shows the message; "
    "cannot be read",
    "宏程序报警：执行#3000=n（报警信息）时程序停止，发出系统的宏程序报警并显示报警信息；不可读",
    source="alarm",
)


def with_macro_alarm_shown(rows: tuple[SystemVariable, ...]) -> tuple[SystemVariable, ...]:
    """``rows`` with their #3000 row replaced by ``MACRO_ALARM_SHOWN``."""
    return tuple(MACRO_ALARM_SHOWN if row.first == 3000 else row for row in rows)
