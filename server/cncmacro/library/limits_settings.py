"""The machine file's ``[limits]`` table: what the machine can do, which a run is held to.

::

    [limits]
    travel = { X = [-500, 0], Y = [-400, 0], Z = [-450, 0] }   # machine coordinates, mm
    feed = 10000        # the highest cutting feed, mm/min (FANUC parameter 1430/1432)
    rapid = 30000       # the rapid rate of every axis, mm/min, or { X = 30000, Z = 24000 }
    spindle = 8000      # the highest spindle speed, rev/min (FANUC parameter 3772)
    tools = [1, 24]     # the T numbers the magazine or turret holds ([[1, 24], [101, 110]] too)
    offsets = [1, 200]  # the tool offset numbers (D, H, a lathe's T offset) the control has

Every key is optional; without the table nothing of it is checked (docs/machine-file.md).
``rapid`` is the timing's rapid rate and ``spindle`` its top spindle speed (``[timing]``'s
``rapid`` and ``max_spindle_speed``, ``dialects/timing.py``): one fact each, so the machine file
gives each in one of the two tables; ``read_limits`` hands them on as timing changes.
A wrong value is an error naming its key.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

from ..bilingual import Detail, detail
from ..dialects.timing import TimingChanges
from .toml_numbers import TOPS, finite_number, machine_quantity, quantity_range

_KEYS = ("travel", "feed", "rapid", "spindle", "tools", "offsets")


@dataclass(frozen=True)
class MachineLimits:
    """The machine's limits a run is held to (module docstring): the travel of each axis in
    machine coordinates (axis letter -> (lowest, highest), mm; a lathe's X as a diameter), the
    highest cutting feed (mm/min), whether the spindle's top speed is the machine's own (then an
    S above it is a warning), and the T numbers and tool offset numbers the machine has, as
    ranges; None where the table does not say."""

    travel: dict[str, tuple[float, float]] = field(default_factory=dict)
    feed: float | None = None
    spindle: float | None = None
    tools: tuple[tuple[int, int], ...] | None = None
    offsets: tuple[tuple[int, int], ...] | None = None


def read_limits(
    table: object, timing: TimingChanges, axes: tuple[str, ...], fail: Callable[[str, Detail], Exception]
) -> tuple[MachineLimits, TimingChanges]:
    """``[limits]`` as ``MachineLimits``, with ``timing`` (the ``[timing]`` changes read so far)
    and the rapid rate and spindle speed it gives added to them; ``axes`` are the profile's, each
    of which a single ``rapid`` rate is the rate of."""
    if not isinstance(table, dict):
        raise fail("limits", detail("must be a table ([limits])", "必须是表（[limits]）"))
    for key in table:
        if key not in _KEYS:
            names = ", ".join(_KEYS)
            raise fail(f"limits.{key}", detail(f"is not a limit of the machine (known: {names})",
                                               f"不是机床限制的设置项（可用的有：{names}）"))  # fmt: skip
    timing = timing.copy()
    travel = _travel(table["travel"], axes, fail) if "travel" in table else {}
    feed = _rate(table, "feed", fail) if "feed" in table else None
    spindle = None
    if "rapid" in table:
        if "rapid" in timing:
            raise fail("limits.rapid", _twice("rapid", "[timing] rapid"))
        rapid = table["rapid"]
        if isinstance(rapid, dict):
            rates = {str(k).upper(): machine_quantity(v, "rate", above_zero=True) for k, v in rapid.items()}
            if not all(len(k) == 1 and k.isascii() and k.isalpha() and r for k, r in rates.items()):
                rng = quantity_range("rate", True)
                raise fail("limits.rapid", detail(f"must be a rate ({rng} mm/min) or a table of axis = rate, "
                                                  "such as { X = 30000, Z = 24000 }",
                                                  f"必须是速度（{rng} mm/min），或“轴地址 = 速度”形式的表，"
                                                  "如 { X = 30000, Z = 24000 }"))  # fmt: skip
            timing["rapid"] = {k: r for k, r in rates.items() if r}
        else:
            every = _rate(table, "rapid", fail)
            timing["rapid"] = dict.fromkeys(axes, every)
            timing["rapid_default"] = every
    if "spindle" in table:
        if "max_spindle_speed" in timing:
            raise fail("limits.spindle", _twice("spindle", "[timing] max_spindle_speed"))
        spindle = _rate(table, "spindle", fail, "rev/min", "r/min", "speed")
        timing["max_spindle_speed"] = spindle
    tools = _ranges(table["tools"], "limits.tools", fail) if "tools" in table else None
    offsets = _ranges(table["offsets"], "limits.offsets", fail) if "offsets" in table else None
    return MachineLimits(travel, feed, spindle, tools, offsets), timing


def _twice(key: str, other: str) -> Detail:
    return detail(f"is the same fact as {other}: give it in one of the two tables",
                  f"与 {other} 是同一项数据：只在其中一个表中给出")  # fmt: skip


def _rate(table: dict[str, object], key: str, fail: Callable[[str, Detail], Exception], unit: str = "mm/min",
          unit_zh: str = "mm/min", kind: str = "rate") -> float:  # fmt: skip
    """A rate (or with ``kind`` "speed" a spindle speed) above 0 under ``key``, at most what a
    machine can have (``toml_numbers.machine_quantity``)."""
    v = machine_quantity(table[key], kind, above_zero=True)
    if v is None:
        rng = quantity_range(kind, True)
        raise fail(f"limits.{key}", detail(f"must be a number {rng} ({unit})", f"必须是数值，{rng}（{unit_zh}）"))
    return v


def _coordinate(v: object) -> float | None:
    """A machine coordinate: a finite number within a machine's travel either side of zero."""
    f = finite_number(v)
    return f if f is not None and abs(f) <= TOPS["length"] else None


def _travel(
    value: object, axes: tuple[str, ...], fail: Callable[[str, Detail], Exception]
) -> dict[str, tuple[float, float]]:
    """``travel``: axis letter -> [lowest, highest] in machine coordinates, for an axis of the
    profile (``axes``): a letter it does not have would never be checked."""
    bad = detail("must map axis letters to [lowest, highest] in machine coordinates, "
                 "such as { X = [-500, 0], Z = [-450, 0] }",
                 "必须是“轴地址 = [最小值，最大值]”（机床坐标）形式的表，"
                 "如 { X = [-500, 0], Z = [-450, 0] }")  # fmt: skip
    if not isinstance(value, dict):
        raise fail("limits.travel", bad)
    out: dict[str, tuple[float, float]] = {}
    for k, v in value.items():
        axis = str(k).upper()
        pair = [_coordinate(x) for x in v] if isinstance(v, list) and len(v) == 2 else None
        if len(axis) != 1 or not axis.isascii() or not axis.isalpha() or pair is None:
            raise fail(f"limits.travel.{k}", bad)
        low, high = pair
        if low is None or high is None:
            raise fail(f"limits.travel.{k}", bad)
        if axis not in axes:
            names = ", ".join(axes)
            raise fail(f"limits.travel.{k}", detail(f"is not an axis of the profile ({names})",
                                                    f"不是该系统的轴（{names}）"))  # fmt: skip
        if low > high:
            raise fail(f"limits.travel.{k}", detail(f"gives its lowest {low:g} above its highest {high:g}",
                                                    f"最小值 {low:g} 大于最大值 {high:g}"))  # fmt: skip
        out[axis] = (low, high)
    return out


def _ranges(value: object, key: str, fail: Callable[[str, Detail], Exception]) -> tuple[tuple[int, int], ...]:
    """``tools``/``offsets``: ``[first, last]``, or a list of such ranges."""
    bad = detail("must be a range [first, last] of whole numbers, or a list of them such as [[1, 24], [101, 110]]",
                 "必须是整数范围 [起始，结束]，或这样的范围的列表，如 [[1, 24], [101, 110]]")  # fmt: skip

    def pair(x: object) -> tuple[int, int] | None:
        if isinstance(x, list) and len(x) == 2 and all(isinstance(v, int) and not isinstance(v, bool) for v in x):
            return (x[0], x[1]) if 0 <= x[0] <= x[1] <= 99_999_999 else None
        return None

    if not isinstance(value, list) or not value:
        raise fail(key, bad)
    single = pair(value)
    if single is not None:
        return (single,)
    out = []
    for x in value:
        p = pair(x)
        if p is None:
            raise fail(key, bad)
        out.append(p)
    return tuple(out)
