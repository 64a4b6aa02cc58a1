"""FANUC 30i/31i/32i-B Custom Macro: the ``fanuc-30i`` profile (``PROFILE``, at the end) and its data:
system variables, their names, G codes and M codes.

Where the 30i reads a number the way the 0i does, the row is ``fanuc_data``'s own (timers,
#3000/#3006, code letters, positions, work offsets, G54.1 P1–P48, the #2001–#2400 and
#2500–#2806 short numbers). What differs or is added (docs/profiles.md "fanuc-30i: sources and
decisions" says where each comes from and what is still to be confirmed):

* 32 interface signals each way, bit by bit (#1000–#1031, #1100–#1131) and four 32-bit words
  (#1032–#1035, #1132–#1135): the layout seed 003 §4.1 gives for parameter MIF = 1;
* 999 tool offsets in memory C (#10001–#13999) instead of 400;
* #3008 program restart (#3005 settings and #3007 mirror image state are the 0i's rows), and the constants #3100
  (vacant), #3101 (π) and #3102 (e), which cannot be written;
* #4000 main program number, 30 modal groups (#4001–#4030) and the same information for the
  block being executed (#4201–#4230, #4302–#4330);
* the position numbers for many axes (#100001 onwards, 50 a kind) as other numbers of #5001…;
* #14001… as other numbers for the G54.1 P1–P48 offsets (#7001…).

``SYSTEM_VARIABLE_NAMES`` are the ``[#_NAME]`` / ``[#_NAME[n]]`` names of those rows. The
simulated machine has four axes (X, Y, Z, A), so the axis rows and names stop at the fourth.
"""

from __future__ import annotations

import math
from dataclasses import replace

from .. import fanuc_data as fanuc
from .. import shared_data as shared
from ..tables import CodeDoc, CommonRange, SystemVariable, SystemVariableName
from .fanuc_0i import PROFILE as FANUC_0I
from .fanuc_0i_lathe import PROFILE as FANUC_0I_LATHE

AXES = 4

# ---------------------------------------------------------------------------------------------
# interface signals: 32 bits each way, and the same signals as 32-bit words


def _words(first: int, access: str, kind: str, prefix: str, en: str, zh: str) -> tuple[SystemVariable, ...]:
    """The four 32-bit words; the first holds the signals #(first - 32)… one bit each
    ({prefix}000–{prefix}031: the same signals, ``source="bits"``)."""
    bits = first - 32
    return tuple(
        SystemVariable(
            first + k,
            first + k,
            access,
            "signals",
            f"Interface {kind} signals {prefix}{k}00-{prefix}{k}31 as one 32-bit number; {en}"
            + (f"; bit i is the same signal as #[{bits}+i]" if k == 0 else ""),
            f"接口{'输入' if kind == 'input' else '输出'}信号{prefix}{k}00～{prefix}{k}31作为一个32位数，{zh}"
            + (f"；第i位即#[{bits}+i]" if k == 0 else ""),
            source="bits" if k == 0 else "store",
            param=f"{bits}:32" if k == 0 else "",
        )
        for k in range(4)
    )


_SIGNALS: tuple[SystemVariable, ...] = (
    *shared.signal_bits(1000, 32, "r", "input", ("UI", "G"), "; sent from the PMC to the macro; reads 0 or 1",
                        "，由PMC送给宏程序，按位读取，值为0或1"),
    *_words(1032, "r", "input", "UI", "read at once", "一次读出"),
    *shared.signal_bits(1100, 32, "rw", "output", ("UO", "F"), "; sent from the macro to the PMC; write 0 or 1, "
                        "reading gives the state last written", "，由宏程序送给PMC，按位写入0或1，读出为当前状态"),
    *_words(1132, "rw", "output", "UO", "written at once, value -99999999 to 99999999",
            "一次写出，取值范围-99999999～99999999"),
)  # fmt: skip

# ---------------------------------------------------------------------------------------------
# tool offsets, memory C: 999 of each kind; #2001-#2400 are the 0i's short numbers

_H_WEAR, _H_GEOMETRY, _D_WEAR, _D_GEOMETRY, _SHORT_WEAR, _SHORT_GEOMETRY = fanuc._TOOL_OFFSETS

_TOOL_OFFSETS: tuple[SystemVariable, ...] = (
    *(replace(row, last=row.first + 998) for row in (_H_WEAR, _H_GEOMETRY, _D_WEAR, _D_GEOMETRY)),
    _SHORT_WEAR,
    _SHORT_GEOMETRY,
)

# ---------------------------------------------------------------------------------------------
# alarm, message stop, time, automatic operation, counters; settings, mirror image, restart;
# the constants

