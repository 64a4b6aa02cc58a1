"""FANUC 0i Custom Macro B data: the system variables, G codes and M codes of a 0i milling control.

``SYSTEM_VARIABLES`` follows chapter 4 "系统变量" of seed 003 (the FANUC-0i thesis): interface
signals with parameter 6001#0 (MIF) = 0 (§4.1), tool offsets for tool compensation memory C with
the #2001–#2400 short numbers (§4.2), the macro alarm and message stop #3000/#3006 (§4.3, §4.4),
timers and date/time (§4.5), automatic operation control #3003/#3004 (§4.6), parts counters
(§4.7), modal information #4001–#4130 (§4.8), positions for four axes (§4.9) and work zero
offsets including G54.1 P1–P48 and the #2500–#2806 short numbers (§4.10). Beside chapter 4 it has
the manual handle interruption #5121–#5124, which the seed leaves out but a 0i control has
(docs/profiles.md). ``G_CODES`` and
``M_CODES`` describe the codes of a 0i milling control; a code's ``group`` is its name in
``MODAL_GROUPS``, or empty for a one-shot (group 00) code. Rows and texts that the GSK980TDi
shares come from ``shared_data``.
"""

from __future__ import annotations

from . import shared_data as shared
from .tables import CodeDoc, SystemVariable

# ---------------------------------------------------------------------------------------------
# §4.1 interface signals (parameter 6001#0 MIF = 0)

_SIGNALS: tuple[SystemVariable, ...] = (
    *shared.signal_bits(
        1000,
        16,
        "r",
        "input",
        ("UI", "G"),
        ", sent from the PMC to the macro; reads 0 or 1",
        "，由PMC送给宏程序，按位读取，值为0或1",
    ),
    SystemVariable(
        1032,
        1032,
        "r",
        "signals",
        "Interface input signals UI000-UI015 (PMC G54-G55) read at once as one 16-bit number: "
        "the sum of #[1000+i] x 2^i",
        "接口输入信号UI000～UI015（PMC G54～G55）作为一个16位数一次读出，等于#[1000+i]×2^i之和",
        source="bits",
        param="1000:16",
    ),
    *shared.signal_bits(
        1100,
        16,
        "rw",
        "output",
        ("UO", "F"),
        ", sent from the macro to the PMC; write 0 or 1, reading gives the state last written",
        "，由宏程序送给PMC，按位写入0或1，读出为当前状态",
    ),
    SystemVariable(
        1132,
        1132,
        "rw",
        "signals",
        "Interface output signals UO000-UO015 (PMC F54-F55) written at once as one 16-bit number; "
        "bit i is the same signal as #[1100+i]",
        "接口输出信号UO000～UO015（PMC F54～F55）作为一个16位数一次写出，第i位即#[1100+i]",
        source="bits",
        param="1100:16",
    ),
    SystemVariable(
        1133,
        1133,
        "rw",
        "signals",
        "Interface output signals UO100-UO131 (PMC F56-F59) written at once as one 32-bit number; "
        "value -99999999 to 99999999",
        "接口输出信号UO100～UO131（PMC F56～F59）作为一个32位数一次写出，取值范围-99999999～99999999",
    ),
)

# ---------------------------------------------------------------------------------------------
# §4.2 tool offsets, tool compensation memory C (400 offsets; #2001-#2400 when 200 or fewer)

_TOOL_OFFSETS: tuple[SystemVariable, ...] = (
    SystemVariable(
        10001,
        10400,
        "rw",
        "tool",
        "Tool length offset H{index}: wear value (memory C); G10 L11 P{index} R_ sets it too",
        "刀具长度补偿H{index}的磨损补偿值（刀补存储器C）；也可用G10 L11 P{index} R_设定",
        "mm",
    ),
    SystemVariable(
        11001,
        11400,
        "rw",
        "tool",
        "Tool length offset H{index}: geometry value (memory C); G10 L10 P{index} R_ sets it too",
        "刀具长度补偿H{index}的形状（几何）补偿值（刀补存储器C）；也可用G10 L10 P{index} R_设定",
        "mm",
    ),
    SystemVariable(
        12001,
        12400,
        "rw",
        "tool",
        "Cutter radius offset D{index}: wear value (memory C); G10 L13 P{index} R_ sets it too",
        "刀具半径补偿D{index}的磨损补偿值（刀补存储器C）；也可用G10 L13 P{index} R_设定",
        "mm",
    ),
    SystemVariable(
        13001,
        13400,
        "rw",
        "tool",
        "Cutter radius offset D{index}: geometry value (memory C); G10 L12 P{index} R_ sets it too",
        "刀具半径补偿D{index}的形状（几何）补偿值（刀补存储器C）；也可用G10 L12 P{index} R_设定",
        "mm",
    ),
    SystemVariable(
        2001,
        2200,
        "rw",
        "tool",
        "Tool length offset H{index}: wear value; short number for #10001-#10200 (#2001 = #10001), "
        "usable with 200 offsets or fewer",
        "刀具长度补偿H{index}的磨损补偿值；#10001～#10200的另一编号（#2001即#10001），刀补数不超过200组时可用",
        "mm",
        "alias",
        "10001",
    ),
    SystemVariable(
        2201,
        2400,
        "rw",
        "tool",
        "Tool length offset H{index}: geometry value; short number for #11001-#11200 (#2201 = #11001), "
        "usable with 200 offsets or fewer",
        "刀具长度补偿H{index}的形状（几何）补偿值；#11001～#11200的另一编号（#2201即#11001），刀补数不超过200组时可用",
        "mm",
        "alias",
        "11001",
    ),
)

