"""Alarm numbers and their texts, in English and Chinese (docs/semantics.md §6).

The numbers are FANUC 0i's where the manuals give no other (every dialect shares them); the
GSK-only numbers (291, 293) come from seeds 001 and 002, the FANUC 30i's for variable names
(1098, 1099) from its alarm list (docs/profiles.md). A macro alarm raised by ``#3000``
(3000+n on fanuc, 5900+n on gsk980tdi) or ``G65 H99`` carries the program's own text instead.
These numbers name an alarm inside the interpreter on every profile; what a person is shown is
the profile's (``Dialect.documented_alarms``, ``Dialect.shown_alarm``, ``alarm_words``): Haas
documents none of them, so its alarms are shown without a number. A message that names an alarm
writes it with ``Dialect.alarm_said`` ("alarm 127", or "alarm") or ``Dialect.alarm_titled`` (with
its text), never with the number typed into the sentence.
"""

from __future__ import annotations

from ..bilingual import Detail, detail, pick
from .tables import AlarmDoc

DECIMAL_POINT = 7
IMPROPER_G_CODE = 10
FEED_ZERO = 11  # PS0011: a cut with a feed of 0 (docs/semantics.md §10.4)
ARC_RADIUS = 20  # PS0020: I, J, K whose end is off the start's circle (docs/semantics.md §8, "Arcs")
ARC_NO_CENTRE = 22  # PS0022: an arc that moves in its plane with neither R nor I, J, K (the same)
PROGRAM_NOT_FOUND = 76
SUBPROGRAM_NESTING = 77
DUPLICATE_PROGRAM = 73
OVERFLOW = 111
# The largest magnitude a variable holds (FANUC: about 10**47); beyond it is alarm 111 (OVERFLOW),
# and a value from outside the program (a preset, the machine file, the persistent file) is refused.
MAX_VALUE = 1e47
DIVISION_BY_ZERO = 112
FORMAT = 114
VARIABLE_NUMBER = 115
WRITE_PROTECTED = 116
BRACKET_NESTING = 118
ARGUMENT_RANGE = 119
MACRO_NESTING = 122
MISSING_END = 124
STATEMENT_FORMAT = 125
LOOP_NUMBER = 126
NC_AND_MACRO = 127
SEQUENCE_NUMBER = 128
G_ARGUMENT = 129
# a lathe's multiple repetitive cycles and threads: the FANUC 0i-TF PS alarms, their texts in plain
# words (docs/semantics.md §10.5)
THREAD_CORNER = 50
CYCLE_P_Q_MISSING = 61
CYCLE_BAD_VALUE = 62
CYCLE_BLOCK_NOT_FOUND = 63
SHAPE_NOT_MONOTONE = 64
SHAPE_FIRST_BLOCK = 65
SHAPE_LAST_BLOCK = 69
ILLEGAL_LEAD = 313  # PS0313: a variable lead (G34) negative, or falling below zero (planner/variable_leads.py)
TOOL_ANGLE = 315
THREAD_MIN_DEPTH = 316
THREAD_DEPTH = 317
GROOVE_RELIEF = 318
GROOVE_END_POINT = 319
GROOVE_AMOUNT = 320
REPEAT_COUNT = 321
SHAPE_PAST_START = 322
SHAPE_COMMAND = 325
SHAPE_NOT_MONOTONE_X = 329
# the machine's limits (docs/semantics.md §11, the machine file's [limits]): FANUC 0i's PS0030 and
# OT0500/OT0501 (stored stroke check 1, the soft limits)
OFFSET_NUMBER = 30
OVERTRAVEL_PLUS = 500
OVERTRAVEL_MINUS = 501
# cutter radius compensation (docs/semantics.md, "Cutter radius compensation"): FANUC's PS alarms
CUTTER_NO_INTERSECTION = 33
CUTTER_ARC_START = 34
CUTTER_SKIP = 35  # PS0035: G31 in G41/G42 (Mitsubishi: program error P608, shown without a number)
CUTTER_PLANE = 37
CUTTER_CORNER = 39  # PS0039: ,C/,R on a start-up, a cancel or a change of side in G41/G42
# a chamfer or corner R that does not fit its moves (planner/corner_stage.py): FANUC's PS0055, the
# GSK980TDi's unnumbered alarms of §3.11.3
CORNER_FIT = 55
# the block after a chamfer or corner R is no move in its plane, or not G01, G02, G03
# (planner/corner_stage.py): FANUC's PS0051 and PS0052
CORNER_NO_MOVE = 51
CORNER_NOT_CUT = 52
CUTTER_INTERFERENCE = 41
# a mill's drilling canned cycles (docs/semantics.md §9): FANUC 0i's PS alarms
REFERENCE_IN_CYCLE = 44  # PS0044: G27-G30 in canned cycle mode (planner/one_shot.py)
PECK_Q_MISSING = 45  # PS0045: G73/G83 with no Q, or Q0 (planner/drill_cycles.py)
# the GSK980TDi's G86 with I0 or I below R (planner/reciprocating_feed.py): its manual gives no
# number, so the number is the interpreter's own and the profile shows the alarm unnumbered
RECIPROCATION_AMOUNT = 9086
# the GSK980TDi's G22/G23 beside another G code or an M, S, T (machine/block_rules.py): no number
# given either, shown unnumbered
NOT_ALONE = 9022
# the GSK980TDi's G12.1 under G99 or in tool nose radius compensation (planner/one_shot.py): no
# number given, shown unnumbered
POLAR_START = 9121
P_VALUE_RANGE = 291
COUNT_TWICE = 293
NO_VARIABLE_NAME = 1098
NAME_SUBSCRIPT = 1099

