"""A control profile as one object: its switches (docs/semantics.md's per-profile rules) and its tables.

The interpreter never asks "is this gsk?"; it reads a switch or a table from here. Each built-in
profile is one module in ``dialects/profiles/`` that defines a ``Dialect`` value; a machine file
narrows or extends it (``Dialect.configured``). Adding a control means adding a profile module
(and its data), not a code path: see docs/profiles.md.
"""

from __future__ import annotations

import importlib
from bisect import bisect_right
from dataclasses import dataclass, field, replace
from functools import cache
from typing import Any

from ..bilingual import Detail, detail, pick
from .alarms import alarm_said, alarm_titled, shown_number
from .cycle_words import CycleWords
from .drill_cycle_words import dwelling_at_r
from .drill_cycles import DrillCycle, LatheDrilling
from .functions_data import BLOCK_IF_WORDS
from .lathe_cycle_rules import LatheCycleRules
from .tables import CodeDoc, CommonRange, FunctionDoc, LatheOffsets, ProgramDoc, SystemVariable, SystemVariableName
from .timing import Timing
from .turning_cycles import LatheCycles, SingleCycle

# G65 argument specification I (docs/semantics.md §5): letter -> local variable number.
ARGUMENTS_I = {
    "A": 1, "B": 2, "C": 3, "I": 4, "J": 5, "K": 6, "D": 7, "E": 8, "F": 9, "H": 11, "M": 13,
    "Q": 17, "R": 18, "S": 19, "T": 20, "U": 21, "V": 22, "W": 23, "X": 24, "Y": 25, "Z": 26,
}  # fmt: skip


def last_address_key(letter: str) -> str:
    """Where the planner keeps the last value written for address ``letter`` on a profile whose
    ``Dialect.last_address_letters`` names it: a system variable row reads it with
    ``source="code"`` and this key as its ``param``."""
    return f"{letter} last"


# the GSK980TDi's tool offsets (seed 000 §3.28.1), the default of ``Dialect.lathe_offsets``
GSK_LATHE_OFFSETS = LatheOffsets(
    axes=(("X", 2700, 2000), ("Z", 2800, 2100), ("Y", 2450, 2400)), radius=(2900, 2200), tip=2300
)


# the key of ``Dialect.no_point_words`` for the letters refused a decimal point in every block
ANY_BLOCK = -1.0


