"""Mitsubishi M70/M80 (M8 series) machining centres, user macro: the ``mitsubishi-m70`` profile.

Tables: ``dialects/mitsubishi_m70_data.py``. The FANUC 0i's macro language and mill (Macro B,
the same G and M codes), with the block form of IF (``IF [cond] THEN`` … ``ELSE`` … ``ENDIF``,
``block_if``), 8-digit program numbers in ``M98 P``, tool compensation at #2001–#2800, and
commons #100–#199 and #500–#999. Its alarms are program errors with numbers of its own (P…),
which the profile does not list yet: they are shown without a number (docs/profiles.md).
"""

from __future__ import annotations

from ..drill_cycles import TAPS_DWELL_AT_BOTTOM
from ..tables import CommonRange
from .fanuc_0i import OTHER_MAKERS, OTHER_MAKERS_TIMING
from .fanuc_0i import PROFILE as FANUC_0I

PROFILE = FANUC_0I.configured(
    **OTHER_MAKERS,  # the FANUC-only rules off (fanuc_0i.py)
    cycle_cancel_clears_dwell=False,  # no source at hand says G80 resets a drilling cycle's P
    drill_cycles=TAPS_DWELL_AT_BOTTOM,  # nor that a tap dwells P again at R, as FANUC's do
    # G00 G81 in one block: the G00 moves, the cycle is cancelled (M700V/M70V programming manual,
    # appendix 2 "Order of G function command priority")
    motion_cancels_cycle_in_block=True,
    timing=OTHER_MAKERS_TIMING,
    name="mitsubishi-m70",
    title="Mitsubishi M70/M80 user macro",
    title_zh="三菱 M70/M80 用户宏程序",
    summary="Mitsubishi M70/M80 (M8 series) machining centres: Macro B with IF..THEN/ELSE/ENDIF blocks",
    summary_zh="三菱 M70/M80（M8 系列）加工中心：用户宏程序 B，支持 IF..THEN/ELSE/ENDIF 块",
    aliases=("m70", "m80", "m800", "meldas", "mitsubishi", "mitsubishi-m80"),
    data_module="mitsubishi_m70_data",
    block_if=True,
    skip_codes=frozenset((31.0, 31.1, 31.2, 31.3)),  # G31.1-G31.3: the multi-step skip (§15.3)
    # §15.2 (6): "When the G31 command is issued during tool radius compensation, program error
    # (P608) will result"; §15.3 (3): G31.1-G31.3 "work the same as the G31 command"
    skip_compensation_alarm=True,
    # the manuals' program errors (P2xx) are not yet listed here: alarms are shown without a number
    documented_alarms=frozenset(),
    # macro words are written in full (no FANUC abbreviations in the M8 manuals at hand)
    keyword_abbreviations=False,
    program_digits=8,
    m98_program_digits=8,
    common_ranges=(CommonRange(100, 199, False), CommonRange(500, 999, True)),
    # length geometry, length wear, radius geometry, radius wear (#2001…, #2201…, #2401…, #2601…)
    tool_offset_bases=(2000, 2200, 2400, 2600),
)
