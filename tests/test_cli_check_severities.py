"""``cncmacro check`` on shop programs: the severity a finding gets is the one a machinist
should meet (issue "never cry wolf"): an error where the control surely stops, a hint where
it runs the block as written."""

from __future__ import annotations

from pathlib import Path

from cli_capture import cli


def _folder(tmp_path: Path, **programs: str) -> Path:
    for name, text in programs.items():
        (tmp_path / f"{name}.nc").write_text(text, encoding="utf-8")
    return tmp_path


# ---------------------------------------------------------------- g65-nc-words


def test_a_modal_g_code_before_g65_on_fanuc_is_only_a_hint_and_check_is_quiet(tmp_path):
    folder = _folder(tmp_path, O1000="O1000\nG90 G54 G65 P1001 A1.\nM30\n", O1001="O1001\n#100=#1\nM99\n")
    for profile in ("fanuc-0i", "fanuc-30i"):
        code, out, err = cli("check", "--dialect", profile, str(folder))
        assert (code, out) == (0, ""), out + err  # nothing to say by default
        code, out, _ = cli("check", "--hints", "--dialect", profile, str(folder))
        assert code == 0
        assert ":2:1: hint: G90 G54 before G65" in out and "[g65-nc-words]" in out


def test_a_modal_g_code_before_g65_stays_an_error_where_the_control_stops_with_alarm_127(tmp_path):
    folder = _folder(tmp_path, O1000="O1000\nG90 G54 G65 P1001 A1.\nM30\n", O1001="O1001\n#100=#1\nM99\n")
    code, out, _ = cli("check", "--dialect", "gsk980tdi", str(folder))
    assert code == 1
    assert ":2:1: error: G90 before G65" in out and "alarm 127" in out
