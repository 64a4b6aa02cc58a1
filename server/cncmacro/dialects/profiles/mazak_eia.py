"""Mazak Mazatrol Matrix and Smooth controls running EIA/ISO programs: the ``mazak-eia`` profile.

Tables: ``dialects/mazak_eia_data.py``. Mazak's EIA/ISO mode runs the FANUC Macro B language
on a mill, with what sets it apart here: the block form of IF (``IF [cond] THEN`` … ``ELSE`` …
``ENDIF``, ``block_if``), AND and OR also spelled ``&&`` and ``||`` (``logical_symbols``), and the
macro words shortened to their first two letters or more (``WH`` for WHILE, ``GO`` for GOTO,
``keyword_abbreviations``, the same list as FANUC's). Program numbers of up to 8 digits in
``M98 P``. Its alarms have numbers of its own, not listed yet: they are shown without a number
(docs/profiles.md "mazak-eia" says where each fact comes from and what is still to confirm).
"""

from __future__ import annotations

from ..drill_cycles import TAPS_DWELL_AT_BOTTOM
from .fanuc_0i import OTHER_MAKERS, OTHER_MAKERS_TIMING
from .fanuc_0i import PROFILE as FANUC_0I

PROFILE = FANUC_0I.configured(
    **OTHER_MAKERS,  # the FANUC-only rules off (fanuc_0i.py)
    cycle_cancel_clears_dwell=False,  # no source at hand says G80 resets a drilling cycle's P
    drill_cycles=TAPS_DWELL_AT_BOTTOM,  # nor that a tap dwells P again at R, as FANUC's do
    timing=OTHER_MAKERS_TIMING,
    name="mazak-eia",
    title="Mazak EIA/ISO (Matrix, Smooth)",
    title_zh="Mazak EIA/ISO（Matrix、Smooth）",
    summary="Mazak Mazatrol Matrix/Smooth machining centres in EIA/ISO: Macro B with IF..THEN/ELSE/ENDIF, && and ||",
    summary_zh="马扎克 Mazatrol Matrix/Smooth 加工中心 EIA/ISO 程序：宏程序 B，支持 IF..THEN/ELSE/ENDIF、&& 和 ||",
    aliases=("mazak", "mazak-matrix", "mazak-smooth", "mazatrol"),
    data_module="mazak_eia_data",
    block_if=True,
    logical_symbols=True,
    keyword_abbreviations=True,
    # of two profiles that read a file alike, mitsubishi-m70 (block IF alone) is named first
    suggestion_rank=1,
    # the manual's alarm numbers are not yet listed here: alarms are shown without a number
    documented_alarms=frozenset(),
    # G31 in G41/G42: no Mazak source at hand gives an alarm for it; a warning, as on Haas
    skip_compensation_alarm=False,
    program_digits=8,
    m98_program_digits=8,
)
