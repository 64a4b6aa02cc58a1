"""docs/semantics.md §8 "G31 and the skip position", docs/machine-file.md "Probing: the [skip]
table": each G31 stops where the machine file's part says (a contact point of its sequence, else
the first plane, bore or boss the straight move reaches), or at its end point with the signal
off; #5061… hold where it stopped. Each test is a small program with the machine file's
``[skip]`` table and the final skip positions it must leave."""

from __future__ import annotations

from pathlib import Path

import pytest

from cncmacro.library.machine_file import MachineFileError, load_machine_file
from cncmacro.machine import Machine
from running import final, lines, machine

SKIP_VARIABLES = ("#101=#5061", "#102=#5062", "#103=#5063")


def skip_table(tmp_path: Path, table: str) -> object:
    """The ``[skip]`` of a machine file holding ``table``."""
    path = tmp_path / ".cncmacro.toml"
    path.write_text(table, encoding="utf-8")
    return load_machine_file(path).skip


def skip_positions(tmp_path: Path, table: str, *program: str, dialect: str = "fanuc") -> tuple[float, ...]:
    """#5061, #5062, #5063 after ``program`` (then its skip positions copied to #101–#103)."""
    v = final(lines(*program, *SKIP_VARIABLES, "M30"), dialect, skip=skip_table(tmp_path, table))
    return v[101], v[102], v[103]


def test_g31_plane_hit_stops_where_the_move_reaches_the_plane(tmp_path: Path) -> None:
    table = "[skip]\nZ = -12.5\n"
    assert skip_positions(tmp_path, table, "G90 G00 X5 Y6 Z10", "G31 Z-20 F100") == (5, 6, -12.5)


def test_g31_incremental_and_the_next_block_start_where_the_skip_stopped(tmp_path: Path) -> None:
    """G91 G31 measures from where the tool is; the block after a touch goes on from the contact."""
    table = "[skip]\nbore = { X = 0, Y = 0, diameter = 50 }\n"
    program = ("G90 G00 X0 Y0 Z-5", "G91 G31 X30 F100", "G01 X-2 F500", "G90", "#104=#5001")
    v = final(lines(*program, *SKIP_VARIABLES, "M30"), skip=skip_table(tmp_path, table))
    assert (v[101], v[104]) == (25, 23)


def test_g31_plane_hit_takes_the_first_plane_along_the_move(tmp_path: Path) -> None:
    """X = ±40 and Y = 30: a diagonal move from the origin reaches Y30 (halfway) before X40."""
    table = "[skip]\nX = [-40, 40]\nY = 30\n"
    assert skip_positions(tmp_path, table, "G90 G00 X0 Y0 Z0", "G31 X60 Y60 F100") == (30, 30, 0)
    assert skip_positions(tmp_path, table, "G90 G00 X0 Y0 Z0", "G31 X-50 F100") == (-40, 0, 0)


def test_g31_bore_hit_stops_where_the_move_leaves_the_bore(tmp_path: Path) -> None:
    table = "[skip]\nbore = { X = 0, Y = 0, diameter = 50 }\n"
    assert skip_positions(tmp_path, table, "G90 G00 X0 Y0 Z-5", "G31 X30 F100") == (25, 0, -5)
    assert skip_positions(tmp_path, table, "G90 G00 X0 Y0 Z-5", "G31 Y-30 F100") == (0, -25, -5)
    x, y, z = skip_positions(tmp_path, table, "G90 G00 X0 Y0 Z-5", "G31 X30 Y30 F100")
    assert (x, y, z) == pytest.approx((25 / 2**0.5, 25 / 2**0.5, -5))


def test_g31_bore_hit_off_centre_and_in_several_bores(tmp_path: Path) -> None:
    table = "[[skip.bore]]\nX = 100\nY = 50\ndiameter = 20\n[[skip.bore]]\nX = -100\nY = 0\ndiameter = 40\n"
    assert skip_positions(tmp_path, table, "G90 G00 X100 Y50", "G31 X120 F100") == (110, 50, 0)
    assert skip_positions(tmp_path, table, "G90 G00 X-100 Y0", "G31 X-130 F100") == (-120, 0, 0)


def test_g31_boss_hit_stops_where_the_move_comes_into_the_boss(tmp_path: Path) -> None:
    table = "[skip]\nboss = { X = 0, Y = 0, diameter = 30 }\nZ = -20\n"
    assert skip_positions(tmp_path, table, "G90 G00 X-40 Y0 Z-5", "G31 X0 F100") == (-15, 0, -5)
    # going down beside the boss: its wall is never crossed, the floor Z-20 is
    assert skip_positions(tmp_path, table, "G90 G00 X-40 Y0 Z-5", "G31 Z-30 F100") == (-40, 0, -20)


