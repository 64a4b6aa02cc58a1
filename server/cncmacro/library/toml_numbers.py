"""A number of the machine file: what a TOML value must be to stand for a quantity.

TOML gives integers of any size, floats with ``inf`` and ``nan``, and booleans, which Python
counts as integers. ``finite_number`` is the one test the machine file's tables make of a number
(``machine_file.py``'s ``[variables]``, ``skip_model.py``'s positions and sizes,
``timing_settings.py``'s rates and seconds); each says in its own message what it wanted.
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
