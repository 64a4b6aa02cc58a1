"""What each letter of a lathe's cycle blocks means, per control: the tables of cycle words of
the ``fanuc-0i-lathe`` and ``gsk980tdi`` profiles (``Dialect.cycle_words``, records in
``cycle_words.py``), for the editor's hover, signature help and completion.

Sources: FANUC Series 0i-TF operator's manual (G-code system A), "Multiple repetitive cycle
(G70–G76)", "Single fixed cycle (G90, G92, G94)", "Thread cutting (G32)", "Coordinate system
setting (G50)", "Constant surface speed control (G96, G97)"; GSK980TDi programming manual §3.18
(G50), §3.22 (G90, G94), §3.23.1–3.23.6 (G71, G72, G73, G70, G74, G75), §3.24.1 (G32), §3.24.9
(G92), §3.24.12 (G76), §3.25 (G96, G97), §3.23.9 and §3.24.6 (the drilling cycles and rigid
taps; FANUC's "canned cycle for drilling"). Where they differ (docs/profiles.md, "Cycle words"):

* the unit of G74/G75's P(Δi) Q(Δk) and G76's Q(Δdmin), P(k), Q(Δd): FANUC takes them in least
  input increments without a decimal point (µm on a metric machine); the GSK980TDi in least
  input increments or in mm, as its state parameter 182.7 chooses;
* F, S and T of G71–G73: FANUC reads them in the second block; the GSK980TDi in either block, and
  its second block of G71/G72 takes K (check the shape is monotone) and J (type II: one more pass
  along the rough contour);
* the GSK980TDi threads take I (threads per inch) in place of F, and its G50 takes U and W;
  its G76 (first block) and G92 take the run-out J and K, and G92 the starts L (§3.24.12,
  §3.24.9), so its lead is written F alone, not FANUC's F(L).
"""

from __future__ import annotations

from .cycle_words import CycleWord, CycleWords, by_code, one_block, two_blocks

w = CycleWord

# ---------------------------------------------------------------- words several codes share
X_END = w("X", "", "X of the end point (a diameter)", "终点的X坐标（直径值）")
Z_END = w("Z", "", "Z of the end point", "终点的Z坐标")
U_END = w("U", "", "end point: X from the start point, incremental (a diameter)", "终点相对起点的X增量（直径值）")
W_END = w("W", "", "end point: Z from the start point, incremental", "终点相对起点的Z增量")
END_POINT = (X_END, Z_END, U_END, W_END)
FEED = w("F", "", "cutting feed", "切削进给速度")
ROUGH_FEED = w(
    "F", "", "roughing feed (an F in the shape counts only for G70)", "粗车进给速度（形状中的F只在G70中有效）"
)
ROUGH_SPEED = w("S", "", "spindle speed while roughing", "粗车时的主轴转速")
ROUGH_TOOL = w("T", "", "tool and offset while roughing", "粗车时的刀具及刀补号")
SHAPE_FIRST = w("P", "ns", "sequence number N of the finishing shape's first block", "精加工形状第一个程序段的顺序号N")
SHAPE_LAST = w("Q", "nf", "sequence number N of the finishing shape's last block", "精加工形状最后一个程序段的顺序号N")
ALLOWANCE_X = w("U", "Δu", "finishing allowance in X (a diameter, signed)", "X方向精加工余量（直径值，带符号）")
ALLOWANCE_Z = w("W", "Δw", "finishing allowance in Z (signed)", "Z方向精加工余量（带符号）")
MONOTONE = w("K", "", "K1: check that the shape is monotone", "K1：检查精加工形状的单调性")
TYPE_II_PASS = w("J", "", "J1: one more pass along the rough contour (type II)", "J1：沿粗车轮廓再运行一次（II型）")
RETRACT_E = w(
    "R", "e", "retract after each cut (at 45°), kept until changed", "每次切削后的退刀量（45°退出），指定后保持"
)
LEAD = w("F", "L", "lead of the thread (per spindle turn)", "螺纹导程（主轴每转）")
THREADS_PER_INCH = w("I", "", "threads per inch, in place of F", "每英寸螺纹牙数（代替F）")
# the GSK980TDi writes the lead F alone: its L is a word of its own, the starts of G92/G78
GSK_LEAD = w("F", "", "lead of the thread (per spindle turn)", "螺纹导程（主轴每转）")
# GSK980TDi G76's first block and G92: the thread's run-out, "J：螺纹退尾时在短轴方向的移动量…K：螺纹退尾
# 时在长轴方向的长度" (§3.24.12; §3.24.9, where both are modal), and G92's "L：多头螺纹的头数…1～99"
GSK_RUN_OUT_J = w(
    "J",
    "",
    "run-out: the move along the short axis as the thread ends (no sign; a radius when it is X)",
    "螺纹退尾时在短轴方向的移动量（不带方向；短轴为X轴时为半径值）",
)
GSK_RUN_OUT_K = w(
    "K",
    "",
    "run-out: its length along the long axis (no sign); left out: as J",
    "螺纹退尾时在长轴方向的长度（不带方向）；省略时按K=J",
)
GSK_STARTS = w("L", "", "starts of the thread, 1-99 (left out: one), kept", "多头螺纹的头数，1～99（省略为单头），模态")

