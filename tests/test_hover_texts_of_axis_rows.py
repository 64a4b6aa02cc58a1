"""A lathe's tool-offset-in-effect rows (#5081…) say "on the diameter" on the X axis only: the
row covers every axis, and the Z axis's #5082 used to end "(X on the diameter)"."""

from __future__ import annotations

from cncmacro.dialects import describe, get_dialect


def _text(profile: str, number: int, locale: str = "en") -> str:
    doc = describe.describe_system_variable(get_dialect(profile), number, locale)
    assert doc is not None
    return doc.text


def test_the_z_axis_tool_offset_says_nothing_of_x() -> None:
    # fanuc-0i-lathe axes X, Z, C, Y: #5081 X, #5082 Z
    assert "(on the diameter)" in _text("fanuc-0i-lathe", 5081)
    assert "diameter" not in _text("fanuc-0i-lathe", 5082) and "X" not in _text("fanuc-0i-lathe", 5082)
    assert "（直径值）" in _text("fanuc-0i-lathe", 5081, "zh-CN")
    assert "直径" not in _text("fanuc-0i-lathe", 5082, "zh-CN")
    assert "diameter" not in _text("haas-lathe", 5082) and "(on the diameter)" in _text("haas-lathe", 5081)
