"""Plain-words messages for lines the grammar rejects, in English and in Chinese.

Lark reports an unexpected character or token with the names of the terminals it expected.
A CNC programmer wants to read "expected ']' to close the '[' at column 5" or "expected a
value after 'X'", so this module turns lark's exceptions into a ``Problem`` with a range and a
message that carries its Chinese (``bilingual.Detail``) for the front ends to choose.
"""

from __future__ import annotations

import re

from lark.exceptions import UnexpectedCharacters, UnexpectedInput, UnexpectedToken

from ..bilingual import Detail, detail, in_language
from .nodes import Problem

_NAMES: dict[str, str] = {
    "NUMBER": detail("a number", "数值"),
    "VARNUM": detail("a variable such as #1", "变量（如 #1）"),
    "HASH": "'#'",
    "NAMED_VAR": detail("a variable name such as #_DATE", "变量名（如 #_DATE）"),
    "LSQB": "'['",
    "RSQB": "']'",
    "LETTER": detail("an address such as X or G", "地址（如 X 或 G）"),
    "P_LETTER": detail("an address such as X or G", "地址（如 X 或 G）"),
    "BRACKET_NAME": detail("a program name in brackets", "方括号中的程序名"),
    "SIGN": detail("'+' or '-'", "'+' 或 '-'"),
    "ADDOP": detail("OR or XOR", "OR 或 XOR"),
    "MULOP": detail("'*', '/', AND or MOD", "'*'、'/'、AND 或 MOD"),
    "RELOP": detail("a comparison (EQ NE GT GE LT LE)", "关系运算符（EQ NE GT GE LT LE）"),
    "EQUALS": "'='",
    "FUNC": detail("a function such as SIN", "函数（如 SIN）"),
    "ATAN": "ATAN",
    "PRM": "PRM",
    "COMMA": "','",
    "CORNER": detail(",C, ,R or ,A", ",C、,R 或 ,A"),
    "ATAN_SEP": "'/'",
    "IF": "IF",
    "THEN": "THEN",
    "GOTO": "GOTO",
    "WHILE": "WHILE",
    "DO": "DO",
    "END": "END",
    "ELSE": "ELSE",
    "ENDIF": "ENDIF",
    "POPEN": "POPEN",
    "PCLOS": "PCLOS",
    "DPRNT": "DPRNT",
    "BPRNT": "BPRNT",
    "DPRNT_ARGS": detail("'[' with the text to print", "'[' 及要输出的内容"),
    "$END": detail("the end of the block", "程序段结束"),
}
_ANOTHER_ITEM = detail("another word or statement", "其他代码字或宏语句")
_A_VALUE = detail("a value (a number, #variable or [expression])", "数值（数字、#变量或 [表达式]）")
_NOTHING_EXPECTED = Detail("", "")
_CORNER_COMMA = detail(
    "unexpected ','; outside brackets a comma starts ,C (chamfer), ,R (corner radius) or ,A (angle)",
    "此处不应出现 ','；方括号之外的逗号只能引出 ,C（倒角）、,R（拐角圆弧）或 ,A（角度）",
)
_CJK = re.compile("[\u4e00-\u9fff]")

# DPRNT[ or BPRNT[ whose text has no ']' on its line (the grammar's DPRNT_ARGS is the whole [...]):
# its text was cut at a '%', which ends the tape wherever it stands, or never closed
_UNCLOSED_PRINT = detail(
    "the text to print has no closing ']' on this line (nor can it hold a '%', which ends the tape)",
    "要输出的内容在本行没有结束的 ']'（内容中也不能含有 '%'：'%' 表示纸带结束）",
)

# What a bare value looks like, to say "expected a value" instead of listing six terminals.
_VALUE_START = {"NUMBER", "VARNUM", "HASH", "NAMED_VAR", "LSQB", "SIGN"}
# What may start a word or a statement, to say "another word or statement" likewise ('[' starts
# an assignment to a name, [#_UO[1]]=1).
_ITEM_START = {
    "LETTER",
    "P_LETTER",
    "VARNUM",
    "HASH",
    "NAMED_VAR",
    "LSQB",
    "IF",
    "WHILE",
    "DO",
    "END",
    "ELSE",
    "ENDIF",
    "GOTO",
    "POPEN",
    "PCLOS",
    "DPRNT",
    "BPRNT",
    "CORNER",
}


