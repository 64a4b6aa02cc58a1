"""``cncmacro check`` on a lathe program read under a mill profile (docs/profiles.md "How a lathe
program is recognised"): the ``profile-suggestion`` is shown at information level and leaves the
exit status alone; the mill corpora and a lathe profile get none; with the comment its quick fix
writes, the program runs as the lathe."""

from __future__ import annotations

import json
from pathlib import Path

from cli_capture import cli, run_json

CORPUS = Path(__file__).resolve().parent / "corpus"
SHAFT = (
    "%\nO0100 (SHAFT)\nT0101 G97 S800 M03\nG50 S2500\nG71 U2. R0.5\nG71 P10 Q20 U0.5 W0.1 F0.25\n"
    "N10 G00 X20.\nG01 Z-20.\nN20 X52.\nM30\n%\n"
)


def test_check_shows_the_lathe_suggestion_as_information_and_exits_zero(tmp_path):
    f = tmp_path / "O0100.nc"
    f.write_text(SHAFT, encoding="utf-8")
    code, out, err = cli("check", str(f))
    assert (code, err) == (0, "")
    # line 6 holds G71 P10 Q20 ...: column 1 in the text format (1-based)
    said = "information: This looks like a lathe program (G71 P10 Q20 on line 6, T0101 on line 3"
    assert out.startswith(f"{f}:6:1: {said}")
    assert out.rstrip().endswith("[profile-suggestion]") and out.count("\n") == 1


def test_check_under_a_lathe_profile_shows_nothing(tmp_path):
    f = tmp_path / "O0100.nc"
    f.write_text(SHAFT, encoding="utf-8")
    for lathe in ("fanuc-0i-lathe", "gsk980tdi"):
        assert cli("check", "--dialect", lathe, str(f)) == (0, "", ""), lathe


def test_check_finds_no_lathe_program_in_the_mill_corpora():
    for mill in ("fanuc-0i", "fanuc-30i", "haas"):
        code, out, _ = cli("check", "--format", "json", str(CORPUS / mill))
        assert code == 0, mill
        found = [d for d in json.loads(out) if d["code"] == "profile-suggestion" and "lathe" in d["message"]]
        assert found == [], mill


def test_with_the_comment_of_the_quick_fix_a_g92_thread_runs_as_a_turning_cycle(tmp_path):
    thread = "%\nO0100 (THREAD)\nT0303\nG97 S600 M03\nG00 X32. Z5.\nG92 X29.2 Z-30. F1.5\nG00 X100. Z100.\nM30\n%\n"
    mill = run_json(tmp_path, thread, "MILL.nc")
    # read as a mill, G92 (line 6) sets coordinates: the rapids of lines 5 and 7 are the only moves
    assert (mill["dialect"], [(m["line"], m["kind"]) for m in mill["moves"]]) == (
        "fanuc-0i",
        [(5, "rapid"), (7, "rapid")],
    )
    fixed = thread.replace("%\n", "%\n(cncmacro: dialect=fanuc-0i-lathe)\n", 1)  # the line the quick fix writes
    lathe = run_json(tmp_path, fixed, "LATHE.nc")
    assert lathe["dialect"] == "fanuc-0i-lathe" and lathe["lathe"] is True
    assert [(m["line"], m["kind"]) for m in lathe["moves"]] == [(6, "rapid"), (7, "cycle"), (8, "rapid")]
