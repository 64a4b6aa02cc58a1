"""The machine file describes the real machine (docs/profiles.md "The machine file"): ``base``
picks the profile, ``common`` the machine's common ranges, ``program_digits`` how M98 P splits,
``programs_on_control`` the macros kept in the control, ``[[system_variables]]`` what the
builder added. Tested through ``cncmacro check`` and ``cncmacro run`` on one workspace
(``tests/data/machine_workspace``; the language server and the debugger use it too)."""

from __future__ import annotations

import contextlib
import io
import json
import shutil
from pathlib import Path

import pytest

from cncmacro.cli.main import main
from cncmacro.library.machine_file import MachineFileError, settings_from_mapping
from running import alarm, final, lines

WORKSPACE = Path(__file__).parent / "data" / "machine_workspace"


def cli(*argv: str) -> tuple[int, str]:
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        status = main(list(argv))
    return status, out.getvalue()


def check_json(folder: Path) -> list[dict[str, object]]:
    _, out = cli("check", "--format", "json", str(folder))
    return json.loads(out) if out.strip() else []


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    folder = tmp_path / "shop"
    shutil.copytree(WORKSPACE, folder)
    return folder


def test_machine_file_check_reports_only_what_this_machine_lacks(workspace: Path) -> None:
    found = [(Path(str(d["file"])).name, d["line"], d["code"]) for d in check_json(workspace)]
    # O1000 calls O9810 (on the control) and M98 P915101 (O915101 with 6 digits): clean.
    # O1001 writes #300 (this machine has #100-#199 only) and calls O8000 (nowhere).
    assert found == [("O1001.nc", 3, "variable-number"), ("O1001.nc", 4, "program-not-found")]


def test_machine_file_variable_number_names_the_machine_common_ranges(workspace: Path) -> None:
    [d] = [d for d in check_json(workspace) if d["code"] == "variable-number"]
    assert "#100-#199, #500-#999" in str(d["message"]) and "common" in str(d["message"])


def test_machine_file_a_standard_g_code_in_calls_is_noted_once_on_gsk980tdi(tmp_path: Path) -> None:
    # GSK980TDi manual §3.32: a code set equal to a standard G code disables the call; check
    # says so once for the machine file, in English and Chinese; FANUC's [calls] G90 is a call
    (tmp_path / "O0005.nc").write_text(lines("O0005", "G00 X50 Z2", "G90 X40 Z-20 F100", "M30"))
    (tmp_path / "O2000.nc").write_text(lines("O2000", "M99"))
    machine = tmp_path / ".cncmacro.toml"
    machine.write_text('base = "gsk980tdi"\n\n[calls]\nG90 = 2000\n')
    shown = str(machine)
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        cli("check", str(tmp_path))
    assert err.getvalue() == (
        f"cncmacro: note: {shown}: [calls] G90: GSK980TDi does not call a program for a standard G code of its own "
        "(a code set equal to a standard G code is disabled); G90 runs as the standard code\n"
    )
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        cli("check", "--locale", "zh-CN", str(tmp_path))
    assert err.getvalue() == (
        f"cncmacro：注意：{shown}：[calls] G90：GSK980TDi 的标准 G 代码不能设为宏程序调用"
        "（设定值与标准 G 代码相同时本功能自动无效），G90 按标准 G 代码执行\n"
    )
    machine.write_text('base = "fanuc-0i"\n\n[calls]\nG90 = 2000\n')
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        cli("check", str(tmp_path))
    assert err.getvalue() == ""


def test_machine_file_run_calls_the_control_macro_and_the_six_digit_program(workspace: Path) -> None:
    status, out = cli("run", "--no-save", "--json", str(workspace / "O1000.nc"))
    r = json.loads(out)
    assert status == 0 and r["status"] == "completed"
    assert r["dialect"] == "fanuc-0i"
    v = r["variables"]
    assert v["1100"] == 1 and v["101"] == 1  # the builder's signal, preset by the machine file
    assert v["100"] == 2  # M98 P915101 L2: O915101 twice, not 91 times O5101
    assert v["102"] == 1  # the run went on after the control's O9810 returned


def test_machine_file_without_it_the_same_folder_has_false_errors(workspace: Path) -> None:
    (workspace / ".cncmacro.toml").unlink()
    found = {(Path(str(d["file"])).name, d["line"], d["code"]) for d in check_json(workspace)}
    assert ("O1000.nc", 5, "program-not-found") not in found  # O9810: the 9000 series is the control's
    assert ("O1000.nc", 6, "program-not-found") in found  # 91 x O5101
    assert ("O1001.nc", 3, "variable-number") not in found  # fanuc-0i alone allows #100-#499


