"""GSK980TDi data: the system variables, G codes and M codes of the GSK980TDi lathe control.

``SYSTEM_VARIABLES`` follows the system-variable tables of the GSK980TDi manual §3.28.1 (seed 000):
interface signals, tool offsets 1-32 (X, Z, Y wear and geometry, nose radius, imaginary tool nose
direction), parts counters, the X/Z work coordinate shift, the macro alarm #3000 (alarm
5900 + value), cutting timers, system date and time, modal information #4001-#4120, positions for
five axes (X, Y, Z, 4th, 5th), manual pulse interrupt amounts and work zero offsets. ``G_CODES``
and ``M_CODES`` describe the lathe's codes; a code's ``group`` is its name in ``MODAL_GROUPS``, or
empty for a one-shot code. On this lathe G98/G99 are feed per minute/per revolution and
G90/G92/G94 are single turning, thread and facing cycles in the motion group. Rows and texts
that the FANUC 0i shares come from ``shared_data``.
"""

from __future__ import annotations

from . import shared_data as shared
from .tables import CodeDoc, SystemVariable

# ---------------------------------------------------------------------------------------------
# 1) interface signals: readable; the CNC acts on G and F signals only


def _bit_rows(first: int, letter: str, en_kind: str, zh_kind: str) -> tuple[SystemVariable, ...]:
    return tuple(
        SystemVariable(
            first + bit,
            first + bit,
            "r",
            "signals",
            f"{en_kind} signal {letter}{54 + bit // 8}.{bit % 8}: its state, 0 or 1",
            f"{zh_kind}信号{letter}{54 + bit // 8}.{bit % 8}的状态（0或1）",
        )
        for bit in range(16)
    )


def _byte_pair_row(number: int, letter: str, low: int, en_kind: str, zh_kind: str) -> SystemVariable:
    """Two bytes of signals read as one number; bytes 54 and 55 are the signals #(number - 32)…
    one bit each (``_bit_rows``), so that row reads them (``source="bits"``)."""
    bits = number - 32 if low == 54 else None
    return SystemVariable(
        number,
        number,
        "r",
        "signals",
        f"{en_kind} signals {letter}{low} and {letter}{low + 1}: the state of both bytes read at once as one number"
        + (f"; bit i is #[{bits}+i]" if bits else ""),
        f"{zh_kind}信号{letter}{low}、{letter}{low + 1}两字节的状态，作为一个数一次读出"
        + (f"；第i位即#[{bits}+i]" if bits else ""),
        source="bits" if bits else "store",
        param=f"{bits}:16" if bits else "",
    )


_SIGNALS: tuple[SystemVariable, ...] = (
    *_bit_rows(1000, "G", "PLC-to-CNC (G)", "PLC→CNC（G）"),
    _byte_pair_row(1032, "G", 54, "PLC-to-CNC (G)", "PLC→CNC（G）"),
    _byte_pair_row(1033, "G", 56, "PLC-to-CNC (G)", "PLC→CNC（G）"),
    _byte_pair_row(1034, "G", 58, "PLC-to-CNC (G)", "PLC→CNC（G）"),
    *_bit_rows(1100, "F", "CNC-to-PLC (F)", "CNC→PLC（F）"),
    _byte_pair_row(1132, "F", 54, "CNC-to-PLC (F)", "CNC→PLC（F）"),
    _byte_pair_row(1133, "F", 56, "CNC-to-PLC (F)", "CNC→PLC（F）"),
    _byte_pair_row(1134, "F", 58, "CNC-to-PLC (F)", "CNC→PLC（F）"),
)

# ---------------------------------------------------------------------------------------------
# 2) tool offsets 1-32: readable and writable

_TOOL_OFFSET_KINDS: tuple[tuple[int, str, str, str], ...] = (
    (2001, "X wear", "X轴磨损补偿值", "mm"),
    (2101, "Z wear", "Z轴磨损补偿值", "mm"),
    (2201, "tool nose radius wear", "刀尖半径磨损补偿值", "mm"),
    (2301, "imaginary tool nose direction T (0-9)", "假想刀尖位置T（0～9）", ""),
    (2401, "Y wear", "Y轴磨损补偿值", "mm"),
    (2451, "Y geometry", "Y轴几何形状补偿值", "mm"),
    (2701, "X geometry", "X轴几何形状补偿值", "mm"),
    (2801, "Z geometry", "Z轴几何形状补偿值", "mm"),
    (2901, "tool nose radius geometry", "刀尖半径几何形状补偿值", "mm"),
)