# ---------------------------------------------------------------------------------------------
# §4.3-§4.7 alarm, message stop, time, automatic operation control, parts counters

_CONTROL: tuple[SystemVariable, ...] = (
    SystemVariable(
        3000,
        3000,
        "w",
        "alarm",
        "Macro alarm: #3000=n (message) with n 0-200 stops the program with alarm 3000+n; "
        "the message (up to 26 characters) is shown with it. Cannot be read",
        "宏程序报警：执行#3000=n（报警信息）（n为0～200）时CNC停止运行，发出报警 3000+n，"
        "可附不超过26个字符的报警信息。不可读",
        source="alarm",
    ),
    SystemVariable(
        3006,
        3006,
        "w",
        "alarm",
        "Stop with message: #3006=n (message) stops after the previous block, like M00, and shows "
        "the message (up to 26 characters); cycle start resumes",
        "停止并显示信息：执行#3006=n（信息）时，程序在前一程序段执行完后停止（同M00），"
        "并显示不超过26个字符的信息；按循环启动可继续运行",
        source="stop",
    ),
    SystemVariable(
        3001,
        3001,
        "rw",
        "time",
        "Millisecond timer: counts in 1 ms steps, reset to 0 at power-on, wraps to 0 at 2147483648 ms",
        "毫秒计时器：以1毫秒为单位计时，通电时复位为0，达到2147483648毫秒时回到0",
        "ms",
        "timer",
        "ms/2147483648",  # whole milliseconds, back to 0 at 2^31 (seed 003 §4.5)
    ),
    SystemVariable(
        3002,
        3002,
        "rw",
        "time",
        "Hour timer: counts in hours, kept through power-off, wraps to 0 at 9544.371767 h",
        "小时计时器：以1小时为单位计时，断电后仍保存数值，达到9544.371767小时时回到0",
        "h",
        "timer",
        "h",
    ),
    SystemVariable(
        3011,
        3011,
        "r",
        "time",
        "Current date as a decimal number YYYYMMDD, e.g. 20010928 for 28 September 2001",
        "当前日期（年/月/日），以十进制数YYYYMMDD表示，例如2001年9月28日为20010928",
        "",
        "date",
    ),
    SystemVariable(
        3012,
        3012,
        "r",
        "time",
        "Current time of day as a decimal number HHMMSS, e.g. 153456 for 3:34:56 pm",
        "当前时刻（时/分/秒），以十进制数HHMMSS表示，例如下午3点34分56秒为153456",
        "",
        "time",
    ),
    SystemVariable(
        3003,
        3003,
        "rw",
        "control",
        "Automatic operation control: 0 = single block stop on, wait for M/S/T completion; "
        "1 = single block stop off, wait; 2 = single block stop on, no wait; 3 = single block stop off, no wait. "
        "0 at power-on",
        "自动运行控制：0=单程序段停止有效，等待辅助功能（M/S/T）完成；1=单程序段停止无效，等待；"
        "2=单程序段停止有效，不等待；3=单程序段停止无效，不等待。通电时为0",
    ),
    SystemVariable(
        3004,
        3004,
        "rw",
        "control",
        "Automatic operation control: 1 = feed hold off, +2 = feedrate override off (always 100%), "
        "+4 = exact stop check off; 0 (all on) to 7 (all off). 0 at power-on",
        "自动运行控制：1=进给暂停无效，+2=进给速度倍率无效（总是100%），+4=准确停止检测无效；"
        "取值0（全部有效）～7（全部无效）。通电时为0",
    ),
    SystemVariable(
        3901,
        3901,
        "rw",
        "counters",
        "Number of parts machined (completed count); cannot be negative",
        "已加工的零件数（完成数），不能为负值",
    ),
    SystemVariable(
        3902,
        3902,
        "rw",
        "counters",
        "Number of parts required (target count); cannot be negative",
        "要求的零件数（目标数），不能为负值",
    ),
)

# ---------------------------------------------------------------------------------------------
# §4.8 modal information: the modal state up to the block before the one being processed

# group number -> (name in MODAL_GROUPS, the codes of the group)
MODAL_GROUP_CODES: dict[int, tuple[str, str]] = {
    1: ("motion", "G00, G01, G02, G03, G33, G75, G77, G78, G79"),
    2: ("plane", "G17, G18, G19"),
    3: ("distance", "G90, G91"),
    4: ("stroke", "G22, G23"),
    5: ("feed", "G94, G95"),
    6: ("units", "G20, G21"),
    7: ("cutter", "G40, G41, G42"),
    8: ("length", "G43, G44, G49"),
    9: ("canned", "G73, G74, G76, G80-G89"),
    10: ("return", "G98, G99"),
    11: ("scaling", "G50, G51"),
    12: ("macro", "G66, G67"),
    13: ("spindle", "G96, G97"),
    14: ("wcs", "G54-G59"),
    15: ("cutting", "G61-G64"),
    16: ("rotation", "G68, G69"),
    17: ("polar", "G15, G16"),
    22: ("mirror", "G50.1, G51.1"),
}


