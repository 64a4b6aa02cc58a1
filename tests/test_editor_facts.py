"""The small pure functions the editor features ask of the lower layers: which local an
argument fills (docs/semantics.md §5), where a jump lands (§4), a variable's class (§2) and a
system variable's description with its axis."""

from __future__ import annotations

from cncmacro.dialects import get_dialect
from cncmacro.dialects.describe import code_doc, describe_system_variable, variable_class
from cncmacro.machine.calls import argument_targets, letters_for_local, map_arguments
from cncmacro.machine.jumps import goto_line, return_line
from cncmacro.syntax import parse_block
from cncmacro.syntax.walk import nodes_at


def test_5_calls_argument_targets_follow_specification_ii_for_repeated_ijk() -> None:
    # seed 000: A1 B2 C3 I14 J15 I6 J7 K9 K11 K12 J30
    letters = list("ABCIJIJKKKJ")
    assert argument_targets(letters) == [1, 2, 3, 4, 5, 7, 8, 6, 9, 12, 11]
    mapped = map_arguments([(x, float(i)) for i, x in enumerate(letters)], get_dialect("gsk980tdi"))
    assert set(mapped.values) == {n for n in argument_targets(letters) if n is not None}


def test_5_calls_argument_targets_name_no_local_for_g_l_n_o_p() -> None:
    assert argument_targets(["X", "L", "P", "Z"]) == [24, None, None, 26]


def test_5_calls_letters_for_local_give_both_specifications() -> None:
    assert letters_for_local(24) == ("X", "K7")
    assert letters_for_local(4) == ("I", "I1")
    assert letters_for_local(1) == ("A", "A")
    assert letters_for_local(10) == (None, "I3")
    assert letters_for_local(34) == (None, None)


def test_4_control_flow_goto_searches_forward_then_from_the_start() -> None:
    assert goto_line([3, 9], 5) == 9
    assert goto_line([3, 9], 9) == 3
    assert goto_line([], 1) is None
    assert return_line([2, 8], 5) == 8 and return_line([2, 8], 9) == 8


def test_2_values_and_variables_classes_follow_the_common_range_setting() -> None:
    gsk = get_dialect("gsk980tdi")
    assert [variable_class(n, gsk) for n in (0, 1, 33, 50, 100, 199, 300, 500, 999, 1000)] == [
        "null", "local", "local", "undefined", "common", "common", "undefined", "persistent", "persistent", "system"
    ]  # fmt: skip
    assert variable_class(300, get_dialect("fanuc")) == "common"


def test_system_variable_description_fills_in_the_axis_in_both_languages() -> None:
    doc = describe_system_variable(get_dialect("fanuc"), 5002, "en")
    assert doc is not None and doc.axis == "Y" and doc.text.startswith("Y axis block end position")
    zh = describe_system_variable(get_dialect("fanuc"), 5002, "zh-CN")
    assert zh is not None and "第2轴（Y）" in zh.text and zh.access == "r" and zh.unit == "mm"
    assert describe_system_variable(get_dialect("fanuc"), 99999999, "en") is None


def test_code_doc_reads_the_dialect_tables() -> None:
    assert code_doc(get_dialect("fanuc"), "G", 1.0).code == "G01"  # type: ignore[union-attr]
    assert code_doc(get_dialect("fanuc"), "X", 1.0) is None


def test_nodes_at_gives_the_innermost_node_last() -> None:
    b = parse_block("#1=SQRT[#2*#3]")
    path = nodes_at(b, 12)
    assert type(path[-1]).__name__ == "Var" and path[-1].number == 3  # type: ignore[attr-defined]
