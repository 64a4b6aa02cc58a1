"""Haas lathes (ST and SL series, Haas control): the system variables, G codes, M codes and cycle
words of the ``haas-lathe`` profile.

The macro side is the Haas mill's (``profiles/haas.py``), so are the rows a lathe reads the same
way: inputs and outputs, alarm, timers and switches, the address codes #4101-#4126, positions,
work offsets G52/G54-G59 (#5201...) and G154 P1-P99, settings and parameters. What a
lathe reads otherwise (docs/profiles.md, "haas-lathe: sources and decisions"):

* the tool offsets by offset number: X, Y and Z geometry at #2001, #2051, #2101, the tool nose
  radius at #2201 and its imaginary tip direction at #2301, X, Y and Z wear at #2701, #2751,
  #2801 and the radius wear at #2901 (50 offsets each), where the T code's last two digits and
  ``G10 P`` reach them (``LATHE_OFFSETS``): Haas keeps the geometry at the low numbers, where a
  FANUC lathe keeps its wear;
* #5081-#5086: the tool offset in effect (geometry plus wear), not a mill's length offset;
* the modal groups #4001-#4021 of the lathe's G codes (group 10 is G98/G99, the feed, and 13
  G96/G97, the spindle);
* none of the mill's length and diameter offsets by tool number (#1601-#2800), its tool data
  through #8550, its pallets (#3028, #7501-#7804) or its spindle tool #3026.

The G codes are the lathe's: ``G50`` clamps the spindle (S) or sets coordinates (X Z),
``G90``/``G92``/``G94`` are the single cycles, ``G70``-``G76`` the multiple repetitive cycles with
Haas's one-block forms (``G71 P Q U W D``, ``G76 X Z K D A F``), ``G98``/``G99`` the feed per
minute and per revolution. A code's ``group`` is its name in ``MODAL_GROUPS``, or empty.
"""

from __future__ import annotations

from . import lathe_cycle_words as lw
from . import shared_data as shared
from .cycle_words import CycleWord, CycleWords, by_code, one_block, two_blocks
from .profiles import haas as mill
from .tables import CodeDoc, LatheOffsets, SystemVariable

AXES = mill.AXES  # X Y Z A B C: #5021 is X, #5022 Y, #5023 Z on a Haas lathe as on its mills

# ---------------------------------------------------------------------------------------------
# tool offsets by offset number (T0101: tool 1, offset 1): base of offset 0, what it is

OFFSET_COUNT = 50

_OFFSET_KINDS: tuple[tuple[int, str, str, str], ...] = (
    (2000, "X geometry (a diameter)", "X轴几何形状补偿（直径值）", "mm"),
    (2050, "Y geometry", "Y轴几何形状补偿", "mm"),
    (2100, "Z geometry", "Z轴几何形状补偿", "mm"),
    (2200, "tool nose radius (geometry)", "刀尖半径（几何形状）", "mm"),
    (2300, "imaginary tool tip direction (0-9)", "假想刀尖方向（0～9）", ""),
    (2700, "X wear (a diameter)", "X轴磨损补偿（直径值）", "mm"),
    (2750, "Y wear", "Y轴磨损补偿", "mm"),
    (2800, "Z wear", "Z轴磨损补偿", "mm"),
    (2900, "tool nose radius wear", "刀尖半径磨损补偿", "mm"),
)

# where the planner reads them (the T code's offset) and G10 P writes them: (axis, geometry, wear)
LATHE_OFFSETS = LatheOffsets(axes=(("X", 2000, 2700), ("Z", 2100, 2800), ("Y", 2050, 2750)),
                             radius=(2200, 2900), tip=2300)  # fmt: skip

_TOOL_OFFSETS: tuple[SystemVariable, ...] = tuple(
    SystemVariable(base + 1, base + OFFSET_COUNT, "rw", "tool",
                   f"Tool offset {{index}}: {en} (the last two digits of T select it: T01{{index:02d}})",
                   f"{{index}}号刀补：{zh}（由T代码的后两位选择：T01{{index:02d}}）", unit)
    for base, en, zh, unit in _OFFSET_KINDS
)  # fmt: skip

