"""FANUC 0i-TF lathe control, G-code system A: the ``fanuc-0i-lathe`` profile.

Tables: ``dialects/fanuc_lathe_data.py`` (a lathe's tool offsets, where ``lathe_offsets`` points,
system A's modal groups). The macro language is the 0i's (``fanuc_0i``); what a lathe changes is
the NC side: X is a diameter and U and W move incrementally, ``G50`` sets coordinates (and with S
clamps the spindle), ``G90``/``G92``/``G94`` are the single fixed cycles and ``G70``–``G76`` the
multiple repetitive cycles, the plane is G18 and ``G99`` (feed per revolution) is in force at
power-on (docs/profiles.md, "fanuc-0i-lathe: sources and decisions"; docs/semantics.md §10.1).
"""

from __future__ import annotations

from dataclasses import replace

from ..dialect import ANY_BLOCK
from ..drill_cycles import FANUC_LATHE_DRILLING
from ..fanuc_lathe_data import LATHE_OFFSETS
from ..lathe_cycle_rules import FANUC_LATHE_RULES
from ..lathe_cycle_words import FANUC_LATHE_CYCLE_WORDS
from ..timing import Timing
from ..turning_cycles import FANUC_LATHE_CYCLES, LATHE_SINGLE_CYCLES
from .fanuc_0i import PROFILE as FANUC_0I

PROFILE = replace(
    FANUC_0I,
    name="fanuc-0i-lathe",
    title="FANUC 0i-TF lathe",
    title_zh="FANUC 0i-TF 车床",
    summary="FANUC 0i-D/0i-F lathes (0i-TD, 0i-TF), G-code system A, Custom Macro B",
    summary_zh="FANUC 0i-D/0i-F 车床（0i-TD、0i-TF），G代码体系A，用户宏程序 B",
    aliases=("fanuc-0i-t", "0i-tf", "0i-td", "fanuc-0i-tf", "fanuc-lathe"),
    data_module="fanuc_lathe_data",
    lathe=True,
    lathe_offsets=LATHE_OFFSETS,
    axes=("X", "Z", "C", "Y"),
    modal_defaults={"plane": 18.0, "feed": 99.0},
    coordinate_setting_code=50.0,
    cycle_codes=frozenset({70.0, 71.0, 72.0, 73.0, 74.0, 75.0, 76.0, 90.0, 92.0, 94.0}),
    drill_cycles={},
    lathe_drilling=FANUC_LATHE_DRILLING,  # G83-G89 along Z and X (planner/lathe_drilling.py)
    single_cycles=LATHE_SINGLE_CYCLES,
    lathe_cycles=FANUC_LATHE_CYCLES,
    cycle_words=FANUC_LATHE_CYCLE_WORDS,
    cycle_rules=FANUC_LATHE_RULES,
    # §8 letters without a decimal point: T; S; G04's P (ms); the P and Q of G70-G76 (sequence numbers,
    # least input increments, G76's digits m r a)
    # a bare A in G00/G01 is the direct drawing angle, as ,A is (parameter 3405#4 CCR = 0: "A", "C",
    # "R" without a comma; the profile's axes have no A, so the word was dropped); parallel lines
    # go straight to the end
    drawing_angle=("A", 1.0, None),
    no_point_words={ANY_BLOCK: "TS", 4.0: "P", **dict.fromkeys((70.0, 71.0, 72.0, 73.0, 74.0, 75.0, 76.0), "PQ")},
    # typical of a small slant-bed lathe; a machine file gives the machine's own (parameter 1420)
    timing=Timing(
        rapid={"X": 12000.0, "Z": 15000.0, "C": 10800.0, "Y": 8000.0},
        tool_change_seconds=1.0,
        tool_change_code="T",
        dwell_p_unit=0.001,
        max_spindle_speed=4000.0,
        helix_fed_on_arc=True,  # as the mills' (fanuc_0i.py)
    ),
)
