"""Polar coordinate interpolation (G112, G12.1) and cylindrical interpolation (G07.1 C_) on a
FANUC 0i-TF turning centre (docs/semantics.md §8, planner/virtual_planes.py): their plane (X and C,
or Z and C on the cylinder) is not simulated, so the moves are drawn as written; what the run must
not do is judge them in G18's Z and X: no compensation pushing Z or X off the part, no arc "with
its end at its start", no alarm PS0037 at the G18 after G07.1 C0. Each program is a shop's
live-tool job; the positions are read off the program."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from cli_capture import cli, run_json
from running import lines

LATHE = "(cncmacro: dialect=fanuc-0i-lathe)"


def check(folder: Path, text: str) -> tuple[int, str]:
    path = folder / "O1001.nc"
    path.write_text(text, encoding="utf-8")
    code, out, _ = cli("check", str(path))
    return code, out


def test_a_slot_under_cylindrical_interpolation_stays_on_the_cylinder_and_is_timed_on_its_surface(
    tmp_path: Path,
) -> None:
    # a slot milled on a D54 cylinder: G19 W0 H0 and G07.1 C27. (its radius) on, G42 and G40 on C
    # moves, G07.1 C0 off, then G18: the tool stays at X54 (the cylinder), no Y, and no PS0037
    text = lines("O1001", LATHE, "G10 P10005 R4. Q0", "T0505", "G98 G00 X54. Z-20. C0.", "G19 W0 H0", "G07.1 C27.",
                 "G01 G42 C30. F250.", "Z-40.", "C90.", "G40 C120.", "G07.1 C0", "G18", "M30")  # fmt: skip
    assert check(tmp_path, text) == (0, "")
    result = run_json(tmp_path, text, "O1001.nc")
    slot = [mv for mv in result["moves"] if 8 <= mv["line"] <= 11]
    assert [(mv["to"]["X"], mv["to"]["Z"], mv["to"]["C"]) for mv in slot] == [
        (54.0, -20.0, 30.0), (54.0, -40.0, 30.0), (54.0, -40.0, 90.0), (54.0, -40.0, 120.0)]  # fmt: skip
    assert all(mv["to"].get("Y", 0.0) == 0.0 and "tool_path" not in mv for mv in slot)
    # on the cylinder's surface (radius 27): C30 is 27 x pi/6 = 14.137 mm, at F250 3.393 s; Z-40 is
    # 20 mm, 4.8 s; C90 (60 deg) 28.274 mm, 6.786 s; C120 14.137 mm, 3.393 s (C's degrees counted
    # as millimetres made them 7.2 s, 14.4 s and 7.2 s)
    arc = 27 * math.pi / 180
    assert [mv["time"] for mv in slot] == pytest.approx([30 * arc / 250 * 60, 20 / 250 * 60, 60 * arc / 250 * 60,
                                                         30 * arc / 250 * 60])  # fmt: skip


def test_compensation_under_polar_interpolation_keeps_the_face_depth(tmp_path: Path) -> None:
    # hex flats milled on the face at Z-5 under G112 with G42: Z stays at -5 from the plunge to the
    # retract (the offset was taken in G18's Z and X before: the tool went to Z-10)
    text = lines("O1001", LATHE, "G10 P10012 R5. Q0", "T1212", "G00 X60. Z5. C0.", "G97 S2000 M13",
                 "G98 G01 Z-5. F200.", "G112", "G42 G01 X40. C0. F300.", "C10.", "X20. C17.321", "X-20.",
                 "X-40. C0.", "X-20. C-17.321", "X20.", "X40. C0.", "G40 X60. C0.", "G113", "G00 Z5.",
                 "M30")  # fmt: skip
    assert check(tmp_path, text) == (0, "")
    result = run_json(tmp_path, text, "O1001.nc")
    flats = [mv for mv in result["moves"] if 9 <= mv["line"] <= 17]
    assert {mv["to"]["Z"] for mv in flats} == {-5.0}
    assert [mv["to"]["X"] for mv in flats] == [40.0, 40.0, 20.0, -20.0, -40.0, -20.0, 20.0, 40.0, 60.0]


def test_an_arc_in_x_and_c_under_polar_interpolation_is_no_zero_arc(tmp_path: Path) -> None:
    # G03 X40. C5. R5. from X40 C-5 turns half a circle in X and C; in G18 it would be an R arc
    # whose end is its start (Z and X the same)
    text = lines("O1001", LATHE, "G00 X50. Z2. C0.", "G112", "G98 G01 X20. C-5. F400.", "Z-3. F100.",
                 "G01 X40. C-5. F200.", "G03 X40. C5. R5.", "G01 X20. C5.", "G03 X20. C-5. R5.", "G00 Z2.",
                 "G113", "M30")  # fmt: skip
    assert check(tmp_path, text) == (0, "")
    arcs = [mv for mv in run_json(tmp_path, text, "O1001.nc")["moves"] if mv["line"] in (8, 10)]
    assert [(mv["to"]["X"], mv["to"]["C"]) for mv in arcs] == [(40.0, 5.0), (20.0, -5.0)]
