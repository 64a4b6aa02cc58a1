"""What each letter of a FANUC mill's drilling canned cycles means: the table of cycle words of the
``fanuc-0i`` and ``fanuc-30i`` profiles (``Dialect.cycle_words``, records in ``cycle_words.py``),
for the editor's hover, signature help and completion. On a mill G73, G74 and G76 drill, tap and
bore; the lathe's G73–G76 are other cycles (``lathe_cycle_words.py``).

Sources: FANUC Series 0i-MF and 30i-B operator's manuals, "Canned cycle for drilling": the format
of each code (``G73 X_ Y_ Z_ R_ Q_ F_ K_``, ``G74 X_ Y_ Z_ R_ P_ F_ K_``, ``G76 X_ Y_ Z_ R_ Q_
P_ F_ K_``, …) and what its letters mean; what each does is ``drill_cycles.py``.
"""

from __future__ import annotations

from dataclasses import replace

from .cycle_words import CycleWord, CycleWords, by_code, one_block

w = CycleWord

X_HOLE = w("X", "", "X of the hole", "孔位X坐标")
Y_HOLE = w("Y", "", "Y of the hole", "孔位Y坐标")
Z_BOTTOM = w("Z", "", "the bottom of the hole", "孔底位置")
R_POINT = w("R", "", "the R point, where the cut starts", "R点（开始切削的位置）")
PECK = w("Q", "", "depth of each peck", "每次切削深度")
DWELL = w("P", "", "dwell at the bottom (ms)", "孔底暂停时间（毫秒）")
# P of a tap that dwells again at the R point on its way out (``DrillCycle.dwell_at_r``: FANUC's
# "P_ : Dwell time at the bottom of the hole and at point R when a return is made")
DWELL_AT_BOTTOM_AND_R = w("P", "", "dwell at the bottom of the hole and again at the R point on the way out (ms)",
                          "孔底及返回到R点时的暂停时间（毫秒）")  # fmt: skip
FEED = w("F", "", "cutting feed", "切削进给速度")
TAP_FEED = w("F", "", "feed: the pitch × the spindle speed", "进给速度：螺距×主轴转速")
SHIFT = w("Q", "", "shift off the wall at the bottom before coming out", "孔底退离孔壁的偏移量")
REPEATS = w("K", "", "number of repeats", "重复次数")
HOLE = (X_HOLE, Y_HOLE, Z_BOTTOM, R_POINT)

FANUC_DRILL_CYCLE_WORDS: dict[float, CycleWords] = by_code(
    one_block("G73", *HOLE, PECK, FEED, REPEATS),
    one_block("G74", *HOLE, DWELL, TAP_FEED, REPEATS),
    one_block("G76", *HOLE, SHIFT, DWELL, FEED, REPEATS),
    one_block("G81", *HOLE, FEED, REPEATS),
    one_block("G82", *HOLE, DWELL, FEED, REPEATS),
    one_block("G83", *HOLE, PECK, FEED, REPEATS),
    one_block("G84", *HOLE, DWELL, TAP_FEED, REPEATS),
    one_block("G85", *HOLE, FEED, REPEATS),
    one_block("G86", *HOLE, FEED, REPEATS),
    one_block(
        "G87",
        X_HOLE,
        Y_HOLE,
        w("Z", "", "where the bore ends, bored upwards", "镗孔终点（向上镗削）"),
        w("R", "", "the R point, below the work", "R点（在工件下方）"),
        SHIFT,
        DWELL,
        FEED,
        REPEATS,
    ),
    one_block("G88", *HOLE, DWELL, FEED, REPEATS),
    one_block("G89", *HOLE, DWELL, FEED, REPEATS),
)


def dwelling_at_r(words: CycleWords) -> CycleWords:
    """``words`` with P read as the dwell at the bottom and again at the R point: the table's
    words of a tap whose cycle dwells at R on this profile (``Dialect.cycle_words_of``), whatever
    the table, shared with profiles whose taps dwell at the bottom only, says of P."""
    forms = tuple(
        replace(form, words=tuple(DWELL_AT_BOTTOM_AND_R if word.letter == "P" else word for word in form.words))
        for form in words.forms
    )
    return replace(words, forms=forms)