def test_g31_no_hit_ends_at_the_end_point_with_the_signal_off(tmp_path: Path) -> None:
    """Nothing in the way: the control runs the block to its end and #5061… hold that end point."""
    table = "[skip]\nbore = { X = 0, Y = 0, diameter = 50 }\nZ = -12.5\n"
    assert skip_positions(tmp_path, table, "G90 G00 X0 Y0 Z-5", "G31 X10 F100") == (10, 0, -5)
    assert skip_positions(tmp_path, table, "G90 G00 X0 Y0 Z-5", "G31 X20 Y5 Z-10 F100") == (20, 5, -10)
    m = machine(lines("G90 G00 X0 Y0 Z-5", "G31 X10 F100", "M30"), skip=skip_table(tmp_path, table))
    m.run()
    assert [n.message for n in m.notes if n.kind == "skip"] == [
        "G31 reached its end point X10: the skip signal did not come on"
    ]
    assert not m.planner.probes[0].hit
    assert skip_positions(tmp_path, "", "G90 G00 X1 Y2 Z3", "G31 Z-20 F100") == (1, 2, -20)


def test_g31_contact_point_sequence_gives_each_g31_its_point_in_order(tmp_path: Path) -> None:
    table = '[skip]\ncontacts = [{ X = 24.98 }, { X = -25.02, Y = 0.01 }, "miss"]\n'
    program = ("G90 G00 X0 Y0 Z-5", "G31 X30 F100", "#111=#5061", "G00 X0", "G31 X-30 F100", "#112=#5061",
               "#113=#5062", "G00 X0 Y0", "G31 Y30 F100")  # fmt: skip
    v = final(lines(*program, *SKIP_VARIABLES, "M30"), skip=skip_table(tmp_path, table))
    assert (v[111], v[112], v[113]) == (24.98, -25.02, 0.01)
    assert (v[101], v[102], v[103]) == (0, 30, -5)  # "miss": the third G31 ran to its end point


def test_g31_sequence_exhausted_the_model_decides_the_rest(tmp_path: Path) -> None:
    table = "[skip]\ncontacts = [{ Z = -0.35 }]\nZ = -1\n"
    program = ("G90 G00 Z10", "G31 Z-5 F100", "#111=#5063", "G00 Z10", "G31 Z-5 F100")
    v = final(lines(*program, *SKIP_VARIABLES, "M30"), skip=skip_table(tmp_path, table))
    assert (v[111], v[103]) == (-0.35, -1)


def test_g31_sequence_exhausted_without_a_model_ends_at_the_end_point(tmp_path: Path) -> None:
    table = "[skip]\ncontacts = [{ Z = -0.35 }]\n"
    program = ("G90 G00 Z10", "G31 Z-5 F100", "#111=#5063", "G00 Z10", "G31 Z-5 F100")
    v = final(lines(*program, *SKIP_VARIABLES, "M30"), skip=skip_table(tmp_path, table))
    assert (v[111], v[103]) == (-0.35, -5)


def test_g31_skip_position_fills_every_axis_of_the_profile(tmp_path: Path) -> None:
    """Haas has six axes: #5061–#5066; the contact point names A and C too."""
    table = "[skip]\ncontacts = [{ X = 1, Y = 2, Z = 3, A = 4, C = 6 }]\n"
    program = ("G90 G00 X0 Y0 Z10 A0 B5 C0", "G31 Z-5 F100", "#104=#5064", "#105=#5065", "#106=#5066")
    v = final(lines(*program, *SKIP_VARIABLES, "M30"), "haas", skip=skip_table(tmp_path, table))
    assert [v[n] for n in range(101, 107)] == [1, 2, 3, 4, 5, 6]  # B was not named: its end point


def test_g31_going_back_past_a_g31_gives_its_contact_point_back(tmp_path: Path) -> None:
    """A snapshot (the debugger's step back) holds how many contact points were used."""
    table = "[skip]\ncontacts = [{ X = 1 }, { X = 2 }]\n"
    m: Machine = machine(lines("G31 X10 F100", "#101=#5061", "M30"), skip=skip_table(tmp_path, table))
    before = m.snapshot()
    m.run()
    assert m.read(101) == 1 and len(m.planner.probes) == 1
    m.restore(before)
    assert m.planner.probes == []
    m.run()
    assert m.read(101) == 1