# the unit of the words given without a decimal point (G74/G75 P Q, G76 Q P)
FANUC_INCREMENTS = (
    "in least input increments, no decimal point (µm on a metric machine)",
    "以最小输入增量为单位，不带小数点（公制机床为µm）",
)
GSK_INCREMENTS = (
    "in least input increments, or in mm as state parameter 182.7 chooses",
    "单位为最小输入增量，或由状态参数№182.7选择为mm",
)


def _in(unit: tuple[str, str], letter: str, symbol: str, en: str, zh: str) -> CycleWord:
    """A word whose value is given in ``unit`` (the profile's)."""
    return w(letter, symbol, f"{en}, {unit[0]}", f"{zh}，{unit[1]}")


def _thread_end_block(unit: tuple[str, str], lead: CycleWord = LEAD) -> tuple[CycleWord, ...]:
    """The second block of G76 (and the GSK980TDi's G78): the end point, the taper, the thread's
    height, the first cut's depth and the lead."""
    return (
        *END_POINT,
        w(
            "R",
            "i",
            "taper: the thread's radius at its start minus at its end (0: straight)",
            "锥度：螺纹起点与终点的半径差（0为直螺纹）",
        ),
        _in(unit, "P", "k", "height of the thread (a radius)", "螺纹牙高（半径值）"),
        _in(unit, "Q", "Δd", "depth of the first cut (a radius)", "第一次切削深度（半径值）"),
        lead,
    )


def _stock_removal(
    extra_first: tuple[CycleWord, ...], extra_second: tuple[CycleWord, ...], flags: bool
) -> list[CycleWords]:
    """G71, G72, G73 and G70: the first blocks with ``extra_first``, the second blocks with
    ``extra_second`` (and, for G71/G72 with ``flags``, K and J)."""
    second = (SHAPE_FIRST, SHAPE_LAST, ALLOWANCE_X, ALLOWANCE_Z, *extra_second)
    flagged = (*second, MONOTONE, TYPE_II_PASS) if flags else second
    g71 = (
        w(
            "U",
            "Δd",
            "depth of each cut (a radius, no sign), kept until changed",
            "每次切深（半径值，无符号），指定后保持",
        ),
        RETRACT_E,
    )
    g72 = (
        w("W", "Δd", "depth of each cut along Z (no sign), kept until changed", "Z向每次切深（无符号），指定后保持"),
        RETRACT_E,
    )
    g73 = (
        w(
            "U",
            "Δi",
            "relief in X: how far out the first pass runs (a radius, signed)",
            "X向退刀量：第一刀离精加工形状的距离（半径值，带符号）",
        ),
        w(
            "W",
            "Δk",
            "relief in Z: how far out the first pass runs (signed)",
            "Z向退刀量：第一刀离精加工形状的距离（带符号）",
        ),
        w("R", "d", "number of passes", "粗车次数"),
    )
    return [
        two_blocks("G71", (*g71, *extra_first), flagged, "PQ", True),
        two_blocks("G72", (*g72, *extra_first), flagged, "PQ", True),
        two_blocks("G73", (*g73, *extra_first), second, "PQ", True),
        one_block(
            "G70",
            w(
                "P",
                "ns",
                "sequence number N of the shape's first block; the shape runs with its own F, S, T",
                "形状第一个程序段的顺序号N；形状按其自身的F、S、T运行",
            ),
            SHAPE_LAST,
        ),
    ]


