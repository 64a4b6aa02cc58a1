"""FANUC 0i-TF lathe data (G-code system A): the system variables, G codes and M codes of a 0i
lathe control, for the ``fanuc-0i-lathe`` profile.

The system variables are the 0i's (``fanuc_data``) where a lathe reads a number the same way
(interface signals, alarm and message, timers, parts counters, positions, work offsets) and a
lathe's own where it differs (docs/profiles.md, "fanuc-0i-lathe: sources and decisions"): the
tool offsets of the lathe's tool compensation memory, X, Z and Y wear and geometry, tool nose
radius wear and geometry and the imaginary tool nose direction, at #10001… for up to 400
offsets with #2001… as the short numbers of offsets 1-64; the modal groups of system A
(#4001…: no G90/G91 group, G98/G99 in group 05); the T code with its offset number (#4120);
the tool offset in effect (#5081…). The 0i mill's #2500-#2806 (short numbers of the work
offsets) are not a lathe's: there #2701… are X geometry offsets. The M codes are the 0i's.
The G codes are the lathe's system A list: ``G50`` sets coordinates and clamps the spindle,
``G90``/``G92``/``G94`` are the single fixed cycles, ``G70``–``G76`` the multiple repetitive
cycles, ``G98``/``G99`` feed per minute and per revolution; there is no G90/G91 distance group,
as U and W move incrementally. A code's ``group`` is its name in ``MODAL_GROUPS``, or empty for
a one-shot code.
"""

from __future__ import annotations

from . import fanuc_data as fanuc
from . import shared_data as shared
from .tables import CodeDoc, LatheOffsets, SystemVariable

M_CODES: tuple[CodeDoc, ...] = fanuc.M_CODES

# ---------------------------------------------------------------------------------------------
# tool offsets, the lathe's tool compensation memory: (wear, geometry) bases of offset 0 in the
# long numbers, the short numbers of offsets 1-64 (or None), what the value is (en, zh, unit)

OFFSET_COUNT = 400  # offsets of the long numbers #10001…
SHORT_COUNT = 64  # offsets that also have a short number #2001…

_OFFSET_KINDS: tuple[tuple[int, int | None, str, str, str], ...] = (
    (10000, 2000, "X wear", "X轴磨损补偿值", "mm"),
    (11000, 2100, "Z wear", "Z轴磨损补偿值", "mm"),
    (12000, 2200, "tool nose radius wear", "刀尖半径磨损补偿值", "mm"),
    (13000, 2300, "imaginary tool nose direction T (0-9)", "假想刀尖方向T（0～9）", ""),
    (14000, 2400, "Y wear", "Y轴磨损补偿值", "mm"),
    (15000, 2700, "X geometry", "X轴几何形状补偿值", "mm"),
    (16000, 2800, "Z geometry", "Z轴几何形状补偿值", "mm"),
    (17000, 2900, "tool nose radius geometry", "刀尖半径几何形状补偿值", "mm"),
    (19000, 2450, "Y geometry", "Y轴几何形状补偿值", "mm"),
)

# where the planner reads and G10 P writes them (Dialect.lathe_offsets): the long numbers
# G10 P0 X(U) Z(W): the workpiece coordinate system shift, the external work offset (#5201…) on a
# control with G54-G59 (the lathe G10 format "G10 P_ X(U)_ Z(W)_ R(C)_ Q_", P0 the shift)
LATHE_OFFSETS = LatheOffsets(axes=(("X", 15000, 10000), ("Z", 16000, 11000), ("Y", 19000, 14000)),
                             radius=(17000, 12000), tip=13000, p0_work_shift=True)  # fmt: skip


def _short_count(short: int) -> int:
    """Offsets a short range holds: 64, but Y's wear and geometry share #2401-#2499 (49 each)."""
    return 49 if short in (2400, 2450) else SHORT_COUNT