def describe_error(code: str, err: UnexpectedInput) -> Problem:
    """A problem with a message and a range for a line that does not parse."""
    unclosed = _unclosed_bracket(code)
    if isinstance(err, UnexpectedCharacters):
        pos = err.pos_in_stream or 0  # lark declares it None on the base class; the lexer sets it
        ch = code[pos] if pos < len(code) else ""
        if ch == "]" and unclosed is None:
            return Problem(detail("']' without a matching '['", "']' 没有与之配对的 '['"), pos, pos + 1)
        if unclosed is not None and ch not in "[]":
            return _unclosed_problem(code, unclosed, pos)
        allowed = set(err.allowed or ())
        if ch == "[" and allowed == {"DPRNT_ARGS"}:
            return Problem(_UNCLOSED_PRINT, pos, pos + 1)
        expected = _expected_text(allowed)
        if ch.isprintable():
            return Problem(detail(f"unexpected '{ch}'{expected}", f"此处不应出现 '{ch}'{expected.zh}"), pos, pos + 1)
        point = f"U+{ord(ch):04X}"
        message = detail(f"unexpected character {point}{expected}", f"此处不应出现字符 {point}{expected.zh}")
        return Problem(message, pos, pos + 1)
    if isinstance(err, UnexpectedToken):
        tok = err.token
        expected_set = set(err.expected or ())
        if tok.type == "$END":
            end = len(code.rstrip())
            if unclosed is not None:
                return _unclosed_problem(code, unclosed, end)
            start = max(0, end - 1)
            expected = _expected_text(expected_set)
            return Problem(detail(f"the block ends too early{expected}", f"程序段提前结束{expected.zh}"), start, end)
        start = tok.start_pos if tok.start_pos is not None else 0
        end = tok.end_pos if tok.end_pos is not None else start + 1
        if tok.type == "LSQB" and expected_set == {"DPRNT_ARGS"}:
            return Problem(_UNCLOSED_PRINT, start, end)
        if tok.type == "COMMA" and "CORNER" in expected_set:
            return Problem(_CORNER_COMMA, start, end)
        if tok.type == "RSQB" and not _open_bracket_before(code, start) and "RSQB" not in expected_set:
            return Problem(detail("']' without a matching '['", "']' 没有与之配对的 '['"), start, end)
        if tok.type == "RELOP" and "RELOP" not in expected_set:
            if _open_bracket_before(code, start):
                message = detail(
                    f"unexpected comparison '{tok}': join conditions as [[a EQ b] AND [c EQ d]]",
                    f"此处不应出现关系运算符 '{tok}'：多个条件应写成 [[a EQ b] AND [c EQ d]]",
                )
            else:
                message = detail(
                    f"the comparison '{tok}' is allowed only inside the [ ] of an IF or WHILE condition",
                    f"关系运算符 '{tok}' 只能用在 IF 或 WHILE 条件的 [ ] 中",
                )
            return Problem(message, start, end)
        if tok.type == "NUMBER" and str(tok).startswith(".") and _VARIABLE_BEFORE(code[:start]):
            shown, whole = _fraction_in_variable(code[:start].rstrip() + str(tok))
            return Problem(
                detail(
                    f"a variable number is a whole number: '{shown}' names no variable (write {whole}, "
                    f"or {whole}. with a point alone, which reads as {whole})",
                    f"变量号必须是整数：'{shown}' 不是变量（应写成 {whole}；只带小数点的 {whole}. 按 {whole} 读取）",
                ),
                start,
                end,
            )
        if tok.type == "NUMBER" and "NUMBER" not in expected_set and expected_set != {"NAMED_VAR"}:
            return Problem(
                detail(
                    f"unexpected number '{tok}': an address letter such as X must come before a value",
                    f"此处不应出现数值 '{tok}'：数值之前必须有地址字母，如 X",
                ),
                start,
                end,
            )
        if unclosed is not None and "RSQB" in expected_set and tok.type not in ("LSQB",):
            return _unclosed_problem(code, unclosed, start)
        expected = _expected_text(expected_set)
        return Problem(detail(f"unexpected '{tok}'{expected}", f"此处不应出现 '{tok}'{expected.zh}"), start, end)
    pos = getattr(err, "pos_in_stream", 0) or 0
    return Problem(detail("the block does not parse", "程序段无法解析"), pos, pos + 1)


_VARIABLE_BEFORE = re.compile(r"#[ \t]*\d+$").search


def _fraction_in_variable(written: str) -> tuple[str, str]:
    """``#2.5`` and ``#2`` from the text up to a fraction after a variable number."""
    m = re.search(r"#[ \t]*\d+\.\d+$", written)
    shown = m.group(0) if m else written
    return shown, shown.split(".")[0]


def _unclosed_problem(code: str, bracket: int, at: int) -> Problem:
    at = min(at, len(code))
    end = max(at, len(code.rstrip()))
    column = bracket + 1
    message = detail(f"expected ']' to close the '[' at column {column}", f"缺少 ']'：第 {column} 列的 '[' 没有闭合")
    return Problem(message, at, max(end, at + 1))


def _open_bracket_before(code: str, pos: int) -> bool:
    """True when a '[' opened before ``pos`` is still open there."""
    return _unclosed_bracket(code[:pos]) is not None


def _unclosed_bracket(code: str) -> int | None:
    """Column of the innermost '[' that is never closed, if any."""
    stack: list[int] = []
    for i, ch in enumerate(code):
        if ch == "[":
            stack.append(i)
        elif ch == "]" and stack:
            stack.pop()
    return stack[-1] if stack else None


def _expected_text(expected: set[str]) -> Detail:
    """ "; expected a, b" (and its Chinese) for the terminals lark expected, or nothing."""
    if not expected:
        return _NOTHING_EXPECTED
    names: list[str] = []
    if len(expected & _ITEM_START) >= 5:
        names.append(_ANOTHER_ITEM)
        expected = expected - _ITEM_START
    if {"NUMBER", "VARNUM", "LSQB"} <= expected:
        names.append(_A_VALUE)
        expected = expected - _VALUE_START - {"FUNC", "ATAN", "PRM"}
    names += _names(expected)
    if len(names) > 5:
        names = [*names[:5], "..."]
    shown = [in_language(n, True) for n in names if n != "..."]
    chinese = "、".join(shown) + ("等" if len(shown) < len(names) else "")  # "..." reads "等" in Chinese
    listed = Detail(", ".join(names), chinese if _CJK.match(chinese) else " " + chinese)  # "应为数值", "应为 '['"
    return detail(f"; expected {listed}", f"；应为{listed.zh}")


def _names(terms: set[str]) -> list[str]:
    seen: list[str] = []
    for t in sorted(terms):
        name = _NAMES.get(t, t)
        if name not in seen:
            seen.append(name)
    return seen
