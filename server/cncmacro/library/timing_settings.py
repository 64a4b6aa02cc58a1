"""The machine file's ``[timing]`` table: the machine's own data for the cycle time.

::

    [timing]
    rapid = { X = 30000, Y = 30000, Z = 24000 }   # mm/min per axis (FANUC parameter 1420)
    tool_change = 2.5              # seconds a tool change takes
    tool_change_code = "M6"        # "M6" (mills) or "T" (a lathe's turret indexes on T)
    dwell_p = "milliseconds"       # the unit of G04 P: "milliseconds" or "seconds"
    max_spindle_speed = 3500       # rev/min, G96's limit
    peck_retract = 0.5             # mm, G73's retract after each peck (FANUC parameter 5114)
    peck_clearance = 1.0           # mm, where G83's rapid back in stops (parameter 5115)

    [timing.m_codes]               # seconds an M code takes
    M08 = 0.5

Every key is optional and goes over the profile's value (``dialects/timing.py``); ``rapid`` and
``m_codes`` axis by axis and code by code. ``timing_changes`` checks the table and gives the
changes as ``Timing.changed`` takes them; a wrong value is an error naming its key.
"""

from __future__ import annotations

from collections.abc import Callable

from ..bilingual import Detail, detail
from ..dialects.timing import TimingChanges
from .toml_numbers import machine_quantity, quantity_range

_KEYS = ("rapid", "tool_change", "tool_change_code", "dwell_p", "max_spindle_speed", "peck_retract",
         "peck_clearance", "m_codes")  # fmt: skip
_DWELL_UNITS = {"milliseconds": 0.001, "seconds": 1.0}


def _number(v: object, kind: str) -> float | None:
    """``v`` as a machine's figure of ``kind``, 0 or more (``toml_numbers.machine_quantity``), or None."""
    return machine_quantity(v, kind)


def timing_changes(table: object, fail: Callable[[str, Detail], Exception]) -> TimingChanges:
    """The changes ``[timing]`` makes to the profile's ``Timing`` (module docstring)."""
    if not isinstance(table, dict):
        raise fail("timing", detail("must be a table ([timing])", "必须是表（[timing]）"))
    out: TimingChanges = {}
    for key in table:
        if key not in _KEYS:
            names = ", ".join(_KEYS)
            raise fail(f"timing.{key}", detail(f"is not a timing setting (known: {names})",
                                               f"不是时间设置项（可用的有：{names}）"))  # fmt: skip
    if "rapid" in table:
        rapid = table["rapid"]
        rates = {str(k).upper(): _number(v, "rate") for k, v in rapid.items()} if isinstance(rapid, dict) else None
        if rates is None or not all(len(k) == 1 and k.isascii() and k.isalpha() and r for k, r in rates.items()):
            rng = quantity_range("rate", True)
            raise fail("timing.rapid", detail(f"must map axis letters to rapid rates ({rng} mm/min), "
                                              "such as { X = 30000, Z = 24000 }",
                                              f"必须是“轴地址 = 快移速度”（{rng} mm/min）形式的表，"
                                              "如 { X = 30000, Z = 24000 }"))  # fmt: skip
        out["rapid"] = {k: r for k, r in rates.items() if r}  # every rate is above 0 here
    if "tool_change" in table:
        v = _number(table["tool_change"], "seconds")
        if v is None:
            rng = quantity_range("seconds")
            raise fail("timing.tool_change", detail(f"must be the seconds a tool change takes ({rng})",
                                                    f"必须是换刀所需的秒数（{rng}）"))  # fmt: skip
        out["tool_change_seconds"] = v
    if "tool_change_code" in table:
        code = table["tool_change_code"]
        if not isinstance(code, str) or not (code.upper() == "T" or _m_code(code) is not None):
            raise fail("timing.tool_change_code", detail('must be an M code ("M6") or "T"',
                                                         '必须是 M 代码（"M6"）或 "T"'))  # fmt: skip
        m = _m_code(code)
        out["tool_change_code"] = "T" if m is None else f"M{m:g}"
    if "dwell_p" in table:
        unit = table["dwell_p"]
        if unit not in _DWELL_UNITS:
            raise fail("timing.dwell_p", detail('must be "milliseconds" or "seconds"',
                                                '必须是 "milliseconds"（毫秒）或 "seconds"（秒）'))  # fmt: skip
        out["dwell_p_unit"] = _DWELL_UNITS[str(unit)]
    if "max_spindle_speed" in table:
        v = _number(table["max_spindle_speed"], "speed")
        if not v:
            rng = quantity_range("speed", True)
            raise fail("timing.max_spindle_speed", detail(f"must be a speed in rev/min ({rng})",
                                                          f"必须是转速，r/min（{rng}）"))  # fmt: skip
        out["max_spindle_speed"] = v
    for key, what, what_zh in (("peck_retract", "G73 retracts after each peck", "G73 每次啄钻后的回退量"),
                               ("peck_clearance", "above the depth reached where G83's rapid back in stops",
                                "G83 快速返回孔内时停在已钻深度之上的距离")):  # fmt: skip
        if key in table:
            v = _number(table[key], "length")
            if v is None:
                rng = quantity_range("length")
                raise fail(f"timing.{key}", detail(f"must be the distance in mm {what} ({rng})",
                                                   f"必须是{what_zh}（mm，{rng}）"))  # fmt: skip
            if key == "peck_retract":
                out["peck_retract"] = v
            else:
                out["peck_clearance"] = v
    if "m_codes" in table:
        codes = table["m_codes"]
        rng = quantity_range("seconds")
        bad = detail(
            f"must map M codes to seconds ({rng}), such as {{ M08 = 0.5 }}",
            f"必须是“M 代码 = 秒数”（{rng}）形式的表，如 {{ M08 = 0.5 }}",
        )
        if not isinstance(codes, dict):
            raise fail("timing.m_codes", bad)
        seconds: dict[float, float] = {}
        for k, v in codes.items():
            m, s = _m_code(str(k)), _number(v, "seconds")
            if m is None or s is None:
                raise fail(f"timing.m_codes.{k}", bad)
            seconds[m] = s
        out["m_code_seconds"] = seconds
    return out


def _m_code(text: str) -> float | None:
    """``M08`` -> 8.0; None when ``text`` is not an M code."""
    digits = text[1:]
    if text[:1].upper() != "M" or not digits.isascii() or not digits.isdigit() or len(digits) > 8:
        return None
    return float(digits)