def tool_offset_rows(count: int) -> tuple[SystemVariable, ...]:
    """The tool offsets of a FANUC lathe with ``count`` offsets at the long numbers (#10001…) and
    their short numbers (#2001…) for offsets 1-64 (the 30i lathe has 999)."""
    return (
        *(
            SystemVariable(long + 1, long + count, "rw", "tool",
                           f"Tool offset {{index}}: {en} (G10 P{{index}} writes wear, G10 P(10000+{{index}}) "
                           "geometry; X values on the diameter)",
                           f"{{index}}号刀补的{zh}（G10 P{{index}}写磨损值，G10 P(10000+{{index}})写几何形状值；"
                           "X为直径值）", unit)
            for long, _, en, zh, unit in _OFFSET_KINDS
        ),
        *(
            SystemVariable(short + 1, short + _short_count(short), "rw", "tool",
                           f"Tool offset {{index}}: {en}; short number for #{long + 1}… (#{short + 1} = #{long + 1}), "
                           f"usable with {SHORT_COUNT} offsets or fewer",
                           f"{{index}}号刀补的{zh}；#{long + 1}…的另一编号（#{short + 1}即#{long + 1}），"
                           f"刀补数不超过{SHORT_COUNT}组时可用", unit, "alias", str(long + 1))
            for long, short, en, zh, unit in _OFFSET_KINDS
            if short is not None
        ),
    )  # fmt: skip


_TOOL_OFFSETS = tool_offset_rows(OFFSET_COUNT)

# ---------------------------------------------------------------------------------------------
# modal information of G-code system A: group number -> (name in MODAL_GROUPS, its codes)

MODAL_GROUP_CODES: dict[int, tuple[str, str]] = {
    1: ("motion", "G00, G01, G02, G03, G32, G34, G90, G92, G94"),
    2: ("spindle", "G96, G97"),
    5: ("feed", "G98, G99"),
    6: ("units", "G20, G21"),
    7: ("cutter", "G40, G41, G42"),
    9: ("stroke", "G22, G23"),
    10: ("canned", "G80, G83-G89"),
    12: ("macro", "G66, G67"),
    14: ("wcs", "G54-G59"),
    15: ("cutting", "G61-G64"),
    16: ("plane", "G17, G18, G19"),
}


def modal_row(group: int) -> SystemVariable:
    """#4000+group: the modal G code of system A's ``group`` (vacant for a group not kept)."""
    return shared.modal_group_row(
        4000 + group,
        group,
        MODAL_GROUP_CODES,
        (
            "Modal information of G-code group {group:02d} (system A); vacant unless the machine presets it",
            "第{group}组G代码（G代码体系A）的模态信息；机床未预设时为空",
        ),
        (
            "Modal G code of group {group:02d} ({codes}; system A) in effect before the current block, read as a "
            "number ({code} reads {value}, not {code})",
            "第{group}组模态G代码（{codes}；G代码体系A），为当前程序段之前的模态，读出的是数值（{code}读出为{value}，而不是{code}）",
        ),
    )


# the code letters of a lathe beside those both controls have (shared_data.CODE_LETTERS)
LATHE_CODE_LETTERS: tuple[tuple[int, str, str, str], ...] = (
    (4102, "B", "B code (second auxiliary function) last commanded", "最近指令的B代码（第2辅助功能）"),
    (
        4120,
        "T",
        "T code last commanded: tool number x 100 + offset number (T0101 reads 101)",
        "最近指令的T代码：刀具号×100+刀补号（T0101读出101）",
    ),
    (
        4130,
        "P",
        "P code: number of the additional work coordinate system selected (G54.1 Pn reads n)",
        "P代码：当前所选的追加工件坐标系号（G54.1 Pn时读出n）",
    ),
)

_MODAL: tuple[SystemVariable, ...] = (
    *(modal_row(group) for group in range(1, 23)),
    *shared.code_letter_rows((*shared.CODE_LETTERS, *LATHE_CODE_LETTERS)),
)

TOOL_OFFSET_IN_EFFECT = SystemVariable(
    5081,
    5084,
    "r",
    "position",
    "{axis} axis tool offset now in effect: the geometry plus the wear of the T code's offset{diameter}; "
    "not readable while moving",
    "第{index}轴（{axis}）当前执行的刀具偏置值：T代码所选刀补的几何形状值与磨损值之和{diameter}，移动中不可读",
    "mm",
    "position",
    "tool",
)


