"""FANUC 0i-TF lathe data (G-code system A): the system variables, G codes and M codes of a 0i
lathe control, for the ``fanuc-0i-lathe`` profile.

The system variables and M codes are the 0i's (``fanuc_data``). The G codes are the lathe's
system A list: ``G50`` sets coordinates and clamps the spindle, ``G90``/``G92``/``G94`` are the
single fixed cycles, ``G70``–``G76`` the multiple repetitive cycles, ``G98``/``G99`` feed per
minute and per revolution; there is no G90/G91 distance group, as U and W move incrementally.
A code's ``group`` is its name in ``MODAL_GROUPS``, or empty for a one-shot code.
"""

from __future__ import annotations

from . import fanuc_data as fanuc
from . import shared_data as shared
from .tables import CodeDoc, SystemVariable

SYSTEM_VARIABLES: tuple[SystemVariable, ...] = fanuc.SYSTEM_VARIABLES
M_CODES: tuple[CodeDoc, ...] = fanuc.M_CODES

G_CODES: tuple[CodeDoc, ...] = (
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
