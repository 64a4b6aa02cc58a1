"""Haas G28: with no axis word it returns every axis to machine zero, and it cancels the tool
length offset (Haas mill operator's manual 96-8000, "G28 Return to Machine Zero Thru Optional
G29 Reference Point": "G28 is used to return all axes to machine zero, unless an axis (or axes)
is specified, in which case only that axis (or axes) is returned to machine zero. G28 cancels
tool length offsets for the following lines of code."; docs/semantics.md §8 "G28"). FANUC's G28
with no axis word moves nothing."""

from __future__ import annotations

import pytest

from running import lines, run

# G54 X-20. Y-10. Z-20. (inches), length offset 1 = 5.; G43 H01 Z1. puts machine Z at -20 + 1 + 5 = -14
_SETUP = ("O1011", "G20 G17 G40 G80 G90 G94", "G10 L2 P1 X-20. Y-10. Z-20.", "G10 L10 P1 R5.", "T1 M06",
          "G00 G54 X1. Y2.", "G43 H01 Z1.")  # fmt: skip


def test_haas_g28_cancels_the_tool_length_offset() -> None:
    # G28 G91 Z0. homes Z (machine 0) and cancels G43: #4008 reads 49 and G00 Z5. goes to machine
    # Z -20 + 5 = -15 (with the offset kept it went to -10)
    text = lines(*_SETUP, "G28 G91 Z0.", "G90", "#101=#5023", "#102=#4008", "G00 Z5.", "#103=#5023", "M30")
    v = run(text, "haas").variables()
    assert (v[101], v[102], v[103]) == pytest.approx((0.0, 49.0, -15.0))


def test_haas_g28_with_axes_keeps_the_others_where_they_are() -> None:
    # G28 X3. Y4. homes X and Y through X3 Y4; Z stays at machine -14 (its offset cancelled, the
    # tool not moved): #5021, #5022, #5023 = 0, 0, -14
    text = lines(*_SETUP, "G28 X3. Y4.", "#104=#5021", "#105=#5022", "#106=#5023", "#107=#4008", "M30")
    v = run(text, "haas").variables()
    assert (v[104], v[105], v[106], v[107]) == pytest.approx((0.0, 0.0, -14.0, 49.0))


def test_haas_g28_without_axes_returns_every_axis_to_machine_zero() -> None:
    # G00 G54 X1. Y1. (machine X -19, Y -9, Z -14), then G28: X, Y, Z at machine 0
    text = lines(*_SETUP, "G00 G90 G54 X1. Y1.", "G28", "#107=#5021", "#108=#5022", "#109=#5023", "M30")
    v = run(text, "haas").variables()
    assert (v[107], v[108], v[109]) == pytest.approx((0.0, 0.0, 0.0))


def test_fanuc_g28_without_axes_moves_nothing_and_keeps_the_length_offset() -> None:
    # FANUC: G28 alone moves nothing; G28 Z0 keeps G43 (#4008 43)
    text = lines("O1", "G21 G90 G10 L2 P1 X-20. Y-10. Z-20.", "G10 L10 P1 R5.", "G00 G54 X1. Y1.", "G43 H01 Z1.",
                 "G28", "#101=#5021", "#102=#5023", "G28 Z0", "#103=#4008", "M30")  # fmt: skip
    v = run(text, "fanuc").variables()
    assert (v[101], v[102], v[103]) == pytest.approx((-19.0, -14.0, 43.0))
