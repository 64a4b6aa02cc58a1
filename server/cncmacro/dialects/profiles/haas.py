"""Haas Next Generation Control (NGC), mills: the ``haas`` profile (``PROFILE``, at the end) and its
data: system variables, G codes and M codes.

The sources and every decision taken where they are silent are in docs/profiles.md "haas: sources
and decisions"; the letters below ([Z], [H], [P], ...) are the ones it lists. In short:

* commons #100–#199, #500–#999 and the NGC's #10000–#10999, all kept at power-off ([Z]);
* six axes X Y Z A B C in the position and work-offset variables ([Z], [H]);
* tool offsets by tool number: length #2001–#2200 and its wear #2201–#2400, diameter #2401–#2600
  and its wear #2601–#2800; flutes #1601… and vibration #1801… ([Z]);
* timers and machine state #3020–#3033, parts counters #3901/#3902, modal groups #4001–#4021
  numbered the Haas way (group 12 is the work coordinate system), address codes #4101–#4126;
* tool life and load #5401–#6000 and the tool data read through #8550;
* work offsets G52/G54–G59 (#5201…), G110–G129 = G154 P1–P20 (#7001… and #14001…), G154
  P21–P99 (#14401…); pallets #7501…; settings #20001… and parameters #30001…, read only;
* the conditional jump ``[cond] M99 P n``, IF [cond] GOTO n written another way ([H1]).

Where Haas reads a number as FANUC 0i does (the date #3011 and time #3012), the row is
``fanuc_data``'s own; #3000, #3001, #3002 and #3006 work as on the 0i but are described in Haas's
terms (no 0i limits on n or on the message).
"""

from __future__ import annotations

from .. import fanuc_data as fanuc
from .. import shared_data as shared
from ..dialect import ARGUMENTS_I, last_address_key
from ..drill_cycles import HAAS_DRILL_CYCLES
from ..haas_programs_data import PROGRAM_DOCS as PROGRAM_DOCS  # the programs on the control, for hover
from ..tables import CodeDoc, CommonRange, SystemVariable
from ..timing import Timing
from .fanuc_0i import OTHER_MAKERS
from .fanuc_0i import PROFILE as FANUC_0I

AXES = ("X", "Y", "Z", "A", "B", "C")


def _one(
    number: int, access: str, group: str, en: str, zh: str, unit: str = "", default: float | None = 0.0
) -> SystemVariable:
    return SystemVariable(number, number, access, group, en, zh, unit, default=default)


def _per_tool(first: int, last: int, access: str, en: str, zh: str, unit: str = "") -> SystemVariable:
    return SystemVariable(first, last, access, "tool", f"Tool {{index}}: {en}", f"{{index}}号刀具：{zh}", unit)


# ---------------------------------------------------------------------------------------------
# inputs, outputs, analog values and axis loads

_LOAD_EXTRA = ("C", "U", "V", "W", "T")

_SIGNALS: tuple[SystemVariable, ...] = (
    SystemVariable(
        1000,
        1063,
        "r",
        "signals",
        "Discrete input number {index} of 64 (#1000 counts as 1); reads 0 or 1",
        "离散输入：64个输入中的第{index}个（#1000为第1个）；读出0或1",
    ),
    SystemVariable(
        1064,
        1068,
        "r",
        "signals",
        "{axis} axis: the highest load seen so far, in percent",
        "{axis}轴（第{index}轴）至今的最大负载（百分比）",
    ),
    SystemVariable(
        1080,
        1087,
        "r",
        "signals",
        "Raw analog-to-digital input number {index} of 8 (#1080 counts as 1)",
        "原始模拟量输入（A/D）：8个中的第{index}个（#1080为第1个）",
    ),
    *(
        _one(1090 + k, "r", "signals", f"Filtered analog-to-digital input {k}", f"第{k}号滤波后的模拟量输入（A/D）")
        for k in range(8)
        if k != 4
    ),
    _one(1094, "r", "signals", "Coolant level (filtered analog input 4)", "切削液液位（第4号滤波模拟量输入）"),
    _one(1098, "r", "signals", "Spindle load in percent (Haas vector drive)", "主轴负载（百分比，Haas矢量驱动器）"),
    SystemVariable(
        1100,
        1155,
        "rw",
        "signals",
        "Discrete output number {index} (#1100 counts as 1); write 1 to turn it on, 0 to turn it off",
        "离散输出：第{index}个（#1100为第1个）；写1接通，写0断开",
    ),
    *(
        _one(
            1264 + k,
            "r",
            "signals",
            f"{axis} axis: the highest load seen so far, in percent",
            f"{axis}轴至今的最大负载（百分比）",
        )
        for k, axis in enumerate(_LOAD_EXTRA)
    ),
    SystemVariable(
        11000,
        11063,
        "r",
        "signals",
        "Discrete input number {index} of 64 (#11000 counts as 1), NGC number (the same inputs as #1000 onwards)",
        "第{index}个离散输入（共64个），NGC变量号（与#1000起的输入相同）",
    ),
)

# ---------------------------------------------------------------------------------------------
# tool data by tool number (1-200)