_TOOL_OFFSETS: tuple[SystemVariable, ...] = tuple(
    SystemVariable(
        first,
        first + 31,
        "rw",
        "tool",
        f"Tool offset {{index}}: {en}",
        f"{{index}}号刀补的{zh}",
        unit,
    )
    for first, en, zh, unit in _TOOL_OFFSET_KINDS
)

# ---------------------------------------------------------------------------------------------
# 3)-8) counters, work coordinate shift, alarm, cutting time, system time, modal information

_CONTROL: tuple[SystemVariable, ...] = (
    SystemVariable(3901, 3901, "rw", "counters", "Number of parts machined (completed)", "已加工的零件数（已完成）"),
    SystemVariable(3902, 3902, "rw", "counters", "Maximum number of parts to machine", "最大加工件数"),
    # the workpiece coordinate system shift, kept as the external work offset of X (#5201, axis 1)
    # and Z (#5203, axis 3), as a FANUC lathe's G10 P0 keeps it (docs/semantics.md §10.1)
    SystemVariable(
        2501,
        2501,
        "rw",
        "work",
        "X work coordinate system shift (on the diameter); the same value as #5201, the X external "
        "work offset: the machine position is the program position plus it",
        "X轴工件坐标系偏移值（直径值）；即#5201（X轴外部工件零点偏移值）：机床位置为编程位置加上此值",
        "mm",
        "alias",
        "5201",
    ),
    SystemVariable(
        2502,
        2502,
        "rw",
        "work",
        "Z work coordinate system shift; the same value as #5203, the Z external work offset: the "
        "machine position is the program position plus it",
        "Z轴工件坐标系偏移值；即#5203（Z轴外部工件零点偏移值）：机床位置为编程位置加上此值",
        "mm",
        "alias",
        "5203",
    ),
    SystemVariable(
        3000,
        3000,
        "w",
        "alarm",
        "Macro alarm: #3000=n (message) stops the program with alarm 5900+n (5900-5999); "
        "the message may be left out. Cannot be read",
        "宏程序报警：执行#3000=n（报警内容）时系统停止运行，发出报警 5900+n（范围5900～5999），"
        "报警内容可省略。只能写不能读",
        source="alarm",
    ),
    SystemVariable(
        3001,
        3001,
        "r",
        "time",
        "Machining time of the current part (single run), in seconds; read only",
        "单次加工时间（单位：秒），可读不可写",
        "s",
        "timer",
        "s",
    ),
    SystemVariable(
        3002,
        3002,
        "rw",
        "time",
        "Accumulated cutting time, in seconds",
        "累加切削时间（单位：秒），可读可写",
        "s",
        "timer",
        "s",
    ),
    SystemVariable(
        3011,
        3011,
        "rw",
        "time",
        "System date as a decimal number YYYYMMDD (year/month/day)",
        "系统日期（年/月/日），以十进制数YYYYMMDD表示",
        "",
        "date",
    ),
    SystemVariable(
        3012,
        3012,
        "rw",
        "time",
        "System time of day as a decimal number HHMMSS (hour/minute/second)",
        "系统时间（时/分/秒），以十进制数HHMMSS表示",
        "",
        "time",
    ),
)

_MODAL_ROWS: tuple[tuple[int, str, str, str, str], ...] = (
    (
        4001,
        "motion",
        "01",
        "G00, G01, G02, G03, G05, G32, G33, G34, G80, G84, G88, G90, G92, G94, "
        "G06.2 (reads 124), G06.3 (126), G32.1 (132), G07.2 (144), G07.3 (146)",
        "G00、G01、G02、G03、G05、G32、G33、G34、G80、G84、G88、G90、G92、G94、"
        "G06.2（读出124）、G06.3（126）、G32.1（132）、G07.2（144）、G07.3（146）",
    ),
    (4002, "spindle", "02", "G96, G97", "G96、G97"),
    (4005, "feed", "03", "G98 feed per minute, G99 feed per revolution", "G98每分钟进给、G99每转进给"),
    (4006, "units", "06", "G20, G21", "G20、G21"),
    (4007, "cutter", "07", "G40, G41, G42", "G40、G41、G42"),
    (4012, "macro", "12", "G66, G67", "G66、G67"),
    (4014, "wcs", "14", "G54-G59", "G54～G59"),
    (4016, "plane", "16", "G17, G18, G19", "G17、G18、G19"),
)