_CONTROL: tuple[SystemVariable, ...] = (
    *fanuc._CONTROL,
    *fanuc.SETTINGS_AND_MIRROR,
    SystemVariable(
        3008,
        3008,
        "r",
        "control",
        "Program restart: 1 while the program is being restarted (searched up to the restart block), else 0",
        "程序再启动状态：正在进行程序再启动时为1，否则为0",
    ),
    SystemVariable(
        3100,
        3100,
        "r",
        "control",
        "Constant: always vacant, like #0; cannot be written",
        "常量：总是空，与#0相同；不能写入",
        source="constant",
        default=None,
    ),
    SystemVariable(
        3101,
        3101,
        "r",
        "control",
        "Constant π (3.14159265358979...), the ratio of a circle's circumference to its diameter; cannot be written",
        "常量：圆周率π（3.14159265358979…）；不能写入",
        source="constant",
        default=math.pi,
    ),
    SystemVariable(
        3102,
        3102,
        "r",
        "control",
        "Constant e (2.71828182845904...), the base of the natural logarithm; cannot be written",
        "常量：自然对数的底e（2.71828182845904…）；不能写入",
        source="constant",
        default=math.e,
    ),
)

# ---------------------------------------------------------------------------------------------
# modal information: up to the previous block (#4001...) and of the block being executed (#4201...)

GROUPS = 30
EXECUTING = 200  # #4201 is #4001 for the block being executed, #4302 is #4102, ...


def _modal_row(group: int, executing: bool) -> SystemVariable:
    """#4000+group as the 0i has it, or #4200+group for the block being executed."""
    if not executing:
        return fanuc._modal_row(group)
    return shared.modal_group_row(
        4000 + group + EXECUTING,
        group,
        fanuc.MODAL_GROUP_CODES,
        (
            "Modal information of G-code group {group:02d} of the block being executed; vacant unless the machine "
            "presets it",
            "正在执行的程序段的第{group}组G代码模态信息；机床未预设时为空",
        ),
        (
            "Modal G code of group {group:02d} ({codes}) of the block being executed, read as a number "
            "({code} reads {value}, not {code})",
            "正在执行的程序段的第{group}组模态G代码（{codes}），读出的是数值（{code}读出为{value}，而不是{code}）",
        ),
    )


_LETTERS = tuple(sorted((*shared.CODE_LETTERS, *fanuc.MILL_CODE_LETTERS)))
_EXECUTING_LETTERS = tuple(
    (n + EXECUTING, letter, f"{en}, of the block being executed", f"正在执行的程序段的{zh}")
    for n, letter, en, zh in _LETTERS
)

_MODAL: tuple[SystemVariable, ...] = (
    SystemVariable(
        4000,
        4000,
        "r",
        "modal",
        "Main program number: the O number of the program the run started in (#4115 is the program now running)",
        "主程序号：运行开始时的程序的O号（#4115为当前正在运行的程序号）",
        source="main",
        default=None,
    ),
    *(_modal_row(group, False) for group in range(1, GROUPS + 1)),
    *shared.code_letter_rows(_LETTERS),
    *(_modal_row(group, True) for group in range(1, GROUPS + 1)),
    *shared.code_letter_rows(_EXECUTING_LETTERS),
)

# ---------------------------------------------------------------------------------------------
# positions: the 0i's numbers, the manual handle interruption, and the numbers for many axes

_EXTENDED_POSITIONS = (  # (first number, the #5001... row it repeats)
    (100001, 5001), (100051, 5021), (100101, 5041), (100151, 5061), (100201, 5081), (100251, 5101),
    (100301, 5121),
)  # fmt: skip


def _extended(first: int, base: int) -> SystemVariable:
    row = next(r for r in fanuc._POSITIONS if r.first == base)
    return replace(
        row,
        first=first,
        last=first + AXES - 1,
        en=f"{row.en} (the number for controls with many axes: the same value as #{base}...)",
        zh=f"{row.zh}（多轴控制用的变量号，与#{base}起的变量值相同）",
    )


_POSITIONS: tuple[SystemVariable, ...] = (
    *fanuc._POSITIONS,
    *(_extended(first, base) for first, base in _EXTENDED_POSITIONS),
)

# ---------------------------------------------------------------------------------------------
# work zero offsets: the 0i's numbers, and #14001... for G54.1 P1-P48

G54_1_LONG = 14001  # G54.1 P1 axis 1 in the numbering that goes on to P300