_TOOLS: tuple[SystemVariable, ...] = (
    _per_tool(1601, 1800, "rw", "number of flutes", "刃数"),
    _per_tool(1801, 2000, "r", "highest vibration recorded", "记录到的最大振动值"),
    _per_tool(
        2001,
        2200,
        "rw",
        "length offset (geometry); G10 L10 P{index} R_ sets it too",
        "长度补偿（形状）；也可用G10 L10 P{index} R_设定",
        "mm",
    ),
    _per_tool(
        2201,
        2400,
        "rw",
        "length wear; G10 L11 P{index} R_ sets it too",
        "长度磨损补偿；也可用G10 L11 P{index} R_设定",
        "mm",
    ),
    _per_tool(
        2401,
        2600,
        "rw",
        "diameter (or radius) offset, geometry; G10 L12 P{index} R_ sets it too",
        "直径（或半径）补偿（形状）；也可用G10 L12 P{index} R_设定",
        "mm",
    ),
    _per_tool(
        2601,
        2800,
        "rw",
        "diameter (or radius) wear; G10 L13 P{index} R_ sets it too",
        "直径（或半径）磨损补偿；也可用G10 L13 P{index} R_设定",
        "mm",
    ),
    _per_tool(
        5401,
        5500,
        "rw",
        "feed timer: seconds the tool has cut at feed",
        "进给计时：刀具以进给速度切削的时间（秒）",
        "s",
    ),
    _per_tool(
        5501,
        5600,
        "rw",
        "total timer: seconds the tool has been in the spindle while running",
        "总计时：刀具在主轴上运行的总时间（秒）",
        "s",
    ),
    _per_tool(5601, 5700, "rw", "tool life monitor limit", "刀具寿命监控的极限值"),
    _per_tool(5701, 5800, "rw", "tool life monitor counter", "刀具寿命监控的计数值"),
    _per_tool(
        5801, 5900, "rw", "tool load monitor: the highest load sensed so far", "刀具负载监控：至今检测到的最大负载"
    ),
    _per_tool(5901, 6000, "rw", "tool load monitor limit", "刀具负载监控的极限值"),
)

# #8550 chooses a tool; #8551-#8564 read that tool's data (one number each)
_TOOL_DATA_FIELDS: tuple[tuple[str, str, str], ...] = (
    ("number of flutes", "刃数", ""),
    ("highest vibration recorded", "记录到的最大振动值", ""),
    ("length offset (geometry)", "长度补偿（形状）", "mm"),
    ("length wear", "长度磨损补偿", "mm"),
    ("diameter offset (geometry)", "直径补偿（形状）", "mm"),
    ("diameter wear", "直径磨损补偿", "mm"),
    ("actual diameter", "实际直径", "mm"),
    ("programmable coolant position", "可编程切削液喷嘴位置", ""),
    ("feed timer (seconds)", "进给计时（秒）", "s"),
    ("total timer (seconds)", "总计时（秒）", "s"),
    ("tool life monitor limit", "刀具寿命监控的极限值", ""),
    ("tool life monitor counter", "刀具寿命监控的计数值", ""),
    ("tool load monitor: highest load sensed so far", "刀具负载监控：至今检测到的最大负载", ""),
    ("tool load monitor limit", "刀具负载监控的极限值", ""),
)

_TOOL_DATA: tuple[SystemVariable, ...] = (
    _one(
        8550,
        "rw",
        "tool",
        "Tool data access: write a tool number here, then #8551-#8564 read that tool's data",
        "刀具数据访问：先在此写入刀具号，之后#8551～#8564读出该刀具的数据",
    ),
    *(
        _one(
            8551 + k,
            "r",
            "tool",
            f"Tool data of the tool chosen in #8550: {en} (0 here: the simulated machine keeps no tool table)",
            f"#8550所选刀具的数据：{zh}（模拟机床没有刀具表，读出为0）",
            unit,
        )
        for k, (en, zh, unit) in enumerate(_TOOL_DATA_FIELDS)
    ),
)

# ---------------------------------------------------------------------------------------------
# alarm, stop, timers, machine state, switches, counters

_FANUC_CONTROL = {r.first: r for r in fanuc._CONTROL}