def _grooving_and_threading(
    unit: tuple[str, str],
    lead: CycleWord = LEAD,
    g76_first_extra: tuple[CycleWord, ...] = (),
    g76_second_extra: tuple[CycleWord, ...] = (),
) -> list[CycleWords]:
    """G74, G75, G76 with the unit of their P and Q, the thread's lead word and G76's own words
    of a profile."""
    g74 = (
        *END_POINT,
        _in(unit, "P", "Δi", "X step between the passes (no sign)", "每次循环的X向移动量（无符号）"),
        _in(unit, "Q", "Δk", "depth of each peck along Z (no sign)", "Z向每次断续进刀量（无符号）"),
        w(
            "R",
            "Δd",
            "relief at the bottom of each pass (leave it out for a blind hole)",
            "切削到终点后的退刀量（切盲孔时省略）",
        ),
        FEED,
    )
    g75 = (
        *END_POINT,
        _in(unit, "P", "Δi", "depth of each peck along X (no sign)", "X向每次断续进刀量（无符号）"),
        _in(unit, "Q", "Δk", "Z step between the passes (no sign)", "每次循环的Z向移动量（无符号）"),
        w(
            "R",
            "Δd",
            "relief at the bottom of each pass (leave it out for a plain groove)",
            "切削到终点后的退刀量（切槽时省略）",
        ),
        FEED,
    )
    g76_first = (
        w(
            "P",
            "m r a",
            "six digits: finishing passes m, chamfer r (tenths of the lead), tool angle a (degrees), e.g. P021060",
            "六位数：精车次数m、退尾量r（导程的0.1倍）、刀尖角度a（度），如P021060",
        ),
        _in(unit, "Q", "Δdmin", "minimum depth of cut (a radius)", "最小切削深度（半径值）"),
        w("R", "d", "finishing allowance (a radius)", "精车余量（半径值）"),
        *g76_first_extra,
    )
    g76_second = (*_thread_end_block(unit, lead), *g76_second_extra)
    return [
        two_blocks(
            "G74",
            (w("R", "e", "return after each peck along Z, kept until changed", "Z向每次进刀后的退刀量，指定后保持"),),
            g74,
            "XZUW",
            False,
        ),
        two_blocks(
            "G75",
            (w("R", "e", "return after each peck along X, kept until changed", "X向每次进刀后的退刀量，指定后保持"),),
            g75,
            "XZUW",
            False,
        ),
        two_blocks("G76", g76_first, g76_second, "XZUW", False),
    ]


def _gsk_enhanced_thread(unit: tuple[str, str]) -> CycleWords:
    """GSK980TDi G78 (§3.24.13): G76's words, its first block's P and D otherwise, with J, K, L, E."""
    first = (
        w(
            "P",
            "m r a",
            "six digits: infeed m (0 equal depths, 1 decreasing as G76), cutting-in r (0 along the middle, "
            "1 the left flank, 2 the right flank, 3 both in turn), tool angle a (degrees), e.g. P010060",
            "六位数：切深方式m（0等距离进刀，1递减式进刀同G76）、切入方式r（0沿牙型中线，1沿左边，2沿右边，"
            "3交错切入）、刀尖角度a（度），如P010060",
        ),
        _in(unit, "Q", "Δdmin", "minimum depth of cut (a radius)", "最小切削量（半径值）"),
        w("R", "d", "finishing allowance (a radius)", "螺纹精车切削量（半径值）"),
        w("J", "", "pull-out along the short axis (no sign)", "退尾时短轴方向的移动量（无符号）"),
        w("K", "", "pull-out length along the long axis (no sign)", "退尾时长轴方向的长度（无符号）"),
        w("D", "", "finishing passes, 0-99", "精车次数，0～99"),
        w("L", "", "starts of the thread, 1-99", "螺纹头数，1～99"),
        w("E", "", "screw-in distance along X (a radius)", "X向旋进距离（半径值）"),
    )
    second = (*_thread_end_block(unit, GSK_LEAD), THREADS_PER_INCH)
    return two_blocks("G78", first, second, "XZUW", False)


