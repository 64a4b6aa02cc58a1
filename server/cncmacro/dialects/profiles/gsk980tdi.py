"""GSK980TDi lathe control (seeds 000, 001, 002).

Tables: ``dialects/gsk980tdi_data.py``. A lathe: X is a diameter, U and W move incrementally.
Commons #100–#199 and #500–#999 (seed 000 "变量的类型"); H-code arithmetic, C-style relations,
bracketed program names and ``#9xxx`` indirection.
"""

from __future__ import annotations

from ..alarms import (
    CORNER_FIT,
    ILLEGAL_LEAD,
    NOT_ALONE,
    OFFSET_NUMBER,
    OVERTRAVEL_MINUS,
    OVERTRAVEL_PLUS,
    POLAR_START,
    RECIPROCATION_AMOUNT,
)
from ..dialect import ANY_BLOCK, Dialect
from ..drill_cycles import GSK_LATHE_DRILLING
from ..lathe_cycle_rules import GSK980TDI_RULES
from ..lathe_cycle_words import GSK980TDI_CYCLE_WORDS
from ..tables import CommonRange
from ..timing import Timing
from ..turning_cycles import GSK_LATHE_CYCLES, GSK_SINGLE_CYCLES

PROFILE = Dialect(
    name="gsk980tdi",
    title="GSK980TDi",
    summary="GSK980TDi lathe control",
    summary_zh="广数 GSK980TDi 车床数控系统",
    aliases=("gsk", "gsk980", "gsk980td"),
    data_module="gsk980tdi_data",
    vacant_differs_in_eq=False,
    vacant_address_is_zero=True,
    nine_indirection=True,
    c_relations=True,
    macro_alarm_base=5900,
    # #3000=n and G65 H99 Pn: "报警范围为5900到5999" (§3.28.1, §3.28.2)
    macro_alarm_numbers=(0, 99),
    # "G65、G66该代码之前只允许出现代码字N且紧跟其后要出现P或H代码字" (§3.28.3 note 3)
    call_first_letters="PH",
    # the soft limits and the offset numbers are the machine's (docs/semantics.md §11); no source
    # at hand gives the GSK980TDi's numbers for these alarms; G34's lead below zero: "因R的增加/减小使
    # 螺距…出现负值时产生报警" (§3.24.4), no number; nor for G86's I0 or I below R ("系统发出报警",
    # §3.23.11); nor for G22/G23 sharing a block (§3.31 note 6); nor for G12.1 under G99 or G41/G42
    # (§3.9 note 3)
    # a chamfer (L) or rounding (D) that does not fit: "CNC 产生报警" (§3.11.3), no number
    unnumbered_alarms=frozenset(
        {
            OVERTRAVEL_PLUS,
            OVERTRAVEL_MINUS,
            OFFSET_NUMBER,
            ILLEGAL_LEAD,
            RECIPROCATION_AMOUNT,
            NOT_ALONE,
            POLAR_START,
            CORNER_FIT,
        }
    ),
    corner_fit_alarm=True,
    h_codes=True,
    bracket_names=True,
    program_digits=4,
    macro_levels=4,
    subprogram_levels=12,
    clamp_repeat_count=True,
    count_in_p_and_l_alarm=True,
    lathe=True,
    axes=("X", "Y", "Z", "C", "B"),
    modal_call_codes=frozenset({0.0, 1.0, 2.0, 3.0, 5.0}),
    # "跳转信号变为“1”时绝对坐标位置被存储在用户宏变量中(#995～#999 分别对应 X，Z，Y，4th，5th)"
    # (§3.16.2); the 4th and 5th axes are C and B here, as #5004 and #5005 number them
    skip_commons=(("X", 995), ("Z", 996), ("Y", 997), ("C", 998), ("B", 999)),
    # "进给速度超过 200mm/min 时被箝制在该速度" (§3.16.2 note)
    skip_feed_clamp=200.0,
    # G23 at power-on (§3.31 note 3)
    modal_defaults={"plane": 18.0, "feed": 98.0, "stroke": 23.0},
    coordinate_setting_code=50.0,
    # "若G54~G59指令与G50共段执行时，G54~G59指令将无效，G50执行有效" (§3.21 note 6)
    coordinate_setting_voids_wcs=True,
    # "执行 G28 代码回机床零点操作后，系统取消刀具长度补偿" (§3.15.1 note 4; G30: §3.15.2 note 3)
    reference_return_cancels_tool_offset=True,
    # "G50 X100 Z50 M3 S300；(设置工件坐标系启动主轴，指定转速)" (§3.24.12's example): under G97 the
    # S of a G50 that sets coordinates is the spindle speed; "G50 S__" alone the clamp (§3.25)
    coordinate_setting_speed=True,
    local_coordinate_code=52.0,  # §3.19: G52 X(U) Z(W), no move
    # G05 / G05.1 three-point arcs, the point relative / absolute (§3.5)
    three_point_arcs={5.0: False, 5.1: True},
    # §3.13: "Q_ 角度是直线与Z轴的夹角 …（单位：0.001°）"; notes 3-5: within ±1° of parallel, an alarm
    drawing_angle=("Q", 0.001, 1.0),
    # the recess grooving cycles G74.1/G75.1 (§3.23.7, §3.23.8), whose step ⑩ ends where they began:
    # "刀具快速返回凹槽切削前起点处"
    unsimulated_codes=frozenset({74.1, 75.1}),
    # §3.17: "刀具首先快速移动到代码的测量位置" (the tool first goes to the measuring position at rapid)
    tool_measure_codes=frozenset({36.0, 37.0}),
    # §3.11: "直线倒角的代码地址为 L", "圆弧倒角的代码地址为 D"
    chamfer_words=("L", "D"),
    # G86 Z(start) A(end) I(stroke) R(advance) F: Z feeds back and forth to A and returns (§3.23.11)
    reciprocating_feed_code=86.0,
    # "G22/G23代码不能与其它G代码及MST代码共段，否则发出报警" (§3.31 note 6); "G12.1，G13.1，G16，G15要
    # 单独编为一段程序" (§3.9 note 1); G51.2 P Q R A, G50.2: "以上指令请单独指定，不要与其它程序指令共段
    # 执行" (§3.36 note 2)
    own_block_codes={
        22.0: ("GMST", "*"),
        23.0: ("GMST", "*"),
        12.1: ("", ""),
        13.1: ("", ""),
        15.0: ("", ""),
        16.0: ("", ""),
        50.2: ("", ""),
        51.2: ("", "PQRA"),
    },
    # ellipse A, B (half axes), Q (angle); parabola P, Q (§3.6, §3.7)
    motion_value_letters={
        6.2: frozenset("ABQ"),
        6.3: frozenset("ABQ"),
        7.2: frozenset("PQ"),
        7.3: frozenset("PQ"),
    },
    # #4001 reads "G124(G06.2)，G126(G06.3)，G132(G32.1)，G144(G07.2)，G146(G07.3)" (§3.28.1)
    motion_numbers={6.2: 124.0, 6.3: 126.0, 32.1: 132.0, 7.2: 144.0, 7.3: 146.0},
    # G6.2/G7.2 go round as G02, G6.3/G7.3 as G03 (§3.6, §3.7)
    conic_moves={6.2: (False, True), 6.3: (False, False), 7.2: (True, True), 7.3: (True, False)},
    cycle_codes=frozenset(
        {70.0, 71.0, 72.0, 73.0, 74.0, 75.0, 76.0, 78.0, 90.0, 92.0, 92.1, 92.3, 94.0, 33.0}
        | {83.0, 84.0, 87.0, 88.0, 83.1, 83.2, 84.1, 84.2, 87.1, 88.1}
    ),
    single_cycles=GSK_SINGLE_CYCLES,
    lathe_drilling=GSK_LATHE_DRILLING,  # G83/G87, G84/G88 (planner/lathe_drilling.py)
    lathe_cycles=GSK_LATHE_CYCLES,
    cycle_words=GSK980TDI_CYCLE_WORDS,
    cycle_rules=GSK980TDI_RULES,
    # G41/G42 compensate a G70-G73 shape only from its first block N(ns) (docs/semantics.md §12)
    shape_compensation_first_block=True,
    common_ranges=(CommonRange(100, 199, False), CommonRange(500, 999, True)),
    # §3.28.1: "公共变量(#100~#199，#500~#999)的值在宏变量页面有显示，也可在该页面下，直接输入数据", and its
    # example keeps the parts made in #100 from run to run ("#100 是已加工零件个数，初始值=0")
    volatile_commons_set_before=True,
    m98_program_digits=4,
    modal_call_needs_distance=True,
    g65_cancels_modal_call=True,  # "G65 调用会自动取消 G66 模态调用" (§3.28.3.2 note 4)
    word_format_alarms=False,
    # §8 letters without a decimal point: T; G04's P (ms); the P and Q of G70-G76 (sequence numbers,
    # least input increments, G76's digits m r a)
    no_point_words={ANY_BLOCK: "T", 4.0: "P", **dict.fromkeys((70.0, 71.0, 72.0, 73.0, 74.0, 75.0, 76.0), "PQ")},
    # §3.26: "CNC上电时，进给速度为CNC状态参数№.030设定的值" (at power-on the feed is state parameter No.030's)
    power_on_feed=("state parameter No.030", "状态参数№.030"),
    arc_radius_alarm=False,  # no alarm for it in the manuals at hand: a warning (docs/semantics.md §8, "Arcs")
    keyword_abbreviations=False,
    # #i = RAND[#j], #i = SRAND[#j，#k]: random numbers (§3.29.1)
    extra_functions=frozenset({"RAND", "SRAND"}),
    bare_function_argument=True,
    # §3.9 note 3: "在C刀补中间或G99状态下不能启动极坐标插补，否则报警"
    polar_start_alarm=True,  # §3.29.2: "IF[#101>=7.22]THEN #101=SIN30"
    if_without_then=False,
    corner_words=False,
    # §3.19 note 2 (G52), §3.21 note 5 (G54-G59): a shift sets the tool nose radius compensation
    # aside until the next move (docs/semantics.md, "Tool nose radius compensation on a lathe")
    shift_cancels_compensation=True,
    # §3.32: a G code set to call a macro that equals a standard G code is no call
    standard_g_calls=False,
    # typical of a small slant-bed lathe; a machine file gives the machine's own. X's rate is
    # the rate of the radius (the tool moves half a diameter change)
    timing=Timing(
        rapid={"X": 6000.0, "Z": 8000.0, "Y": 6000.0},
        rapid_default=3600.0,
        tool_change_seconds=1.0,
        tool_change_code="T",
        dwell_p_unit=0.001,
        max_spindle_speed=3000.0,
    ),
)
