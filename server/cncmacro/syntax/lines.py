"""Splitting a line into the part the grammar reads and the parts it does not.

Before a line reaches the block grammar, its comments ``( ... )``, the end-of-block ``;`` (and
whatever follows it), a leading block delete ``/`` or ``/n`` and a ``%`` tape mark (or a DOS
end-of-file character 0x1A at the start of the line, read as one) are taken out
and replaced by spaces, so the remaining code keeps the columns of the original line. The
result also carries the comments themselves and the problems found on the way (an unclosed
comment is a warning; a second block after ``;`` on the same line is an error).
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from ..bilingual import detail
from .nodes import Comment, Problem

_BLOCK_DELETE = re.compile(r"[ \t]*/[ \t]*([1-9](?![0-9.]))?")
_SPECIAL = re.compile("[(;\uff1b/%\x1a]")
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
    """True when the line holds a comment, an end-of-block mark, a '/' or a '%'."""
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
            pos = close + 1
            continue
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
    return Prepared(code, tuple(comments), block_delete, False, tuple(problems))


def _next_special(line: str, pos: int) -> int:
    """Index of the next '(' or ';' (ASCII or full-width) at or after pos, or -1."""
    best = -1
    for ch in ("(", ";", "\uff1b"):
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