def _single_cycles(
    thread_extra: tuple[CycleWord, ...], lead: CycleWord = LEAD, g92_extra: tuple[CycleWord, ...] = ()
) -> list[CycleWords]:
    """G90, G92, G94 and G32; a thread takes ``thread_extra`` too, G92 ``g92_extra``."""
    taper_x = w(
        "R",
        "",
        "taper: X at the start of the cut minus at its end (a radius, signed); 0 or none: straight",
        "锥度：切削起点与终点的X坐标差（半径值，带符号）；0或省略为圆柱",
    )
    taper_z = w(
        "R",
        "",
        "taper: Z at the start of the cut minus at its end (signed); 0 or none: a flat face",
        "锥度：切削起点与终点的Z坐标差（带符号）；0或省略为平端面",
    )
    return [
        one_block("G90", *END_POINT, taper_x, FEED),
        one_block("G92", *END_POINT, taper_x, lead, *thread_extra, *g92_extra),
        one_block("G94", *END_POINT, taper_z, FEED),
        one_block("G32", *END_POINT, lead, *thread_extra),
    ]


def _fanuc_drilling() -> list[CycleWords]:
    """The 0i-TF's drilling cycles (G-code system A, "canned cycle for drilling"): on the face
    along Z (G83, G84, G85), on the side along X (G87, G88, G89); docs/semantics.md §10.3."""
    c = w("C", "", "angle of the hole (the C axis, degrees)", "孔的角度位置（C轴，度）")
    h = w("H", "", "angle of the hole, incremental (the C axis, degrees)", "孔的角度位置增量（C轴，度）")
    r = w("R", "", "from the initial level to the R point, signed (along X a radius)",
          "从初始平面到R点的距离，带符号（沿X轴为半径值）")  # fmt: skip
    q = _in(FANUC_INCREMENTS, "Q", "", "depth of each peck", "每次钻削深度")
    pause = w("P", "", "dwell at the bottom (ms)", "孔底暂停时间（毫秒）")
    feed = w("F", "", "cutting feed (a tap: its lead under G99)", "切削进给速度（攻丝：G99时为螺距）")
    k = w("K", "", "number of repeats (0: keep the data, drill nothing)", "重复次数（0：只保存数据不钻孔）")
    face = (w("X", "", "X of the hole (a diameter)", "孔位置的X坐标（直径值）"), c,
            w("Z", "", "Z of the bottom of the hole", "孔底的Z坐标"),
            w("W", "", "bottom of the hole: Z from the R point, incremental", "孔底相对R点的Z增量"), h)  # fmt: skip
    side = (w("Z", "", "Z of the hole", "孔位置的Z坐标"), c,
            w("X", "", "X of the bottom of the hole (a diameter)", "孔底的X坐标（直径值）"),
            w("U", "", "bottom of the hole: X from the R point, incremental (a diameter)",
              "孔底相对R点的X增量（直径值）"), h)  # fmt: skip
    return [
        one_block("G83", *face, r, q, pause, feed, k),
        one_block("G84", *face, r, pause, feed, k),
        one_block("G85", *face, r, pause, feed, k),
        one_block("G87", *side, r, q, pause, feed, k),
        one_block("G88", *side, r, pause, feed, k),
        one_block("G89", *side, r, pause, feed, k),
    ]