_CONTROL: tuple[SystemVariable, ...] = (
    SystemVariable(
        3000,
        3000,
        "w",
        "alarm",
        "Programmable alarm: #3000=n (message) stops the program with alarm n "
        "and shows the message on the alarm page; RESET clears it. Cannot be read",
        "可编程报警：#3000=n（信息）使程序停止并产生报警n，报警页显示该信息；按RESET清除。不可读",
        source="alarm",
    ),
    SystemVariable(
        3001,
        3001,
        "rw",
        "time",
        "Millisecond timer: counts in milliseconds; write 0 to restart it",
        "毫秒计时器：以毫秒计时；写0重新开始计时",
        "ms",
        "timer",
        "ms",
    ),
    SystemVariable(
        3002,
        3002,
        "rw",
        "time",
        "Hour timer: counts in hours; write 0 to restart it",
        "小时计时器：以小时计时；写0重新开始计时",
        "h",
        "timer",
        "h",
    ),
    _one(
        3003,
        "rw",
        "control",
        "Single block suppression: 1 runs the following blocks as one even in single block mode, 0 ends it",
        "单程序段抑制：写1时其后的程序段在单段方式下也连续执行，写0恢复",
    ),
    _one(
        3004,
        "rw",
        "control",
        "Override control: 1 disables FEED HOLD, 2 fixes the feed override at 100%, 4 "
        "disables exact stop; add them, 0 restores all",
        "倍率控制：1使进给保持无效，2使进给倍率固定为100%，4使准确停止检测无效；可相加，写0全部恢复",
    ),
    SystemVariable(
        3006,
        3006,
        "w",
        "alarm",
        "Programmable stop with message: #3006=n (message) stops like M00 and shows the message; cycle start goes on",
        "带信息的可编程停止：#3006=n（信息）像M00一样停止并显示信息；按循环启动继续",
        source="stop",
    ),
    _FANUC_CONTROL[3011],
    _FANUC_CONTROL[3012],
    SystemVariable(
        3020,
        3020,
        "r",
        "time",
        "Power-on timer: seconds since the control was turned on; read only",
        "通电计时器：控制器通电以来的秒数；只读",
        "s",
        "timer",
        "s",
    ),
    SystemVariable(
        3021,
        3021,
        "rw",
        "time",
        "Cycle start timer: seconds of running since cycle start",
        "循环启动计时器：循环启动以来的运行秒数",
        "s",
        "timer",
        "s",
    ),
    _one(3022, "rw", "time", "Feed timer: seconds spent moving at feed", "进给计时器：以进给速度运动的秒数", "s"),
    SystemVariable(
        3023,
        3023,
        "r",
        "time",
        "Present part timer: seconds spent on the part being made; read only",
        "当前工件计时器：加工当前工件所用的秒数；只读",
        "s",
        "timer",
        "s",
    ),
    _one(
        3024,
        "r",
        "time",
        "Last complete part timer: seconds the last finished part took; read only",
        "上一完成工件计时器：上一个完成的工件所用的秒数；只读",
        "s",
    ),
    _one(
        3025,
        "r",
        "time",
        "Previous part timer: seconds the part before took; read only",
        "前一工件计时器：前一个工件所用的秒数；只读",
        "s",
    ),
    SystemVariable(
        3026,
        3026,
        "r",
        "control",
        "Tool in the spindle: the number of the tool now loaded (here the T of the last T_ M06: the simulated "
        "machine loads the tool T names); read only",
        "主轴上的刀具：当前装在主轴上的刀具号（模拟机床以最近的T_ M06中的T为准）；只读",
        source="code",
        param="T",
    ),
    _one(3027, "r", "control", "Spindle speed now, in rev/min; read only", "主轴当前转速（r/min）；只读"),
    _one(
        3028,
        "r",
        "control",
        "Pallet loaded on the receiver: its number (machines with a pallet changer); read only",
        "接收器上已装载的托盘号（带托盘交换装置的机床）；只读",
    ),
    _one(3030, "rw", "control", "Single block switch: 1 on, 0 off", "单程序段开关：1为开，0为关"),
    _one(3031, "rw", "control", "Dry run switch: 1 on, 0 off", "空运行开关：1为开，0为关"),
    _one(
        3032,
        "rw",
        "control",
        "Block delete switch: 1 on (blocks starting with / are skipped), 0 off",
        "程序段跳过开关：1为开（跳过以/开头的程序段），0为关",
    ),
    _one(
        3033, "rw", "control", "Optional stop switch: 1 on (M01 stops), 0 off", "选择停止开关：1为开（M01停止），0为关"
    ),
    _one(3901, "rw", "counters", "M30 counter 1: parts counted at each M30", "M30计数器1：每执行一次M30计数一次"),
    _one(3902, "rw", "counters", "M30 counter 2: parts counted at each M30", "M30计数器2：每执行一次M30计数一次"),
)

# ---------------------------------------------------------------------------------------------
# modal information: the previous block's group codes (#4001-#4021) and address codes (#4101-#4126)

GROUPS = 21

# Haas group number -> (name in MODAL_GROUPS, the codes of the group)
MODAL_GROUP_CODES: dict[int, tuple[str, str]] = {
    1: ("motion", "G00, G01, G02, G03"),
    2: ("plane", "G17, G18, G19"),
    3: ("distance", "G90, G91"),
    5: ("feed", "G93, G94, G95"),
    6: ("units", "G20, G21"),
    7: ("cutter", "G40, G41, G42, G141"),
    8: ("length", "G43, G44, G49, G143, G234"),
    9: ("canned", "G73, G74, G76, G77, G80-G89"),
    10: ("return", "G98, G99"),
    11: ("scaling", "G50, G51"),
    12: ("wcs", "G54-G59, G110-G129, G154"),
    15: ("cutting", "G61, G64"),
    16: ("rotation", "G68, G69"),
}


def _modal_row(group: int) -> SystemVariable:
    return shared.modal_group_row(
        4000 + group,
        group,
        MODAL_GROUP_CODES,
        (
            "Modal G code of group {group:02d} of the previous block; vacant unless the machine presets it",
            "前一程序段第{group}组的模态G代码；机床未预设时为空",
        ),
        (
            "Modal G code of group {group:02d} ({codes}) as of the previous block, read as a number "
            "({code} reads {value})",
            "前一程序段第{group}组的模态G代码（{codes}），读出的是数值（{code}读出为{value}）",
        ),
    )


# the codes the planner keeps on every profile (B is an axis on Haas, so not among them)
_CODE_LETTERS = {"D", "F", "H", "M", "S", "T", "N", "O"}
# #4100 + the local variable an argument letter fills (A #4101, I #4104, D #4107, F #4109, Z #4126);
# #4114 and #4115 are N and O as on FANUC
_ADDRESSES = {4100 + n: letter for letter, n in ARGUMENTS_I.items()} | {4114: "N", 4115: "O"}
# the other letters: each block's axis, arc and cycle words leave their value there ([Z]:
# #4101-#4126 the last block's address codes; docs/profiles.md "Variables and ranges")
LAST_ADDRESS_LETTERS = frozenset(_ADDRESSES.values()) - _CODE_LETTERS


def _address_row(number: int) -> SystemVariable:
    letter = _ADDRESSES.get(number)
    if letter is None:
        return SystemVariable(
            number,
            number,
            "r",
            "modal",
            f"No address: #{number - 4100} is no argument letter; vacant",
            f"无对应地址：#{number - 4100}没有对应的自变量字母；为空",
            default=None,
        )
    if letter in _CODE_LETTERS:
        return SystemVariable(
            number,
            number,
            "r",
            "modal",
            f"Address {letter}: its value in the previous block (the last one commanded)",
            f"地址{letter}：前一程序段的值（最近一次指令的值）",
            source="code",
            param=letter,
        )
    return SystemVariable(
        number,
        number,
        "r",
        "modal",
        f"Address {letter}: its value in the previous block (the last one written); "
        f"vacant until a block writes {letter}",
        f"地址{letter}：前一程序段的值（最近一次指令的值）；尚无程序段指令{letter}时为空",
        source="code",
        param=last_address_key(letter),
        default=None,
    )


