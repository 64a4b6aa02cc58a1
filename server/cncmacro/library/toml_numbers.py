"""A number of the machine file: what a TOML value must be to stand for a quantity.

TOML gives integers of any size, floats with ``inf`` and ``nan``, and booleans, which Python
counts as integers. ``finite_number`` is the one test the machine file's tables make of a number
(``machine_file.py``'s ``[variables]``, ``skip_model.py``'s positions and sizes,
``timing_settings.py``'s rates and seconds); each says in its own message what it wanted.
``machine_quantity`` also holds a machine's own figure (a time, a rate, a speed, a length) to
what a machine can have (``TOPS``): ``tool_change = 1e308`` is finite, but two tool changes
would make the cycle time infinite.
"""

from __future__ import annotations


def finite_number(value: object) -> float | None:
    """``value`` as a finite float, or None: a bool, text, an integer too large for a float,
    inf or nan is not a number here."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    try:
        v = float(value)
    except OverflowError:
        return None
    return v if abs(v) < float("inf") else None


# The most a machine's own figure can be, by kind: generous beyond any machine built (the fastest
# linear-motor axes rapid at about 120 m/min, spindles turn up to about 200,000 rev/min), so no
# real machine file is refused, and far enough below a double's range that no sum of them in a
# run can overflow.
TOPS = {
    "seconds": 3_600.0,  # a tool change, an M code: an hour
    "rate": 1_000_000.0,  # mm/min: a kilometre a minute
    "speed": 1_000_000.0,  # rev/min
    "length": 100_000.0,  # mm: a hundred metres of travel
}


def machine_quantity(value: object, kind: str, above_zero: bool = False) -> float | None:
    """``value`` as a machine's figure of ``kind`` (``TOPS``): a finite number from 0 (above 0
    with ``above_zero``) to the kind's top, or None."""
    v = finite_number(value)
    if v is None or v < 0.0 or (above_zero and v == 0.0) or v > TOPS[kind]:
        return None
    return v


def quantity_range(kind: str, above_zero: bool = False) -> str:
    """The range ``machine_quantity`` takes, for a message: ``0 to 3600``, ``above 0, at most 1000000``."""
    top = f"{TOPS[kind]:g}" if TOPS[kind] < 1e6 else f"{TOPS[kind]:.0f}"
    return f"above 0, at most {top}" if above_zero else f"0 to {top}"