@dataclass(frozen=True)
class Dialect:
    """Everything that differs between controls. Field names say what each switch decides."""

    name: str
    title: str
    data_module: str
    # §2 vacant: fanuc tells vacant from 0 in EQ/NE; gsk980tdi treats vacant as 0 everywhere
    vacant_differs_in_eq: bool
    # §2 addresses: a vacant address value drops the word (fanuc) or is 0 (gsk980tdi)
    vacant_address_is_zero: bool
    # §2 #9 followed by a common variable number is indirection (gsk980tdi)
    nine_indirection: bool
    # §3 C-style relations == != < > <= >=
    c_relations: bool
    # §6 #3000=n raises alarm base+n
    macro_alarm_base: int
    # §7 G65 Hm P Q R arithmetic and branches
    h_codes: bool
    # §5 bracketed program names P[CUT]
    bracket_names: bool
    # §5 digits allowed in P for a program number
    program_digits: int
    # §5 nesting
    macro_levels: int
    subprogram_levels: int
    # §5 L above 9999 is clamped (True) or an error (False)
    clamp_repeat_count: bool
    # §5 a count in P together with L is alarm 293
    count_in_p_and_l_alarm: bool
    # §8 a lathe: X is a diameter and U, V, W, H are incremental X, Y, Z, C
    lathe: bool
    # the axes in system-variable order (#5001 is the first)
    axes: tuple[str, ...]
    # §5 the codes after whose blocks a G66 modal call is made (the block's one-shot code, else the
    # motion mode in force: GSK980TDi G00, G01, G02, G03, G05, §3.28.3.2 note 2); None: after any
    # block with a move command (FANUC: "a block specifying movement along axes")
    modal_call_codes: frozenset[float] | None = None
    # the profile's title in Chinese, for the editor's Chinese texts ("" where it reads as the English)
    title_zh: str = ""
    # the modal state at power-on (MODAL_GROUPS names -> G code)
    modal_defaults: dict[str, float] = field(default_factory=dict)
    # which G code sets the coordinate system (G92 on a mill, G50 on this lathe)
    coordinate_setting_code: float = 92.0
    # §8 a work offset code (G54-G59) in the block of ``coordinate_setting_code`` is void, and the
    # offset in force stays (GSK980TDi §3.21 note 6); False: the block selects it as well
    coordinate_setting_voids_wcs: bool = False
    # §10.1 a lathe's G28/G30 cancels the tool offset at the reference point: the tool vector is 0
    # until the next T (GSK980TDi §3.15.1 note 4, §3.15.2 note 3); on a mill, G28/G30 cancels the
    # tool length offset as G49 does (Haas 96-8000: "G28 cancels tool length offsets for the
    # following lines of code"; §8); False: it stays (FANUC)
    reference_return_cancels_tool_offset: bool = False
    # §8 a G28 with no axis word returns every axis to the reference point (Haas 96-8000: "G28 is
    # used to return all axes to machine zero, unless an axis (or axes) is specified"); False: it
    # moves nothing (FANUC)
    reference_return_all_axes: bool = False
    # §10.4 whether an S in a lathe's coordinate setting block that also sets coordinates (X, Z, U,
    # W) is the spindle speed under G97 rather than the G96 clamp (GSK980TDi: its G76 example's
    # "G50 X100 Z50 M3 S300；(设置工件坐标系启动主轴，指定转速)", §3.24.12); ``G50 S`` alone, and
    # any under G96, stays the clamp
    coordinate_setting_speed: bool = False
    # §8 the code that sets a local coordinate system (G52 IP: its origin in work coordinates, IP0
    # cancels; FANUC's and Haas's), None where the control has none
    local_coordinate_code: float | None = 52.0
    # §8 one-shot codes whose axis word is a value, not a move: cylindrical interpolation's
    # ``G07.1 C_`` (G107 in FANUC's system B) names the cylinder's radius, ``G07.1 C0`` ends it
    axis_value_codes: frozenset[float] = frozenset((7.1, 107.0))
    # §8 polar coordinate interpolation: its codes, each turning it on (True) or off
    # (planner/virtual_planes.py); cylindrical interpolation is ``axis_value_codes``' C
    polar_interpolation_codes: dict[float, bool] = field(
        default_factory=lambda: {12.1: True, 112.0: True, 13.1: False, 113.0: False}
    )
    # §8 the skip codes (G31, probing.py), and the multi-step skip's G31.1-G31.3 where the control
    # has them: each stops where its signal comes on, as G31 does
    skip_codes: frozenset[float] = frozenset((31.0,))
    # §8 the commons in which a G31 stores where the skip signal came on, by axis (axis letter,
    # variable): GSK980TDi #995-#999 for X, Z, Y, 4th, 5th (§3.16.2); empty where the skip position
    # is read from system variables (#5061…)
    skip_commons: tuple[tuple[str, int], ...] = ()
    # §9 the fastest a skip move goes, in mm/min: a G31 with a faster feed goes at this one
    # (GSK980TDi 200, §3.16.2 note); None: at its feed, as any cutting move
    skip_feed_clamp: float | None = None
    # §8 workpiece coordinate system preset (FANUC G92.1 IP0, G50.3 on a lathe): the named axes'
    # coordinate shift (G92, G52) is cancelled, the tool does not move
    preset_codes: frozenset[float] = frozenset((92.1, 50.3))
    # §8 three-point arcs (GSK980TDi G05, G05.1): motion code -> whether its I, K point on the arc
    # is absolute (else relative to the start, as G02/G03's I, K) (planner/three_point_arcs.py)
    three_point_arcs: dict[float, bool] = field(default_factory=dict)
    # §8 the angle of direct drawing dimension programming written as an NC word in G00/G01 blocks
    # (GSK980TDi §3.13: Q, in 0.001°; FANUC 0i-TF with parameter 3405#4 CCR = 0: A, in degrees) as
    # (letter, degrees per unit, the tolerance in degrees within which two lines, or a line and the
    # named axis's, count as parallel: an alarm; None: parallel lines go straight to the end, as
    # FANUC's do); None where the angle is only the corner word ``,A``
    drawing_angle: tuple[str, float, float | None] | None = None
    # §8 the cycles the control has whose passes are not simulated (planner/one_shot.py): every word
    # of their blocks is the cycle's (none moves an axis), the tool is left at its start point, and
    # the run notes once a block that the cycle is not simulated (the `not-simulated` information)
    unsimulated_codes: frozenset[float] = frozenset()
    # §10.1 the chamfer and corner rounding words of a G01/G02/G03 block (GSK980TDi §3.11: L a
    # straight chamfer of that length, type I, D a rounding arc), cut between the block's move and
    # the next (planner/corner_stage.py); None: the profile has none
    chamfer_words: tuple[str, str] | None = None
    # §10.1 automatic tool offset measurement (GSK980TDi G36 X_, G37 Z_, §3.17): the tool goes to
    # the measuring position at rapid whatever the motion in force, which stays; the offset's update
    # by the measuring signal is not simulated (a `not-simulated` note)
    tool_measure_codes: frozenset[float] = frozenset()
    # §10.3 the code of an independent reciprocating feed cycle along Z (GSK980TDi's G86 Z A I R F,
    # planner/reciprocating_feed.py); None where the control has none
    reciprocating_feed_code: float | None = None
    # §1 the G codes the manual wants in a block of their own (machine/block_rules.py): code ->
    # (the letters whose word beside it is an alarm, the letters that may stand beside it, "*" any);
    # a word of another letter but N is a warning (the manual asks, gives no alarm)
    own_block_codes: dict[float, tuple[str, str]] = field(default_factory=dict)
    # §8 motion codes whose blocks carry values under letters that may name an axis elsewhere
    # (GSK980TDi's ellipse G6.2/G6.3: A, B half axes and Q; parabola G7.2/G7.3: P, Q): motion code
    # -> those letters, which are never an axis word in that mode
    motion_value_letters: dict[float, frozenset[str]] = field(default_factory=dict)
    # §8 motion codes that #4001 (group 01) reads as another number: GSK980TDi's G6.2 reads 124,
    # G6.3 126, G32.1 132, G7.2 144, G7.3 146 (§3.28.1); a code not listed reads as itself
    motion_numbers: dict[float, float] = field(default_factory=dict)
    # §8 conic moves (GSK980TDi's ellipse G6.2/G6.3, parabola G7.2/G7.3): motion code -> (a
    # parabola, else an ellipse; clockwise in G02's sense) (planner/conic_moves.py)
    conic_moves: dict[float, tuple[bool, bool]] = field(default_factory=dict)
    # which G codes are canned cycles that leave the tool where it started
    cycle_codes: frozenset[float] = frozenset()
    # §5 fanuc wants I, J, K in that order within each set (a warning otherwise)
    ijk_order_matters: bool = False
    # §8 the G-code table lists every code of the control and its alarms for a refused word are
    # known: a G code outside the table and the machine's call codes is alarm 010, a decimal point
    # in an M code alarm 007; without this switch both are warnings and a run goes on
    word_format_alarms: bool = False
    # §8 the letters the control takes without a decimal point, by the G code of the block they are
    # in (``ANY_BLOCK``: in every block): ``T0101.``, ``G04 P1.5`` (P in ms), a lathe cycle's P and Q
    # in least increments or sequence numbers. A literal written with one is a warning that says
    # how the run reads it (machine/words.py ``point_refused``)
    no_point_words: dict[float, str] = field(default_factory=dict)
    # §8 "Arcs": I, J, K whose end point is off the start's circle by more than the tolerance is
    # alarm PS0020 (FANUC's list); without this switch the run notes it and goes on
    arc_radius_alarm: bool = False
    # §8 "Arcs": a G02/G03 block that moves in its plane with neither R nor an offset word of the
    # plane is alarm PS0022 "R or I, J, K command not found" (FANUC's list); without this switch it
    # is cut as a straight line
    arc_centre_alarm: bool = False
    # §10.4 the parameter whose feed a control cuts at after power-on when no program gave F
    # (English, Chinese: GSK980TDi §3.26, state parameter No.030); None where the feed is 0 then
    # and a cut alarms (FANUC PS0011 "feed zero (command)"): planner/missing_feed.py says which
    power_on_feed: tuple[str, str] | None = None
    # "Cutter radius compensation": a path whose offset reverses a block or finds no corner, and a
    # plane change in G41/G42, are FANUC's alarms PS0041, PS0033 and PS0037; without this switch
    # the run notes them and goes on (a start-up or cancel on an arc, PS0034, is an alarm on every mill)
    cutter_alarms: bool = False
    # "Cutter radius compensation": a skip (``skip_codes``: G31) commanded while G41/G42 is in force
    # is the control's alarm (FANUC PS0035 "CAN NOT COMMANDED G31", Mitsubishi program error P608);
    # without this switch it is a warning (the GSK980TDi and Haas manuals ask for G40 first but name
    # no alarm) and the skip is made as programmed
    skip_compensation_alarm: bool = False
    # "Cutter radius compensation": a chamfer or corner R (``,C``/``,R``) on a start-up, a cancel or
    # a change between G41 and G42 is the control's alarm (FANUC PS0039 "CHF/CNR NOT ALLOWED IN
    # G41,G42", mills and lathes); without this switch nothing is said (the corner is not simulated)
    corner_compensation_alarm: bool = False
    # §8 "Chamfer and corner words": a chamfer or corner R that does not fit its moves (a move too
    # short, a radius too large) is the control's alarm (FANUC PS0055 "MISSING MOVE VALUE IN
    # CHF/CNR"; the GSK980TDi's unnumbered alarms of §3.11.3); without this switch the corner is
    # left sharp and the run notes it (planner/corner_stage.py)
    corner_fit_alarm: bool = False
    # §8 "Chamfer and corner words": the block after a chamfer or corner R that does not go on with a
    # G01, G02 or G03 move in the plane is the control's alarm (FANUC PS0051 "MISSING MOVE AFTER
    # CHF/CNR": no move, or one off the plane; PS0052 "CODE IS NOT G01 AFTER CHF/CNR": a G00, a
    # cycle, a return); without this switch the corner is left sharp and the run goes on
    corner_next_alarm: bool = False
    # "Cutter radius compensation": G41/G42 written again in offset mode on the side in force ends
    # the previous block on the perpendicular of its end, inside or outside (FANUC 30i-MA and 15i-MB
    # manuals, "cutter compensation G code in the offset mode"); without this switch it
    # changes nothing and the corner is the usual intersection (Mitsubishi M700V/M70V §12.4: G41/G42
    # without I, J gives the "intersection point calculation type vector")
    repeated_side_perpendicular: bool = False
    # "Cutter radius compensation": a coordinate shift in offset mode (G52, G54-G59, G92/G50) sets
    # the compensation aside, the move before it ending on its perpendicular, and the next move in
    # the plane starts it again (GSK980TDi §3.19 note 2, §3.21 note 5); without this switch the
    # offset goes on, the corner worked out in the coordinates in force after the shift
    shift_cancels_compensation: bool = False
    # §10.2/§12 tool nose radius compensation in G70-G73 (GSK980TDi §3.23.1): only a G41/G42 on the
    # shape's first block N(ns) compensates the shape, the cycle's end cancels it, and a compensation
    # in force before the cycle is set aside for it; without this switch G70 runs its shape in the
    # compensation in force (FANUC)
    shape_compensation_first_block: bool = False
    # §1 the first two or more letters of a macro word stand for the word (WH for WHILE)
    keyword_abbreviations: bool = False
    # §4 IF [cond] <statement> without THEN runs the statement (FANUC profiles, Haas); elsewhere
    # alarm 114
    if_without_then: bool = False
    # §4 Haas's conditional jump ``[cond] M99 P n`` (IF [cond] GOTO n written another way) is read;
    # elsewhere it is a ``dialect-feature`` error and the run stops there with alarm 114
    conditional_m99: bool = False
    # §4 an IF that is followed by NC words, or by nothing, governs the rest of its block: the words
    # run when the condition holds and are passed over when it does not (Haas); elsewhere it is a
    # ``dialect-feature`` error and the run stops there with alarm 114
    if_governs_block: bool = False
    # §4 the block form of IF: ``IF [cond] THEN`` alone on its line runs the blocks up to its
    # ``ELSE`` when the condition holds, else those after the ``ELSE`` up to its ``ENDIF``; block
    # IFs nest (Mitsubishi M70/M80, Mazak EIA/ISO); elsewhere IF..THEN alone,
    # ELSE and ENDIF are ``dialect-feature`` errors and the run stops there with alarm 114
    block_if: bool = False
    # §5 a machine file's ``[calls]`` may make one of the profile's own G codes call a program
    # (FANUC's parameters 6050–6059 take any code); off: such an entry is no call, the standard
    # code runs (GSK980TDi manual §3.32: when the code set equals a standard G code the call is
    # disabled), and the machine file's note says so (``library/profiles.py``)
    standard_g_calls: bool = True
    # §3 AND and OR may be spelled ``&&`` and ``||`` (Mazak's EIA/ISO programs:
    # ``IF [[#1 GT 0] && [#2 LT 5]] GOTO 10``); elsewhere they are ``dialect-feature`` errors and the
    # run stops at the block with alarm 114
    logical_symbols: bool = False
    # where a profile suggestion tries this profile among the others (lower first, then by name):
    # of two profiles that read a file alike, the one that reads less beyond it is named (a file
    # with only block IFs gets mitsubishi-m70 rather than mazak-eia, which also reads && and ||)
    suggestion_rank: int = 0
    # §1 §8 the manual documents the comma words ,C ,R (chamfer, corner radius) and ,A (angle) on a
    # move (FANUC, Haas); without it they are read and run alike but earn a ``corner-word`` warning
    corner_words: bool = True
    # other names the profile answers to (``fanuc`` for ``fanuc-0i``), in machine files, file
    # comments, settings and on the command line
    aliases: tuple[str, ...] = ()
    # one line on what the profile is, for a programmer choosing one (English, Chinese)
    summary: str = ""
    summary_zh: str = ""
    # §2 the common variables: every range the control can have, the default in force unless a
    # machine file names fewer (docs/semantics.md §2 "Common variables")
    common_ranges: tuple[CommonRange, ...] = (CommonRange(100, 499, False), CommonRange(500, 999, True))
    # §2 whether the commons cleared at power-off hold, when a program starts, what the operator typed
    # in or an earlier run left (GSK980TDi: its manual's parts counter in #100, "初始值=0"): unknown to
    # an analysis until the program writes them, as the kept ones (machine/unknown_values.py)
    volatile_commons_set_before: bool = False
    # §2 the common ranges each part system (path) of a multi-path control keeps its own, the
    # machine's other commons being shared by the paths (a machine file's ``part_system_commons``;
    # empty: the machine file does not say, and nothing is said of sharing)
    part_system_commons: tuple[tuple[int, int], ...] = ()
    # §5 M98 P: digits of a program number; a P with more digits carries the repeat count before them
    m98_program_digits: int = 4
    # system variables a machine file adds or describes anew; they win over the profile's rows
    extra_rows: tuple[SystemVariable, ...] = ()
    # plain G and M codes a machine file declares (``[codes]``: codes the machine builder added,
    # Doosan's G120.1): listed before the table's, they run as plain codes and hover with their text
    extra_codes: tuple[CodeDoc, ...] = ()
    # §2 address letters whose last value written in a block the address variables read, beside
    # the codes every profile keeps (F, S, T, M, D, H, B, N, O): on Haas every letter of
    # #4101-#4126, the axis, arc and cycle words too; none on FANUC and GSK, whose #4101-#4130
    # hold only those codes (``last_address_key`` names where each is kept)
    last_address_letters: frozenset[str] = frozenset()
    # programs kept on the control rather than in the workspace (the profile's, as Haas's
    # O9000-O9999, or a machine file's ``programs_on_control``): a call to one returns at once
    programs_on_control: tuple[tuple[int, int], ...] = ()

    # §5 a modal G code before G65/G66 in its block: "alarm" (only N may precede the call, alarm 127)
    # or "execute" (the G code takes effect and stays in force, then the macro is called)
    modal_g_before_call: str = "alarm"
    # §5 the letters one of which must come right after G65/G66, in the manual's order (GSK980TDi
    # §3.28.3 note 3: "PH"); another word there is a warning, the manual giving no alarm for it.
    # Empty: any order
    call_first_letters: str = ""
    # §6 the n of ``#3000=n`` and ``G65 H99 Pn`` the control takes (GSK980TDi: 0-99, alarms
    # 5900-5999); outside it the run stops with alarm 119, an argument out of range. None: not limited
    macro_alarm_numbers: tuple[int, int] | None = None
    # §6 the alarm numbers the control itself shows, of those the interpreter raises (FANUC 0i's,
    # the GSK's, 3000+n / 5900+n for #3000): None, every one (FANUC, GSK); a set, only these, the
    # others shown without a number (Haas, whose manuals document none of them)
    documented_alarms: frozenset[int] | None = None
    # §6 of those, the alarms the control surely has but whose number no source gives (gsk980tdi's
    # over-travel and offset number alarms): shown without a number
    unnumbered_alarms: frozenset[int] = frozenset()
    # §5 DPRNT ``#i[ab]``: the most places a format may reserve, a + b (0: no limit; Haas 8, a
    # format of none or more is alarm 114 there), and whether the whole part is printed in full
    # (Haas: at least one digit, the field widened past a) or as its last a digits (FANUC)
    dprnt_places: int = 0
    dprnt_whole_part: bool = False
    # §5 ``M99 Pn`` in the main program: True, a branch to Nn in every run, as GOTO n (Haas: "M99
    # P10 branches to N10"); False, the main program's end, which a run of one pass stops at
    # (``m99_ends_main``) and the debugger and ``--repeat`` continue from Nn
    main_m99_p_jumps: bool = False
    # §5 G65 P.. L k (k > 1): whether a pass after the first starts with the locals as the pass
    # before left them (Haas: the arguments are set on the first pass only) or with a fresh level
    # filled from the call's arguments again (False: each pass a call of its own)
    macro_repeat_keeps_locals: bool = False
    # §5 a G65 call cancels the G66 modal call in force, as G67 does, before it calls (GSK980TDi
    # §3.28.3.2 note 4); False: G66 stays in force through a G65 (FANUC)
    g65_cancels_modal_call: bool = False
    # §5 G66 calls after a block that moves some distance (True: ``G0 U0 W0`` calls nothing) or
    # after any block with a move command (False)
    modal_call_needs_distance: bool = False

    # §8 where a mill keeps its tool offsets by offset number n: the bases of H length geometry,
    # H length wear, D diameter geometry and D diameter wear (#base + n). G43/G44 H adds length
    # geometry and wear; G10 L10, L11, L12 and L13 write them in that order. FANUC memory C keeps
    # them at #11001, #10001, #13001, #12001; Haas at #2001, #2201, #2401, #2601.
    tool_offset_bases: tuple[int, int, int, int] = (11000, 10000, 13000, 12000)
    # §8 other L numbers of G10 that write a tool offset, each as the L10-L13 it stands for
    # (Haas: "L1 or L11", the length wear); none on FANUC and GSK
    g10_tool_l_aliases: tuple[tuple[float, float], ...] = ()
    # §10.1 where a lathe keeps its tool offsets (X, Z, Y geometry and wear, nose radius, tip):
    # the T code's offset number selects them and G10 P writes them. The GSK980TDi keeps them at
    # #2001…/#2701… (the default); the FANUC 0i-TF at #10001…/#15001…, with #2001… as the short
    # numbers of offsets 1-64
    lathe_offsets: LatheOffsets = GSK_LATHE_OFFSETS

    # §10.1 the same control as a lathe, which a machine file's ``lathe = true`` selects (the 30i
    # lathes: ``fanuc-30i``'s); None: the profile has no lathe form
    lathe_variant: Dialect | None = None

    # §2 system variable names [#_NAME] and [#_NAME[n]] (the data module's SYSTEM_VARIABLE_NAMES)
    variable_names: bool = False
    # §3 functions beyond the common set: names (POW, ADP, PRM) and extra forms by signature (ATAN[a,b])
    extra_functions: frozenset[str] = frozenset()
    # §10.1 polar coordinate interpolation (G12.1) may not start under feed per revolution (G99)
    # or in tool nose radius compensation (G41/G42): the control's alarm (GSK980TDi §3.9 note 3);
    # elsewhere it starts as written
    polar_start_alarm: bool = False
    # §3 a one-argument function followed by a bare number (``SIN30``, the GSK980TDi manual's own
    # example) reads it as its argument; elsewhere a ``syntax`` finding and alarm 114
    bare_function_argument: bool = False

    # §5 the M code of a local subprogram call (Haas ``M97 P<n> L<k>``: run from Nn of the
    # program running until M99, then back after the call); None: no such call, the code is a
    # plain M code
    local_subprogram_code: float | None = None
    # §4 an M code that jumps to block P of the program when discrete input Q, #1000 + Q, is 0, and
    # goes on otherwise (Haas M96 [H4]: "M96 P10 Q27 (Loop to N10 if spare input [#27] is 0)");
    # None: no such code
    input_jump_code: float | None = None
    # §8 ``G54 Pn`` selects extra work offset n as ``G54.1 Pn`` does (FANUC: "G54.1 Pn or G54 Pn")
    extra_offset_by_g54_p: bool = False
    # §8 the G code that selects extra work offset Pn (Haas ``G154 P1``–``P99``), as G54.1 Pn
    # does on FANUC; None: the code is not the control's
    extra_offset_code: float | None = None
    # §8 G codes that each select one extra work offset, the first P1 (Haas G110–G129 = G154
    # P1–P20)
    extra_offset_aliases: tuple[float, ...] = ()
    # §8 the variable of axis 1 of extra offset P1 (each further P adds 20), the one G54.1/G154
    # Pn and G10 L20 Pn read and write, and how many extra offsets there are (G10 L20 P range)
    extra_offset_variables: int = 7001
    extra_offset_count: int = 48

    # §9 what each drilling canned cycle of a mill does at the bottom and on the way out
    # (drill_cycles.py; a canned code not listed drills as G81), and the word that repeats a
    # cycle block (K on FANUC, L on Haas)
    drill_cycles: dict[float, DrillCycle] = field(default_factory=dict)
    # §10.3 a lathe's drilling cycles (drill_cycles.py's ``LatheDrilling``), None on a mill
    lathe_drilling: LatheDrilling | None = None
    cycle_repeat_letter: str = "K"
    # §9 G27-G30 while a drilling canned cycle is in force (its group not at G80) stop the run with
    # alarm PS0044 "G27-G30 not allowed in fixed cyc" (FANUC's list); without this switch they run
    reference_in_cycle_alarm: bool = False
    # §9 a mill's peck drilling (G73, G83) with no Q in force, or Q0, stops the run with alarm PS0045
    # "address Q not found (G73/G83)" (FANUC's list), and Q is kept only within one canned cycle
    # mode (G80 and G00-G03 clear the hole data); without this switch such a hole is drilled in one
    # feed, as G81
    peck_q_alarm: bool = False
    # §9 a drilling cycle's dwell P is hole data that G80 and a G00-G03 clear (FANUC's "canned cycle
    # for drilling"; Haas 96-8000, G73: "the dwell time will be reset to zero"): a cycle named after
    # them without P dwells nothing; without this switch the last P stays until another is given
    cycle_cancel_clears_dwell: bool = False
    # §9 a G00-G03 in the block of a drilling cycle's code moves as written and cancels the cycle
    # (Mitsubishi M700V/M70V programming manual, appendix "Order of G function command priority":
    # "Group 1 command is executed", "Group 9 is canceled"); without this switch the cycle is named
    # and drills the block's hole
    motion_cancels_cycle_in_block: bool = False
    # §9 a lathe's single fixed cycles (G90, G92, G94): which axis each goes in along first and
    # whether it comes out at rapid (turning_cycles.py); a turning cycle not listed is drawn as
    # one cut from where it starts to its end point
    single_cycles: dict[float, SingleCycle] = field(default_factory=dict)
    # §10.3 a lathe's threads and grooving cycles as its manual has them: the thread codes, the
    # word of a variable lead, whether G74/G75's X amounts are diameters (turning_cycles.py)
    lathe_cycles: LatheCycles = field(default_factory=LatheCycles)
    # what each letter of a cycle block means, by G code (cycle_words.py: a lathe's G70–G76 with
    # their first and second blocks, G90/G92/G94, G32, G50, G96/G97; a mill's drilling cycles),
    # for the editor's hover, signature help and completion
    cycle_words: dict[float, CycleWords] = field(default_factory=dict)
    # §10.5 what the control refuses in its multiple repetitive cycles G70–G76
    # (lathe_cycle_rules.py); None on a mill, whose G73/G74/G76 are drilling cycles
    cycle_rules: LatheCycleRules | None = None

    # what the machine takes time for: rapid rates, tool change, M codes, dwell units (timing.py;
    # the cycle time, planner/cycle_time.py)
    timing: Timing = field(default_factory=Timing)

    def configured(self, **changes: Any) -> Dialect:
        """This profile as one machine has it (a machine file's commons, digits and variables).
        ``changes`` are fields of ``Dialect`` by name; an unknown name is a ``TypeError``."""
        return replace(self, **changes)

    def cycle_words_of(self, code: float) -> CycleWords | None:
        """What each letter of cycle ``code``'s blocks means on this profile (``cycle_words``), P
        following the cycle's data: a tap that dwells P again at the R point
        (``DrillCycle.dwell_at_r``: FANUC's G74/G84, a lathe's G84/G88) says so."""
        words = self.cycle_words.get(code)
        if words is None:
            return None
        drill = self.drill_cycles.get(code)
        if drill is None and self.lathe_drilling is not None and code in self.lathe_drilling.cycles:
            drill = self.lathe_drilling.cycles[code].cycle
        return dwelling_at_r(words) if drill is not None and drill.dwell_at_r else words

    def shown_alarm(self, number: int) -> int | None:
        """The number a person is shown for the interpreter's alarm ``number`` on this control,
        or None where the control documents none (``documented_alarms``)."""
        if number in self.unnumbered_alarms:
            return None
        return shown_number(number, self.documented_alarms)

    def shown_title(self, locale: str | None) -> str:
        """The profile's title in the language of ``locale``."""
        return pick(locale, self.title, self.title_zh or self.title)

    def alarm_said(self, number: int, width: int = 0) -> Detail:
        """The interpreter's alarm ``number`` as a message names it on this control (English,
        Chinese): "alarm 127" ("报警 127"), or "alarm" ("报警") alone where it documents no number;
        ``width`` pads the number with zeros ("alarm 007"). The one way a check, a hover or a block
        rule writes an alarm into its text (docs/semantics.md §6)."""
        return alarm_said(self.shown_alarm(number), width)

    def alarm_titled(self, number: int, width: int = 0) -> Detail:
        """Alarm ``number`` with its text: "alarm 010 improper G code", or "alarm: improper G code"
        where this control documents no number for it."""
        return alarm_titled(self.shown_alarm(number), number, width)

    def on_control(self, number: int) -> bool:
        """Whether program ``number`` lives on the control (the profile or a machine file says so)."""
        return any(first <= number <= last for first, last in self.programs_on_control)

    def common_range_of(self, number: int) -> CommonRange | None:
        """The common range ``#number`` is in, or None."""
        for r in self.common_ranges:
            if r.first <= number <= r.last:
                return r
        return None

    def missing_variable(self, number: int) -> Detail:
        """What to tell a programmer about ``#number`` when it does not exist (English, Chinese):
        below #1000 it names the machine's common ranges, which a machine file may widen."""
        if 100 <= number < 1000:
            shown = [r.text() for r in self.common_ranges]
            ranges = Detail(", ".join(shown), "、".join(shown))
            return detail(f"#{number} is not a common variable of this machine ({self.title}: {ranges}; "
                          "a machine with more sets 'common' in .cncmacro.toml)",
                          f"#{number} 不是本机床的公共变量（{self.title}：{ranges.zh}；"
                          "机床有更多公共变量时，请在机床设置文件中设定）")  # fmt: skip
        return detail(f"#{number} does not exist on {self.title}", f"{self.title} 没有变量 #{number}")

    def shared_common(self, number: int) -> bool | None:
        """Whether common ``#number`` is shared by the part systems of the machine (False: each
        keeps its own), or None where the machine file does not say (``part_system_commons``)."""
        if not self.part_system_commons:
            return None
        return not any(first <= number <= last for first, last in self.part_system_commons)

    def allows_common(self, first: int, last: int) -> CommonRange | None:
        """The profile's common range that holds ``#first``–``#last``, or None."""
        for r in self.common_ranges:
            if r.first <= first <= last <= r.last:
                return r
        return None

    @property
    def drills(self) -> bool:
        """Whether the canned drilling cycles (G80's group) run here: on a mill, and on a lathe
        with drilling cycles (``lathe_drilling``); G00–G03 cancel them (group 01 over the cycle's)."""
        return not self.lathe or self.lathe_drilling is not None

    @property
    def incremental_letters(self) -> dict[str, str]:
        """On a lathe, U V W H move X Y Z C incrementally."""
        if not self.lathe:
            return {}
        return {"U": "X", "V": "Y", "W": "Z", "H": "C"}

    def system_variables(self) -> tuple[SystemVariable, ...]:
        return self.extra_rows + _tables(self.data_module)[0]

    def system_variable(self, number: int) -> SystemVariable | None:
        """The table row that describes ``#number``, or None when it does not exist."""
        for row in self.extra_rows:
            if row.first <= number <= row.last:
                return row
        rows, firsts = _tables(self.data_module)[:2]
        k = bisect_right(firsts, number) - 1
        if k >= 0 and number <= rows[k].last:
            return rows[k]
        return None

    def g_codes(self) -> tuple[CodeDoc, ...]:
        """The G codes: the machine file's (``extra_codes``), then the profile's table."""
        return tuple(c for c in self.extra_codes if c.code[0] == "G") + _tables(self.data_module)[2]

    def m_codes(self) -> tuple[CodeDoc, ...]:
        """The M codes: the machine file's (``extra_codes``), then the profile's table."""
        return tuple(c for c in self.extra_codes if c.code[0] == "M") + _tables(self.data_module)[3]

    def system_variable_names(self) -> tuple[SystemVariableName, ...]:
        """The ``[#_NAME]`` names, empty for a dialect without them."""
        return tuple(_tables(self.data_module)[4].values()) if self.variable_names else ()

    def variable_name(self, name: str) -> SystemVariableName | None:
        """The row of ``[#_NAME]`` (``name`` without ``#_``, any case), or None."""
        return _tables(self.data_module)[4].get(name.upper()) if self.variable_names else None

    def program_docs(self) -> tuple[ProgramDoc, ...]:
        """The programs on the control that the data module documents (its ``PROGRAM_DOCS``;
        empty for a module without them), in number order."""
        return tuple(_tables(self.data_module)[5].values())

    def program_doc(self, number: int) -> ProgramDoc | None:
        """What the maker documents of program ``number`` kept on the control, or None."""
        return _tables(self.data_module)[5].get(number)

    def functions(self) -> tuple[FunctionDoc, ...]:
        """The common functions, then the forms ``extra_functions`` adds (by name or signature),
        each alarm their texts name as this control shows it."""
        extra = self.extra_functions | BLOCK_IF_WORDS if self.block_if else self.extra_functions
        return _functions_shown(extra, self.documented_alarms)