_MODAL: tuple[SystemVariable, ...] = (
    *(_modal_row(group) for group in range(1, GROUPS + 1)),
    *(_address_row(number) for number in range(4101, 4127)),
)

# ---------------------------------------------------------------------------------------------
# positions (six axes)

_POSITION_KINDS = (
    (5001, "end", "end point of the previous block, work coordinates", "前一程序段的终点（工件坐标系）"),
    (5021, "machine", "present position, machine coordinates", "当前位置（机床坐标系）"),
    # Haas's present work position is read as the programmed one, without the tool length offset
    # (docs/profiles.md, haas); FANUC's #5041 includes it (docs/semantics.md §10.1)
    (5041, "end", "present position, work coordinates", "当前位置（工件坐标系）"),
    # its skip position is read in the same frame as its present work position: as programmed
    (
        5061,
        "skip_programmed",
        "where the skip signal came on in the last G31 (its end point if it never did), work coordinates",
        "上一个G31中跳转信号接通的位置（未接通时为该段终点，工件坐标系）",
    ),
    (5081, "tool", "tool length offset in effect", "当前生效的刀具长度补偿值"),
)

_POSITIONS: tuple[SystemVariable, ...] = tuple(
    SystemVariable(
        first,
        first + len(AXES) - 1,
        "r",
        "position",
        f"{{axis}} axis {en}; reading it stops the look-ahead until the block before has run",
        f"{{axis}}轴（第{{index}}轴）{zh}；读取时预读停止，直到前面的程序段执行完",
        "mm",
        "position",
        param,
    )
    for first, param, en, zh in _POSITION_KINDS
)

# ---------------------------------------------------------------------------------------------
# work offsets: G52 and G54-G59 (#5201...), G110-G129 = G154 P1-P20 (#7001...), G154 P1-P99
# (#14001..., where the offsets are kept; #7001... are other numbers for P1-P20), pallets

G154_SHORT = 7001  # G110 (G154 P1) axis 1; each offset adds 20, G129 (P20) is #7381
G154_LONG = 14001  # G154 P1 axis 1 in the numbering that goes on to P99 (#15961)
SHORT_P = 20


def _wcs(first: int, en: str, zh: str, unit: str = "mm") -> SystemVariable:
    return SystemVariable(
        first, first + len(AXES) - 1, "rw", "work", f"{{axis}} axis {en}", f"{{axis}}轴（第{{index}}轴）{zh}", unit
    )


_WORK_NAMES = (
    ("G52 work offset (local shift)", "G52工件偏置（局部平移）"),
    *(
        (f"G{53 + i} work offset; G10 L2 P{i} sets it too", f"G{53 + i}工件偏置；也可用G10 L2 P{i}设定")
        for i in range(1, 7)
    ),
)

_WORK_OFFSETS: tuple[SystemVariable, ...] = (
    *(_wcs(5201 + 20 * i, en, zh) for i, (en, zh) in enumerate(_WORK_NAMES)),
    *(
        SystemVariable(
            G154_SHORT + 20 * (p - 1),
            G154_SHORT + 20 * (p - 1) + len(AXES) - 1,
            "rw",
            "work",
            f"{{axis}} axis work offset of G{109 + p} (G154 P{p}); another number for #{G154_LONG + 20 * (p - 1)}...",
            f"{{axis}}轴（第{{index}}轴）G{109 + p}（G154 P{p}）的工件偏置；即#{G154_LONG + 20 * (p - 1)}起的变量",
            "mm",
            "alias",
            str(G154_LONG + 20 * (p - 1)),
        )
        for p in range(1, SHORT_P + 1)
    ),
    *(
        _wcs(
            G154_LONG + 20 * (p - 1),
            f"work offset of G154 P{p}" + (f" (G{109 + p})" if p <= SHORT_P else "") + f"; G10 L20 P{p} sets it too",
            f"G154 P{p}" + (f"（G{109 + p}）" if p <= SHORT_P else "") + f"的工件偏置；也可用G10 L20 P{p}设定",
        )
        for p in range(1, 100)
    ),
)

_PALLETS: tuple[SystemVariable, ...] = (
    SystemVariable(
        7501,
        7504,
        "rw",
        "control",
        "Pallet {index}: priority in the pallet schedule (read only while the pallet is loaded)",
        "{index}号托盘：在托盘调度中的优先级（托盘装载时只读）",
    ),
    SystemVariable(
        7601,
        7604,
        "rw",
        "control",
        "Pallet {index}: status (read only while the pallet is loaded)",
        "{index}号托盘：状态（托盘装载时只读）",
    ),
    SystemVariable(
        7701,
        7704,
        "r",
        "control",
        "Pallet {index}: the part program number assigned to it",
        "{index}号托盘：分配给它的加工程序号",
    ),
    SystemVariable(
        7801, 7804, "r", "counters", "Pallet {index}: how many times it has been used", "{index}号托盘：已使用的次数"
    ),
)

# ---------------------------------------------------------------------------------------------
# settings and parameters, read only

_SETTINGS: tuple[SystemVariable, ...] = (
    SystemVariable(
        20001,
        29999,
        "r",
        "control",
        "Setting {index} (the control's settings page); read only",
        "设定{index}（控制器的设定页）；只读",
    ),
    SystemVariable(
        30001,
        39999,
        "r",
        "control",
        "Parameter {index} (the control's parameters); read only",
        "参数{index}（控制器的参数）；只读",
    ),
)