def _modal_row(group: int) -> SystemVariable:
    return shared.modal_group_row(
        4000 + group,
        group,
        MODAL_GROUP_CODES,
        (
            "Modal information of G-code group {group:02d}; vacant unless the machine presets it",
            "第{group}组G代码的模态信息；机床未预设时为空",
        ),
        (
            "Modal G code of group {group:02d} ({codes}) in effect before the current block, read as a number "
            "({code} reads {value}, not {code})",
            "第{group}组模态G代码（{codes}），为当前程序段之前的模态，读出的是数值（{code}读出为{value}，而不是{code}）",
        ),
    )


# the code letters of a mill beside those both controls have (shared_data.CODE_LETTERS)
MILL_CODE_LETTERS: tuple[tuple[int, str, str, str], ...] = (
    (4102, "B", "B code (second auxiliary function) last commanded", "最近指令的B代码（第2辅助功能）"),
    (4107, "D", "D code (cutter radius offset number) in effect", "当前的D代码（刀具半径补偿号）"),
    (4111, "H", "H code (tool length offset number) in effect", "当前的H代码（刀具长度补偿号）"),
    (4120, "T", "T code (tool number) last commanded", "最近指令的T代码（刀具号）"),
    (
        4130,
        "P",
        "P code: number of the additional work coordinate system selected (G54.1 Pn reads n)",
        "P代码：当前所选的追加工件坐标系号（G54.1 Pn时读出n）",
    ),
)

_MODAL: tuple[SystemVariable, ...] = (
    *(_modal_row(group) for group in range(1, 23)),
    *shared.code_letter_rows((*shared.CODE_LETTERS, *MILL_CODE_LETTERS)),
)

# ---------------------------------------------------------------------------------------------
# §4.9 positions (axes 1-4); read only

# Not in seed 003: the distance the manual handle added during automatic operation (manual
# handle interruption); 0 on the simulated machine, which has no handle.
HANDLE_INTERRUPTION = SystemVariable(
    5121,
    5124,
    "r",
    "position",
    "{axis} axis manual handle interruption: the distance the handle moved the axis during automatic "
    "operation (0 here: the simulated machine has no handle)",
    "第{index}轴（{axis}）手轮中断量：自动运行中用手轮插入移动的距离（模拟机床没有手轮，读出为0）",
    "mm",
    "position",
    "handle",
)

_POSITIONS: tuple[SystemVariable, ...] = (
    *shared.axis_position_rows(4),
    SystemVariable(
        5061,
        5064,
        "r",
        "position",
        "{axis} axis skip position: where the skip signal came on in the last G31 block (its end point if "
        "it never came on), work coordinates, with tool offset; readable while moving",
        "第{index}轴（{axis}）跳转信号位置：上一个G31程序段中跳转信号接通时的位置（未接通时为该程序段终点），"
        "工件坐标系，含刀具补偿，移动中可读",
        "mm",
        "position",
        "skip",
    ),
    SystemVariable(
        5081,
        5084,
        "r",
        "position",
        "{axis} axis tool length offset now in effect (the value being executed, not that of a block "
        "read ahead); not readable while moving",
        "第{index}轴（{axis}）当前执行的刀具长度补偿值（不是预读程序段的值，移动中不可读）",
        "mm",
        "position",
        "tool",
    ),
    SystemVariable(
        5101,
        5104,
        "r",
        "position",
        "{axis} axis servo position deviation (following error); not readable while moving",
        "第{index}轴（{axis}）伺服位置偏差（移动中不可读）",
        "mm",
        "position",
        "servo",
    ),
    HANDLE_INTERRUPTION,
)

# ---------------------------------------------------------------------------------------------
# §4.10 work zero offsets, G54.1 P1-P48 and the #2500-#2806 short numbers

_AXIS_NAMES: tuple[tuple[str, str], ...] = (
    ("X", "第1轴（X）"),
    ("Y", "第2轴（Y）"),
    ("Z", "第3轴（Z）"),
    ("4th", "第4轴"),
)