def mill_only(row: SystemVariable) -> bool:
    """A 0i mill row a lathe reads otherwise: the H/D tool offsets, the modal information and code
    letters, the tool length offset in effect, and the work offsets' short numbers #2500-#2806."""
    return row.group in ("tool", "modal") or row.first == 5081 or 2500 <= row.first <= 2806


SYSTEM_VARIABLES: tuple[SystemVariable, ...] = (
    *(row for row in fanuc.SYSTEM_VARIABLES if not mill_only(row)),
    *_TOOL_OFFSETS,
    *_MODAL,
    TOOL_OFFSET_IN_EFFECT,
)

# codes a 0i-TF has that read the same as on the 0i mill's table (``fanuc_data``), so that a lathe
# program is never told that a code of its control does not exist (docs/profiles.md)
_MILL_ROWS = {c.code: c for c in fanuc.G_CODES}
_SAME_AS_MILL = ("G07.1", "G09", "G11", "G12.1", "G13.1", "G22", "G23", "G25", "G26", "G27", "G29", "G30.1",
                 "G36", "G37", "G52", "G53", "G54.1", "G61", "G63", "G64", "G107", "G112", "G113", "G50.2", "G51.2",
                 "G50.3")  # fmt: skip

G_CODES: tuple[CodeDoc, ...] = (
    *(_MILL_ROWS[code] for code in _SAME_AS_MILL),
    CodeDoc("G68", "", "Mirror image for double turrets (balance cut) on", "双刀架镜像（平衡切削）开"),
    CodeDoc("G69", "", "Mirror image for double turrets (balance cut) off", "双刀架镜像（平衡切削）关"),
    *shared.codes("G00", "G01"),
    CodeDoc(
        "G02",
        "motion",
        "Circular interpolation clockwise (R or I K; I is a radius)",
        "顺时针圆弧插补（R或I K；I为半径值）",
    ),
    CodeDoc(
        "G03",
        "motion",
        "Circular interpolation counterclockwise (R or I K; I is a radius)",
        "逆时针圆弧插补（R或I K；I为半径值）",
    ),
    CodeDoc(
        "G04", "", "Dwell: G04 X_ or U_ (seconds) or G04 P_ (milliseconds)", "暂停：G04 X_或U_（秒）或G04 P_（毫秒）"
    ),
    CodeDoc("G10", "", "Programmable data input (work and tool offsets)", "可编程数据输入（工件及刀具偏置）"),
    *shared.codes("G17"),
    CodeDoc("G18", "plane", "ZX plane selection (the lathe's usual plane)", "ZX平面选择（车床常用平面）"),
    *shared.codes("G19", "G20", "G21"),
    CodeDoc(
        "G28",
        "",
        "Return to the reference position through the intermediate point (G28 U0 W0)",
        "经由中间点返回参考点（G28 U0 W0）",
    ),
    CodeDoc("G30", "", "Return to the 2nd, 3rd or 4th reference position", "返回第2、第3或第4参考点"),
    CodeDoc("G31", "", "Skip function", "跳转功能"),
    CodeDoc("G32", "motion", "Thread cutting: G32 X(U)_ Z(W)_ F_ (lead)", "螺纹切削：G32 X(U)_ Z(W)_ F_（导程）"),
    CodeDoc(
        "G34",
        "motion",
        "Variable-lead thread cutting: G34 X(U)_ Z(W)_ F_ K_ (lead change per turn)",
        "变导程螺纹切削：G34 X(U)_ Z(W)_ F_ K_（每转导程增减量）",
    ),
    CodeDoc("G40", "cutter", "Tool nose radius compensation cancel", "刀尖半径补偿取消"),
    CodeDoc("G41", "cutter", "Tool nose radius compensation left", "刀尖半径左补偿"),
    CodeDoc("G42", "cutter", "Tool nose radius compensation right", "刀尖半径右补偿"),
    CodeDoc(
        "G50",
        "",
        "Coordinate system setting (G50 X_ Z_) or maximum spindle speed (G50 S_)",
        "坐标系设定（G50 X_ Z_）或主轴最高转速限制（G50 S_）",
    ),
    *shared.work_coordinate_codes(6),
    CodeDoc(
        "G65",
        "",
        "Macro call G65 P_ L_ arguments (a new level of local variables)",
        "宏程序非模态调用G65 P_ L_ 自变量（局部变量进入新的一级）",
    ),
    *shared.codes("G66", "G67"),
    CodeDoc("G70", "", "Finishing cycle: G70 P(ns) Q(nf)", "精加工循环：G70 P(ns) Q(nf)"),
    CodeDoc(
        "G71",
        "",
        "Stock removal in turning: G71 U(Δd) R(e) / G71 P(ns) Q(nf) U(Δu) W(Δw) F_",
        "外圆粗车循环：G71 U(Δd) R(e) / G71 P(ns) Q(nf) U(Δu) W(Δw) F_",
    ),
    CodeDoc(
        "G72",
        "",
        "Stock removal in facing: G72 W(Δd) R(e) / G72 P(ns) Q(nf) U(Δu) W(Δw) F_",
        "端面粗车循环：G72 W(Δd) R(e) / G72 P(ns) Q(nf) U(Δu) W(Δw) F_",
    ),
    CodeDoc(
        "G73",
        "",
        "Pattern repeating: G73 U(Δi) W(Δk) R(d) / G73 P(ns) Q(nf) U(Δu) W(Δw) F_",
        "仿形粗车循环：G73 U(Δi) W(Δk) R(d) / G73 P(ns) Q(nf) U(Δu) W(Δw) F_",
    ),
    CodeDoc(
        "G74",
        "",
        "End face peck drilling: G74 R(e) / G74 X(U)_ Z(W)_ P(Δi) Q(Δk) R(Δd) F_",
        "端面深孔钻削循环：G74 R(e) / G74 X(U)_ Z(W)_ P(Δi) Q(Δk) R(Δd) F_",
    ),
    CodeDoc(
        "G75",
        "",
        "Outer/inner diameter grooving: G75 R(e) / G75 X(U)_ Z(W)_ P(Δi) Q(Δk) R(Δd) F_",
        "外径/内径切槽循环：G75 R(e) / G75 X(U)_ Z(W)_ P(Δi) Q(Δk) R(Δd) F_",
    ),
    CodeDoc(
        "G76",
        "",
        "Multiple threading: G76 P(m r a) Q(Δdmin) R(d) / G76 X(U)_ Z(W)_ R(i) P(k) Q(Δd) F(L)",
        "复合螺纹切削循环：G76 P(m r a) Q(Δdmin) R(d) / G76 X(U)_ Z(W)_ R(i) P(k) Q(Δd) F(L)",
    ),
    CodeDoc("G80", "canned", "Canned cycle for drilling cancel", "钻孔固定循环取消"),
    CodeDoc("G83", "canned", "Face drilling cycle", "端面钻孔循环"),
    CodeDoc("G84", "canned", "Face tapping cycle", "端面攻丝循环"),
    CodeDoc("G85", "canned", "Face boring cycle", "端面镗孔循环"),
    CodeDoc("G87", "canned", "Side drilling cycle", "侧面钻孔循环"),
    CodeDoc("G88", "canned", "Side tapping cycle", "侧面攻丝循环"),
    CodeDoc("G89", "canned", "Side boring cycle", "侧面镗孔循环"),
    CodeDoc(
        "G90",
        "motion",
        "Outer/inner diameter cutting cycle: G90 X(U)_ Z(W)_ R_ F_",
        "外径/内径车削循环：G90 X(U)_ Z(W)_ R_ F_",
    ),
    CodeDoc(
        "G92",
        "motion",
        "Thread cutting cycle: G92 X(U)_ Z(W)_ R_ F_ (lead)",
        "螺纹切削循环：G92 X(U)_ Z(W)_ R_ F_（导程）",
    ),
    CodeDoc("G94", "motion", "End face turning cycle: G94 X(U)_ Z(W)_ R_ F_", "端面车削循环：G94 X(U)_ Z(W)_ R_ F_"),
    CodeDoc("G96", "spindle", "Constant surface speed control on (S in m/min)", "恒线速度控制（S为米/分）"),
    CodeDoc("G97", "spindle", "Constant surface speed control off (S in rpm)", "取消恒线速度控制（S为转/分）"),
    CodeDoc("G98", "feed", *shared.FEED_PER_MINUTE),
    CodeDoc("G99", "feed", *shared.FEED_PER_REVOLUTION),
)
