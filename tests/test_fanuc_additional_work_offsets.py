"""FANUC's additional workpiece coordinate systems on the mill and the lathe profile
(docs/semantics.md §8, "G154 extra work offsets"): ``G54.1 Pn`` and its other form ``G54 Pn``
select extra offset n (#7001 + 20(n-1) onwards), which the positions and #4130 read; a 0i-TF
lathe has them too (it was alarm 010 there). Expected values are worked by hand."""

from __future__ import annotations

import pytest

from running import final, lines


@pytest.mark.parametrize("profile", ["fanuc-0i", "fanuc-0i-lathe"])
@pytest.mark.parametrize("select", ["G54.1 P2", "G54 P2"])
def test_g54_1_pn_and_g54_pn_select_the_additional_offset_and_4130_reads_n(profile: str, select: str) -> None:
    # G10 L20 P2 Z-300. writes extra offset P2's Z (#7023 on the mill, the third axis; on the
    # lathe X, Z are axes 1, 2: #7022). After G00 Z5. in P2, the machine Z (#5023 / #5022) is
    # 5 - 300 = -295; #4130 reads 2 and #4014 54.1 while P2 is in force; after G54, #4130
    # reads 0 and #4014 54
    z = 5023 if profile == "fanuc-0i" else 5022
    text = lines(f"(cncmacro: dialect={profile})", "G10 L20 P2 Z-300.", select, "G00 Z5.", f"#100=#{z}",
                 "#101=#4130", "#102=#4014", "G54", "#103=#4130", "#104=#4014", "M30")  # fmt: skip
    v = final(text, profile)
    assert (v[100], v[101], v[102], v[103], v[104]) == (-295.0, 2.0, 54.1, 0.0, 54.0)
