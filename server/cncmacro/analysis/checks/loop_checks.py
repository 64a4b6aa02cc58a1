"""Loop and block IF checks across lines (docs/semantics.md §4): ``loop-number``,
``loop-mismatch`` and ``if-mismatch``.

The pairs and the unpaired markers come from ``syntax/program.py``. A DO or END number must be
a whole 1, 2 or 3, and loops may nest at most 3 deep (``loop-number``, alarm 126, as the
interpreter's ``loop_number`` and ``MAX_LOOP_DEPTH`` decide). A DO without its END (124), an
END without a DO (126) and crossing loops (126) are ``loop-mismatch``; a marker whose number is
already wrong is reported once, as ``loop-number``, because that is the alarm the control gives.
On a control with the block form of IF (``Dialect.block_if``), an ``IF [..] THEN`` without its
ENDIF, an ELSE or ENDIF without its IF, a second ELSE and a branch that crosses a loop are
``if-mismatch`` (the run stops there with the format alarm); elsewhere those blocks are already
``dialect-feature`` errors.
"""

from __future__ import annotations

from ...bilingual import pick
from ...dialects.alarms import LOOP_NUMBER, MISSING_END, STATEMENT_FORMAT
from ...dialects.dialect import Dialect
from ...machine.blocks import MAX_LOOP_DEPTH
from ...syntax.nodes import Block, Do, Else, End, EndIf, If, Number, While
from ...syntax.program import Program
from ..diagnostics import Diagnostic, Related, diagnostic


def _valid_number(num: Number) -> bool:
    v = num.value
    return v == int(v) and 1 <= v <= 3


def _marker_span(block: Block) -> tuple[int, int]:
    for s in block.statements:
        if isinstance(s, (While, Do, End)):
            return s.start, s.end
    return 0, 1


def _branch_span(block: Block) -> tuple[int, int]:
    for s in block.statements:
        if isinstance(s, (If, Else, EndIf)):
            return s.start, s.end
    return 0, 1


def if_diagnostics(program: Program, file: str, locale: str, dialect: Dialect) -> list[Diagnostic]:
    """Every ``if-mismatch`` finding of ``program`` on a dialect with the block form of IF."""
    if not dialect.block_if:
        return []
    alarm = dialect.alarm_said(STATEMENT_FORMAT)
    out: list[Diagnostic] = []
    for problem in program.if_problems:
        line = problem.line
        if program.after_tape(line):
            continue
        start, end = _branch_span(program.blocks[line])
        related: tuple[Related, ...] = ()
        if problem.kind == "if-without-endif":
            message = pick(locale, f"IF [...] THEN has no ENDIF in its program ({alarm})",
                           f"IF [...] THEN 在其程序中没有对应的 ENDIF（{alarm.zh}）")  # fmt: skip
        elif problem.kind == "second-else":
            other = problem.other_line if problem.other_line is not None else line
            message = pick(locale, f"a second ELSE for the IF [...] THEN whose ELSE is on line {other + 1} ({alarm})",
                           f"同一 IF [...] THEN 的第二个 ELSE（第一个在第 {other + 1} 行）（{alarm.zh}）")  # fmt: skip
            related = (Related(file, other, *_branch_span(program.blocks[other]), pick(locale, "the first ELSE",
                                                                                       "第一个 ELSE")),)  # fmt: skip
        elif problem.kind == "crossing":
            word = "ELSE" if program.blocks[line].branch_marker() == "ELSE" else "ENDIF"
            message = pick(locale, f"{word} ends a branch of its IF [...] THEN across a WHILE/DO loop: a block IF "
                                   f"and a loop may not cross ({alarm})",
                           f"{word} 结束 IF [...] THEN 的分支时与 WHILE/DO 循环交叉：块形式 IF 与循环不能交叉"
                           f"（{alarm.zh}）")  # fmt: skip
            if problem.other_line is not None:
                related = (Related(file, problem.other_line, *_marker_span(program.blocks[problem.other_line]),
                                   pick(locale, "the loop", "循环")),)  # fmt: skip
        else:
            word = "ELSE" if problem.kind == "else-without-if" else "ENDIF"
            message = pick(locale, f"{word} has no IF [...] THEN before it ({alarm})",
                           f"{word} 之前没有对应的 IF [...] THEN（{alarm.zh}）")  # fmt: skip
        out.append(diagnostic(file, line, start, line, end, "if-mismatch", message, related))
    return out