SYSTEM_VARIABLES: tuple[SystemVariable, ...] = (
    *_SIGNALS,
    *_TOOLS,
    *_TOOL_DATA,
    *_CONTROL,
    *_MODAL,
    *_POSITIONS,
    *_WORK_OFFSETS,
    *_PALLETS,
    *_SETTINGS,
)

# ---------------------------------------------------------------------------------------------
# G codes of a Haas mill (group: the name in MODAL_GROUPS of the Haas group; empty for group 00
# and for groups the simulated machine does not keep)


def _g(code: str, group: str, en: str, zh: str) -> CodeDoc:
    return CodeDoc(code, group, en, zh)


G_CODES: tuple[CodeDoc, ...] = (
    *shared.codes("G00", "G01"),
    _g(
        "G02",
        "motion",
        "Circular interpolation clockwise (R or I J K), helical with a third axis",
        "顺时针圆弧插补（R或I J K），带第三轴时为螺旋线插补",
    ),
    _g(
        "G03",
        "motion",
        "Circular interpolation counterclockwise (R or I J K), helical with a third axis",
        "逆时针圆弧插补（R或I J K），带第三轴时为螺旋线插补",
    ),
    _g(
        "G04",
        "",
        "Dwell: G04 P_ (seconds with a decimal point, milliseconds without)",
        "暂停：G04 P_（带小数点时单位为秒，不带时为毫秒）",
    ),
    _g("G09", "", "Exact stop for this block", "本程序段准确停止"),
    _g(
        "G10",
        "",
        "Set offsets: L2 work offsets G52/G54-G59, L20 G110-G129 and G154 P1-P99, L10-L13 tool length "
        "and diameter offsets and wear",
        "设定偏置：L2为G52/G54～G59工件偏置，L20为G110～G129及G154 P1～P99，L10～L13为刀具长度、直径补偿及磨损",
    ),
    _g(
        "G12",
        "",
        "Circular pocket milling, clockwise: G12 I_ (radius) K_ Q_ Z_ D_ F_",
        "顺时针圆形型腔铣削：G12 I_（半径）K_ Q_ Z_ D_ F_",
    ),
    _g(
        "G13",
        "",
        "Circular pocket milling, counterclockwise: G13 I_ (radius) K_ Q_ Z_ D_ F_",
        "逆时针圆形型腔铣削：G13 I_（半径）K_ Q_ Z_ D_ F_",
    ),
    *shared.codes("G17"),
    _g("G18", "plane", "XZ plane selection", "XZ平面选择"),
    *shared.codes("G19", "G20", "G21"),
    _g(
        "G28",
        "",
        "Return to machine zero through the point given (G91 G28 Z0 goes straight up)",
        "经指定点返回机床零点（G91 G28 Z0直接向上返回）",
    ),
    _g("G29", "", "Return from machine zero through the G28 point", "经G28的中间点从机床零点返回"),
    _g(
        "G31",
        "",
        "Feed until skip: moves until the probe signal comes on (the position in #5061...)",
        "跳转进给：移动直到探头信号接通（位置存入#5061起的变量）",
    ),
    _g("G35", "", "Automatic tool diameter measurement (tool probe)", "自动测量刀具直径（对刀仪）"),
    _g("G36", "", "Automatic work offset measurement (spindle probe)", "自动测量工件偏置（主轴测头）"),
    _g("G37", "", "Automatic tool length measurement (tool probe)", "自动测量刀具长度（对刀仪）"),
    _g("G40", "cutter", "Cutter compensation cancel", "刀具半径补偿取消"),
    _g("G41", "cutter", "Cutter compensation left (2D)", "刀具半径左补偿（二维）"),
    _g("G42", "cutter", "Cutter compensation right (2D)", "刀具半径右补偿（二维）"),
    _g("G43", "length", "Tool length compensation + (H: tool number of the offset)", "刀具长度正向补偿（H为补偿号）"),
    _g("G44", "length", "Tool length compensation -", "刀具长度负向补偿"),
    _g(
        "G47",
        "",
        "Text engraving: G47 P0 (text in the comment) or P1 (serial number)",
        "文字雕刻：G47 P0（注释中的文字）或P1（序列号）",
    ),
    _g("G49", "length", "Tool length compensation cancel (G43/G44/G143/G234)", "刀具长度补偿取消（G43/G44/G143/G234）"),
    _g("G50", "scaling", "Scaling cancel", "比例缩放取消"),
    _g("G51", "scaling", "Scaling: G51 X_ Y_ Z_ (centre) P_ (factor)", "比例缩放：G51 X_ Y_ Z_（中心）P_（比例）"),
    _g(
        "G52",
        "",
        "Set local coordinate system (a shift added to the work offset)",
        "设定局部坐标系（在工件偏置上附加平移）",
    ),
    _g("G53", "", "Machine coordinates for this block only", "仅本程序段使用机床坐标"),
    *shared.work_coordinate_codes(len(AXES), offsets_zh="偏置"),
    _g("G60", "", "Single direction positioning", "单方向定位"),
    _g("G61", "cutting", "Exact stop mode", "准确停止方式"),
    _g("G64", "cutting", "Exact stop mode cancel (cutting mode)", "准确停止方式取消（切削方式）"),
    _g(
        "G65",
        "",
        "Macro subprogram call: G65 P(program) L(repeat count) arguments; a new level of local variables",
        "宏程序调用：G65 P（程序号）L（重复次数）自变量；局部变量进入新的一级",
    ),
    _g(
        "G68",
        "rotation",
        "Coordinate rotation: G68 X_ Y_ (centre) R_ (angle, degrees)",
        "坐标旋转：G68 X_ Y_（中心）R_（角度，度）",
    ),
    _g("G69", "rotation", "Coordinate rotation cancel", "坐标旋转取消"),
    _g(
        "G70",
        "",
        "Bolt hole circle: holes on a full circle in the canned cycle in force",
        "螺栓孔圆周：按当前固定循环在整圆上加工一组孔",
    ),
    _g(
        "G71",
        "",
        "Bolt hole arc: holes on an arc in the canned cycle in force",
        "螺栓孔圆弧：按当前固定循环在圆弧上加工一组孔",
    ),
    _g(
        "G72",
        "",
        "Bolt holes along an angle (a line) in the canned cycle in force",
        "沿角度（直线）排列的螺栓孔：按当前固定循环加工",
    ),
    _g("G73", "canned", "High-speed peck drilling cycle", "高速深孔钻循环"),
    _g("G74", "canned", "Reverse (left-hand) tapping cycle", "反向（左旋）攻丝循环"),
    _g(
        "G76",
        "canned",
        "Fine boring cycle (spindle orients and shifts before retract)",
        "精镗循环（孔底主轴定向并偏移后退刀）",
    ),
    _g("G77", "canned", "Back bore cycle", "背镗循环"),
    _g("G80", "canned", "Canned cycle cancel", "固定循环取消"),
    _g("G81", "canned", "Drilling cycle", "钻孔循环"),
    _g("G82", "canned", "Spot drilling cycle with dwell at the bottom", "带孔底暂停的点钻循环"),
    _g("G83", "canned", "Peck drilling cycle (full retract each peck)", "深孔钻循环（每次退到R点）"),
    _g("G84", "canned", "Tapping cycle", "攻丝循环"),
    _g("G85", "canned", "Boring cycle (feed in, feed out)", "镗孔循环（切削进给退刀）"),
    _g(
        "G86",
        "canned",
        "Bore and stop cycle (spindle stops at the bottom, rapid out)",
        "镗孔循环（孔底主轴停止，快速退刀）",
    ),
    _g("G87", "canned", "Bore in and manual retract cycle", "镗孔后手动退刀循环"),
    _g("G88", "canned", "Bore in, dwell, manual retract cycle", "镗孔、暂停后手动退刀循环"),
    _g("G89", "canned", "Bore in, dwell, bore out cycle", "镗孔、暂停后切削进给退刀循环"),
    _g("G90", "distance", "Absolute positioning", "绝对值编程"),
    _g("G91", "distance", "Incremental positioning", "增量值编程"),
    _g("G92", "", shared.SET_COORDINATES_EN, "设定工件坐标系（使当前位置成为指定的坐标值）"),
    _g("G93", "feed", "Inverse time feed", "反比时间进给"),
    _g("G94", "feed", "Feed per minute", "每分钟进给"),
    _g("G95", "feed", "Feed per revolution", "每转进给"),
    _g("G98", "return", "Canned cycle: return to the initial point", "固定循环返回初始点"),
    _g("G99", "return", "Canned cycle: return to the R plane", "固定循环返回R平面"),
    _g("G100", "", "Mirror image cancel", "镜像取消"),
    _g("G101", "", "Mirror image on for the axes given", "对指定的轴启用镜像"),
    _g(
        "G103",
        "",
        "Limit block look-ahead: G103 P_ blocks (P0 or no P: no limit)",
        "限制预读程序段数：G103 P_（P0或不写P为不限制）",
    ),
    _g(
        "G107", "", "Cylindrical mapping (a linear axis wrapped on a rotary axis)", "圆柱映射（将直线轴映射到旋转轴上）"
    ),
    *(
        _g(
            f"G{109 + p}",
            "wcs",
            f"Additional work coordinate system {6 + p}, the same as G154 P{p} (offsets "
            f"#{G154_SHORT + 20 * (p - 1)}...)",
            f"附加工件坐标系{6 + p}，同G154 P{p}（偏置#{G154_SHORT + 20 * (p - 1)}起）",
        )
        for p in range(1, SHORT_P + 1)
    ),
    _g("G136", "", "Automatic work offset centre measurement (spindle probe)", "自动测量工件偏置中心（主轴测头）"),
    _g("G141", "cutter", "3D+ cutter compensation", "三维刀具半径补偿"),
    _g("G143", "length", "Five-axis tool length compensation +", "五轴刀具长度正向补偿"),
    _g(
        "G150",
        "",
        "General purpose pocket milling (the pocket's shape in a subprogram: G150 P_ ...)",
        "通用型腔铣削（型腔轮廓写在子程序中：G150 P_ …）",
    ),
    _g("G153", "canned", "Five-axis high-speed peck drilling cycle", "五轴高速深孔钻循环"),
    _g(
        "G154",
        "wcs",
        "Select work coordinates G154 P1-P99 (offsets #14001 + 20(P-1) onwards; P1-P20 are G110-G129)",
        "选择工件坐标系G154 P1～P99（偏置从#14001+20(P-1)起；P1～P20即G110～G129）",
    ),
    _g("G174", "", "Rigid tapping, not vertical, counterclockwise", "非垂直方向刚性攻丝（逆时针）"),
    _g("G184", "", "Rigid tapping, not vertical, clockwise", "非垂直方向刚性攻丝（顺时针）"),
    _g(
        "G187",
        "",
        "Accuracy control: G187 P1 (rough), P2 (medium), P3 (finish) E_ (corner tolerance); "
        "G187 alone returns to Setting 191",
        "精度控制：G187 P1（粗加工）、P2（中等）、P3（精加工）E_（拐角公差）；单独的G187恢复设定191",
    ),
    _g("G234", "length", "Tool centre point control (TCPC)", "刀具中心点控制（TCPC）"),
    _g("G254", "", "Dynamic work offset (DWO)", "动态工件偏置（DWO）"),
    _g("G255", "", "Dynamic work offset cancel", "动态工件偏置取消"),
    _g("G268", "", "Feature coordinate system on (a tilted working plane)", "特征坐标系开启（倾斜工作平面）"),
    _g("G269", "", "Feature coordinate system off", "特征坐标系关闭"),
)