_WORK_OFFSETS: tuple[SystemVariable, ...] = (
    *fanuc._WORK_OFFSETS,
    *(
        SystemVariable(
            G54_1_LONG + 20 * (p - 1),
            G54_1_LONG + 20 * (p - 1) + AXES - 1,
            "rw",
            "work",
            f"{{axis}} axis work zero offset of G54.1 P{p}; another number for #{7001 + 20 * (p - 1)}...",
            f"第{{index}}轴（{{axis}}）G54.1 P{p}的工件零点偏移值；即#{7001 + 20 * (p - 1)}起的变量",
            "mm",
            "alias",
            str(7001 + 20 * (p - 1)),
        )
        for p in range(1, 49)
    ),
)

SYSTEM_VARIABLES: tuple[SystemVariable, ...] = (
    *_SIGNALS,
    *_TOOL_OFFSETS,
    *_CONTROL,
    *_MODAL,
    *_POSITIONS,
    *_WORK_OFFSETS,
)

# ---------------------------------------------------------------------------------------------
# system variable names


def _name(name: str, first: int, last: int, en: str, zh: str) -> SystemVariableName:
    return SystemVariableName(name, first, last, en, zh)


_WCS_NAMES = tuple(
    _name(f"WZG{53 + i}", 5201 + 20 * i, 5200 + 20 * i + AXES, f"G{53 + i} work zero offset of axis n",
          f"第n轴的G{53 + i}工件零点偏移值")
    for i in range(1, 7)
)  # fmt: skip

_LETTER_NAMES = {"B": "B", "D": "D", "F": "F", "H": "H", "M": "M", "N": "N", "O": "O", "S": "S", "T": "T", "P": "WZP"}

SYSTEM_VARIABLE_NAMES: tuple[SystemVariableName, ...] = (
    _name("UI", 1000, 1031, "interface input signal UI(n-1), bit by bit", "接口输入信号UI(n-1)（按位）"),
    _name("UIL", 1032, 1035, "interface input signals as 32-bit words", "接口输入信号（32位数）"),
    _name("UO", 1100, 1131, "interface output signal UO(n-1), bit by bit", "接口输出信号UO(n-1)（按位）"),
    _name("UOL", 1132, 1135, "interface output signals as 32-bit words", "接口输出信号（32位数）"),
    _name("OFSHW", 10001, 10999, "tool length offset Hn, wear", "刀具长度补偿Hn的磨损补偿值"),
    _name("OFSHG", 11001, 11999, "tool length offset Hn, geometry", "刀具长度补偿Hn的形状补偿值"),
    _name("OFSDW", 12001, 12999, "cutter radius offset Dn, wear", "刀具半径补偿Dn的磨损补偿值"),
    _name("OFSDG", 13001, 13999, "cutter radius offset Dn, geometry", "刀具半径补偿Dn的形状补偿值"),
    _name("ALM", 3000, 3000, "macro alarm", "宏程序报警"),
    _name("CLOCK1", 3001, 3001, "millisecond timer", "毫秒计时器"),
    _name("CLOCK2", 3002, 3002, "hour timer", "小时计时器"),
    _name("CNTL1", 3003, 3003, "single block stop and waiting for M/S/T completion", "单程序段停止与辅助功能完成等待"),
    _name("CNTL2", 3004, 3004, "feed hold, feedrate override and exact stop check", "进给暂停、进给倍率与准确停止检测"),
    _name("SETDT", 3005, 3005, "settings data", "设定数据"),
    _name("MSGSTP", 3006, 3006, "stop with a message", "停止并显示信息"),
    _name("MIRRIMG", 3007, 3007, "mirror image state", "镜像状态"),
    _name("PRSTAT", 3008, 3008, "program restart state", "程序再启动状态"),
    _name("DATE", 3011, 3011, "date YYYYMMDD", "日期（年月日）"),
    _name("TIME", 3012, 3012, "time HHMMSS", "时刻（时分秒）"),
    _name("EMPTY", 3100, 3100, "vacant", "空"),
    _name("PI", 3101, 3101, "the constant π", "圆周率π"),
    _name("E", 3102, 3102, "the constant e", "自然对数的底e"),
    _name("PRTSA", 3901, 3901, "number of parts machined", "已加工零件数"),
    _name("PRTSN", 3902, 3902, "number of parts required", "要求的零件数"),
    _name("BUFG", 4001, 4000 + GROUPS, "modal G code of group n up to the previous block",
          "到前一程序段为止的第n组模态G代码"),
    *(_name(f"BUF{_LETTER_NAMES[letter]}", n, n, f"{letter} code up to the previous block",
            f"到前一程序段为止的{letter}代码") for n, letter, _en, _zh in _LETTERS),
    _name("ACTG", 4201, 4200 + GROUPS, "modal G code of group n of the block being executed",
          "正在执行的程序段的第n组模态G代码"),
    *(_name(f"ACT{_LETTER_NAMES[letter]}", n + EXECUTING, n + EXECUTING, f"{letter} code of the block being executed",
            f"正在执行的程序段的{letter}代码") for n, letter, _en, _zh in _LETTERS),
    _name("ABSIO", 5001, 5000 + AXES, "block end position of axis n, work coordinates",
          "第n轴的程序段终点位置（工件坐标系）"),
    _name("ABSMT", 5021, 5020 + AXES, "current position of axis n, machine coordinates",
          "第n轴的当前位置（机床坐标系）"),
    _name("ABSOT", 5041, 5040 + AXES, "current position of axis n, work coordinates", "第n轴的当前位置（工件坐标系）"),
    _name("ABSKP", 5061, 5060 + AXES, "skip signal position of axis n", "第n轴的跳转信号位置"),
    _name("TOFS", 5081, 5080 + AXES, "tool length offset of axis n", "第n轴的刀具长度补偿值"),
    _name("SVERR", 5101, 5100 + AXES, "servo position deviation of axis n", "第n轴的伺服位置偏差"),
    _name("WZCMN", 5201, 5200 + AXES, "external work zero offset of axis n", "第n轴的外部工件零点偏移值"),
    *_WCS_NAMES,
)  # fmt: skip