def test_machine_file_a_stub_in_the_workspace_stands_for_a_control_macro(workspace: Path) -> None:
    (workspace / "O9810.nc").write_text("O9810 (STUB)\n#102=41\nM99\n", encoding="utf-8")
    _, out = cli("run", "--no-save", "--json", str(workspace / "O1000.nc"))
    assert json.loads(out)["variables"]["102"] == 42


def test_machine_file_writing_a_read_only_builder_variable_is_alarm_116() -> None:
    settings = settings_from_mapping({"system_variables": [{"number": 1100, "access": "r", "en": "clamped"}]})
    assert alarm(lines("#1100=1", "M30"), **_fields(settings)) == (116, 1)
    assert final(lines("#1=#1100", "M30"), presets={1100: 1}, **_fields(settings))[1] == 1


def _fields(settings: object) -> dict[str, object]:
    return {"system_variables": settings.system_variables}  # type: ignore[attr-defined]


def test_machine_file_program_digits_default_splits_the_count() -> None:
    from cncmacro.dialects import get_dialect
    from cncmacro.machine.calls import program_and_count

    assert program_and_count("30040", 30040.0, None, get_dialect("fanuc-0i"), []) == (40, 3)
    six = get_dialect("fanuc-0i").configured(m98_program_digits=6)
    assert program_and_count("915101", 915101.0, None, six, []) == (915101, 1)
    assert program_and_count("12915101", 12915101.0, None, six, []) == (915101, 12)


@pytest.mark.parametrize(
    ("mapping", "key"),
    [
        ({"base": "mazak-m"}, "'base'"),
        ({"base": "fanuc-0i", "dialect": "fanuc-0i"}, "'dialect'"),
        ({"common": [[50, 199]]}, "'common'"),
        ({"common": [[100, 199], [1000, 1100]]}, "'common'"),
        ({"common": "100-199"}, "'common'"),
        ({"base": "gsk980tdi", "common": [[300, 200]]}, "'common'"),
        ({"program_digits": 3}, "'program_digits'"),
        ({"program_digits": "6"}, "'program_digits'"),
        ({"programs_on_control": ["O9000-O8000"]}, "'programs_on_control'"),
        ({"programs_on_control": "O9000"}, "'programs_on_control'"),
        ({"programs_on_control": ["P9000"]}, "'programs_on_control'"),
        ({"system_variables": [{"number": 500, "en": "x"}]}, "'system_variables[1]'"),
        ({"system_variables": [{"number": 1100}]}, "'system_variables[1].en'"),
        ({"system_variables": [{"number": 1100, "en": "x", "access": "x"}]}, "'system_variables[1].access'"),
        ({"system_variables": [{"number": 1100, "en": "x", "name": "y"}]}, "'system_variables[1].name'"),
    ],
)
def test_machine_file_a_bad_value_names_its_key(mapping: dict[str, object], key: str) -> None:
    with pytest.raises(MachineFileError) as e:
        settings_from_mapping(mapping, "shop.toml")
    said = e.value.args[0]
    assert said.startswith(f"shop.toml: {key} ") and said.zh.startswith(f"shop.toml：{key} ")


def test_machine_file_a_bad_key_stops_check_and_run_with_nothing_half_applied(workspace: Path) -> None:
    toml = workspace / ".cncmacro.toml"
    text = toml.read_text(encoding="utf-8").replace("program_digits = 6", "program_digits = 9")
    toml.write_text(text, encoding="utf-8")
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        status, out = cli("run", "--no-save", str(workspace / "O1000.nc"))
    assert status == 2 and out == ""
    assert "'program_digits' must be a whole number from 4 to 8" in err.getvalue()


def test_machine_file_old_common_form_still_names_the_volatile_range() -> None:
    s = settings_from_mapping({"common": [100, 299]})
    assert s.common == ((100, 299), (500, 999))
    assert final(lines("#299=1", "#500=2", "M30"), common=s.common)[299] == 1
    assert alarm(lines("#300=1", "M30"), common=s.common)[0] == 115


def test_machine_file_a_preset_the_profile_lacks_stops_run_but_not_check(workspace: Path) -> None:
    toml = workspace / ".cncmacro.toml"
    toml.write_text(toml.read_text(encoding="utf-8") + "98000 = 1\n", encoding="utf-8")  # under [variables]
    found = [(Path(str(d["file"])).name, d["code"]) for d in check_json(workspace)]
    assert ("O1001.nc", "variable-number") in found  # check still reports the other findings
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        status, _ = cli("run", "--no-save", str(workspace / "O1000.nc"))
    assert status == 2 and "#98000 is not a variable of FANUC 0i Custom Macro B" in err.getvalue()
