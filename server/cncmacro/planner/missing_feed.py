"""A cut with no feed, or per revolution with no spindle speed: said once a run.

Under G93 (inverse time feed) F is the block's own: a cut whose block writes no F is timed at the
last F (1/F minutes, as if written again) and is a ``no-feed`` warning too, once a run (Haas: "feedrate
(F) is mandatory for all interpolated motion blocks"; ``inverse_time_cut``).

A cutting move (G01, G02, G03, a cycle's cutting pass, a thread) whose F is 0 because the program
never gave one takes no time here (cycle_time.py), and on a FANUC control stops with alarm PS0011
"feed zero (command)"; but F is modal and kept from one program to the next, so a program that
never writes F may run on a feed an earlier program left (and the GSK980TDi powers on with the
feed of its state parameter No.030: ``Dialect.power_on_feed``). Likewise a feed per revolution (or
a thread) with no S turns nothing: the axes wait for the spindle. Both are a warning
(``no-feed``), once a run each, on the first such cut (docs/semantics.md §10.4).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..bilingual import detail
from ..dialects.alarms import FEED_ZERO

if TYPE_CHECKING:
    from .planner import Planner

# the ``codes`` keys set once a run has been told of a cut with no feed, or with no spindle speed,
# or of a G93 cut without its own F
NO_FEED_GIVEN = "no-feed-noted"
NO_SPEED_GIVEN = "no-speed-noted"
NO_INVERSE_FEED_GIVEN = "no-inverse-feed-noted"
# the note's kind and subject (the diagnostic code the analysis shows it under)
NO_FEED = "no-feed"


def missing_feed(p: Planner, feed: float, per_rev: bool, speed: float) -> bool:
    """Whether a cut at ``feed`` (per revolution, or a thread, at spindle ``speed`` where
    ``per_rev``) cannot be timed and has not been noted yet: no feed, or no speed to turn it by.
    The straight runs leave such a line to the compiled path, which notes it."""
    if feed <= 0.0:
        return NO_FEED_GIVEN not in p.codes
    return per_rev and speed <= 0.0 and NO_SPEED_GIVEN not in p.codes


def note_missing_feed(p: Planner, feed: float, per_rev: bool, speed: float, line: int, thread: bool = False) -> None:
    """Note a cut (a ``thread``'s) on ``line`` with no feed, or per revolution (``per_rev``:
    G95/G99 or a thread) at spindle ``speed`` 0, once a run each (module docstring)."""
    codes = p.codes
    if feed <= 0.0:
        if NO_FEED_GIVEN in codes:
            return
        codes[NO_FEED_GIVEN] = 1.0
        power_on = p.dialect.power_on_feed
        if power_on is None:
            alarm = p.dialect.alarm_titled(FEED_ZERO, 3)
            en = f"the control stops with {alarm} unless an earlier program left a feed (F is modal)"
            zh = f"除非之前的程序留下了进给速度（F 为模态），否则控制器以{alarm.zh}停止"
        else:
            en = (
                f"the control cuts at the feed an earlier program left (F is modal) or, after power-on, "
                f"at the feed of {power_on[0]}"
            )
            zh = f"控制器以之前程序留下的进给速度（F 为模态）切削，上电后则以{power_on[1]}设定的进给速度切削"
        what, what_zh = (
            ("a thread with no lead", "没有导程的螺纹") if thread else ("a cut with no feed", "无进给速度的切削")
        )
        p.host.note(NO_FEED, detail(
            f"{what}: this program gives no F before it (or F0), so the cycle time counts the cut as taking no "
            f"time; {en}; give F before the cut",
            f"{what_zh}：本程序在此之前没有指令 F（或为 F0），加工时间按该切削不耗时计算；{zh}；请在切削前指令 F"),
            line, NO_FEED)  # fmt: skip
        return
    if not per_rev or speed > 0.0 or NO_SPEED_GIVEN in codes:
        return
    codes[NO_SPEED_GIVEN] = 1.0
    what, what_zh = ("a thread", "螺纹") if thread else ("a feed per revolution", "每转进给")
    p.host.note(NO_FEED, detail(
        f"{what} with no spindle speed: the tool moves by the turns of the spindle and this program gives no S "
        "(or S0) before it, so the cycle time counts the cut as taking no time; on the control the axes wait for "
        "the spindle to turn, unless an earlier program left it turning; give S before the cut",
        f"没有主轴转速的{what_zh}：刀具随主轴的旋转移动，而本程序在此之前没有指令 S（或为 S0），"
        "加工时间按该切削不耗时计算；除非之前的程序使主轴保持旋转，否则控制器上各轴等待主轴旋转；"
        "请在切削前指令 S"), line, NO_FEED)  # fmt: skip


def inverse_time_cut(p: Planner, feed: float, line: int, length: float = 0.0) -> float:
    """The seconds of a cut on ``line``, ``length`` mm long, under G93 at inverse time ``feed``
    (cycle_time.py's ``inverse_time_seconds``, which clamps it at the highest cutting feed),
    noting once a run a block that writes no F of its own (timed at the last F) and, as any cut,
    one with no feed at all."""
    codes = p.codes
    if feed <= 0.0:
        note_missing_feed(p, feed, False, 0.0, line)
    elif not p.block_feed and NO_INVERSE_FEED_GIVEN not in codes:
        codes[NO_INVERSE_FEED_GIVEN] = 1.0
        p.host.note(NO_FEED, detail(
            f"a G93 cut with no F in its block: under inverse time feed F is each block's own (1/F minutes for "
            f"the block) and the control requires it in every block that cuts; the cycle time takes the last "
            f"F{feed:g} ({60.0 / feed:g} s); give F in every G93 cut",
            f"G93 下本切削程序段没有 F：反比时间进给的 F 只对本程序段有效（程序段用时 1/F 分钟），"
            f"系统要求每个切削程序段都指令 F；加工时间按上一个 F{feed:g}（{60.0 / feed:g} 秒）计算；"
            f"请在每个 G93 切削程序段中指令 F"),
            line, NO_FEED)  # fmt: skip
    return p.times.inverse_time_seconds(feed, length)