# ---------------------------------------------------------------------------------------------
# G and M codes: the 0i's, with M98 reading P as the whole program number


def _m98() -> CodeDoc:
    return CodeDoc(
        "M98",
        "",
        "Subprogram call: M98 P(program number, up to 8 digits) L(repeat count 1-9999); the count is "
        "given in L only. No new level of local variables",
        "子程序调用：M98 P（程序号，最多8位）L（重复次数1～9999）；调用次数只能用L指定。局部变量不改变级别",
    )


G_CODES: tuple[CodeDoc, ...] = fanuc.G_CODES
M_CODES: tuple[CodeDoc, ...] = tuple(_m98() if c.code == "M98" else c for c in fanuc.M_CODES)


# ---------------------------------------------------------------------------------------------
# the profile: the 0i's switches, with names, the 30i functions, 8-digit program numbers in
# M98 P, and the common ranges the 30i can have (#100-#499 and #500-#999 with the option that
# adds commons, #98000-#98499 extended; docs/profiles.md)

_MILL = FANUC_0I.configured(
    name="fanuc-30i",
    title="FANUC 30i-B Custom Macro",
    title_zh="FANUC 30i-B 用户宏程序",
    summary="FANUC 30i/31i/32i-B (and 30i-class horizontal machining centres): names, 8-digit programs",
    summary_zh="FANUC 30i/31i/32i-B（及同级卧式加工中心）：系统变量名、8 位程序号",
    aliases=("fanuc30i", "30i", "31i", "32i", "fanuc-31i", "fanuc-32i", "fanuc-30i-b"),
    data_module="profiles.fanuc_30i",
    variable_names=True,
    extra_functions=frozenset({"POW", "ADP", "PRM", "ATAN[a,b]"}),
    m98_program_digits=8,
    common_ranges=(CommonRange(100, 499, False), CommonRange(500, 999, True), CommonRange(98000, 98499, True)),
)

# the 30i lathes, system A (``lathe = true`` in the machine file; docs/profiles.md "fanuc-30i
# lathes"): the 30i's macro language with the NC side and power-on state of the 0i-TF lathe
LATHE = _MILL.configured(
    title="FANUC 30i-B lathe (G-code system A)",
    title_zh="FANUC 30i-B 车床（G代码体系A）",
    data_module="fanuc_30i_lathe_data",
    lathe=True,
    lathe_offsets=FANUC_0I_LATHE.lathe_offsets,
    drawing_angle=FANUC_0I_LATHE.drawing_angle,
    axes=FANUC_0I_LATHE.axes,
    modal_call_codes=FANUC_0I_LATHE.modal_call_codes,
    modal_defaults=FANUC_0I_LATHE.modal_defaults,
    coordinate_setting_code=FANUC_0I_LATHE.coordinate_setting_code,
    cycle_codes=FANUC_0I_LATHE.cycle_codes,
    drill_cycles=FANUC_0I_LATHE.drill_cycles,
    lathe_drilling=FANUC_0I_LATHE.lathe_drilling,
    single_cycles=FANUC_0I_LATHE.single_cycles,
    lathe_cycles=FANUC_0I_LATHE.lathe_cycles,
    cycle_rules=FANUC_0I_LATHE.cycle_rules,
    cycle_words=FANUC_0I_LATHE.cycle_words,
    cycle_cancel_clears_dwell=FANUC_0I_LATHE.cycle_cancel_clears_dwell,
    timing=FANUC_0I_LATHE.timing,
)

PROFILE = _MILL.configured(lathe_variant=LATHE)