_Tables = tuple[
    tuple[SystemVariable, ...],
    list[int],
    tuple[CodeDoc, ...],
    tuple[CodeDoc, ...],
    dict[str, SystemVariableName],
    dict[int, ProgramDoc],
]


@cache
def _tables(module: str) -> _Tables:
    mod = importlib.import_module(f"{__package__}.{module}")
    rows = tuple(sorted(mod.SYSTEM_VARIABLES, key=lambda r: r.first))
    names = {n.name: n for n in getattr(mod, "SYSTEM_VARIABLE_NAMES", ())}
    programs = {p.number: p for p in sorted(getattr(mod, "PROGRAM_DOCS", ()), key=lambda p: p.number)}
    return rows, [r.first for r in rows], tuple(mod.G_CODES), tuple(mod.M_CODES), names, programs


@cache
def _functions(extra: frozenset[str]) -> tuple[FunctionDoc, ...]:
    mod = importlib.import_module(f"{__package__}.functions_data")
    added = tuple(f for f in mod.EXTRA_FUNCTIONS if f.name in extra or f.signature in extra)
    return (*mod.FUNCTIONS, *added)


@cache
def _functions_shown(extra: frozenset[str], documented: frozenset[int] | None) -> tuple[FunctionDoc, ...]:
    """``_functions`` with each ``{alarm}`` of a text filled as a control documenting ``documented`` shows it."""
    out = []
    for f in _functions(extra):
        if f.alarm is not None:
            said = alarm_said(shown_number(f.alarm, documented))
            f = replace(f, en=f.en.replace("{alarm}", said), zh=f.zh.replace("{alarm}", said.zh))
        out.append(f)
    return tuple(out)
