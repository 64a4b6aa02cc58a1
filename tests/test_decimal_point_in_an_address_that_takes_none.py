"""A decimal point in an address the lathe controls take without one (docs/semantics.md §8, "Words
a control refuses"): T, G04's P (milliseconds), the P and Q of G70–G76. The manuals write these
without a decimal point (FANUC 0i-TF: in least input increments, "without a decimal point"; the
GSK980TDi gives their units, §3.14, §3.23.5, §3.23.6, §3.24.12, and is silent on a point), and
neither gives the alarm a point raises there, so each is a warning that says how the run reads
the value; an M code with a point stays alarm 007."""

from __future__ import annotations

from pathlib import Path

import pytest

from analysis_helpers import analyse_files
from running import lines


def _points(tmp_path: Path, profile: str, *body: str) -> list[tuple[int, int, str, str]]:
    """The ``decimal-point`` findings of ``body``: (0-based line, column, severity, message)."""
    found = analyse_files(tmp_path, {"O0001.CNC": lines(f"O0001 (cncmacro: dialect={profile})", *body)}, profile)
    return [(d.line, d.column, d.severity, d.message) for d in found if d.code == "decimal-point"]


@pytest.mark.parametrize("profile", ["fanuc-0i-lathe", "gsk980tdi"])
def test_g74_q_with_a_point_is_a_warning_that_the_run_reads_it_in_least_increments(
    tmp_path: Path, profile: str
) -> None:
    # G74 Z-30. Q5.: Q is read as 5 least input increments of 0.001 mm = 0.005 mm (6,400 pecks),
    # so the warning says so and how to write 5 mm: Q5000
    found = _points(tmp_path, profile, "G99 G97 S800 M03", "G00 X0 Z2.", "G74 R1.", "G74 Z-30. Q5. F0.1", "M30")
    assert len(found) == 1
    line, col, severity, message = found[0]
    assert (line, col, severity) == (4, 10, "warning")
    assert "0.005 mm" in message and "Q5000" in message


def test_g76_p_and_q_t_and_g04_p_with_a_point_are_each_said(tmp_path: Path) -> None:
    found = _points(tmp_path, "fanuc-0i-lathe", "G97 S500 M03", "T0101.", "G04 P1.5", "G00 X24. Z5.",
                    "G76 P010060 Q0.1 R0.05", "G76 X18.05 Z-30. P0.975 Q0.4 F1.5", "M30")  # fmt: skip
    messages = {(line, message.split(":")[0]) for line, _, _, message in found}
    assert messages == {(2, "T0101."), (3, "P1.5"), (5, "Q0.1"), (6, "P0.975"), (6, "Q0.4")}
    by_word = {message.split(":")[0]: message for _, _, _, message in found}
    assert "1.5 ms (0.0015 s)" in by_word["P1.5"]  # P in ms: 1.5 ms
    assert "0.000975 mm" in by_word["P0.975"] and "P975" in by_word["P0.975"]  # 0.975 x 0.001 mm
    assert all(severity == "warning" for _, _, severity, _ in found)


def test_the_same_words_without_a_point_and_an_m_code_with_one(tmp_path: Path) -> None:
    assert _points(tmp_path, "fanuc-0i-lathe", "T0101", "G04 P1500", "G00 X24. Z5.", "G76 P010060 Q100 R0.05",
                   "G76 X18.05 Z-30. P975 Q400 F1.5", "M30") == []  # fmt: skip
    found = _points(tmp_path, "fanuc-0i-lathe", "M03.", "M30")
    assert [(line, severity) for line, _, severity, _ in found] == [(1, "error")]  # alarm 007, as before


@pytest.mark.parametrize(("profile", "said"), [("fanuc-0i", True), ("fanuc-30i", True), ("haas", False)])
def test_a_mills_g04_p_and_t_with_a_point(tmp_path: Path, profile: str, said: bool) -> None:
    # FANUC mills take G04's P in ms and T without a point, as the lathe does: G04 P2. is 2 ms, not
    # the 2 s meant, and is said; on Haas "G04 P10. is a dwell of 10 seconds" (a point is meant)
    found = _points(tmp_path, profile, "G04 P2.", "T01.", "M06", "M30")
    assert [message.split(":")[0] for _, _, _, message in found] == (["P2.", "T01."] if said else [])
    if said:
        assert "2 ms (0.002 s)" in found[0][3] and "P2000" in found[0][3]
