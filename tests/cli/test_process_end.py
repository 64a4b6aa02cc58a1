"""A command that ends its process leaves what it holds to the end of the process, out of the
garbage collector's reach (cli/process_end.py: a long run's records are not walked again after
the run and at exit); ``main`` called with arguments, by a process that goes on, leaves the
collector as it was, so that nothing it made is kept for good."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import cncmacro.cli.check_work
import cncmacro.cli.main
import cncmacro.cli.run
from cli_capture import cli

PROGRAM = "O0001\nG10 L12 P1 R3.\nG21 G17 G90 G94 F800\nG41 D1 G01 X10. Y0\nX20.\nY10.\nG40 G00 X0 Y0\nM30\n"
SERVER = Path(__file__).resolve().parents[2] / "server"


def test_main_called_with_arguments_leaves_nothing_to_the_end_of_the_process(tmp_path, monkeypatch):
    program = tmp_path / "O0001.nc"
    program.write_text(PROGRAM, encoding="utf-8")
    calls: list[str] = []
    monkeypatch.setattr(cncmacro.cli.run, "keep_to_the_end", lambda: calls.append("run"))
    monkeypatch.setattr(cncmacro.cli.main, "keep_to_the_end", lambda: calls.append("main"))
    code, out, err = cli("run", "--no-save", str(program))
    assert code == 0, err
    assert "moves (4):" in out
    assert calls == []


def test_the_command_of_its_own_process_writes_the_same_run_and_leaves_it_to_the_end(tmp_path):
    program = tmp_path / "O0001.nc"
    program.write_text(PROGRAM, encoding="utf-8")
    script = (
        "import gc, sys\n"
        "from cncmacro.cli.main import main\n"
        f"sys.argv = ['cncmacro', 'run', '--no-save', {str(program)!r}]\n"
        "code = main()\n"
        "print('frozen' if gc.get_freeze_count() else 'not frozen', file=sys.stderr)\n"
        "sys.exit(code)\n"
    )
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, cwd=SERVER, check=False)
    assert done.returncode == 0, done.stderr
    assert done.stderr.strip().endswith("frozen") and "not frozen" not in done.stderr
    assert done.stdout == cli("run", "--no-save", str(program))[1]


CAM = "O0002\nG90 G21 G17 F800\nN10 G01 X10. Y0\nX20. Y5.\nN20 G02 X30. Y15. R10.\nG00 X0 Y0\nM30\n"


def test_a_check_called_by_a_process_that_goes_on_collects_what_it_left(tmp_path):
    program = tmp_path / "O0002.nc"
    program.write_text(CAM, encoding="utf-8")
    code, out, err = cli("check", str(program))
    assert code == 0, out + err
    assert not cncmacro.cli.check_work._left.behind  # collected: nothing of its run kept for good


def test_the_check_of_its_own_process_leaves_its_run_and_loads_no_grammar_for_plain_lines(tmp_path):
    """The process's own check of a file of plain lines, labelled or not, reads them without the
    grammar (lark takes 25 ms to load) and starts no worker pool (10 ms), and leaves what its
    one group made to the end of the process (a third of a second on a 1M-line file)."""
    program = tmp_path / "O0002.nc"
    program.write_text(CAM, encoding="utf-8")
    script = (
        "import sys\n"
        "from cncmacro.cli import check_work\n"
        "from cncmacro.cli.main import main\n"
        f"sys.argv = ['cncmacro', 'check', '--jobs', '2', {str(program)!r}]\n"
        "code = main()\n"
        "print(check_work._left.behind, 'lark' in sys.modules, 'concurrent.futures.process' in sys.modules,"
        " file=sys.stderr)\n"
        "sys.exit(code)\n"
    )
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, cwd=SERVER, check=False)
    assert done.returncode == 0, done.stderr
    assert done.stderr.split() == ["True", "False", "False"]