ALARMS: dict[int, AlarmDoc] = {
    a.number: a
    for a in (
        AlarmDoc(DECIMAL_POINT, "illegal use of decimal point", "小数点使用不当"),
        AlarmDoc(IMPROPER_G_CODE, "improper G code", "G代码不当"),
        AlarmDoc(FEED_ZERO, "feed zero (command)", "进给速度为零（指令）"),
        AlarmDoc(ARC_RADIUS, "over tolerance of radius", "圆弧半径超差"),
        AlarmDoc(ARC_NO_CENTRE, "R or I, J, K command not found", "未指令 R 或 I、J、K"),
        AlarmDoc(PROGRAM_NOT_FOUND, "program not found", "未找到程序"),
        AlarmDoc(DUPLICATE_PROGRAM, "program number already in use", "程序号已被使用"),
        AlarmDoc(SUBPROGRAM_NESTING, "subprogram nesting too deep", "子程序嵌套过深"),
        AlarmDoc(OVERFLOW, "calculated value out of range", "运算结果超出范围"),
        AlarmDoc(DIVISION_BY_ZERO, "division by zero", "除数为零"),
        AlarmDoc(FORMAT, "illegal expression format", "表达式格式错误"),
        AlarmDoc(VARIABLE_NUMBER, "variable number out of range", "变量号超出范围"),
        AlarmDoc(WRITE_PROTECTED, "write-protected variable", "变量禁止写入"),
        AlarmDoc(BRACKET_NESTING, "brackets nested more than 5 deep", "括号嵌套超过5层"),
        AlarmDoc(ARGUMENT_RANGE, "argument out of range", "自变量超出范围"),
        AlarmDoc(MACRO_NESTING, "macro call nesting too deep", "宏程序调用嵌套过深"),
        AlarmDoc(MISSING_END, "missing END statement", "缺少END语句"),
        AlarmDoc(STATEMENT_FORMAT, "illegal macro statement format", "宏语句格式错误"),
        AlarmDoc(LOOP_NUMBER, "illegal loop number", "循环号错误"),
        AlarmDoc(NC_AND_MACRO, "NC word and macro statement in one block", "NC代码与宏语句在同一程序段"),
        AlarmDoc(SEQUENCE_NUMBER, "sequence number not found", "未找到顺序号"),
        AlarmDoc(G_ARGUMENT, "illegal address in the argument list", "自变量中使用了非法地址"),
        AlarmDoc(
            THREAD_CORNER, "chamfering or corner R in a thread cutting block", "螺纹切削程序段中指令了倒角或拐角R"
        ),
        AlarmDoc(CYCLE_P_Q_MISSING, "P or Q is not in the multiple repetitive cycle block", "复合循环程序段中没有P或Q"),
        AlarmDoc(CYCLE_BAD_VALUE, "illegal depth of cut in the rough cutting cycle", "粗车循环的切削量不当"),
        AlarmDoc(
            CYCLE_BLOCK_NOT_FOUND, "the block of the specified sequence number is not found", "未找到指定顺序号的程序段"
        ),
        AlarmDoc(
            SHAPE_NOT_MONOTONE,
            "the finishing shape is not a monotonous change (first axis)",
            "精加工形状不是单调变化（第1轴）",
        ),
        AlarmDoc(
            SHAPE_FIRST_BLOCK, "G00/G01 is not in the first block of the shape program", "形状程序的第一段中没有G00/G01"
        ),
        AlarmDoc(
            SHAPE_LAST_BLOCK, "the last block of the shape program is an illegal command", "形状程序的最后一段指令不当"
        ),
        AlarmDoc(ILLEGAL_LEAD, "illegal lead command", "导程指令不当"),
        AlarmDoc(TOOL_ANGLE, "illegal tool nose angle in the threading cycle", "螺纹切削循环中的刀尖角度不当"),
        AlarmDoc(
            THREAD_MIN_DEPTH,
            "illegal depth of cut in the threading cycle (the minimum depth above the thread height)",
            "螺纹切削循环中的切削量不当（最小切深大于螺纹牙高）",
        ),
        AlarmDoc(
            THREAD_DEPTH,
            "illegal thread command in the threading cycle (height or depth of cut zero or negative)",
            "螺纹切削循环中的螺纹指令不当（牙高或切深为零或负值）",
        ),
        AlarmDoc(
            GROOVE_RELIEF, "illegal relief amount in the drilling cycle (G74/G75)", "钻孔循环（G74/G75）的退刀量不当"
        ),
        AlarmDoc(
            GROOVE_END_POINT,
            "illegal end point command in the drilling cycle (G74/G75)",
            "钻孔循环（G74/G75）的终点不当",
        ),
        AlarmDoc(
            GROOVE_AMOUNT,
            "illegal movement or cut amount in the drilling cycle (G74/G75)",
            "钻孔循环（G74/G75）的移动量或切削量不当",
        ),
        AlarmDoc(
            REPEAT_COUNT,
            "illegal repeat count in the pattern repeating cycle (G73)",
            "封闭切削循环（G73）的重复次数不当",
        ),
        AlarmDoc(SHAPE_PAST_START, "the finishing shape goes over the starting point", "精加工形状超出了循环起点"),
        AlarmDoc(SHAPE_COMMAND, "unavailable command in the shape program", "形状程序中有不可用的指令"),
        AlarmDoc(
            SHAPE_NOT_MONOTONE_X,
            "the finishing shape is not a monotonous change (second axis)",
            "精加工形状不是单调变化（第2轴）",
        ),
        AlarmDoc(OFFSET_NUMBER, "illegal offset number", "刀补号不当"),
        AlarmDoc(OVERTRAVEL_PLUS, "+ overtravel (soft limit 1)", "+ 向超程（软限位 1）"),
        AlarmDoc(OVERTRAVEL_MINUS, "- overtravel (soft limit 1)", "- 向超程（软限位 1）"),
        AlarmDoc(CUTTER_NO_INTERSECTION, "no intersection at cutter compensation", "刀具半径补偿求不出交点"),
        AlarmDoc(
            CUTTER_ARC_START,
            "no circular move allowed in the start-up or cancel block",
            "刀补建立或取消的程序段中不能用圆弧",
        ),
        AlarmDoc(CUTTER_SKIP, "G31 cannot be commanded in cutter compensation", "刀具半径补偿方式中不能指令 G31"),
        AlarmDoc(CUTTER_PLANE, "cannot change the plane in G41/G42", "G41/G42 方式中不能变更平面"),
        AlarmDoc(
            CUTTER_CORNER,
            "chamfering or corner R not allowed at a start-up, cancel or change of side in G41/G42",
            "G41/G42 建立、取消或切换时不能指令倒角或拐角R",
        ),
        AlarmDoc(CUTTER_INTERFERENCE, "interference in cutter compensation", "刀具半径补偿干涉"),
        AlarmDoc(
            CORNER_FIT,
            "missing move value in chamfering or corner R (the move is shorter than the chamfer or corner R)",
            "倒角或拐角R的移动量不足（移动量小于倒角或拐角R）",
        ),
        AlarmDoc(
            CORNER_NO_MOVE,
            "missing move after chamfering or corner R (the next block does not move in the plane)",
            "倒角或拐角R之后缺少移动（下一程序段在该平面内没有移动）",
        ),
        AlarmDoc(
            CORNER_NOT_CUT,
            "code is not G01 after chamfering or corner R (the next block is not G01, G02 or G03)",
            "倒角或拐角R之后的代码不是 G01（下一程序段不是 G01、G02 或 G03）",
        ),
        AlarmDoc(REFERENCE_IN_CYCLE, "G27-G30 not allowed in a canned cycle", "固定循环中不能指令 G27-G30"),
        AlarmDoc(PECK_Q_MISSING, "address Q not found (G73/G83)", "未指令地址 Q（G73/G83）"),
        AlarmDoc(
            RECIPROCATION_AMOUNT,
            "illegal stroke in the reciprocating feed cycle (G86)",
            "往复进给循环（G86）的进刀量不当",
        ),
        AlarmDoc(NOT_ALONE, "the code must be in a block of its own", "该代码须单独编为一段"),
        AlarmDoc(
            POLAR_START,
            "polar coordinate interpolation started under G99 or in tool nose radius compensation",
            "在 G99 状态或刀尖半径补偿中启动极坐标插补",
        ),
        AlarmDoc(P_VALUE_RANGE, "P value out of range", "P值超出范围"),
        AlarmDoc(COUNT_TWICE, "repeat count given in both P and L", "P和L同时指定了调用次数"),
        AlarmDoc(NO_VARIABLE_NAME, "no such variable name", "没有该变量名"),
        AlarmDoc(NAME_SUBSCRIPT, "illegal subscript [ ] of a variable name", "变量名的下标[ ]错误"),
    )
}