_WORK_OFFSETS: tuple[SystemVariable, ...] = (
    *(
        SystemVariable(
            5201 + 20 * i,
            5204 + 20 * i,
            "rw",
            "work",
            f"{{axis}} axis {en}; G10 L2 P{i} sets it too",
            f"第{{index}}轴（{{axis}}）{zh}；也可用G10 L2 P{i}设定",
            "mm",
        )
        for i, (en, zh) in enumerate(shared.WCS_NAMES)
    ),
    *(
        SystemVariable(
            7001 + 20 * (p - 1),
            7004 + 20 * (p - 1),
            "rw",
            "work",
            f"{{axis}} axis work zero offset of the additional work coordinate system G54.1 P{p}; "
            f"G10 L20 P{p} sets it too",
            f"第{{index}}轴（{{axis}}）追加工件坐标系G54.1 P{p}的工件零点偏移值；也可用G10 L20 P{p}设定",
            "mm",
        )
        for p in range(1, 49)
    ),
    *(
        SystemVariable(
            2500 + 100 * axis + i,
            2500 + 100 * axis + i,
            "rw",
            "work",
            f"{_AXIS_NAMES[axis][0]} axis {en}; another number for #{5201 + 20 * i + axis}",
            f"{_AXIS_NAMES[axis][1]}{zh}；即#{5201 + 20 * i + axis}",
            "mm",
            "alias",
            str(5201 + 20 * i + axis),
        )
        for axis in range(4)
        for i, (en, zh) in enumerate(shared.WCS_NAMES)
    ),
)

# Not in seed 003: the setting data and the mirror image state, which the 0i's custom macro chapter
# lists after the automatic operation control (#3003, #3004): "SETTING 值：SETTING 值可用变量读和写。
# 二进制数转换为十进制数。" (the settings are read and written, binary converted to decimal) and
# "镜像：使用外部开关或SETTING 操作设置的各轴镜像状态…" (the mirror image state of each axis, set by an
# external switch or on the setting screen; read). Stored values here, 0 unless the machine file
# gives them. Not in ``_CONTROL``: Haas, Mitsubishi and Mazak take rows from that, and no source at
# hand gives these numbers there.
SETTINGS_AND_MIRROR: tuple[SystemVariable, ...] = (
    SystemVariable(
        3005,
        3005,
        "rw",
        "control",
        "Settings data as a number: each bit is one setting (TV check, ISO code for punching, inch input, ...); "
        "writing changes the settings",
        "设定数据（作为一个数）：每一位是一项设定（TV检查、穿孔代码ISO、英制输入等）；写入即改变设定",
    ),
    SystemVariable(
        3007,
        3007,
        "r",
        "control",
        "Mirror image state: bit n-1 is 1 while axis n is mirrored by the external switch or the setting screen "
        "(read only)",
        "镜像状态：第n轴由外部开关或设定画面设为镜像时，第n-1位为1（只读）",
    ),
)

SYSTEM_VARIABLES: tuple[SystemVariable, ...] = (
    *_SIGNALS,
    *_TOOL_OFFSETS,
    *_CONTROL,
    *SETTINGS_AND_MIRROR,
    *_MODAL,
    *_POSITIONS,
    *_WORK_OFFSETS,
)

# ---------------------------------------------------------------------------------------------
# G and M codes of a FANUC 0i milling control

