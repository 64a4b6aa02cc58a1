"""docs/semantics.md §5, external output: ``BPRNT[ a #b[c] ... ]`` sends each variable as a binary
number, its value x 10^c rounded to a whole number in 4 bytes (highest first, a negative in two's
complement, a vacant variable 00000000h), its characters in ISO code (bit 8 the even parity bit,
``*`` a space) and a LF at the end. ``cncmacro run``, its ``--json`` and the Debug Console show
the record as one line that says it is BPRNT's binary record: the bytes in hex (a value's four as
one word) and what they hold. It was printed as DPRNT text (``X12.5[3]``, the ``[3]`` as written)."""

from __future__ import annotations

import json
from pathlib import Path

from cli_capture import cli
from cncmacro.debugging.breakpoints import Breakpoints
from cncmacro.debugging.history import History
from cncmacro.debugging.stepping import CONTINUE, Stepper
from running import lines, machine, run

# The FANUC-compatible NCT 2000M/99M manual's own example (§20, binary data output, p. 193):
#   #110=318.49362 [3]: 318493.62 -> 318494 = 0004DC1Eh
#   #120=0.723415  [3]: 723.415   -> 723    = 000002D3h
#   #112=23.9      [0]: 23.9      -> 24     = 00000018h
# characters, ISO code with even parity in bit 8:
#   C = 43h (3 ones: parity set) -> C3; * = space 20h (1 one) -> A0; / = 2Fh (5 ones) -> AF;
#   X = 58h (3 ones) -> D8; Y = 59h (4 ones) -> 59; M = 4Dh (4 ones) -> 4D; then LF 0Ah
# 4 characters + 4 bytes + 1 + 4 + 1 + 4 + LF = 19 bytes, the manual's 19 rows of bits
PROGRAM = lines("#110=318.49362", "#120=0.723415", "#112=23.9", "POPEN", "BPRNT[C*/X#110[3]Y#120[3]M#112[0]]",
                "PCLOS", "M30")  # fmt: skip
RECORD = (
    'BPRNT binary record, 19 bytes: C3 A0 AF D8 0004DC1E 59 000002D3 4D 00000018 0A ("C /X" 318494 "Y" 723 "M" 24 LF)'
)
RECORD_ZH = (
    'BPRNT 二进制记录，19 字节：C3 A0 AF D8 0004DC1E 59 000002D3 4D 00000018 0A（"C /X" 318494 "Y" 723 "M" 24 LF）'
)


def test_bprnt_sends_each_value_as_a_32_bit_whole_number_scaled_by_its_places() -> None:
    assert run(PROGRAM).output == [RECORD]


def test_bprnt_sends_a_negative_in_twos_complement_and_vacant_as_zero() -> None:
    # #1 = -1.5 [2]: -150; 2^32 - 150 = 4294967146 = FFFFFF6Ah; #2 vacant: 00000000h
    # A = 41h, B = 42h (two ones each: no parity bit); 1 + 4 + 1 + 4 + LF = 11 bytes
    m = run(lines("#1=-1.5", "BPRNT[A#1[2]B#2[1]]", "M30"))
    assert m.output == ['BPRNT binary record, 11 bytes: 41 FFFFFF6A 42 00000000 0A ("A" -150 "B" 0 LF)']


def test_cncmacro_run_shows_the_bprnt_record_not_as_dprnt_text(tmp_path: Path) -> None:
    f = tmp_path / "O0001.nc"
    f.write_text("O0001\n" + PROGRAM, encoding="utf-8")
    code, out, _ = cli("run", "--no-save", str(f))
    assert code == 0 and RECORD in out.splitlines() and "DPRNT" not in out
    code, out, _ = cli("run", "--no-save", "--json", str(f))
    assert json.loads(out)["output"] == [RECORD]
    code, out, _ = cli("run", "--no-save", "--locale", "zh-CN", str(f))
    assert RECORD_ZH in out.splitlines()


def console(locale: str | None) -> list[tuple[str, str]]:
    """What the Debug Console is sent, run to the end in ``locale``."""
    m = machine(PROGRAM)
    history = History(interval=4)
    history.reset(m)
    said: list[tuple[str, str]] = []
    s = Stepper(m, Breakpoints(), history, lambda t, category: said.append((t, category)))
    s.locale = locale
    assert s.run(CONTINUE).reason == "exited"
    return said


def test_the_debug_console_shows_the_bprnt_record() -> None:
    assert (RECORD + "\n", "stdout") in console(None)
    assert (RECORD_ZH + "\n", "stdout") in console("zh-CN")