def shown_number(number: int, documented: frozenset[int] | None) -> int | None:
    """The number a person is shown for alarm ``number`` on a control that documents
    ``documented`` (``Dialect.documented_alarms``: None, every one)."""
    return number if documented is None or number in documented else None


def alarm_words(shown: int | None, locale: str = "en", width: int = 0) -> str:
    """How a person reads an alarm's number: "alarm 128" ("报警 128"), or "alarm" ("报警")
    alone where the profile documents no number for it (``Dialect.shown_alarm``). ``width``
    pads the number with zeros as a message writes it ("alarm 007")."""
    if shown is None:
        return pick(locale, "alarm", "报警")
    return pick(locale, f"alarm {shown:0{width}d}", f"报警 {shown:0{width}d}")


def alarm_said(shown: int | None, width: int = 0) -> Detail:
    """``alarm_words`` in both languages, for a message that names the alarm: "(alarm 127)",
    "stops with alarm 127", and where no number is shown "(alarm)", "stops with alarm"."""
    return detail(alarm_words(shown, "en", width), alarm_words(shown, "zh", width))


def alarm_titled(shown: int | None, number: int, width: int = 0) -> Detail:
    """The alarm named with its text: "alarm 010 improper G code" ("报警 010 G代码不当"), or, where
    no number is shown, "alarm: improper G code" ("报警：G代码不当")."""
    doc = ALARMS[number]
    if shown is None:
        return detail(f"alarm: {doc.en}", f"报警：{doc.zh}")
    return detail(f"alarm {shown:0{width}d} {doc.en}", f"报警 {shown:0{width}d} {doc.zh}")


def alarm_text(number: int, locale: str = "en") -> str:
    """The standard text of an alarm number, or a generic one."""
    doc = ALARMS.get(number)
    if doc is None:
        return pick(locale, "alarm", "报警")
    return pick(locale, doc.en, doc.zh)
