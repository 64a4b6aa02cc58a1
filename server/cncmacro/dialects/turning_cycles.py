"""The path of a lathe's single fixed cycles (G90, G92, G94) and what differs between lathe
controls in their threads and grooving cycles: the control's data for the planner
(docs/semantics.md §9, §10.3).

Each goes in along one axis at rapid, cuts along the other to the end point, comes back out
along the first (at the feed; a thread's G92 pulls out at rapid) and returns along the second
at rapid to where it started (the GSK980TDi programming manual's G90 axial cutting cycle, G92
thread cutting cycle and G94 radial cutting cycle). G90 and G92 go in along X first and cut
along Z; G94 goes in along Z first and faces along X. ``planner/turning_cycles.py`` turns one into its legs.

``LatheCycles`` holds what the two lathe manuals say differently (``Dialect.lathe_cycles``):
which G codes cut a thread, the word of a variable lead's change per revolution, and whether
G74/G75's X amounts are diameters.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class SingleCycle:
    """A single fixed cycle: the axis it goes in along first, whether it comes out along it at
    rapid (a thread's pull-out) rather than at the feed, whether it cuts a thread (its F is
    the lead, per revolution), whether it is a tapping cycle (``tap``: in to the end point and
    back out to the start, both at the lead per revolution, the spindle reversed between them),
    and the letter of its number of starts (``starts``: a thread of L starts is cut L times;
    modal, as the cycle's other words, unless ``starts_modal`` is off: one start where the block
    leaves it out); ``widening``: the letters of the crest width, the tool's width and the step
    along the long axis (modal, the step in least input increments) of a thread whose root is
    widened by passes stepped along it (GSK980TDi G92.3: E, A, Q; planner/turning_cycles.py)."""

    first: str
    rapid_out: bool = False
    thread: bool = False
    tap: bool = False
    starts: str | None = None
    starts_modal: bool = True
    widening: tuple[str, str, str] | None = None


LATHE_SINGLE_CYCLES: dict[float, SingleCycle] = {
    90.0: SingleCycle("X"),
    92.0: SingleCycle("X", rapid_out=True, thread=True),
    94.0: SingleCycle("Z"),
}
# GSK980TDi (its manual, §3.22 and §3.24): G92 and the rigid G92.1 and variable-pitch G92.3 thread
# cycles cut L starts (§3.24.9 "L：多头螺纹的头数 … 模态参数", §3.24.10, §3.24.14 as G92), and G33
# taps: "刀具的运动轨迹是从起点到终点，再从终点回到起点", each of its L starts in turn (§3.24.5)
GSK_SINGLE_CYCLES: dict[float, SingleCycle] = {
    90.0: SingleCycle("X"),
    92.0: SingleCycle("X", rapid_out=True, thread=True, starts="L"),
    92.1: SingleCycle("X", rapid_out=True, thread=True, starts="L"),
    # "余量加工循环切削的次数＝(F－E－A)/Q ＋ 1" (§3.24.14): E the crest, A the tool, Q the step
    92.3: SingleCycle("X", rapid_out=True, thread=True, widening=("E", "A", "Q")),
    94.0: SingleCycle("Z"),
    33.0: SingleCycle("Z", thread=True, tap=True, starts="L", starts_modal=False),  # "省略 L 时默认为 1 头"
}


@dataclass(frozen=True)
class LatheCycles:
    """A lathe control's threading and grooving data (docs/semantics.md §10.3):

    - ``thread_codes``: the modal G codes that cut a thread, their F the lead per revolution
      whatever G98/G99 says (G32, G34 on both lathe profiles; GSK's G33 taps instead);
    - ``variable_lead``: a variable-lead thread code and the word that gives its lead's change
      per revolution (G34: K on the FANUC 0i-TF, R on the GSK980TDi);
    - ``groove_x_on_diameter``: whether G74/G75's P(Δi) and G74's R(Δd), amounts along X, are
      diameters (GSK980TDi §3.23.5/§3.23.6 say so) rather than radii;
    - ``increment``: the millimetres of one unit of a cycle's P and Q written without a decimal
      point (the least input increment, 0.001 mm; a tenth of that in inches under G20);
    - ``one_block``: whether G71, G72, G73 and G76 take the first block's parameters in the
      block that runs the cycle, in the program's unit (Haas: ``G71 P Q U W D``, D the depth of
      cut, a radius; ``G73 P Q I K U W D``, I and K the relief, D the passes; ``G76 X Z K D A I
      F``, K the thread height and D the first pass's depth, radii, A the tool angle, I the
      taper, a radius), with no finishing pass beyond the one at full height.
      A two-block cycle (FANUC's notation, which such a control reads too) still takes its first
      block's words where the cycle block lacks them;
    - ``taper_letters``: the letter of a single cycle's taper where it is not R (Haas: I in
      G90 and G92, a radius, K in G94);
    - ``groove_letters``: the letters of G74/G75's step along X and step along Z where they are
      not P and Q (Haas: I and K, in the program's unit with a decimal point; X amounts radii);
    - ``left_hand``: the modal codes whose negative F (or I) is a left-hand thread of lead |F|
      (GSK980TDi: G32.1 §3.24.2, G92.1 §3.24.10, G84/G88 §3.24.6: "F（I）> 0 右旋螺纹，F（I）< 0
      左旋螺纹"); elsewhere a negative lead cuts nothing;
    - ``threads_per_inch``: the letter that gives a thread's pitch as threads per inch instead of
      F's lead (GSK980TDi: I in G32, G33, G92, G76, "每英寸螺纹的牙数"): the lead is 25.4 / I mm
      (1 / I inch under G20);
    - ``roughing_from_offset_start``: whether G71/G72 follow the GSK980TDi's numbered steps
      (§3.23.1, §3.23.2 ①–⑧): from the start point A at rapid to A′ (A moved by the finishing
      allowances), the levels Δd apart counted from A′, each cut's return along the cut axis to
      A′'s coordinate, and at the end from C′ straight to A at rapid; else the levels count from
      A and the tool comes back out, along and in to A;
    - ``roughing_retract_at_feed``: whether G71/G72's 45° retract e is cut at the feed (GSK step
      ④, "按切削进给速度退刀") rather than at rapid;
    - ``pattern_through_offset_starts``: whether each G73 pass starts at the start point offset
      as the pass (An), reached at rapid from A or from the last pass's end (Cn), and goes to the
      offset shape's first point (Bn) in the mode of the shape's first block, the last pass
      ending with a rapid to A (GSK §3.23.3 ①–⑤); else each pass goes from A to Bn at rapid and
      back to A at rapid;
    - ``pattern_min_passes``: the fewest passes G73 cuts (GSK §3.23.3: a count of 1 is cut in 2).
    """

    thread_codes: frozenset[float] = frozenset()
    variable_lead: dict[float, str] = field(default_factory=dict)
    groove_x_on_diameter: bool = False
    increment: float = 0.001
    one_block: bool = False
    taper_letters: dict[float, str] = field(default_factory=dict)
    groove_letters: tuple[str, str] | None = None
    threads_per_inch: str | None = None
    left_hand: frozenset[float] = frozenset()
    roughing_from_offset_start: bool = False
    roughing_retract_at_feed: bool = False
    pattern_through_offset_starts: bool = False
    pattern_min_passes: int = 1


FANUC_LATHE_CYCLES = LatheCycles(frozenset({32.0, 34.0}), {34.0: "K"})
# GSK980TDi: G32.1 (rigid), G32.2/G32.3 (arc threads, §3.24.3) cut at the lead too; G71/G72 and
# G73 move as their numbered steps say (§3.23.1–§3.23.3)
GSK_LATHE_CYCLES = LatheCycles(
    frozenset({32.0, 32.1, 32.2, 32.3, 34.0}),
    {34.0: "R"},
    groove_x_on_diameter=True,
    threads_per_inch="I",
    left_hand=frozenset({32.1, 92.1, 84.0, 88.0}),
    roughing_from_offset_start=True,
    roughing_retract_at_feed=True,
    pattern_through_offset_starts=True,
    pattern_min_passes=2,
)
