"""The command line's own words (docs/cli.md): the language it speaks (``--locale`` in every
spelling a user or an editor hands over, else ``LC_ALL``/``LC_MESSAGES``/``LANG`` in POSIX
order), the controls its help names (all of the registry's), and ``--set``."""

from __future__ import annotations

from pathlib import Path

import pytest

from cli_capture import cli
from cncmacro.dialects.registry import all_profiles

ALARM = "O1000\n#3000=1(NO TOOL)\nM30\n"


def _program(tmp_path: Path, text: str = ALARM) -> str:
    path = tmp_path / "O1000.nc"
    path.write_text(text, encoding="utf-8")
    return str(path)


@pytest.mark.parametrize("spelling", ["zh-CN", "zh-cn", "zh_CN.UTF-8", "zh", "zh-tw", "zh_TW.UTF-8", "ZH-HK"])
def test_every_spelling_of_a_chinese_locale_gives_chinese(tmp_path, spelling):
    code, out, err = cli("run", "--no-save", "--locale", spelling, _program(tmp_path))
    assert code == 1, err
    assert "报警 3001：NO TOOL" in out and "ALARM" not in out


@pytest.mark.parametrize("spelling", ["en", "en-US", "en_GB.UTF-8", "C", "POSIX"])
def test_english_locales_give_english(tmp_path, spelling):
    code, out, _ = cli("run", "--no-save", "--locale", spelling, _program(tmp_path))
    assert code == 1 and "ALARM 3001: NO TOOL" in out


def test_a_locale_in_another_language_is_refused_with_the_forms_it_takes(tmp_path):
    code, _, err = cli("check", "--locale", "fr", _program(tmp_path))
    assert code == 2
    assert "unknown locale 'fr'" in err and "zh-CN" in err and "zh_CN.UTF-8" in err


@pytest.mark.parametrize(
    ("environment", "chinese"),
    [
        ({"LANG": "zh_CN.UTF-8"}, True),
        ({"LC_MESSAGES": "zh_CN.UTF-8", "LANG": "en_US.UTF-8"}, True),
        ({"LC_ALL": "en_US.UTF-8", "LC_MESSAGES": "zh_CN.UTF-8", "LANG": "zh_CN.UTF-8"}, False),
        ({"LC_ALL": "zh_TW.UTF-8", "LANG": "C"}, True),
        ({"LC_ALL": "", "LC_MESSAGES": "", "LANG": "zh_CN.GB18030"}, True),  # empty ones do not count
        ({"LANG": "de_DE.UTF-8"}, False),  # a language cncmacro does not write: English
        ({}, False),
    ],
)
def test_without_locale_the_environment_decides_in_posix_order(tmp_path, monkeypatch, environment, chinese):
    for name in ("LC_ALL", "LC_MESSAGES", "LANG"):
        monkeypatch.delenv(name, raising=False)
    for name, value in environment.items():
        monkeypatch.setenv(name, value)
    _, out, _ = cli("run", "--no-save", _program(tmp_path))
    assert ("报警 3001：NO TOOL" in out) is chinese
    assert ("ALARM 3001: NO TOOL" in out) is not chinese
    _, out, _ = cli("check", _program(tmp_path))
    assert ("运行到宏程序报警 3001：NO TOOL" in out) is chinese, out


def test_an_explicit_locale_wins_over_the_environment(tmp_path, monkeypatch):
    monkeypatch.setenv("LC_ALL", "zh_CN.UTF-8")
    _, out, _ = cli("run", "--no-save", "--locale", "en", _program(tmp_path))
    assert "ALARM 3001: NO TOOL" in out


def test_the_top_level_help_names_every_control_profile_of_the_registry():
    code, out, _ = cli("--help")
    assert code == 0
    flat = " ".join(out.split())
    for profile in all_profiles():
        assert f"{profile.title} ({profile.name})" in flat
    assert "Haas" in flat


def test_set_takes_the_variable_number_with_or_without_its_hash(tmp_path):
    program = _program(tmp_path, "O1000\n#101=#100+1\nM30\n")
    for preset in ("100=5", "#100=5", " #100 = 5 "):
        code, out, err = cli("run", "--no-save", "--set", preset, program)
        assert code == 0, err
        assert "#101 = 6" in out  # 5 + 1


@pytest.mark.parametrize("preset", ["100", "x=1", "#[100]=1", "100=abc", "100=nan", "=5"])
def test_a_bad_set_says_the_form_it_expects(tmp_path, preset):
    code, _, err = cli("run", "--no-save", "--set", preset, _program(tmp_path))
    assert code == 2
    assert "write it as NUMBER=VALUE, e.g. --set 100=5 or --set '#100=5'" in err
    _, _, err = cli("run", "--no-save", "--locale", "zh-CN", "--set", preset, _program(tmp_path))
    assert "应写成“变量号=数值”" in err


def test_a_variable_that_cannot_be_preset_is_named_plainly_in_both_languages(tmp_path):
    program = _program(tmp_path)
    code, _, err = cli("run", "--no-save", "--dialect", "haas", "--set", "3026=1", program)
    assert code == 2
    assert err == "cncmacro run: #3026 (Tool in the spindle: the number of the tool now loaded) " \
        "is computed by the machine and cannot be preset\n"  # fmt: skip
    _, _, err = cli("run", "--no-save", "--dialect", "haas", "--locale", "zh-cn", "--set", "3026=1", program)
    assert err == "cncmacro run：#3026（主轴上的刀具：当前装在主轴上的刀具号）由机床计算，不能预设\n"
    _, _, err = cli("run", "--no-save", "--set", "#9999=1", program)
    assert err.startswith("cncmacro run: #9999 is not a variable of FANUC 0i Custom Macro B that can be preset (")


def test_a_per_axis_variable_that_cannot_be_preset_names_its_axis_not_a_placeholder(tmp_path):
    program = _program(tmp_path)
    code, _, err = cli("run", "--no-save", "--set", "#5001=1", program)
    assert code == 2
    assert err == "cncmacro run: #5001 (X axis block end position, work coordinates, without tool offset) " \
        "is computed by the machine and cannot be preset\n"  # fmt: skip
    _, _, err = cli("run", "--no-save", "--locale", "zh-cn", "--set", "#5002=1", program)
    assert err == "cncmacro run：#5002（第2轴（Y）程序段终点位置）由机床计算，不能预设\n"


def test_a_machine_file_number_of_thousands_of_digits_is_named_with_its_line(tmp_path):
    # Python refuses to convert more than 4300 digits; its own words used to reach the user
    (tmp_path / ".cncmacro.toml").write_text('dialect = "haas"\nmax_blocks = ' + "9" * 5000 + "\n", encoding="utf-8")
    code, _, err = cli("run", "--no-save", _program(tmp_path))
    assert code == 2
    assert "a number of 5000 digits, more than any setting can use (line 2)" in err
    assert "set_int_max_str_digits" not in err


def test_a_machine_file_budget_of_no_block_is_refused(tmp_path):
    (tmp_path / ".cncmacro.toml").write_text("max_blocks = 0\n", encoding="utf-8")
    code, _, err = cli("run", "--no-save", _program(tmp_path))
    assert code == 2 and "'max_blocks' must be at least 1" in err
