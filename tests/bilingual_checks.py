"""The rules a ``detail(en, zh)`` written in the source must follow, read from its syntax tree:
the tests that walk the parser's and the interpreter's messages share them.

A Chinese text exists where the English has words, no English words are left in it (text in
quotes is source text and stays as written), and it shows the same values as the English
(``x.zh`` and ``in_language(x, True)`` show ``x``, in its Chinese).
"""

from __future__ import annotations

import ast
import re

CJK = re.compile(r"[\u4e00-\u9fff]")
PROSE = re.compile(r"[a-z]{2,}")  # English prose is lower case; codes (G01, L0, #100, U+DCFF) are not
QUOTED = re.compile(r"'[^']*'")


def called_name(node: ast.AST) -> str | None:
    """The name a call (or a name or attribute) refers to: ``detail``, ``m.note`` -> ``note``."""
    if isinstance(node, ast.Call):
        node = node.func
    return node.id if isinstance(node, ast.Name) else node.attr if isinstance(node, ast.Attribute) else None


def literal_parts(expr: ast.expr) -> tuple[str, set[str]] | None:
    """The literal text of a string or f-string and the values it shows; None for anything else."""
    if isinstance(expr, ast.Constant) and isinstance(expr.value, str):
        return expr.value, set()
    if isinstance(expr, ast.JoinedStr):
        text = "".join(v.value for v in expr.values if isinstance(v, ast.Constant))
        return text, {_shown(v.value) for v in expr.values if isinstance(v, ast.FormattedValue)}
    return None


def _shown(value: ast.expr) -> str:
    if isinstance(value, ast.Attribute) and value.attr == "zh":
        value = value.value
    elif isinstance(value, ast.Call) and called_name(value) == "in_language" and value.args:
        value = value.args[0]
    return ast.unparse(value)


def detail_problems(call: ast.Call) -> list[str]:
    """What is wrong with one ``detail(en, zh)`` call."""
    if len(call.args) != 2 or call.keywords:
        return ["detail takes the English and the Chinese"]
    en, zh = call.args
    if isinstance(zh, ast.Call) and called_name(zh) == "alarm_text":
        return []  # an alarm's standard text: both languages come from the dialect's alarm table
    en_parts, zh_parts = literal_parts(en), literal_parts(zh)
    if en_parts is None or zh_parts is None:
        return ["both texts must be written out (a string or an f-string)"]
    problems = []
    if PROSE.search(en_parts[0]) and not CJK.search(zh_parts[0]):
        problems.append(f"no Chinese in {ast.unparse(zh)}")
    if PROSE.search(QUOTED.sub("", zh_parts[0])):
        problems.append(f"English words left in {ast.unparse(zh)}")
    if en_parts[1] != zh_parts[1]:
        problems.append(f"{ast.unparse(en)} and {ast.unparse(zh)} show different values")
    return problems
