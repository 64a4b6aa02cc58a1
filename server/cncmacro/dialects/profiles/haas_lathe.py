"""Haas lathes (ST and SL series, Haas control): the ``haas-lathe`` profile.

Tables: ``dialects/haas_lathe_data.py``. The macro language is the Haas mill's (``haas``): its
commons, five-digit programs, M97 local calls, ``[cond] M99 P``, IF governing its block, G154
P1-P99 and no alarm numbers. What a lathe changes is the NC side, as on ``fanuc-0i-lathe``: X is
a diameter and U and W move incrementally, ``G50`` sets coordinates (and with S clamps the
spindle), ``G90``/``G92``/``G94`` are the single cycles and ``G70``-``G76`` the multiple
repetitive cycles, the plane is G18 and ``G99`` (feed per revolution) is in force at power-on.
Haas's own: the tool offsets at #2001... (geometry) and #2701... (wear), the cycles written in one
block (``G71 P Q U W D``, ``G76 X Z K D A``, ``G75 X Z I K``) and the tapers I and K of the single
cycles (docs/profiles.md, "haas-lathe: sources and decisions").
"""

from __future__ import annotations

from dataclasses import replace

from ..haas_lathe_data import AXES, CYCLE_WORDS, LATHE_OFFSETS
from ..lathe_cycle_rules import FANUC_LATHE_RULES
from ..timing import Timing
from ..turning_cycles import LATHE_SINGLE_CYCLES, LatheCycles
from .haas import PROFILE as HAAS_MILL

# G32 is the only thread code of a move (no G34); the cycles take Haas's letters
HAAS_LATHE_CYCLES = LatheCycles(
    thread_codes=frozenset({32.0}),
    one_block=True,
    taper_letters={90.0: "I", 92.0: "I", 94.0: "K"},
    groove_letters=("I", "K"),
)

# G76's tool angle is A, any of 0-120 degrees, not the FANUC first block's fixed list
HAAS_LATHE_RULES = replace(FANUC_LATHE_RULES, tool_angles=None, thread_codes=frozenset({32.0, 76.0, 92.0}))

PROFILE = replace(
    HAAS_MILL,
    name="haas-lathe",
    title="Haas lathe",
    title_zh="Haas 车床",
    summary="Haas lathes (ST, SL series): the Haas macro language with G71/G76 in one block, offsets at #2001/#2701",
    summary_zh="Haas 车床（ST、SL 系列）：Haas 宏程序，G71/G76 单段格式，刀补在 #2001/#2701",
    aliases=("haas-st", "haas-sl", "haas-turn", "haas-ngc-lathe"),
    data_module="haas_lathe_data",
    lathe=True,
    lathe_offsets=LATHE_OFFSETS,
    axes=AXES,
    modal_defaults={"plane": 18.0, "feed": 99.0},
    unsimulated_codes=frozenset(),  # the mill's G12/G13, G47, G70-G72, G150 are not the lathe's codes
    coordinate_setting_code=50.0,
    cycle_codes=frozenset({70.0, 71.0, 72.0, 73.0, 74.0, 75.0, 76.0, 90.0, 92.0, 94.0}),
    # the mill's G28 rules (96-8000) are not taken over: no Haas lathe source at hand gives them
    reference_return_all_axes=False,
    reference_return_cancels_tool_offset=False,
    drill_cycles={},
    single_cycles=LATHE_SINGLE_CYCLES,
    lathe_cycles=HAAS_LATHE_CYCLES,
    cycle_words=CYCLE_WORDS,
    cycle_rules=HAAS_LATHE_RULES,
    g10_tool_l_aliases=(),
    # G112/G113 are the XY-to-XC interpolation on a lathe: extra offsets by G154 P1-P99 only
    extra_offset_aliases=(),
    # an ST-20's rapids (945 in/min on X and Z, 24 m/min), its turret's index and 4,000 rev/min;
    # a machine file gives the machine's own
    timing=Timing(
        rapid={"X": 24000.0, "Z": 24000.0},
        rapid_default=10800.0,
        tool_change_seconds=0.5,
        tool_change_code="T",
        dwell_p_unit=0.001,
        dwell_p_point_seconds=True,
        max_spindle_speed=4000.0,
    ),
)