def loop_diagnostics(program: Program, file: str, locale: str, dialect: Dialect) -> list[Diagnostic]:
    """Every loop-number and loop-mismatch finding of ``program``, its alarms as ``dialect`` shows them."""
    out: list[Diagnostic] = []
    loop = dialect.alarm_said(LOOP_NUMBER)
    missing = dialect.alarm_said(MISSING_END)
    blocks = program.blocks
    bad_lines: set[int] = set()
    for line in program.markers:
        if program.after_tape(line):
            break  # past the closing '%': not read
        marker = blocks[line].loop_marker()
        if marker is None or _valid_number(marker[1]):
            continue
        kind, num = marker
        bad_lines.add(line)
        start, end = num.start, num.end
        out.append(
            diagnostic(file, line, start, line, max(end, start + 1), "loop-number",
                       pick(locale, f"{kind} {num.text}: the loop number must be 1, 2 or 3 ({loop})",
                            f"{kind} {num.text}：循环号必须为 1、2 或 3（{loop.zh}）"))
        )  # fmt: skip
    open_ends: list[int] = []
    for pair in sorted(program.loops, key=lambda p: p.do_line):
        while open_ends and open_ends[-1] < pair.do_line:
            open_ends.pop()
        open_ends.append(pair.end_line)
        if len(open_ends) > MAX_LOOP_DEPTH and pair.do_line not in bad_lines:
            start, end = _marker_span(blocks[pair.do_line])
            out.append(
                diagnostic(file, pair.do_line, start, pair.do_line, end, "loop-number",
                           pick(locale, f"loops nested {len(open_ends)} deep; at most {MAX_LOOP_DEPTH} ({loop})",
                                f"循环嵌套 {len(open_ends)} 层，最多 {MAX_LOOP_DEPTH} 层（{loop.zh}）"))
            )  # fmt: skip
    for problem in program.loop_problems:
        if problem.line in bad_lines:
            continue
        line = problem.line
        start, end = _marker_span(blocks[line])
        n = problem.number
        related: tuple[Related, ...] = ()
        milder = False
        if problem.kind == "do-without-end":  # the control looks for the END only to leave the loop (§4)
            milder = True
            message = pick(locale, f"DO {n} has no END {n} ({missing}): the control raises it where the WHILE "
                                   f"condition is false and it looks for END {n} to go on after it",
                           f"DO {n} 没有对应的 END {n}（{missing.zh}）：WHILE 条件不成立、系统查找 END {n} "
                           "以执行其后的程序段时报警")  # fmt: skip
        elif problem.kind == "end-without-do":
            message = pick(locale, f"END {n} has no DO {n} before it ({loop})",
                           f"END {n} 之前没有对应的 DO {n}（{loop.zh}）")  # fmt: skip
        else:
            other = problem.other_line if problem.other_line is not None else line
            message = pick(
                locale,
                f"END {n} closes its loop while the loop opened on line {other + 1} is still open: "
                f"loops may not cross ({loop})",
                f"END {n} 结束循环时，第 {other + 1} 行开始的循环尚未结束：循环不能交叉（{loop.zh}）",
            )
            o_start, o_end = _marker_span(blocks[other])
            related = (Related(file, other, o_start, o_end, pick(locale, "the inner loop", "内层循环")),)
        out.append(diagnostic(file, line, start, line, end, "loop-mismatch", message, related, milder=milder))
    return out