M_CODES: tuple[CodeDoc, ...] = (
    _g("M00", "", "Program stop; cycle start resumes", "程序停止，按循环启动继续"),
    _g(
        "M01",
        "",
        "Optional stop (when the optional stop switch, #3033, is on)",
        "选择停止（仅在选择停止开关#3033打开时有效）",
    ),
    _g("M02", "", "Program end", "程序结束"),
    _g("M03", "", "Spindle forward (clockwise) at S", "主轴正转（顺时针），转速S"),
    _g("M04", "", "Spindle reverse (counterclockwise) at S", "主轴反转（逆时针），转速S"),
    *shared.codes("M05"),
    _g(
        "M06",
        "",
        "Tool change: loads the tool chosen by T (#3026 then reads it)",
        "换刀：换上T指定的刀具（之后#3026读出该刀号）",
    ),
    _g("M07", "", "Shower coolant on", "淋浴式切削液开"),
    _g("M08", "", "Coolant on", "切削液开"),
    _g("M09", "", "Coolant off", "切削液关"),
    _g("M10", "", "Fourth axis brake on", "第四轴制动"),
    _g("M11", "", "Fourth axis brake off", "第四轴松开制动"),
    _g("M12", "", "Fifth axis brake on", "第五轴制动"),
    _g("M13", "", "Fifth axis brake off", "第五轴松开制动"),
    _g("M16", "", "Tool change (the same as M06)", "换刀（同M06）"),
    _g("M19", "", "Orient spindle (P_ angle in degrees)", "主轴定向（P_为角度，度）"),
    *(
        _g(
            f"M{n}",
            "",
            f"Optional user M function {n} with M-FIN (waits for the finish signal)",
            f"可选用户M功能{n}，带M-FIN（等待完成信号）",
        )
        for n in range(21, 29)
    ),
    _g("M30", "", "Program end and reset (counts #3901/#3902)", "程序结束并复位（#3901/#3902计数）"),
    _g("M31", "", "Chip conveyor forward", "排屑器正转"),
    _g("M33", "", "Chip conveyor stop", "排屑器停止"),
    _g(
        "M34",
        "",
        "Coolant spigot position up one step (programmable coolant)",
        "切削液喷嘴位置上调一格（可编程切削液）",
    ),
    _g(
        "M35",
        "",
        "Coolant spigot position down one step (programmable coolant)",
        "切削液喷嘴位置下调一格（可编程切削液）",
    ),
    _g("M36", "", "Pallet part ready (pallet changer)", "托盘工件就绪（托盘交换装置）"),
    _g(
        "M39",
        "",
        "Rotate the tool carousel (side-mount changer) to the tool given",
        "将刀库转到指定刀具（侧挂式换刀装置）",
    ),
    _g("M41", "", "Spindle low gear", "主轴低速挡"),
    _g("M42", "", "Spindle high gear", "主轴高速挡"),
    _g("M46", "", "Jump to block P if pallet Q is loaded", "托盘Q已装载时跳转到P程序段"),
    _g("M48", "", "Check that the program suits the pallet loaded", "检查当前程序是否适合已装载的托盘"),
    _g("M49", "", "Set the status of a pallet", "设定托盘状态"),
    _g("M50", "", "Execute a pallet change", "执行托盘交换"),
    *(_g(f"M{n}", "", f"Optional user relay {n - 50} on", f"可选用户继电器{n - 50}接通") for n in range(51, 59)),
    _g("M59", "", "Set output relay P_ (on)", "接通输出继电器P_"),
    *(_g(f"M{n}", "", f"Optional user relay {n - 60} off", f"可选用户继电器{n - 60}断开") for n in range(61, 69)),
    _g("M69", "", "Clear output relay P_ (off)", "断开输出继电器P_"),
    _g("M75", "", "Set the G35 or G136 reference point", "设定G35或G136的参考点"),
    _g("M76", "", "Control display off", "关闭控制器显示"),
    _g("M77", "", "Control display on", "打开控制器显示"),
    _g("M78", "", "Alarm if the skip signal came on (after G31)", "跳转信号已接通时报警（G31之后）"),
    _g("M79", "", "Alarm if the skip signal did not come on (after G31)", "跳转信号未接通时报警（G31之后）"),
    _g("M80", "", "Automatic door open", "自动门打开"),
    _g("M81", "", "Automatic door close", "自动门关闭"),
    _g("M82", "", "Tool unclamp", "刀具松开"),
    _g("M83", "", "Automatic air gun on", "自动气枪开"),
    _g("M84", "", "Automatic air gun off", "自动气枪关"),
    _g("M86", "", "Tool clamp", "刀具夹紧"),
    _g("M88", "", "Through-spindle coolant on", "主轴中心出水开"),
    _g("M89", "", "Through-spindle coolant off", "主轴中心出水关"),
    _g(
        "M95",
        "",
        "Sleep mode: M95 (hh:mm) waits that long, then the program goes on",
        "睡眠方式：M95 (hh:mm)等待该时长后继续",
    ),
    _g("M96", "", "Jump to block P if discrete input Q is 0", "离散输入Q为0时跳转到P程序段"),
    _g(
        "M97",
        "",
        "Local subprogram call: M97 P(sequence number in this program) L(repeat count); returns at M99",
        "本地子程序调用：M97 P（本程序中的顺序号）L（重复次数）；遇M99返回",
    ),
    _g(
        "M98",
        "",
        "Subprogram call: M98 P(program number, up to 5 digits) L(repeat count); the count is given in "
        "L only. No new level of local variables",
        "子程序调用：M98 P（程序号，最多5位）L（重复次数）；调用次数只能用L指定。局部变量不改变级别",
    ),
    _g(
        "M99",
        "",
        f"{shared.M99_EN}; M99 P_ in a main program jumps to block P",
        "从子程序返回调用程序段的下一段（M99 Pn返回到Nn段）；主程序中从头重复执行，M99 P_则跳转到P程序段",
    ),
    _g("M104", "", "Probe arm extend (tool setting arm)", "对刀臂伸出"),
    _g("M105", "", "Probe arm retract (tool setting arm)", "对刀臂缩回"),
    _g(
        "M109",
        "",
        "Interactive user input: the comment is the prompt, P names the variable that receives the key pressed",
        "交互式用户输入：注释为提示，P指定接收按键值的变量",
    ),
    _g(
        "M130",
        "",
        "Display media (an image or video) while the program goes on",
        "显示媒体（图片或视频）并继续执行程序",
    ),
    _g("M131", "", "Cancel the media display", "取消媒体显示"),
    _g("M138", "", "Spindle speed variation on", "主轴变速（防振）开"),
    _g("M139", "", "Spindle speed variation off", "主轴变速（防振）关"),
    _g("M158", "", "Mist condenser on", "油雾冷凝器开"),
    _g("M159", "", "Mist condenser off", "油雾冷凝器关"),
)


