"""Splitting a line into the part the grammar reads and the parts it does not.

Before a line reaches the block grammar, its comments ``( ... )``, the end-of-block ``;`` (and
whatever follows it), a leading block delete ``/`` or ``/n`` and a ``%`` tape mark (or a DOS
end-of-file character 0x1A at the start of the line, read as one) are taken out
and replaced by spaces, so the remaining code keeps the columns of the original line. The
result also carries the comments themselves and the problems found on the way (an unclosed
comment is a warning; a second block after ``;`` on the same line is an error, and so is a ``)``
outside a comment: a comment ends at its first ``)``). A ``%`` after the code of a line
(``M30%``) ends the tape there, as a ``%`` line does: the code before it is kept.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from ..bilingual import detail
from .nodes import Comment, Problem

_BLOCK_DELETE = re.compile(r"[ \t]*/[ \t]*([1-9](?![0-9.]))?")
_SPECIAL = re.compile("[();\uff1b/%\x1a]")
_UNCLOSED_COMMENT = detail("comment not closed: ')' is missing", "注释没有结束：缺少 ')'")
_FULL_WIDTH_END = detail("full-width '；' read as the end-of-block ';'", "全角 '；' 按程序段结束符 ';' 处理")


@dataclass(slots=True)
class Prepared:
    """A line made ready for the grammar."""

    code: str
    comments: tuple[Comment, ...] = ()
    block_delete: int | None = None
    tape: bool = False
    problems: tuple[Problem, ...] = ()


def has_special(line: str) -> bool:
    """True when the line holds a comment (or a stray ')'), an end-of-block mark, a '/' or a '%'."""
    return _SPECIAL.search(line) is not None


def prepare(line: str) -> Prepared:
    """Take comments, ``;``, block delete and ``%`` out of ``line``; columns are kept."""
    if _SPECIAL.search(line) is None:
        return Prepared(line)
    stripped = line.lstrip(" \t")
    if stripped.startswith(("%", "\x1a")):  # a tape mark, or DOS's end of file: see program.py
        return Prepared("", tape=True)

    comments: list[Comment] = []
    problems: list[Problem] = []
    pieces: list[str] = []
    pos = 0
    n = len(line)
    tape = False
    nested = -1  # where a '(' inside the last comment stands: a ')' after it closes nothing
    while pos < n:
        i = _next_special(line, pos)
        if i < 0:
            pieces.append(line[pos:])
            break
        pieces.append(line[pos:i])
        ch = line[i]
        if ch == "(":
            close = line.find(")", i + 1)
            if close < 0:
                comments.append(Comment(line[i + 1 :], False, i, n))
                problems.append(Problem(_UNCLOSED_COMMENT, i, n, "warning"))
                pieces.append(" " * (n - i))
                break
            comments.append(Comment(line[i + 1 : close], True, i, close + 1))
            pieces.append(" " * (close + 1 - i))
            inner = line.find("(", i + 1, close)
            nested = inner if inner >= 0 else -1
            pos = close + 1
            continue
        if ch == ")":
            problems.append(_stray_close(line, i, nested, comments))
            if nested >= 0:  # the text between the comment and this ')' is told of here, not again
                pieces[-1] = " " * len(pieces[-1])
            pieces.append(" " * (n - i))
            break
        if ch in "%\x1a":  # the tape's end after the code of the line (M30%): nothing after it is read
            tape = True
            pieces.append(" " * (n - i))
            break
        # an end-of-block mark: the rest may hold only comments, blanks and more marks
        if ch == "\uff1b":
            problems.append(Problem(_FULL_WIDTH_END, i, i + 1, "warning"))
        pieces.append(" " * (n - i))
        _scan_after_end(line, i + 1, comments, problems)
        break
    code = "".join(pieces)

    block_delete = None
    if "/" in code:
        m = _BLOCK_DELETE.match(code)
        if m:
            block_delete = int(m.group(1)) if m.group(1) else 0
            code = " " * m.end() + code[m.end() :]
    return Prepared(code, tuple(comments), block_delete, tape, tuple(problems))


def _stray_close(line: str, at: int, nested: int, comments: list[Comment]) -> Problem:
    """The error of a ')' outside any comment. After a comment that held a '(' it names the
    rule: a comment ends at its first ')', so ``(CUT (ROUGH) PASS)`` ends after ``ROUGH`` and
    `` PASS)`` is read as program text, which the control cannot read (docs/semantics.md §1)."""
    end = len(line.rstrip())
    if nested >= 0 and comments:
        last = comments[-1]
        between = line[last.end : at]
        start = last.end + len(between) - len(between.lstrip(" \t"))
        shown = line[last.start : last.end]
        rest = line[start : at + 1].strip()
        return Problem(
            detail(
                f"'{rest}' is read as program text: a comment ends at its first ')', so '{shown}' "
                f"ends there (the '(' inside it opens nothing); write the inner brackets another way, "
                f"e.g. [ ] or -",
                f"'{rest}' 被当作程序代码读取：注释在第一个 ')' 处结束，所以 '{shown}' 到此为止"
                f"（注释中的 '(' 不会开始新的注释）；内层括号请改用其他写法，如 [ ] 或 -",
            ),
            start,
            max(end, at + 1),
        )
    return Problem(detail("')' without a matching '(': no comment is open here",
                          "')' 没有与之配对的 '('：此处没有打开的注释"), at, max(end, at + 1))  # fmt: skip


def _next_special(line: str, pos: int) -> int:
    """Index of the next '(', ')', ';' (ASCII or full-width) or tape mark at or after pos, or -1."""
    best = -1
    for ch in ("(", ")", ";", "\uff1b", "%", "\x1a"):
        i = line.find(ch, pos)
        if i >= 0 and (best < 0 or i < best):
            best = i
    return best


def _scan_after_end(line: str, pos: int, comments: list[Comment], problems: list[Problem]) -> None:
    """Read what follows ';': comments are kept, other text is a second block (an error)."""
    n = len(line)
    while pos < n:
        ch = line[pos]
        if ch in " \t;\uff1b":
            pos += 1
        elif ch == "(":
            close = line.find(")", pos + 1)
            end = n if close < 0 else close + 1
            comments.append(Comment(line[pos + 1 : end - 1 if close >= 0 else n], close >= 0, pos, end))
            if close < 0:
                problems.append(Problem(_UNCLOSED_COMMENT, pos, n, "warning"))
            pos = end
        else:
            end = len(line.rstrip())
            problems.append(
                Problem(
                    detail(
                        "text after the end-of-block ';': one line holds one block, so this text is not read",
                        "程序段结束符 ';' 之后还有内容：一行只能写一个程序段，这些内容不会被读取",
                    ),
                    pos,
                    end,
                )
            )
            return