# the lathe's T code beside the code letters both controls have (shared_data.CODE_LETTERS)
_CODE_LETTERS: tuple[tuple[int, str, str, str], ...] = (
    (
        4120,
        "T",
        "T code last commanded: tool number x 100 + offset number (T0101 reads 101)",
        "最近指令的T代码：刀具号×100+刀补号（T0101读出101）",
    ),
)


_MODAL: tuple[SystemVariable, ...] = (
    *(
        SystemVariable(
            number,
            number,
            "r",
            "modal",
            f"Modal G code of group {group} ({codes}), read as a number ({code} reads {value})",
            f"{group}组模态G代码（{zh_codes}），读出的是数值（{code}读出为{value}）",
            source="modal",
            param=name,
        )
        for number, name, group, codes, zh_codes in _MODAL_ROWS
        for code, value in (shared.modal_example(codes),)
    ),
    *shared.code_letter_rows((*shared.CODE_LETTERS, *_CODE_LETTERS)),
)

# ---------------------------------------------------------------------------------------------
# 9)-11) positions, manual pulse interrupt, work zero offsets: readable (axes X, Y, Z, 4th, 5th)

_POSITIONS: tuple[SystemVariable, ...] = (
    *shared.axis_position_rows(5),
    SystemVariable(
        5121,
        5125,
        "r",
        "position",
        "Axis {index} ({axis}) manual pulse generator interrupt amount: the distance added by the handwheel "
        "during automatic operation",
        "第{index}轴（{axis}）手脉中断值：自动运行中用手脉插入的移动量",
        "mm",
        "position",
        "handle",
    ),
)