# ---------------------------------------------------------------------------------------------
# the profile: the 0i's macro language with Haas's numbers, codes and limits

PROFILE = FANUC_0I.configured(
    **OTHER_MAKERS,  # the FANUC-only rules off (fanuc_0i.py); G04 P10. is 10 s here (Timing.dwell_p_point_seconds)
    name="haas",
    title="Haas NGC mill",
    title_zh="Haas NGC 铣床",
    summary="Haas Next Generation Control (NGC) mills: 5-digit programs, #10000 commons, G154 P1-P99, O9xxx probing",
    summary_zh="Haas 新一代控制系统（NGC）铣床：5 位程序号、#10000 公共变量、G154 P1～P99、O9xxx 测头宏程序",
    aliases=("haas-ngc", "haas-mill", "haasngc", "ngc"),
    data_module="profiles.haas",
    axes=AXES,
    program_digits=5,
    m98_program_digits=5,
    word_format_alarms=False,
    arc_radius_alarm=False,  # no alarm for it in the manuals at hand: a warning (docs/semantics.md §8, "Arcs")
    cutter_alarms=False,  # no number for the interference or plane alarms in the manuals at hand (§12)
    # G31: "Do not use Cutter Compensation (G41, G42) with a G31" (96-8000), no alarm named: a warning
    skip_compensation_alarm=False,
    keyword_abbreviations=False,
    if_without_then=True,
    conditional_m99=True,
    if_governs_block=True,
    common_ranges=(CommonRange(100, 199, True), CommonRange(500, 999, True), CommonRange(10000, 10999, True)),
    programs_on_control=((9000, 9999),),
    local_subprogram_code=97.0,
    # circular pocket G12/G13, engraving G47, the bolt patterns G70/G71/G72 (a hole of the drilling
    # cycle in force at each point), general pocket G150 ([H1]): known, not simulated
    unsimulated_codes=frozenset({12.0, 13.0, 47.0, 70.0, 71.0, 72.0, 150.0}),
    input_jump_code=96.0,  # M96 P Q: to N(P) when input Q (#1000 + Q) is 0 ([H4])
    # G101 X_ Y_: the mirror image's centre on the axes given, G100 cancels (docs/semantics.md §8)
    axis_value_codes=frozenset((7.1, 107.0, 100.0, 101.0)),
    documented_alarms=frozenset(),  # no Haas source numbers FANUC's alarms or #3000=n: none shown
    dprnt_places=8,  # DPRNT #1[54] is illegal, #1[03] prints 1.544 ([H5] p. 125)
    dprnt_whole_part=True,
    main_m99_p_jumps=True,  # N50 M99 P10 in a main program branches to N10 ([H1], [H5])
    macro_repeat_keeps_locals=True,  # G65 L: the arguments are set on the first pass only ([H5])
    last_address_letters=LAST_ADDRESS_LETTERS,  # #4101-#4126: every letter's last value ([Z])
    extra_offset_code=154.0,
    extra_offset_aliases=tuple(float(g) for g in range(110, 130)),
    extra_offset_variables=G154_LONG,
    extra_offset_count=99,
    tool_offset_bases=(2000, 2200, 2400, 2600),
    g10_tool_l_aliases=((1.0, 11.0),),  # G10 L1 = L11, the length wear ([U])
    # G28 alone homes every axis, and G28 cancels the tool length offset (96-8000, G28)
    reference_return_all_axes=True,
    reference_return_cancels_tool_offset=True,
    drill_cycles=HAAS_DRILL_CYCLES,  # its G77 back bore, G87 bore in and manual retract
    cycle_words={},  # Haas repeats with L and reads more letters in G73 and G83: not described yet
    cycle_repeat_letter="L",  # L repeats a canned cycle (K is a peck's minimum on G73/G83)
    # 96-8000, G73: "When the canned cycle is cancelled (i.e. G00, G01, G80, RESET) the dwell time
    # will be reset to zero"
    cycle_cancel_clears_dwell=True,
    # rapids of 1,000 in/min on X, Y, Z (a VF-2's), a typical tool change; a dwell's P counts
    # seconds written with a decimal point and milliseconds without (as the G04 row says)
    timing=Timing(
        rapid={"X": 25400.0, "Y": 25400.0, "Z": 25400.0},
        rapid_default=10800.0,
        tool_change_seconds=2.8,
        tool_change_code="M6",
        dwell_p_unit=0.001,
        dwell_p_point_seconds=True,
        max_spindle_speed=8100.0,
    ),
)
