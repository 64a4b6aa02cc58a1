"""docs/semantics.md §2 "Values and variables" and §3 "Expressions": how they are read."""

from __future__ import annotations

import pytest

from cncmacro.syntax.nodes import Binary, Bracket, FunctionCall, IndirectVar, Number, Relation, Unary, Var
from conftest import block, error


def value(text: str):
    """The right-hand side of ``#1=<text>``."""
    return block("#1=" + text).statements[0].value


def test_variable_with_number_and_vacant_zero():
    assert block("#2=#0").statements[0].value == Var(0, 3, 5)


def test_indirect_variable_on_both_sides():
    s = block("#[#100+1]=#[#2]").statements[0]
    assert isinstance(s.target, IndirectVar) and isinstance(s.value, IndirectVar)


def test_gsk_indirection_through_9_is_an_ordinary_number_here():
    # #9100 = #[#100] on gsk980tdi is the interpreter's business; the parser keeps 9100
    s = block("#9102=#9102+#21").statements[0]
    assert s.target.number == 9102


def test_assignment_needs_a_variable_on_the_left():
    error("5=#1")
    error("#=3")


def test_precedence_product_before_sum():
    v = value("#2+#3*2")
    assert isinstance(v, Binary) and v.op == "+" and v.right.op == "*"


def test_left_to_right_within_a_level():
    v = value("#2-#3-#4")
    assert v.op == "-" and v.left.op == "-"


@pytest.mark.parametrize("op", ["AND", "MOD"])
def test_and_mod_are_product_level(op):
    v = value(f"#2+#3 {op} #4")
    assert v.op == "+" and v.right.op == op


@pytest.mark.parametrize("op", ["OR", "XOR"])
def test_or_xor_are_sum_level(op):
    v = value(f"#2*#3 {op} #4")
    assert v.op == op and v.left.op == "*"


def test_unary_minus():
    v = value("-#2*3")
    assert isinstance(v, Binary) and isinstance(v.left, Unary)
    w = block("X-[#1]").words[0]
    assert isinstance(w.value, Unary) and isinstance(w.value.operand, Bracket)


def test_signed_literal_word_is_one_number():
    w = block("X-12.5").words[0]
    assert w.value == Number(-12.5, "-12.5", 1, 6)


@pytest.mark.parametrize(
    "name", ["SIN", "COS", "TAN", "ASIN", "ACOS", "SQRT", "ABS", "LN", "EXP", "ROUND", "FIX", "FUP", "BIN", "BCD"]
)
def test_every_function(name):
    v = value(f"{name}[#2]")
    assert isinstance(v, FunctionCall) and v.name == name and len(v.args) == 1


def test_function_needs_brackets():
    error("#1=SIN#2")


def test_atan_two_arguments():
    v = value("ATAN[#2]/[#3]")
    assert isinstance(v, FunctionCall) and v.name == "ATAN" and len(v.args) == 2


def test_atan_one_argument_then_division():
    v = value("ATAN[#2]/2")
    assert isinstance(v, Binary) and v.op == "/" and v.left.name == "ATAN"


def test_atan_two_arguments_inside_a_product():
    v = value("2*ATAN[#2]/[#3]")
    assert v.op == "*" and isinstance(v.right, FunctionCall) and len(v.right.args) == 2


def test_comparison_outside_a_condition_is_alarm_114():
    p = error("#2=[1 LT 2]")
    assert "only in an IF or WHILE condition" in p.message and p.alarm == 114  # the check names it (alarm 114)
    error("X[#1 GT 2]")


def test_c_style_relations_parse_in_every_dialect():
    cond = block("IF[#100==100]THEN #100=0").statements[0].condition
    assert cond.inner == Relation("EQ", "==", Var(100, 3, 7), Number(100.0, "100", 9, 12), 3, 12)
    for op, name in [("!=", "NE"), ("<", "LT"), (">", "GT"), ("<=", "LE"), (">=", "GE")]:
        rel = block(f"IF[#1{op}2]GOTO5").statements[0].condition.inner
        assert (rel.op, rel.spelling) == (name, op)


def test_compound_condition_with_bracketed_sides():
    cond = block("IF[[#1 EQ #0] OR [#2 LT 0]] GOTO 5").statements[0].condition
    assert isinstance(cond.inner, Binary) and cond.inner.op == "OR"


def test_compound_condition_without_brackets_is_an_error():
    p = error("IF[#1 EQ 1 AND #2 EQ 2] GOTO 3")
    assert "[[a EQ b] AND [c EQ d]]" in p.message


def test_condition_without_comparison_is_an_error():
    assert "needs a comparison" in error("IF[#1]GOTO5").message


def test_unclosed_bracket_message_names_its_column():
    p = error("#1=[#2+3")
    assert p.message == "expected ']' to close the '[' at column 4"


def test_stray_closing_bracket():
    assert error("#1=#2]").message == "']' without a matching '['"


def test_deep_brackets_parse_without_recursion_error():
    text = "#1=" + "[" * 1000 + "1" + "]" * 1000
    b = block(text)
    depth = 0
    e = b.statements[0].value
    while isinstance(e, Bracket):
        depth += 1
        e = e.inner
    assert depth == 1000