def _gsk_drilling() -> list[CycleWords]:
    """The GSK980TDi's drilling cycles (§3.23.9) and rigid taps (§3.24.6): from where the hole is
    positioned, no R point; docs/semantics.md §10.3."""
    c = w("C", "", "angle of the hole (the C axis, degrees)", "钻孔位置（C轴，度）")
    q = _in(GSK_INCREMENTS, "Q", "", "depth of each peck (a radius), kept", "每次进刀量（半径值），模态")
    retract = w("R", "", "retract after each peck (mm, a radius; 1 when left out), kept",
                "每次进刀后的退刀量（mm，半径值；省略时为1），模态")  # fmt: skip
    pause = w("P", "", "dwell at the bottom (ms), kept", "孔底暂停时间（毫秒），模态")
    k = w(
        "K", "", "number of holes drilled (U, H: each at the next position)", "钻孔重复次数（增量编程时在不同位置钻孔）"
    )
    j = w("J", "", "J0: high-speed pecks (retract R); J1: back to the start after each peck",
          "J0：高速深孔钻（退R）；J1：每次退回钻孔起始位置")  # fmt: skip
    lead = w("F", "", "lead of the tap (per spindle turn, whatever G98/G99)", "螺纹导程（主轴每转，与G98/G99无关）")
    face_hole = (w("X", "", "X of the hole (a diameter)", "钻孔位置X坐标（直径值）"), c,
                 w("Z", "", "Z of the bottom of the hole", "孔底位置Z坐标"))  # fmt: skip
    side_hole = (w("Z", "", "Z of the hole", "钻孔位置Z坐标"), c,
                 w("X", "", "X of the bottom of the hole (a diameter)", "孔底位置X坐标（直径值）"))  # fmt: skip
    feed = w("F", "", "cutting feed", "切削进给速度")
    return [
        one_block("G83", *face_hole, pause, q, retract, feed, k, j),
        one_block("G87", *side_hole, pause, q, retract, feed, k, j),
        one_block("G84", *face_hole, pause, lead, THREADS_PER_INCH, k),
        one_block("G88", *side_hole, pause, lead, THREADS_PER_INCH, k),
    ]


def _spindle(g50_extra: tuple[CycleWord, ...]) -> list[CycleWords]:
    """G50 (coordinates, spindle clamp), G96, G97."""
    return [
        one_block(
            "G50",
            w(
                "X",
                "",
                "the X the tool is at from now on (a diameter): sets the work coordinates",
                "设定刀具当前位置的X坐标（直径值），建立工件坐标系",
            ),
            w(
                "Z",
                "",
                "the Z the tool is at from now on: sets the work coordinates",
                "设定刀具当前位置的Z坐标，建立工件坐标系",
            ),
            *g50_extra,
            w(
                "S",
                "",
                "maximum spindle speed (rev/min), the clamp of constant surface speed (G96)",
                "主轴最高转速限制（转/分），在恒线速（G96）时有效",
            ),
        ),
        one_block("G96", w("S", "", "surface speed (m/min; ft/min in inch)", "切削线速度（米/分；英制为英尺/分）")),
        one_block("G97", w("S", "", "spindle speed (rev/min)", "主轴转速（转/分）")),
    ]


FANUC_LATHE_CYCLE_WORDS: dict[float, CycleWords] = by_code(
    *_stock_removal((), (ROUGH_FEED, ROUGH_SPEED, ROUGH_TOOL), flags=False),
    *_grooving_and_threading(FANUC_INCREMENTS),
    *_single_cycles(()),
    *_fanuc_drilling(),
    *_spindle(()),
)

_EITHER_BLOCK = (
    w(
        "F",
        "",
        "roughing feed (here or in the other block; an F in the shape counts only for G70)",
        "粗车进给速度（可在任一程序段中；形状中的F只在G70中有效）",
    ),
    w("S", "", "spindle speed while roughing (here or in the other block)", "粗车时的主轴转速（可在任一程序段中）"),
    w(
        "T",
        "",
        "tool and offset while roughing (here or in the other block)",
        "粗车时的刀具及刀补号（可在任一程序段中）",
    ),
)

GSK980TDI_CYCLE_WORDS: dict[float, CycleWords] = by_code(
    *_stock_removal(_EITHER_BLOCK, _EITHER_BLOCK, flags=True),
    *_grooving_and_threading(GSK_INCREMENTS, GSK_LEAD, (GSK_RUN_OUT_J, GSK_RUN_OUT_K), (THREADS_PER_INCH,)),
    _gsk_enhanced_thread(GSK_INCREMENTS),
    *_single_cycles((THREADS_PER_INCH,), GSK_LEAD, (GSK_RUN_OUT_J, GSK_RUN_OUT_K, GSK_STARTS)),
    *_gsk_drilling(),
    *_spindle(
        (
            w("U", "", "change of the tool's X coordinate (a diameter)", "刀具当前位置X坐标的增量（直径值）"),
            w("W", "", "change of the tool's Z coordinate", "刀具当前位置Z坐标的增量"),
        )
    ),
)