_WORK_OFFSETS: tuple[SystemVariable, ...] = tuple(
    SystemVariable(
        5201 + 20 * i,
        5205 + 20 * i,
        "r",
        "work",
        f"{{axis}} axis {en} (read only; set by G10 L2 P{i} or on the offset page)",
        f"第{{index}}轴（{{axis}}）{zh}（只读；用G10 L2 P{i}或在偏置页面设定）",
        "mm",
    )
    for i, (en, zh) in enumerate(shared.WCS_NAMES)
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
# G and M codes of the GSK980TDi lathe

G_CODES: tuple[CodeDoc, ...] = (
    *shared.codes("G00", "G01"),
    CodeDoc("G02", "motion", "Circular interpolation clockwise (R or I K)", "顺时针圆弧插补（R或I K）"),
    CodeDoc("G03", "motion", "Circular interpolation counterclockwise (R or I K)", "逆时针圆弧插补（R或I K）"),
    CodeDoc("G04", "", "Dwell: G04 P_ (milliseconds) or G04 X_/U_ (seconds)", "暂停：G04 P_（毫秒）或G04 X_/U_（秒）"),
    CodeDoc(
        "G05",
        "motion",
        "Three-point circular interpolation: an arc from the current point through an intermediate point to the end",
        "三点圆弧插补：从当前点经中间点到终点的圆弧",
    ),
    CodeDoc(
        "G05.1",
        "motion",
        "Three-point circular interpolation with the intermediate point absolute: G05.1 X_ Z_ I(X, a diameter) K(Z)",
        "三点圆弧插补，中间点为绝对坐标：G05.1 X_ Z_ I（X，直径值）K（Z）",
    ),
    CodeDoc(
        "G06.2",
        "motion",
        "Elliptical interpolation clockwise (rear tool post): G6.2 X(U)_ Z(W)_ A(semi-major axis) B(semi-minor axis) "
        "Q(angle of the major axis to Z)",
        "椭圆插补（后刀座坐标系顺时针）：G6.2 X(U)_ Z(W)_ A（长半轴）B（短半轴）Q（长轴与Z轴的夹角）",
    ),
    CodeDoc(
        "G06.3",
        "motion",
        "Elliptical interpolation counterclockwise (rear tool post): G6.3 X(U)_ Z(W)_ A_ B_ Q_",
        "椭圆插补（后刀座坐标系逆时针）：G6.3 X(U)_ Z(W)_ A_ B_ Q_",
    ),
    CodeDoc("G07.1", "", "Cylindrical interpolation on/off", "圆柱插补开/关"),
    CodeDoc(
        "G07.2",
        "motion",
        "Parabolic interpolation clockwise (rear tool post): G7.2 X(U)_ Z(W)_ P(focal parameter) Q(angle of the axis)",
        "抛物线插补（后刀座坐标系顺时针）：G7.2 X(U)_ Z(W)_ P（焦距参数）Q（对称轴夹角）",
    ),
    CodeDoc(
        "G07.3",
        "motion",
        "Parabolic interpolation counterclockwise (rear tool post): G7.3 X(U)_ Z(W)_ P_ Q_",
        "抛物线插补（后刀座坐标系逆时针）：G7.3 X(U)_ Z(W)_ P_ Q_",
    ),
    CodeDoc("G10", "", "Programmable data input (work and tool offsets)", "可编程数据输入（工件及刀具偏置）"),
    CodeDoc(
        "G12.1",
        "",
        "Polar coordinate interpolation on (also G112), in a block of its own",
        "极坐标插补方式开（也可用G112），单独编为一段",
    ),
    CodeDoc(
        "G13.1",
        "",
        "Polar coordinate interpolation off (also G113), in a block of its own",
        "极坐标插补方式取消（也可用G113），单独编为一段",
    ),
    CodeDoc(
        "G15",
        "",
        "Polar coordinate programming off, in polar interpolation (X and C Cartesian again), in a block of its own",
        "取消极坐标编程（极坐标插补中，恢复直角坐标编程），单独编为一段",
    ),
    CodeDoc(
        "G16",
        "",
        "Polar coordinate programming in polar interpolation: X the length, C the angle; in a block of its own",
        "极坐标编程（极坐标插补中，X为长度、C为角度），单独编为一段",
    ),
    *shared.codes("G17"),
    CodeDoc("G18", "plane", "ZX plane selection (the lathe's usual plane)", "ZX平面选择（车床常用平面）"),
    *shared.codes("G19", "G20", "G21"),
    CodeDoc(
        "G22",
        "stroke",
        "Stored stroke check 2 on: G22 X_ Z_ (Y_) the limits on the plus side, I_ K_ (J_) on the minus side, "
        "in machine coordinates; no move",
        "存储行程限位2检测开：G22 X_ Z_（Y_）正方向极限，I_ K_（J_）负方向极限，机床坐标；不产生移动",
    ),
    CodeDoc("G23", "stroke", "Stored stroke check 2 off (in force at power-on)", "存储行程限位2检测关（上电初始模态）"),
    CodeDoc(
        "G28",
        "",
        "Return to the machine reference point through the intermediate point given by the axis words",
        "经由轴地址指定的中间点返回机床参考点",
    ),
    CodeDoc("G30", "", "Return to the 2nd, 3rd or 4th reference point", "返回第2、第3或第4参考点"),
    CodeDoc(
        "G31",
        "",
        "Skip function: linear move that stops when the skip signal comes on",
        "跳转功能：直线移动，跳转信号接通时停止",
    ),
    CodeDoc(
        "G32",
        "motion",
        "Thread cutting with constant lead: G32 X(U)_ Z(W)_ F_ (lead) or I_ (threads per inch)",
        "等螺距螺纹切削：G32 X(U)_ Z(W)_ F_（螺距）或I_（每英寸牙数）",
    ),
    CodeDoc(
        "G32.1",
        "motion",
        "Rigid thread cutting: G32.1 X(U)_ Z(W)_ C(H)_ F(I)_ J_ K_ S_",
        "刚性螺纹切削：G32.1 X(U)_ Z(W)_ C(H)_ F(I)_ J_ K_ S_",
    ),
    CodeDoc("G32.2", "motion", "Arc thread cutting clockwise", "顺时针圆弧螺纹切削"),
    CodeDoc("G32.3", "motion", "Arc thread cutting counterclockwise", "逆时针圆弧螺纹切削"),
    CodeDoc(
        "G33",
        "motion",
        "Tapping cycle: G33 Z(W)_ F(lead) or I(threads per inch) L(starts); in at the lead per revolution, "
        "the spindle reversed, out to the start",
        "攻丝循环：G33 Z(W)_ F（螺距）或I（每英寸牙数）L（头数）；按每转一个螺距进刀，主轴反转退回起点",
    ),
    CodeDoc("G34", "motion", "Thread cutting with variable lead", "变螺距螺纹切削"),
    CodeDoc("G36", "", "Automatic tool offset measurement along X: G36 X_", "X轴自动刀具偏移：G36 X_"),
    CodeDoc("G37", "", "Automatic tool offset measurement along Z: G37 Z_", "Z轴自动刀具偏移：G37 Z_"),
    CodeDoc("G40", "cutter", "Tool nose radius compensation cancel", "刀尖半径补偿取消"),
    CodeDoc("G41", "cutter", "Tool nose radius compensation left", "刀尖半径左补偿"),
    CodeDoc("G42", "cutter", "Tool nose radius compensation right", "刀尖半径右补偿"),
    CodeDoc(
        "G50",
        "",
        shared.SET_COORDINATES_EN,
        "坐标系设定（使当前位置成为指定的坐标值）",
    ),
    CodeDoc("G50.2", "", "Polygon cutting off (the tool and work axes out of step)", "多边形切削取消（解除同步）"),
    CodeDoc(
        "G51.2",
        "",
        "Polygon cutting on: G51.2 P(work turns) Q(tool turns) R_ A_; the tool axis turns in step with the spindle",
        "多边形切削开始：G51.2 P（工件轴转数）Q（刀具轴转数）R_ A_，刀具轴与主轴同步旋转",
    ),
    CodeDoc(
        "G52",
        "",
        "Local coordinate system: G52 X(U)_ Z(W)_ its origin in work coordinates (G52 X0 Z0 cancels); no move",
        "局部坐标系：G52 X(U)_ Z(W)_ 为其原点在工件坐标系中的位置（G52 X0 Z0取消）；不产生移动",
    ),
    CodeDoc(
        "G53", "", "Rapid positioning in machine coordinates (this block only)", "机床坐标系定位（快速，仅本段有效）"
    ),
    *shared.work_coordinate_codes(5),
    CodeDoc(
        "G65",
        "",
        "Macro call G65 P_ L_ arguments (opens a new level of local variables), "
        "or macro arithmetic/branch G65 Hm P#i Q#j R#k",
        "宏程序非模态调用G65 P_ L_ 自变量（局部变量进入新的一级），或宏运算/转移命令G65 Hm P#i Q#j R#k",
    ),
    *shared.codes("G66", "G67"),
    CodeDoc("G70", "", "Finishing cycle: G70 P(ns) Q(nf)", "精加工循环：G70 P(ns) Q(nf)"),
    CodeDoc("G71", "", "Axial rough turning cycle (outer/inner diameter)", "轴向粗车循环（外圆/内孔）"),
    CodeDoc("G72", "", "Radial rough facing cycle", "径向粗车循环（端面）"),
    CodeDoc("G73", "", "Closed-loop (pattern repeating) cutting cycle", "封闭切削循环（仿形粗车）"),
    CodeDoc("G74", "", "Face peck drilling / axial grooving cycle", "轴向切槽多重循环（端面深孔钻）"),
    CodeDoc("G74.1", "", "Axial recess grooving cycle", "轴向凹槽切削循环"),
    CodeDoc("G75", "", "Radial grooving cycle", "径向切槽多重循环"),
    CodeDoc("G75.1", "", "Radial recess grooving cycle", "径向凹槽切削循环"),
    CodeDoc("G76", "", "Multiple thread cutting cycle", "多重螺纹切削循环"),
    CodeDoc("G78", "", "Enhanced thread cutting cycle", "增强型螺纹切削循环"),
    CodeDoc("G80", "motion", "Drilling/tapping cycle cancel", "钻孔/攻丝固定循环取消"),
    CodeDoc("G83", "motion", "Face (axial) drilling cycle", "端面（轴向）钻孔循环"),
    CodeDoc("G83.1", "motion", "Face drilling cycle for an inclined hole", "端面钻斜孔循环"),
    CodeDoc("G83.2", "motion", "Face drilling cycle for an inclined hole (second form)", "端面钻斜孔循环（第二种）"),
    CodeDoc("G84", "motion", "Face (axial) tapping cycle", "端面（轴向）攻丝循环"),
    CodeDoc("G84.1", "motion", "Face rigid tapping cycle for an inclined hole", "端面刚性攻丝循环（斜孔）"),
    CodeDoc("G84.2", "motion", "Rigid tapping cycle", "刚性攻丝循环"),
    CodeDoc("G86", "", "Independent reciprocating feed cycle", "独立往复进给循环"),
    CodeDoc(
        "G86.1",
        "",
        "Independent reciprocating feed cycle stop: Z back to its start",
        "独立往复进给循环中止，Z轴返回起始位置",
    ),
    CodeDoc("G87", "motion", "Side (radial) drilling cycle", "侧面（径向）钻孔循环"),
    CodeDoc("G87.1", "motion", "Side drilling cycle for an inclined hole", "侧面钻斜孔循环"),
    CodeDoc("G88", "motion", "Side (radial) tapping cycle", "侧面（径向）攻丝循环"),
    CodeDoc("G88.1", "motion", "Side rigid tapping cycle for an inclined hole", "侧面刚性攻丝循环（斜孔）"),
    CodeDoc("G90", "motion", "Outer/inner diameter turning cycle (single pass)", "外圆/内孔切削循环（单一固定循环）"),
    CodeDoc(
        "G92",
        "motion",
        "Thread cutting cycle (single pass): G92 X(U)_ Z(W)_ F(lead) or I(threads per inch) J_ K_ L(starts) R(taper)",
        "螺纹切削循环（单一固定循环）：G92 X(U)_ Z(W)_ F（螺距）或I（每英寸牙数）J_ K_ L（头数）R（锥度）",
    ),
    CodeDoc(
        "G92.1",
        "motion",
        "Rigid thread cutting cycle: G92.1 X(U)_ Z(W)_ F_ L_ S_",
        "刚性螺纹切削循环：G92.1 X(U)_ Z(W)_ F_ L_ S_",
    ),
    CodeDoc(
        "G92.3", "motion", "Variable-pitch thread cutting cycle with equal crest width", "变螺距等牙尖宽度螺纹切削循环"
    ),
    CodeDoc("G94", "motion", "Facing cycle (single pass)", "端面切削循环（单一固定循环）"),
    CodeDoc("G112", "", "Polar coordinate interpolation on (the same as G12.1)", "极坐标插补方式开（同G12.1）"),
    CodeDoc("G113", "", "Polar coordinate interpolation off (the same as G13.1)", "极坐标插补方式取消（同G13.1）"),
    CodeDoc(
        "G165",
        "",
        "Chip breaking by oscillation: G165 P(per revolution; P0 ends it)/L_ Q(amplitude) K_",
        "自动断屑（振荡）：G165 P（每转断屑次数，P0结束）/L_ Q（振荡幅度）K_",
    ),
    *shared.codes("G96", "G97"),
    CodeDoc("G98", "feed", *shared.FEED_PER_MINUTE),
    CodeDoc("G99", "feed", *shared.FEED_PER_REVOLUTION),
)

M_CODES: tuple[CodeDoc, ...] = (
    CodeDoc("M00", "", "Program pause; cycle start resumes", "程序暂停，按循环启动继续"),
    *shared.codes("M01", "M02", "M03", "M04", "M05"),
    CodeDoc("M08", "", "Coolant on", "冷却液开"),
    CodeDoc("M09", "", "Coolant off", "冷却液关"),
    CodeDoc("M10", "", "Tailstock forward (standard PLC)", "尾座进（标准PLC）"),
    CodeDoc("M11", "", "Tailstock back (standard PLC)", "尾座退（标准PLC）"),
    # "在 G84/G88 指令之前指定 M29 S_ … 在相同程序段中指令 M29 S_" (§3.24.6)
    CodeDoc(
        "M29",
        "",
        "Rigid tapping: M29 S_ before G84/G88 (or in the same block); no axis move between M29 and G84/G88",
        "刚性攻丝：在G84/G88之前（或同一程序段中）指定M29 S_；M29与G84/G88之间不可指定轴移动",
    ),
    *shared.codes("M30"),
    CodeDoc("M32", "", "Lubrication on (standard PLC)", "润滑开（标准PLC）"),
    CodeDoc("M33", "", "Lubrication off (standard PLC)", "润滑关（标准PLC）"),
    CodeDoc(
        "M98",
        "",
        "Subprogram call: M98 P(program) L(count) Q(start sequence number); with more than 4 digits in P "
        "the last 4 are the program and the digits before them the count (not together with L: alarm 293). "
        "No new level of local variables",
        "子程序调用：M98 P（程序号）L（次数）Q（开始的顺序号）；P超过4位时右边4位为程序号，前面为调用次数"
        "（不可再用L指定次数，否则293号报警）。局部变量不改变级别",
    ),
    CodeDoc(
        "M99",
        "",
        shared.M99_EN,
        "从子程序或宏程序返回调用程序段的下一段（M99 Pn返回到Nn段）；在主程序中则反复执行当前程序",
    ),
    CodeDoc(
        "M198",
        "",
        "Call a subprogram on the external input/output device (usually a USB stick); otherwise like M98",
        "调用外部输入/输出设备（通常为U盘）中的子程序，用法同M98",
    ),
)
