"""A decimal point in S on the FANUC profiles (docs/semantics.md §8, "Words a control refuses"):
"M03 S1000.0; (An illegal statement. S-value must be an integer number)", and on a mill
parameter 3451#2 lets S take one decimal place, rounded ("S1000.5 ; (Equivalent to S1001, if
parameter 3451#2 = 1)"; cncforum.net, "CNC Macro | Real versus Integer Values"). So `S1000.` is a
``decimal-point`` warning, as T and G04's P are (``Dialect.no_point_words``), that says how the run
reads it; a value in brackets (`S[1000.]`) is an expression and rounded, no finding. Haas,
Mitsubishi and Mazak turn the FANUC-only rules off (fanuc_0i.OTHER_MAKERS); GSK is silent."""

from __future__ import annotations

from pathlib import Path

import pytest

from analysis_helpers import analyse_files
from running import final, lines


def _points(tmp_path: Path, profile: str, *body: str) -> list[tuple[int, int, str, str]]:
    """The ``decimal-point`` findings of ``body``: (0-based line, column, severity, message)."""
    found = analyse_files(tmp_path, {"O0001.CNC": lines(f"O0001 (cncmacro: dialect={profile})", *body)}, profile)
    return [(d.line, d.column, d.severity, d.message) for d in found if d.code == "decimal-point"]


@pytest.mark.parametrize(
    ("profile", "said"),
    [("fanuc-0i", True), ("fanuc-30i", True), ("fanuc-0i-lathe", True), ("haas", False), ("mitsubishi-m70", False),
     ("mazak-eia", False), ("gsk980tdi", False)],
)  # fmt: skip
def test_s_with_a_point_is_a_decimal_point_warning_on_fanuc(tmp_path: Path, profile: str, said: bool) -> None:
    # S1000. is on line 1 (0-based, after the O line), column 0; the run reads S1000
    found = _points(tmp_path, profile, "S1000. M03", "M30")
    assert [(line, col, severity) for line, col, severity, _ in found] == ([(1, 0, "warning")] if said else [])
    if said:
        assert found[0][3].startswith("S1000.:") and "S1000" in found[0][3].split(":", 1)[1]


def test_s_without_a_point_or_in_brackets_is_no_finding(tmp_path: Path) -> None:
    assert _points(tmp_path, "fanuc-0i", "S1000 M03", "S[1000.] M03", "#1=1000.5", "S#1 M03", "M30") == []


def test_the_run_reads_s_with_a_point_rounded() -> None:
    # the warning does not stop the run: S1000.5 reads #4119 = 1001 (rounded half away, as S#1 is)
    v = final(lines("S1000.5 M03", "#101=#4119", "M30"), "fanuc")
    assert v[101] == 1001