G_CODES: tuple[CodeDoc, ...] = (
    *shared.codes("G00", "G01"),
    CodeDoc(
        "G02", "motion", "Circular/helical interpolation clockwise (R or I J K)", "顺时针圆弧/螺旋线插补（R或I J K）"
    ),
    CodeDoc(
        "G03",
        "motion",
        "Circular/helical interpolation counterclockwise (R or I J K)",
        "逆时针圆弧/螺旋线插补（R或I J K）",
    ),
    CodeDoc("G02.2", "motion", "Involute interpolation, clockwise", "渐开线插补（顺时针）"),
    CodeDoc("G03.2", "motion", "Involute interpolation, counterclockwise", "渐开线插补（逆时针）"),
    CodeDoc("G02.3", "motion", "Exponential interpolation, positive rotation", "指数函数插补（正转）"),
    CodeDoc("G03.3", "motion", "Exponential interpolation, negative rotation", "指数函数插补（反转）"),
    CodeDoc("G02.4", "motion", "3-D circular interpolation, clockwise", "三维圆弧插补（顺时针）"),
    CodeDoc("G03.4", "motion", "3-D circular interpolation, counterclockwise", "三维圆弧插补（逆时针）"),
    CodeDoc("G04", "", "Dwell: G04 X_ (seconds) or G04 P_ (milliseconds)", "暂停：G04 X_（秒）或G04 P_（毫秒）"),
    CodeDoc(
        "G05",
        "",
        "High-speed cycle machining; G05 P10000 / G05 P0: AI contour control on / off",
        "高速循环加工；G05 P10000 / G05 P0：AI轮廓控制开/关",
    ),
    CodeDoc(
        "G05.1",
        "",
        "AI contour control / smooth interpolation: G05.1 Q1 on, G05.1 Q0 off",
        "AI轮廓控制/平滑插补：G05.1 Q1开，G05.1 Q0关",
    ),
    CodeDoc("G06.2", "motion", "NURBS interpolation", "NURBS曲线插补"),
    CodeDoc("G07", "", "Hypothetical axis interpolation", "假想轴插补"),
    CodeDoc(
        "G07.1",
        "",
        "Cylindrical interpolation: G07.1 C_ (the cylinder's radius) on, G07.1 C0 off",
        "圆柱插补：G07.1 C_（圆柱半径）开，G07.1 C0关",
    ),
    CodeDoc("G08", "", "AI look-ahead control: G08 P1 on, G08 P0 off", "AI先行控制：G08 P1开，G08 P0关"),
    CodeDoc("G09", "", "Exact stop check for this block only", "准确停止（仅本程序段）"),
    CodeDoc(
        "G10",
        "",
        "Programmable data input: G10 L2 Pp (work zero offsets, P0 external, P1-P6 G54-G59), "
        "G10 L10-L13 P_ R_ (tool offsets), G10 L20 Pn (G54.1 Pn), G10 L50 (parameters)",
        "可编程数据输入：G10 L2 Pp（工件零点偏移，P0外部，P1～P6为G54～G59），G10 L10～L13 P_ R_（刀具补偿），"
        "G10 L20 Pn（G54.1 Pn），G10 L50（参数）",
    ),
    CodeDoc(
        "G10.6",
        "",
        "Tool retract and recover: the retract distance for a later retract signal",
        "刀具退回和返回：指定退刀信号到来时的退刀量",
    ),
    CodeDoc("G10.9", "", "Diameter / radius programming switch (lathe)", "直径/半径编程切换（车床）"),
    CodeDoc(
        "G11", "", "End the programmable parameter input mode started by G10 L50", "取消G10 L50开始的可编程参数输入方式"
    ),
    CodeDoc("G12.1", "", "Polar coordinate interpolation mode", "极坐标插补方式"),
    CodeDoc("G13.1", "", "Polar coordinate interpolation cancel", "极坐标插补取消"),
    CodeDoc("G15", "polar", "Polar coordinate command cancel", "极坐标指令取消"),
    CodeDoc(
        "G16",
        "polar",
        "Polar coordinate command: the first axis word is the radius, the second the angle",
        "极坐标指令：平面第1轴地址为半径，第2轴地址为角度",
    ),
    *shared.codes("G17"),
    CodeDoc("G18", "plane", "ZX plane selection", "ZX平面选择"),
    *shared.codes("G19", "G20", "G21"),
    CodeDoc("G22", "stroke", "Stored stroke check on", "存储行程检查功能有效"),
    CodeDoc("G23", "stroke", "Stored stroke check off", "存储行程检查功能无效"),
    CodeDoc("G25", "", "Spindle speed fluctuation detection off", "主轴速度波动检测无效"),
    CodeDoc("G26", "", "Spindle speed fluctuation detection on", "主轴速度波动检测有效"),
    CodeDoc("G27", "", "Reference position return check", "返回参考点检查"),
    CodeDoc(
        "G28",
        "",
        "Return to the reference position through the intermediate point given by the axis words",
        "经由轴地址指定的中间点自动返回参考点",
    ),
    CodeDoc(
        "G29", "", "Return from the reference position through the G28 intermediate point", "经由G28中间点从参考点返回"
    ),
    CodeDoc(
        "G30",
        "",
        "Return to the 2nd, 3rd or 4th reference position (P2, P3, P4; P2 if omitted)",
        "返回第2、第3或第4参考点（P2、P3、P4；省略时为P2）",
    ),
    CodeDoc("G30.1", "", "Floating reference position return", "浮动参考点返回"),
    CodeDoc(
        "G31",
        "",
        "Skip function: linear move that stops when the skip signal comes on; the position is stored in #5061-#5064",
        "跳转功能：直线移动，跳转信号接通时停止，该位置存入#5061～#5064",
    ),
    CodeDoc("G32", "motion", "Thread cutting (lathe)", "螺纹切削（车床）"),
    CodeDoc("G31.8", "", "EGB-axis skip", "电子齿轮箱轴跳转"),
    CodeDoc("G31.9", "", "Continuous high-speed skip", "连续高速跳转"),
    CodeDoc("G33", "motion", "Thread cutting", "螺纹切削"),
    CodeDoc("G34", "", "Variable-lead thread cutting (lathe)", "变螺距螺纹切削（车床）"),
    CodeDoc("G35", "", "Circular thread cutting, clockwise (lathe)", "圆弧螺纹切削（顺时针，车床）"),
    CodeDoc(
        "G36",
        "",
        "Circular thread cutting, counterclockwise, or automatic tool offset in X (lathe)",
        "圆弧螺纹切削（逆时针）或X向自动刀具补偿（车床）",
    ),
    CodeDoc(
        "G37",
        "",
        "Automatic tool length measurement (mill) / automatic tool offset (lathe)",
        "刀具长度自动测量（铣床）/自动刀具补偿（车床）",
    ),
    CodeDoc("G38", "", "Cutter compensation: keep the offset vector", "刀具半径补偿：保持偏置矢量"),
    CodeDoc("G39", "", "Corner offset circular interpolation", "拐角偏移圆弧插补"),
    CodeDoc("G40", "cutter", "Cutter radius compensation cancel", "刀具半径补偿取消"),
    CodeDoc("G41", "cutter", "Cutter radius compensation left (D offset number)", "刀具半径补偿左侧（D为补偿号）"),
    CodeDoc("G42", "cutter", "Cutter radius compensation right (D offset number)", "刀具半径补偿右侧（D为补偿号）"),
    CodeDoc("G40.1", "", "Normal direction control cancel", "法线方向控制取消"),
    CodeDoc("G41.1", "", "Normal direction control, left", "法线方向控制（左侧）"),
    CodeDoc("G42.1", "", "Normal direction control, right", "法线方向控制（右侧）"),
    CodeDoc("G41.2", "cutter", "3-D cutter compensation, left (5-axis)", "三维刀具半径补偿（左侧，五轴）"),
    CodeDoc("G42.2", "cutter", "3-D cutter compensation, right (5-axis)", "三维刀具半径补偿（右侧，五轴）"),
    CodeDoc(
        "G43", "length", "Tool length compensation + direction (H offset number)", "刀具长度补偿正方向（H为补偿号）"
    ),
    CodeDoc(
        "G44", "length", "Tool length compensation - direction (H offset number)", "刀具长度补偿负方向（H为补偿号）"
    ),
    CodeDoc("G43.1", "length", "Tool length compensation in the tool axis direction", "刀具轴向的刀具长度补偿"),
    CodeDoc("G43.4", "length", "Tool centre point control, type 1 (5-axis)", "刀具中心点控制类型1（五轴）"),
    CodeDoc("G43.5", "length", "Tool centre point control, type 2 (5-axis)", "刀具中心点控制类型2（五轴）"),
    CodeDoc("G41.3", "cutter", "3-D cutter compensation, leading edge offset", "三维刀具半径补偿（前缘偏置）"),
    CodeDoc(
        "G43.7", "length", "Tool offset in the turning manner (machining centre)", "车削方式的刀具偏置（加工中心）"
    ),
    CodeDoc("G43.8", "length", "Cutting point command, type 1", "切削点指令（类型1）"),
    CodeDoc("G43.9", "length", "Cutting point command, type 2", "切削点指令（类型2）"),
    CodeDoc("G45", "", "Tool position offset: increase by the offset", "刀具位置偏置：伸长一个偏置量"),
    CodeDoc("G46", "", "Tool position offset: decrease by the offset", "刀具位置偏置：缩短一个偏置量"),
    CodeDoc("G47", "", "Tool position offset: increase by twice the offset", "刀具位置偏置：伸长两倍偏置量"),
    CodeDoc("G48", "", "Tool position offset: decrease by twice the offset", "刀具位置偏置：缩短两倍偏置量"),
    CodeDoc("G49", "length", "Tool length compensation cancel", "刀具长度补偿取消"),
    CodeDoc("G49.1", "length", "Tool length compensation cancel (30i series)", "刀具长度补偿取消（30i系列）"),
    CodeDoc("G50", "scaling", "Scaling cancel", "比例缩放取消"),
    CodeDoc(
        "G51",
        "scaling",
        "Scaling: G51 X_ Y_ Z_ (centre) P_ or I_ J_ K_ (factor)",
        "比例缩放：G51 X_ Y_ Z_（中心）P_或I_ J_ K_（比例）",
    ),
    CodeDoc("G50.1", "mirror", "Programmable mirror image cancel", "可编程镜像取消"),
    CodeDoc(
        "G51.1",
        "mirror",
        "Programmable mirror image about the axis positions given",
        "可编程镜像（以指定的轴位置为对称轴）",
    ),
    CodeDoc("G50.2", "", "Polygon turning cancel", "多边形车削取消"),
    CodeDoc("G51.2", "", "Polygon turning", "多边形车削"),
    CodeDoc("G50.3", "", "Workpiece coordinate system preset (lathe)", "工件坐标系预置（车床）"),
    CodeDoc("G50.4", "", "Synchronous control cancel (multi-path)", "同步控制取消（多通道）"),
    CodeDoc("G51.4", "", "Synchronous control start (multi-path)", "同步控制开始（多通道）"),
    CodeDoc("G50.5", "", "Composite control cancel (multi-path)", "混合控制取消（多通道）"),
    CodeDoc("G51.5", "", "Composite control start (multi-path)", "混合控制开始（多通道）"),
    CodeDoc("G50.6", "", "Superimposed control cancel (multi-path)", "叠加控制取消（多通道）"),
    CodeDoc("G51.6", "", "Superimposed control start (multi-path)", "叠加控制开始（多通道）"),
    CodeDoc(
        "G52",
        "",
        "Local coordinate system: shifts the current work coordinate system by the axis words (G52 IP0 cancels)",
        "局部坐标系设定：将当前工件坐标系平移轴地址指定的量（G52 IP0取消）",
    ),
    CodeDoc(
        "G53",
        "",
        "Move in machine coordinates for this block only (offsets ignored)",
        "机床坐标系选择（仅本程序段，以机床坐标移动）",
    ),
    CodeDoc("G53.1", "", "Tool axis direction control (after G68.2)", "刀具轴向控制（在G68.2之后）"),
    *shared.work_coordinate_codes(4),
    CodeDoc(
        "G54.1",
        "wcs",
        "Additional work coordinate system G54.1 Pn, n = 1-48 (offsets #7001 + 20(n-1) onwards; #4130 reads n)",
        "追加工件坐标系G54.1 Pn，n=1～48（偏移值从#7001+20(n-1)起；#4130读出n）",
    ),
    CodeDoc("G54.2", "", "Rotary table dynamic fixture offset: G54.2 Pn", "旋转工作台动态夹具偏置：G54.2 Pn"),
    CodeDoc("G54.4", "", "Workpiece setting error compensation", "工件设置误差补偿"),
    CodeDoc("G60", "", "Single direction positioning", "单方向定位"),
    CodeDoc("G61", "cutting", "Exact stop mode", "准确停止方式"),
    CodeDoc("G62", "cutting", "Automatic corner override mode", "自动拐角倍率方式"),
    CodeDoc("G63", "cutting", "Tapping mode (override and feed hold ignored)", "攻丝方式（倍率和进给暂停无效）"),
    CodeDoc("G64", "cutting", "Cutting mode (no exact stop between blocks)", "切削方式（程序段间不做准确停止）"),
    CodeDoc(
        "G65",
        "",
        "Macro call: G65 P(program) L(repeat count) arguments; opens a new level of local variables",
        "宏程序非模态调用：G65 P（程序号）L（重复次数）自变量；局部变量进入新的一级",
    ),
    *shared.codes("G66", "G67"),
    CodeDoc(
        "G66.1",
        "macro",
        "Modal macro call of every block: G66.1 P_ (known, not simulated)",
        "每个程序段都调用的模态宏程序调用：G66.1 P_（可识别，不作仿真）",
    ),
    CodeDoc(
        "G68",
        "rotation",
        "Coordinate system rotation: G68 X_ Y_ (centre) R_ (angle, degrees)",
        "坐标系旋转：G68 X_ Y_（中心）R_（角度，度）",
    ),
    CodeDoc("G68.2", "rotation", "Tilted working plane command", "倾斜工作平面指令"),
    CodeDoc(
        "G68.3", "rotation", "Tilted working plane command by the tool axis direction", "按刀具轴向的倾斜工作平面指令"
    ),
    CodeDoc("G68.4", "rotation", "Tilted working plane command, incremental", "倾斜工作平面指令（增量方式）"),
    CodeDoc("G69", "rotation", "Coordinate system rotation cancel", "坐标系旋转取消"),
    CodeDoc("G70", "", "Finishing cycle (lathe)", "精加工循环（车床）"),
    CodeDoc("G71", "", "Stock removal in turning (lathe)", "外圆粗车循环（车床）"),
    CodeDoc("G72", "", "Stock removal in facing (lathe)", "端面粗车循环（车床）"),
    CodeDoc("G72.1", "", "Figure copy by rotation", "图形复制（旋转）"),
    CodeDoc("G72.2", "", "Figure copy by parallel shift", "图形复制（平移）"),
    CodeDoc("G73", "canned", "High-speed peck drilling cycle", "高速深孔钻循环"),
    CodeDoc("G74", "canned", "Left-hand (counter) tapping cycle", "左旋攻丝循环"),
    CodeDoc(
        "G75",
        "motion",
        "Plunge grinding cycle (grinding machine); grooving cycle in X (lathe)",
        "切入式磨削循环（磨床）；X向切槽循环（车床）",
    ),
    CodeDoc(
        "G76",
        "canned",
        "Fine boring cycle (spindle orients and shifts before retract)",
        "精镗循环（孔底主轴定向并偏移后退刀）",
    ),
    CodeDoc(
        "G77",
        "motion",
        "Direct constant-dimension plunge grinding cycle (grinding machine)",
        "直接定尺寸切入式磨削循环（磨床）",
    ),
    CodeDoc(
        "G78", "motion", "Continuous-feed surface grinding cycle (grinding machine)", "连续进给平面磨削循环（磨床）"
    ),
    CodeDoc(
        "G79", "motion", "Intermittent-feed surface grinding cycle (grinding machine)", "间歇进给平面磨削循环（磨床）"
    ),
    CodeDoc("G80", "canned", "Canned cycle cancel", "固定循环取消"),
    CodeDoc("G81", "canned", "Drilling cycle, spot drilling", "钻孔循环、点钻循环"),
    CodeDoc(
        "G82", "canned", "Drilling cycle with dwell at the bottom (counter boring)", "带孔底暂停的钻孔循环（锪孔）"
    ),
    CodeDoc("G83", "canned", "Peck drilling cycle (full retract each peck)", "深孔钻循环（每次退到R点）"),
    CodeDoc("G84", "canned", "Tapping cycle", "攻丝循环"),
    CodeDoc("G84.2", "canned", "Rigid tapping cycle (FS15 format)", "刚性攻丝循环（FS15格式）"),
    CodeDoc("G84.3", "canned", "Left-hand rigid tapping cycle (FS15 format)", "左旋刚性攻丝循环（FS15格式）"),
    CodeDoc("G80.4", "", "Electronic gear box synchronization cancel", "电子齿轮箱同步取消"),
    CodeDoc("G81.4", "", "Electronic gear box synchronization start", "电子齿轮箱同步开始"),
    CodeDoc("G81.1", "", "Chopping (grinding machine)", "往复振荡磨削（磨床）"),
    CodeDoc("G85", "canned", "Boring cycle (feed in, feed out)", "镗孔循环（切削进给退刀）"),
    CodeDoc(
        "G86", "canned", "Boring cycle (spindle stops at the bottom, rapid out)", "镗孔循环（孔底主轴停止，快速退刀）"
    ),
    CodeDoc("G87", "canned", "Back boring cycle", "背镗循环"),
    CodeDoc(
        "G88",
        "canned",
        "Boring cycle (dwell and spindle stop at the bottom, manual retract)",
        "镗孔循环（孔底暂停、主轴停止，手动退刀）",
    ),
    CodeDoc("G89", "canned", "Boring cycle (dwell at the bottom, feed out)", "镗孔循环（孔底暂停，切削进给退刀）"),
    CodeDoc("G90", "distance", "Absolute programming", "绝对值编程"),
    CodeDoc("G91", "distance", "Incremental programming", "增量值编程"),
    CodeDoc("G91.1", "", "Maximum incremental amount check", "最大增量值检查"),
    CodeDoc(
        "G92",
        "",
        shared.SET_COORDINATES_EN,
        "设定工件坐标系（使当前位置成为指定的坐标值）",
    ),
    CodeDoc("G92.1", "", "Workpiece coordinate system preset", "工件坐标系预置"),
    CodeDoc("G93", "feed", "Inverse time feed", "反比时间进给"),
    CodeDoc("G94", "feed", *shared.FEED_PER_MINUTE),
    CodeDoc("G95", "feed", *shared.FEED_PER_REVOLUTION),
    *shared.codes("G96", "G97"),
    CodeDoc("G96.1", "", "Spindle indexing, waiting for its completion", "主轴分度（等待完成）"),
    CodeDoc("G96.2", "", "Spindle indexing without waiting", "主轴分度（不等待）"),
    CodeDoc("G96.3", "", "Spindle indexing completion check", "主轴分度完成确认"),
    CodeDoc("G96.4", "", "Spindle SV speed control mode", "主轴SV速度控制方式"),
    CodeDoc("G98", "return", "Canned cycle: return to the initial level", "固定循环返回初始平面"),
    CodeDoc("G99", "return", "Canned cycle: return to the R point level", "固定循环返回R点平面"),
    CodeDoc("G107", "", "Cylindrical interpolation (the same as G07.1)", "圆柱插补（同G07.1）"),
    CodeDoc("G112", "", "Polar coordinate interpolation mode (the same as G12.1)", "极坐标插补方式（同G12.1）"),
    CodeDoc("G113", "", "Polar coordinate interpolation cancel (the same as G13.1)", "极坐标插补取消（同G13.1）"),
    CodeDoc("G160", "", "In-feed control cancel (grinding machine)", "切入控制取消（磨床）"),
    CodeDoc("G161", "", "In-feed control (grinding machine)", "切入控制（磨床）"),
)