TOOL_OFFSET_IN_EFFECT = SystemVariable(
    5081,
    5081 + len(AXES) - 1,
    "r",
    "position",
    "{axis} axis tool offset in effect: the geometry plus the wear of the T code's offset{diameter}",
    "{axis}轴（第{index}轴）当前生效的刀具偏置：T代码所选刀补的几何形状值与磨损值之和{diameter}",
    "mm",
    "position",
    "tool",
)

# ---------------------------------------------------------------------------------------------
# modal information: the previous block's group codes (#4001-#4021), in the lathe's groups

MODAL_GROUP_CODES: dict[int, tuple[str, str]] = {
    1: ("motion", "G00, G01, G02, G03, G32, G90, G92, G94"),
    2: ("plane", "G17, G18, G19"),
    6: ("units", "G20, G21"),
    7: ("cutter", "G40, G41, G42"),
    9: ("canned", "G80-G89"),
    10: ("feed", "G98, G99"),
    12: ("wcs", "G54-G59, G154"),
    13: ("spindle", "G96, G97"),
    15: ("cutting", "G61, G64"),
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


def mill_only(row: SystemVariable) -> bool:
    """A Haas mill row a lathe reads otherwise or lacks: the tool data by tool number
    (#1601-#2800) and through #8550, the spindle tool and pallets (#3026, #3028, #7501-#7804),
    the mill's modal groups and its length offset in effect (#5081)."""
    first = row.first
    return (
        1601 <= first <= 2800
        or 8550 <= first <= 8564
        or first in (3026, 3028, 5081)
        or 7501 <= first <= 7804
        or 4001 <= first <= 4000 + mill.GROUPS
    )


SYSTEM_VARIABLES: tuple[SystemVariable, ...] = (
    *(row for row in mill.SYSTEM_VARIABLES if not mill_only(row)),
    *_TOOL_OFFSETS,
    *(_modal_row(group) for group in range(1, mill.GROUPS + 1)),
    TOOL_OFFSET_IN_EFFECT,
)

# ---------------------------------------------------------------------------------------------
# G codes of a Haas lathe


def _g(code: str, group: str, en: str, zh: str) -> CodeDoc:
    return CodeDoc(code, group, en, zh)


_MILL_ROWS = {c.code: c for c in mill.G_CODES}
# codes a Haas lathe reads as its mills do
_SAME_AS_MILL = ("G09", "G31", "G52", "G53", "G61", "G64", "G65", "G103")

G_CODES: tuple[CodeDoc, ...] = (
    *shared.codes("G00", "G01"),
    _g(
        "G02",
        "motion",
        "Circular interpolation clockwise (R or I K; I is a radius)",
        "顺时针圆弧插补（R或I K；I为半径值）",
    ),
    _g(
        "G03",
        "motion",
        "Circular interpolation counterclockwise (R or I K; I is a radius)",
        "逆时针圆弧插补（R或I K；I为半径值）",
    ),
    _g(
        "G04",
        "",
        "Dwell: G04 P_ (seconds with a decimal point, milliseconds without)",
        "暂停：G04 P_（带小数点时单位为秒，不带时为毫秒）",
    ),
    _g(
        "G10",
        "",
        "Set offsets: G10 P_ X Z R Q (tool wear; geometry by P plus 10000), L2 and L20 work offsets",
        "设定偏置：G10 P_ X Z R Q（刀具磨损；P加10000为几何形状），L2、L20为工件偏置",
    ),
    _g("G14", "", "Secondary spindle swap on (the sub-spindle runs the main spindle's program)", "副主轴切换开"),
    _g("G15", "", "Secondary spindle swap cancel", "副主轴切换取消"),
    *shared.codes("G17"),
    _g("G18", "plane", "ZX plane selection (the lathe's plane)", "ZX平面选择（车床平面）"),
    *shared.codes("G19", "G20", "G21"),
    _g("G28", "", "Return to machine zero (G28 U0 W0 through the point given)", "返回机床零点（G28 U0 W0经指定点）"),
    _g("G29", "", "Return from machine zero through the G28 point", "经G28的中间点从机床零点返回"),
    _g("G32", "motion", "Thread cutting: G32 X(U)_ Z(W)_ F_ (lead)", "螺纹切削：G32 X(U)_ Z(W)_ F_（导程）"),
    _g("G40", "cutter", "Tool nose compensation cancel", "刀尖半径补偿取消"),
    _g(
        "G41",
        "cutter",
        "Tool nose compensation left (the radius and tip direction of the T code's offset)",
        "刀尖半径左补偿（使用T代码所选刀补的半径及刀尖方向）",
    ),
    _g(
        "G42",
        "cutter",
        "Tool nose compensation right (the radius and tip direction of the T code's offset)",
        "刀尖半径右补偿（使用T代码所选刀补的半径及刀尖方向）",
    ),
    _g(
        "G50",
        "",
        "Spindle speed clamp (G50 S_, the highest speed under G96) or set coordinates (G50 X_ Z_)",
        "主轴最高转速限制（G50 S_，G96下的最高转速）或设定坐标系（G50 X_ Z_）",
    ),
    *(_MILL_ROWS[code] for code in _SAME_AS_MILL),
    *shared.work_coordinate_codes(len(AXES), offsets_zh="偏置"),
    _g("G70", "", "Finishing cycle: G70 P(first block) Q(last block)", "精加工循环：G70 P（首段）Q（末段）"),
    _g(
        "G71",
        "",
        "O.D./I.D. stock removal: G71 P Q U W D F (one block) or G71 U R / G71 P Q U W F",
        "外径/内径粗车循环：G71 P Q U W D F（单段）或G71 U R / G71 P Q U W F",
    ),
    _g(
        "G72",
        "",
        "End face stock removal: G72 P Q U W D F (one block) or G72 W R / G72 P Q U W F",
        "端面粗车循环：G72 P Q U W D F（单段）或G72 W R / G72 P Q U W F",
    ),
    _g(
        "G73",
        "",
        "Irregular path stock removal: G73 P Q I K U W D F (one block) or G73 U W R / G73 P Q U W F",
        "仿形粗车循环：G73 P Q I K U W D F（单段）或G73 U W R / G73 P Q U W F",
    ),
    _g(
        "G74",
        "",
        "End face grooving or peck drilling: G74 X(U) Z(W) I K D F",
        "端面切槽或啄式钻孔循环：G74 X(U) Z(W) I K D F",
    ),
    _g("G75", "", "O.D./I.D. grooving: G75 X(U) Z(W) I K D F", "外径/内径切槽循环：G75 X(U) Z(W) I K D F"),
    _g(
        "G76",
        "",
        "Threading cycle, multiple pass: G76 X(U) Z(W) K (height) D (first depth) A (angle) I (taper) F (lead)",
        "多次螺纹切削循环：G76 X(U) Z(W) K（牙高）D（首次切深）A（刀尖角）I（锥度）F（导程）",
    ),
    _g("G80", "canned", "Canned cycle cancel", "固定循环取消"),
    _g("G81", "canned", "Drilling cycle along Z", "Z向钻孔循环"),
    _g("G82", "canned", "Spot drilling cycle with a dwell at the bottom", "带孔底暂停的点钻循环"),
    _g("G83", "canned", "Peck drilling cycle", "深孔啄钻循环"),
    _g("G84", "canned", "Tapping cycle", "攻丝循环"),
    _g("G85", "canned", "Boring cycle (feed in, feed out)", "镗孔循环（切削进给退刀）"),
    _g("G86", "canned", "Bore and stop cycle", "镗孔并停止循环"),
    _g("G89", "canned", "Bore in, dwell, bore out cycle", "镗孔、暂停后切削进给退刀循环"),
    _g("G90", "motion", "O.D./I.D. turning cycle: G90 X(U)_ Z(W)_ I_ F_", "外径/内径车削循环：G90 X(U)_ Z(W)_ I_ F_"),
    _g("G92", "motion", "Threading cycle: G92 X(U)_ Z(W)_ I_ F_ (lead)", "螺纹切削循环：G92 X(U)_ Z(W)_ I_ F_（导程）"),
    _g("G94", "motion", "End facing cycle: G94 X(U)_ Z(W)_ K_ F_", "端面车削循环：G94 X(U)_ Z(W)_ K_ F_"),
    _g("G95", "", "Live tooling rigid tap (face)", "动力刀具刚性攻丝（端面）"),
    _g(
        "G96",
        "spindle",
        "Constant surface speed on (S in m/min, or ft/min in inches)",
        "恒线速度控制开（S为米/分，英制为英尺/分）",
    ),
    _g("G97", "spindle", "Constant surface speed off (S in rev/min)", "恒线速度控制关（S为转/分）"),
    _g("G98", "feed", *shared.FEED_PER_MINUTE),
    _g("G99", "feed", *shared.FEED_PER_REVOLUTION),
    _g("G112", "", "XY to XC interpolation (live tooling on the C axis)", "XY到XC插补（C轴动力刀具）"),
    _g("G113", "", "XY to XC interpolation cancel", "XY到XC插补取消"),
    _g(
        "G154",
        "wcs",
        "Select work coordinates G154 P1-P99 (offsets #14001 + 20(P-1) onwards)",
        "选择工件坐标系G154 P1～P99（偏置从#14001+20(P-1)起）",
    ),
    _g("G184", "", "Reverse tapping cycle for left-hand threads", "反向攻丝循环（左旋螺纹）"),
    _g("G186", "", "Reverse live tool rigid tap", "动力刀具反向刚性攻丝"),
    _g("G187", "", "Accuracy control (smoothness) for high-speed machining", "精度控制（高速加工平滑度）"),
    _g("G195", "", "Forward live tool radial tapping (diameter)", "动力刀具径向正向攻丝"),
    _g("G196", "", "Reverse live tool radial tapping (diameter)", "动力刀具径向反向攻丝"),
    _g("G241", "", "Radial drilling cycle (live tooling)", "径向钻孔循环（动力刀具）"),
    _g("G242", "", "Radial spot drilling cycle (live tooling)", "径向点钻循环（动力刀具）"),
    _g("G243", "", "Radial peck drilling cycle (live tooling)", "径向啄式钻孔循环（动力刀具）"),
)

# ---------------------------------------------------------------------------------------------
# M codes of a Haas lathe

_MILL_M = {c.code: c for c in mill.M_CODES}
_SAME_M_AS_MILL = ("M00", "M01", "M02", "M03", "M04", "M05", "M08", "M09", "M30", "M31", "M33", "M41", "M42",
                   "M59", "M69", "M76", "M77", "M78", "M79", "M95", "M96", "M97", "M98", "M99", "M109")  # fmt: skip

M_CODES: tuple[CodeDoc, ...] = (
    *(_MILL_M[code] for code in _SAME_M_AS_MILL),
    _g("M10", "", "Chuck clamp", "卡盘夹紧"),
    _g("M11", "", "Chuck unclamp", "卡盘松开"),
    _g("M12", "", "Automatic air jet on", "自动吹气开"),
    _g("M13", "", "Automatic air jet off", "自动吹气关"),
    _g("M14", "", "Main spindle brake on (C axis)", "主轴制动（C轴）"),
    _g("M15", "", "Main spindle brake off", "主轴松开制动"),
    _g("M19", "", "Orient the spindle (R_ angle in degrees)", "主轴定向（R_为角度，度）"),
    _g("M21", "", "Tailstock advance", "尾座前进"),
    _g("M22", "", "Tailstock retract", "尾座后退"),
    _g("M23", "", "Chamfer out of thread on (G76, G92)", "螺纹退尾倒角开（G76、G92）"),
    _g("M24", "", "Chamfer out of thread off", "螺纹退尾倒角关"),
    _g("M36", "", "Parts catcher on (swings in)", "接料器开（摆入）"),
    _g("M37", "", "Parts catcher off (swings out)", "接料器关（摆出）"),
    _g("M38", "", "Spindle speed variation on", "主轴变速（防振）开"),
    _g("M39", "", "Spindle speed variation off", "主轴变速（防振）关"),
    _g("M43", "", "Turret unlock (for service)", "刀塔松开（维修用）"),
    _g("M44", "", "Turret lock (for service)", "刀塔锁紧（维修用）"),
    *(_g(f"M{n}", "", f"Optional user relay {n - 50} on", f"可选用户继电器{n - 50}接通") for n in range(51, 59)),
    *(_g(f"M{n}", "", f"Optional user relay {n - 60} off", f"可选用户继电器{n - 60}断开") for n in range(61, 69)),
    _g("M85", "", "Automatic door open", "自动门打开"),
    _g("M86", "", "Automatic door close", "自动门关闭"),
    _g("M88", "", "High-pressure coolant on", "高压切削液开"),
    _g("M89", "", "High-pressure coolant off", "高压切削液关"),
    _g("M104", "", "Tool presetter arm down", "对刀臂放下"),
    _g("M105", "", "Tool presetter arm up", "对刀臂收回"),
    _g("M110", "", "Secondary spindle chuck clamp", "副主轴卡盘夹紧"),
    _g("M111", "", "Secondary spindle chuck unclamp", "副主轴卡盘松开"),
    _g("M119", "", "Secondary spindle orient", "副主轴定向"),
    _g("M133", "", "Live tool forward (P_ rev/min)", "动力刀具正转（P_为转速）"),
    _g("M134", "", "Live tool reverse (P_ rev/min)", "动力刀具反转（P_为转速）"),
    _g("M135", "", "Live tool stop", "动力刀具停止"),
    _g("M143", "", "Secondary spindle forward", "副主轴正转"),
    _g("M144", "", "Secondary spindle reverse", "副主轴反转"),
    _g("M145", "", "Secondary spindle stop", "副主轴停止"),
    _g("M146", "", "Steady rest clamp", "中心架夹紧"),
    _g("M147", "", "Steady rest unclamp", "中心架松开"),
)

# ---------------------------------------------------------------------------------------------
# cycle words: FANUC's, with Haas's one-block G71, G72 and G76 and its G74/G75/G90/G92/G94 letters

w = CycleWord
_DEPTH_D = w(
    "D",
    "",
    "depth of each roughing cut (a radius, positive), in this block",
    "每次粗车切深（半径值，正值），写在本程序段",
)
_ROUGH_I = w("I", "", "roughing allowance in X (a radius, signed)", "X方向粗车余量（半径值，带符号）")
_ROUGH_K = w("K", "", "roughing allowance in Z (signed)", "Z方向粗车余量（带符号）")
_TYPE_II = w("R", "", "R1: type II roughing (a shape whose X turns back)", "R1：II型粗车（X方向可折返的形状）")
_ONE_BLOCK_ROUGH = (lw.SHAPE_FIRST, lw.SHAPE_LAST, lw.ALLOWANCE_X, lw.ALLOWANCE_Z, _DEPTH_D, _ROUGH_I, _ROUGH_K,
                    lw.ROUGH_FEED, lw.ROUGH_SPEED, lw.ROUGH_TOOL, _TYPE_II)  # fmt: skip


_ONE_BLOCK_PATTERN = (
    lw.SHAPE_FIRST,
    lw.SHAPE_LAST,
    w(
        "I",
        "",
        "relief in X from the first pass to the last (a radius, signed)",
        "X方向总退刀量：首刀至末刀（半径值，带符号）",
    ),
    w("K", "", "relief in Z from the first pass to the last (signed)", "Z方向总退刀量：首刀至末刀（带符号）"),
    lw.ALLOWANCE_X,
    lw.ALLOWANCE_Z,
    w("D", "", "number of passes", "切削次数"),
    lw.ROUGH_FEED,
    lw.ROUGH_SPEED,
    lw.ROUGH_TOOL,
)


def _two_or_one(code: str, first: tuple[CycleWord, ...]) -> CycleWords:
    """G71/G72: FANUC's first block (``first``) and Haas's one block that runs the cycle."""
    return two_blocks(code, first, _ONE_BLOCK_ROUGH, "PQ", True)


_GROOVE = (
    *lw.END_POINT,
    w("I", "", "step along X (a radius), in the program's unit", "X方向每次移动量（半径值），以程序单位"),
    w("K", "", "step along Z, in the program's unit", "Z方向每次移动量，以程序单位"),
    w("D", "", "tool clearance on the way back to the start", "返回起点时的刀具间隙"),
    lw.FEED,
)
_THREAD = (
    *lw.END_POINT,
    w("K", "", "thread height (a radius)", "螺纹牙高（半径值）"),
    w("D", "", "depth of the first pass (a radius)", "第一次切深（半径值）"),
    w("A", "", "tool angle in degrees (0 when not given: straight infeed)", "刀尖角度（度；不写为0：径向进刀）"),
    w("I", "", "taper: the radius at the start less the radius at the end", "锥度：起点半径减终点半径"),
    w("P", "", "cutting method P1-P4 (single or double edge, constant load or depth)",
      "切削方式P1～P4（单刃或双刃，等切削量或等切深）"),
    w("Q", "", "thread start angle (no decimal point)", "螺纹起始角（不带小数点）"),
    lw.LEAD,
)  # fmt: skip


def _haas_block(code: str, second: tuple[CycleWord, ...]) -> CycleWords:
    """G74-G76: FANUC's first block, which the run still reads, and Haas's one block with the end point."""
    fanuc = lw.FANUC_LATHE_CYCLE_WORDS[float(code[1:])]
    return two_blocks(code, fanuc.forms[0].words, second, "XZUW", False)


CYCLE_WORDS: dict[float, CycleWords] = {
    # the FANUC lathe's but its drilling cycles (G83-G89 along Z and X), which a Haas lathe writes
    # otherwise (live tooling G95, G186, ...; not described here)
    **{code: words for code, words in lw.FANUC_LATHE_CYCLE_WORDS.items() if not 83.0 <= code <= 89.0},
    **by_code(
        _two_or_one(
            "G71",
            (
                w("U", "Δd", "depth of each cut (a radius), two-block form", "每次切深（半径值），双段格式"),
                lw.RETRACT_E,
            ),
        ),
        _two_or_one(
            "G72", (w("W", "Δd", "depth of each cut along Z, two-block form", "Z向每次切深，双段格式"), lw.RETRACT_E)
        ),
        two_blocks("G73", lw.FANUC_LATHE_CYCLE_WORDS[73.0].forms[0].words, _ONE_BLOCK_PATTERN, "PQ", True),
        _haas_block("G74", _GROOVE),
        _haas_block("G75", _GROOVE),
        _haas_block("G76", _THREAD),
        one_block("G90", *lw.END_POINT, w("I", "", "taper in X (a radius)", "X方向锥度（半径值）"), lw.FEED),
        one_block("G92", *lw.END_POINT, w("I", "", "taper in X (a radius)", "X方向锥度（半径值）"), lw.LEAD),
        one_block("G94", *lw.END_POINT, w("K", "", "taper in Z", "Z方向锥度"), lw.FEED),
    ),
}
