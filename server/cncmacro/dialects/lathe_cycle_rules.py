"""What a lathe control refuses in its multiple repetitive cycles (G70–G76): the data the
findings of docs/semantics.md §10.5 read, per profile. The rules themselves are
``planner/cycle_rules.py``'s.

- ``tool_angles``: the tool tip angles a G76 first block's P may give (its last two digits);
  None where any angle the P field holds is taken (GSK980TDi: 00–99).
- ``pockets``: how many pockets a type II shape of G71/G72 may have.
- ``shape_blocks``: how many blocks N(P)…N(Q) may hold (None: no limit stated).
- ``shape_g_codes``: the only G codes a shape may hold (None: the manual gives no list); a G
  code outside it is a warning, since the manual states the list but not the alarm.
- ``check_word``: the word of the second G71/G72 block that turns the monotone check on
  (``K1`` on the GSK980TDi); None where the control checks it by a parameter.
- ``thread_codes``: the thread cutting codes, whose blocks take no chamfer or corner R.
- ``surely``: the findings whose alarm the profile's manual documents (an error); the others
  are warnings (the manual states the rule but no alarm).

Sources: FANUC Series 0i-TF operator's manual, "Multiple repetitive cycle (G70–G76)" and its
alarm list (PS0061–PS0069, PS0315–PS0329); GSK980TDi programming manual §3.23.1–§3.23.6 and
§3.24.12 (docs/semantics.md §10.5).
"""

from __future__ import annotations

from dataclasses import dataclass

# the finding kinds (planner/cycle_rules.py), by the alarm each stands for
P_Q_MISSING = "p-q-missing"
DEPTH = "depth"
REPEAT = "repeat"
TOOL_ANGLE = "tool-angle"
THREAD_MIN_DEPTH = "thread-min-depth"
THREAD_DEPTH = "thread-depth"
GROOVE_RELIEF = "groove-relief"
GROOVE_END = "groove-end"
GROOVE_STEP_MISSING = "groove-step-missing"  # a warning on every profile: neither manual gives the step a default
GROOVE_AMOUNT = "groove-amount"
FIRST_BLOCK = "first-block"
LAST_BLOCK = "last-block"
SHAPE_COMMAND = "shape-command"
SHAPE_G_CODE = "shape-g-code"
SHAPE_BLOCKS = "shape-blocks"
THREAD_CORNER = "thread-corner"
LABEL_NOT_FOUND = "label-not-found"


@dataclass(frozen=True)
class LatheCycleRules:
    """A lathe profile's limits on its multiple repetitive cycles (module docstring)."""

    tool_angles: frozenset[float] | None
    pockets: int
    shape_blocks: int | None
    shape_g_codes: frozenset[float] | None
    check_word: str | None
    thread_codes: frozenset[float]
    surely: frozenset[str]


_COMMON_SURE = frozenset({P_Q_MISSING, DEPTH, REPEAT, THREAD_MIN_DEPTH, THREAD_DEPTH, GROOVE_END, GROOVE_AMOUNT,
                          FIRST_BLOCK, SHAPE_COMMAND, LABEL_NOT_FOUND})  # fmt: skip

# FANUC 0i-TF: G76's tool angles 80, 60, 55, 30, 29 and 0 (PS0315); type II up to 10 pockets
FANUC_LATHE_RULES = LatheCycleRules(
    tool_angles=frozenset({0.0, 29.0, 30.0, 55.0, 60.0, 80.0}),
    pockets=10,
    shape_blocks=None,
    shape_g_codes=None,
    check_word=None,
    thread_codes=frozenset({32.0, 34.0, 76.0, 92.0}),
    surely=_COMMON_SURE | {TOOL_ANGLE, LAST_BLOCK, THREAD_CORNER},
)

# GSK980TDi §3.23.1 notes 8, 9 and the K word; type II up to 20 pockets; G76's angle 00–99
GSK980TDI_RULES = LatheCycleRules(
    tool_angles=None,
    pockets=20,
    shape_blocks=200,
    shape_g_codes=frozenset(
        {0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.2, 6.3, 7.2, 7.3, 40.0, 41.0, 42.0, 96.0, 97.0, 98.0, 99.0}
    ),
    check_word="K",
    thread_codes=frozenset({32.0, 34.0, 76.0, 92.0}),
    surely=_COMMON_SURE,
)