M_CODES: tuple[CodeDoc, ...] = (
    CodeDoc("M00", "", "Program stop; cycle start resumes", "程序暂停，按循环启动继续"),
    *shared.codes("M01", "M02", "M03", "M04", "M05"),
    CodeDoc("M06", "", "Tool change (the tool chosen by T)", "换刀（换上T指定的刀具）"),
    CodeDoc("M08", "", "Coolant on", "切削液开"),
    CodeDoc("M09", "", "Coolant off", "切削液关"),
    CodeDoc("M19", "", "Spindle orientation", "主轴定向"),
    # FANUC "Rigid tapping": "M29 S****; specified prior to a tapping command" (G84, G74; a lathe's
    # G84/G88), the M code of parameter 5210, M29 when it is 0
    CodeDoc(
        "M29",
        "",
        "Rigid tapping: M29 S_ before G84/G74 (a lathe's G84/G88) puts the spindle in rigid tapping mode (the M "
        "code of parameter 5210, M29 by default)",
        "刚性攻丝：在G84/G74（车床G84/G88）之前指定M29 S_，主轴进入刚性攻丝方式（M代码由参数5210设定，默认M29）",
    ),
    *shared.codes("M30"),
    CodeDoc(
        "M98",
        "",
        "Subprogram call: M98 P(program) L(repeat count); with more than 4 digits in P the last 4 are the "
        "program and those before them the count. No new level of local variables",
        "子程序调用：M98 P（程序号）L（重复次数）；P超过4位时后4位为程序号，前面为调用次数。局部变量不改变级别",
    ),
    CodeDoc(
        "M99",
        "",
        shared.M99_EN,
        "从子程序或宏程序返回调用程序段的下一段（M99 Pn返回到Nn段）；在主程序中则从头重复执行",
    ),
    CodeDoc(
        "M198",
        "",
        "Call a subprogram stored on the external input/output device or memory card (otherwise like M98)",
        "调用外部输入/输出设备或存储卡中的子程序（其余同M98）",
    ),
)
