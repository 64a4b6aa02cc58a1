"""Mitsubishi M70/M80 (M8 series, machining centres) user macro: the tables of the ``mitsubishi-m70``
profile (``dialects/profiles/mitsubishi_m70.py``).

The M8 series runs the FANUC Macro B language, so where it reads a number the way a FANUC 0i does
the row is ``fanuc_data``'s own: the timers and clock (#3001, #3002, #3011, #3012), #3003/#3004,
#3006, the parts counters, the modal information (#4001…, #4101…), the positions (#5001…, the
skip positions #5061…, the tool length offset #5081…) and the work offsets (#5201…, G54.1 P1–P48
at #7001…). What is its own (docs/profiles.md "mitsubishi-m70" says where each comes from and
what is still to be confirmed):

* 32 interface signals each way, bit by bit (#1000–#1031, #1100–#1131), and the same signals as
  32-bit words (#1032–#1035, #1132–#1135);
* the tool compensation tables by their short numbers, 200 offsets each: tool length geometry
  #2001–#2200 (``#[2000+n]``), length wear #2201–#2400, radius geometry #2401–#2600 and radius
  wear #2601–#2800; so FANUC's #2500–#2806 work offset short numbers are not here;
* #3000 raises the control's macro alarm with the program's message.
"""

from __future__ import annotations

from . import fanuc_data as fanuc
from .shared_data import with_m98_count_in_l, with_macro_alarm_shown
from .tables import CodeDoc, SystemVariable

# ---------------------------------------------------------------------------------------------
# interface signals: 32 bits each way, and four 32-bit words each way


def _bits(first: int, access: str, kind: str, prefix: str, en: str, zh: str) -> tuple[SystemVariable, ...]:
    kind_zh = "输入" if kind == "input" else "输出"
    return tuple(
        SystemVariable(first + bit, first + bit, access, "signals",
                       f"User macro {kind} signal {bit} ({prefix}{bit}){en}",
                       f"用户宏程序{kind_zh}信号{bit}（{prefix}{bit}）{zh}")
        for bit in range(32)
    )  # fmt: skip


def _words(first: int, access: str, kind: str, en: str, zh: str) -> tuple[SystemVariable, ...]:
    kind_zh = "输入" if kind == "input" else "输出"
    return tuple(
        SystemVariable(first + k, first + k, access, "signals",
                       f"User macro {kind} signals, word {k + 1}: 32 signals as one number; {en}",
                       f"用户宏程序{kind_zh}信号第{k + 1}组：32个信号作为一个数，{zh}")
        for k in range(4)
    )  # fmt: skip


_SIGNALS: tuple[SystemVariable, ...] = (
    *_bits(1000, "r", "input", "UI", ", from the PLC to the macro; reads 0 or 1", "，由PLC送给宏程序，读出为0或1"),
    *_words(1032, "r", "input", "read at once", "一次读出"),
    *_bits(1100, "rw", "output", "UO", ", from the macro to the PLC; write 0 or 1, reading gives the state "
           "last written", "，由宏程序送给PLC，写入0或1，读出为当前状态"),
    *_words(1132, "rw", "output", "written at once", "一次写出"),
)  # fmt: skip

# ---------------------------------------------------------------------------------------------
# tool compensation: length and radius, geometry and wear, 200 offsets each


def _offsets(first: int, en: str, zh: str, g10: str) -> SystemVariable:
    return SystemVariable(
        first,
        first + 199,
        "rw",
        "tool",
        f"Tool compensation {{index}}: {en}; G10 {g10} P{{index}} R_ sets it too",
        f"刀具补偿{{index}}号：{zh}；也可用G10 {g10} P{{index}} R_设定",
        "mm",
    )


_TOOL_OFFSETS: tuple[SystemVariable, ...] = (
    _offsets(2001, "tool length geometry (shape), which G43 H{index} adds with its wear",
             "刀长形状补偿值，G43 H{index}时与其磨损值一起加上", "L10"),
    _offsets(2201, "tool length wear", "刀长磨损补偿值", "L11"),
    _offsets(2401, "tool radius geometry (shape), which G41/G42 D{index} offsets by with its wear",
             "刀具半径形状补偿值，G41/G42 D{index}时与其磨损值一起偏移", "L12"),
    _offsets(2601, "tool radius wear", "刀具半径磨损补偿值", "L13"),
)  # fmt: skip

# ---------------------------------------------------------------------------------------------
# macro alarm, clocks, control, counters: FANUC's rows, #3000 said as this control shows it

_CONTROL: tuple[SystemVariable, ...] = with_macro_alarm_shown(fanuc._CONTROL)

# the work offsets without FANUC's #2500-#2806 short numbers, which are tool offsets here
_WORK_OFFSETS: tuple[SystemVariable, ...] = tuple(row for row in fanuc._WORK_OFFSETS if row.first >= 5000)

SYSTEM_VARIABLES: tuple[SystemVariable, ...] = (
    *_SIGNALS,
    *_TOOL_OFFSETS,
    *_CONTROL,
    *fanuc._MODAL,
    *fanuc._POSITIONS,
    *_WORK_OFFSETS,
)

# ---------------------------------------------------------------------------------------------
# G and M codes: the FANUC mill's, M98 reading P as the whole program number


# the multi-step skip (M700V/M70V programming manual §15.3 "Multi-step Skip Function; G31.n"):
# G31.1, G31.2, G31.3 X_ Y_ Z_ F_, each a G31 on its own skip signal
G_CODES: tuple[CodeDoc, ...] = (
    *fanuc.G_CODES,
    *(
        CodeDoc(f"G31.{n}", "", f"Multi-step skip {n}: a G31 that stops on skip signal {n}",
                f"多段跳转{n}：在跳转信号{n}接通时停止的G31")
        for n in (1, 2, 3)
    ),
)  # fmt: skip
# not FANUC's M29 row (its parameter 5210): no source at hand gives this control's tapping M code
M_CODES: tuple[CodeDoc, ...] = with_m98_count_in_l(tuple(c for c in fanuc.M_CODES if c.code != "M29"))