@pytest.mark.parametrize(
    ("table", "key", "line", "words"),
    [
        ("[skip]\ncylinder = { X = 0, Y = 0, diameter = 5 }\n", "skip.cylinder", 2, "not an axis letter or a shape"),
        ('[skip]\nZ = -1\nbore = { X = 0, Y = 0, diameter = "50" }\n', "skip.bore", 3, "diameter"),
        ("[skip]\nbore = { X = 0, diameter = 50 }\n", "skip.bore", 2, "two axes"),
        ("[skip]\nboss = 5\n", "skip.boss", 2, "two axes"),
        ('[skip]\n\nX = "left"\n', "skip.X", 3, "finite numbers"),
        ("[skip]\nZ = []\n", "skip.Z", 2, "position"),
        ("[skip]\ncontacts = [{ X = 1 }, { X = true }]\n", "skip.contacts", 2, "contact 2"),
        ("[skip]\ncontacts = { X = 1 }\n", "skip.contacts", 2, "list of contact points"),
        ('base = "fanuc"\nskip = 3\n', "skip", 2, "table"),
        ("# a hostile file\n[skip]\nX = [" + ", ".join(["1"] * 201) + "]\n", "skip", 2, "more than 200 surfaces"),
        (
            "[[skip.bore]]\nX = 0\nY = 0\ndiameter = 10\n[[skip.bore]]\nX = 0\nY = 0\ndiameter = -1\n",
            "skip.bore",
            1,
            "(table 2)",
        ),
    ],
)
def test_g31_bad_skip_table_is_an_error_naming_its_line(
    tmp_path: Path, table: str, key: str, line: int, words: str
) -> None:
    with pytest.raises(MachineFileError) as e:
        skip_table(tmp_path, table)
    assert e.value.key == key and e.value.line == line - 1
    assert words in str(e.value) and key in str(e.value) and e.value.located().endswith(f"(line {line})")
    assert e.value.args[0].zh  # and in Chinese


GSK_SKIP_COMMONS = ("#101=#995", "#102=#996", "#103=#997", "#104=#998", "#105=#999")


def test_g31_on_gsk980tdi_stores_where_the_signal_came_on_in_995_to_999(tmp_path: Path) -> None:
    """GSK980TDi manual §3.16.2: "跳转信号变为“1”时绝对坐标位置被存储在用户宏变量中(#995～#999 分别对应
    X，Z，Y，4th，5th)". The face at Z2: from X40 Z10 the G31 stops at Z2, so #995 = 40 (X as the
    program writes it, a diameter), #996 = 2, #997 = #998 = #999 = 0 (Y, C, B where they are)."""
    table = "[skip]\nZ = 2\n"
    program = ("#995=-1", "#996=-1", "#997=-1", "#998=-1", "#999=-1", "G00 X40 Z10", "G98 G31 Z-20 F50")
    v = final(lines(*program, *GSK_SKIP_COMMONS, "M30"), "gsk980tdi", skip=skip_table(tmp_path, table))
    assert [v[n] for n in range(101, 106)] == [40, 2, 0, 0, 0]


def test_g31_on_gsk980tdi_stores_x_as_a_diameter_and_a_miss_leaves_them(tmp_path: Path) -> None:
    """A diameter probed from X40 down to X30 touches at X35.5 (the contact point, work coordinates
    as the program writes them): #995 = 35.5, #996 = 10 (Z where it is). The second G31 misses: the
    manual says nothing of a G31 that ends without the signal, so #995 and #996 stay 35.5 and 10,
    though the tool ends at X20 Z0."""
    table = '[skip]\ncontacts = [{ X = 35.5 }, "miss"]\n'
    program = ("G00 X40 Z10", "G31 X30 F50", "#106=#995", "#107=#996", "G00 X40 Z10", "G31 X20 Z0 F50")
    v = final(lines(*program, *GSK_SKIP_COMMONS, "#108=#5001", "M30"), "gsk980tdi", skip=skip_table(tmp_path, table))
    assert (v[106], v[107], v[101], v[102], v[108]) == (35.5, 10, 35.5, 10, 20)


def test_g31_on_gsk980tdi_without_a_skip_table_leaves_995_to_999_as_they_were() -> None:
    """``cncmacro run`` without [skip]: the G31 runs to its end with the signal off; #996 keeps -999."""
    v = final(lines("#996=-999", "G00 X40 Z10", "G31 Z-20 F50", "#102=#996", "M30"), "gsk980tdi")
    assert v[102] == -999
