"""FANUC 0i Custom Macro B (0i-MD/0i-MF mills): the default profile, once named ``fanuc``.

Tables: ``dialects/fanuc_data.py`` (seed 003 chapter 4). Commons: #100–#499 (the 0i's optional
extension of #100–#199; a machine file narrows it) and #500–#999 kept at power-off.
"""

from __future__ import annotations

from dataclasses import replace

from ..dialect import ANY_BLOCK, Dialect
from ..drill_cycle_words import FANUC_DRILL_CYCLE_WORDS
from ..drill_cycles import FANUC_DRILL_CYCLES
from ..tables import CommonRange
from ..timing import Timing

PROFILE = Dialect(
    name="fanuc-0i",
    title="FANUC 0i Custom Macro B",
    title_zh="FANUC 0i 用户宏程序B",
    summary="FANUC 0i-D/0i-F mills and lathes, Custom Macro B",
    summary_zh="FANUC 0i-D/0i-F 铣床与车床，用户宏程序 B",
    aliases=("fanuc", "fanuc0i", "0i", "fanuc-0i-mf", "fanuc-0i-md"),
    data_module="fanuc_data",
    vacant_differs_in_eq=True,
    vacant_address_is_zero=False,
    nine_indirection=False,
    c_relations=False,
    macro_alarm_base=3000,
    h_codes=False,
    bracket_names=False,
    program_digits=8,
    macro_levels=4,
    subprogram_levels=10,
    clamp_repeat_count=False,
    count_in_p_and_l_alarm=False,
    lathe=False,
    axes=("X", "Y", "Z", "A"),
    modal_defaults={"plane": 17.0, "feed": 94.0},
    coordinate_setting_code=92.0,
    # §8 letters without a decimal point, as on the lathe (fanuc_0i_lathe.py): T, S (one place where
    # parameter 3451#2 allows it), and G04's P (ms)
    no_point_words={ANY_BLOCK: "TS", 4.0: "P"},
    cycle_codes=frozenset({73.0, 74.0, 76.0, 81.0, 82.0, 83.0, 84.0, 85.0, 86.0, 87.0, 88.0, 89.0}),
    drill_cycles=FANUC_DRILL_CYCLES,
    extra_offset_by_g54_p=True,  # "G54.1 Pn or G54 Pn" (0i-MF, adding workpiece coordinate systems)
    cycle_words=FANUC_DRILL_CYCLE_WORDS,
    reference_in_cycle_alarm=True,  # PS0044 (docs/semantics.md §9, "Drilling canned cycles")
    peck_q_alarm=True,  # PS0045 (the same)
    cycle_cancel_clears_dwell=True,  # G80 and G00-G03 clear the hole data, P among them (the same)
    ijk_order_matters=True,
    word_format_alarms=True,
    arc_radius_alarm=True,
    arc_centre_alarm=True,  # PS0022 (docs/semantics.md §8, "Arcs")
    cutter_alarms=True,
    skip_compensation_alarm=True,  # PS0035 (docs/semantics.md, "Cutter radius compensation")
    corner_compensation_alarm=True,  # PS0039 (the same)
    corner_fit_alarm=True,  # PS0055 (docs/semantics.md §8, "Chamfer and corner words")
    corner_next_alarm=True,  # PS0051, PS0052 (the same)
    repeated_side_perpendicular=True,  # G41 again in G41: the perpendicular (the same)
    keyword_abbreviations=True,
    if_without_then=True,
    modal_g_before_call="execute",
    common_ranges=(CommonRange(100, 499, False), CommonRange(500, 999, True)),
    # the protected 9000 series (parameter 3202 NE9), where the builder's and the probe maker's
    # macros live (Renishaw Inspection Plus O9810…): in the control's memory, not the folder
    programs_on_control=((9000, 9999),),
    m98_program_digits=4,
    # typical of a small vertical machining centre; a machine file gives the machine's own
    # (rapid rates: parameter 1420)
    timing=Timing(
        rapid={"X": 24000.0, "Y": 24000.0, "Z": 24000.0, "A": 10800.0},
        tool_change_seconds=3.0,
        tool_change_code="M6",
        dwell_p_unit=0.001,
        helix_fed_on_arc=True,  # "the feedrate along the circumference of two circular interpolated axes"
    ),
)

# The FANUC-only rules, off where a control of another maker is built on this profile (Haas,
# Mitsubishi, Mazak): no source at hand gives them there. G54 Pn as G54.1 Pn; the alarms PS0044
# (G27-G30 in a canned cycle), PS0045 (G73/G83 without Q; Haas pecks by Q or by I, J, K), PS0022
# (an arc without R or I, J, K), PS0039 (,C/,R on a compensation start-up, cancel or change of
# side), PS0055 (a chamfer or corner R that does not fit its moves) and PS0051/PS0052 (the block
# after it not a G01, G02 or G03 move in the plane); G41/G42 again in offset
# mode ending the previous block on its perpendicular (Mitsubishi's manual has the intersection
# there); T, S and G04's P refused a decimal point (Haas's G04 P10. is
# 10 s).
# The helix fed along its arc is one of them too, in the timing: ``OTHER_MAKERS_TIMING``
OTHER_MAKERS: dict[str, object] = {
    "extra_offset_by_g54_p": False,
    "reference_in_cycle_alarm": False,
    "peck_q_alarm": False,
    "arc_centre_alarm": False,
    "corner_compensation_alarm": False,
    "corner_fit_alarm": False,
    "corner_next_alarm": False,
    "repeated_side_perpendicular": False,
    "no_point_words": {},
}
OTHER_MAKERS_TIMING = replace(PROFILE.timing, helix_fed_on_arc=False)  # a helix fed along itself
