"""docs/semantics.md §8 "G31": the skip position #5061… is in the same frame as the current
position #5041…. FANUC's position-information table marks both "tool offset included" (seed 003
§4.9; the YASNAC LX3 lathe's table: ABSKP "Included"), so under G43 the skip position carries the
tool length offset, and on a lathe the T offset. Haas keeps both without it (its #5041 row), so
its skip position stays the programmed point."""

from __future__ import annotations

from pathlib import Path

from cncmacro.library.machine_file import load_machine_file
from running import final, lines


def skip_table(tmp_path: Path, table: str) -> object:
    path = tmp_path / ".cncmacro.toml"
    path.write_text(table, encoding="utf-8")
    return load_machine_file(path).skip


# G10 L10 P20 R120.: H20 = 120 (geometry), no wear; G43 H20 adds 120 to Z.
# The face the programmed point meets is Z-10 ([skip] positions are the programmed point).
PROBE = (
    "G21 G17 G90 G40 G49 G80",
    "G10 L10 P20 R120.",
    "G54 G00 X0 Y0",
    "G43 H20 Z20.",
    "G31 Z-30. F200",
    "#101=#5063",
    "#102=#5043",
    "#103=#5003",
)


def test_skip_position_includes_the_tool_length_offset_as_the_current_position_does(tmp_path: Path) -> None:
    """The touch at programmed Z-10 with H20 = 120: #5063 = -10 + 120 = 110, the same as #5043;
    #5003 (block end point, no offset) = -10."""
    for dialect in ("fanuc", "fanuc-30i"):
        v = final(lines(*PROBE, "M30"), dialect, skip=skip_table(tmp_path, "[skip]\nZ = -10.0\n"))
        assert (v[101], v[102], v[103]) == (110, 110, -10), dialect


def test_skip_position_keeps_the_offset_in_force_at_the_touch(tmp_path: Path) -> None:
    """G49 after the G31 does not change the stored skip position: 110 stays; #5043 then reads
    the programmed Z, -10 (the tool stays where it is, the program position takes the difference
    only with the next move: here none)."""
    program = (*PROBE, "G49", "#104=#5063")
    v = final(lines(*program, "M30"), "fanuc", skip=skip_table(tmp_path, "[skip]\nZ = -10.0\n"))
    assert v[104] == 110


def test_skip_position_without_offset_and_no_hit(tmp_path: Path) -> None:
    """No G43 and no touch: #5063 is the end point, -30 (nothing to add)."""
    program = ("G90 G00 X0 Y0 Z20.", "G31 Z-30. F200", "#101=#5063")
    v = final(lines(*program, "M30"), "fanuc", skip=skip_table(tmp_path, "[skip]\nZ = -40.0\n"))
    assert v[101] == -30


def test_haas_skip_position_stays_the_programmed_point_as_its_current_position(tmp_path: Path) -> None:
    """Haas: #5043 reads the programmed Z (its table), and #5063 the same, -10. G43 H20 takes
    the length from #2020 (Haas's tool length offsets, #2001…)."""
    program = ("G21 G17 G90 G40 G49 G80", "#2020=120.", "G54 G00 X0 Y0", "G43 H20 Z20.", "G31 Z-30. F200",
               "#101=#5063", "#102=#5043")  # fmt: skip
    v = final(lines(*program, "M30"), "haas", skip=skip_table(tmp_path, "[skip]\nZ = -10.0\n"))
    assert (v[101], v[102]) == (-10, -10)


def test_lathe_skip_position_includes_the_t_offset(tmp_path: Path) -> None:
    """fanuc-0i-lathe: G10 P10001 Z2. sets offset 1's Z geometry to 2, T0101 puts it in force.
    The G31 along Z stops at the face Z-5 (the programmed point): #5062 (Z) = -5 + 2 = -3, as
    #5042 reads (YASNAC LX3's lathe table: ABSKP tool position offset "Included")."""
    program = ("G10 P10001 X0 Z2.", "T0101", "G00 X20. Z10.", "G98 G31 Z-20. F100", "#101=#5062", "#102=#5042")
    v = final(lines(*program, "M30"), "fanuc-0i-lathe", skip=skip_table(tmp_path, "[skip]\nZ = -5.0\n"))
    assert (v[101], v[102]) == (-3, -3)
