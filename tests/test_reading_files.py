"""docs/semantics.md §1 "Text and blocks": files in UTF-8 or GBK/GB18030, with BOM and CRLF, and
binary files reported rather than parsed."""

from __future__ import annotations

from pathlib import Path

import pytest

from cncmacro.library.files import (
    BinaryFileError,
    decode_program,
    encode_program,
    find_program_files,
    is_program_file,
    o_number,
)
from cncmacro.syntax.document import ParsedDocument, split_lines

GSK_TEXT = "O0100 (刀具磨损补偿)\nG65 P[螺纹切削]\nM30\n"


def test_utf8_with_bom():
    src = decode_program(b"\xef\xbb\xbfO1 (X)\nM30\n")
    assert src.text.startswith("O1") and src.bom and src.encoding == "utf-8"
    assert encode_program(src) == b"\xef\xbb\xbfO1 (X)\nM30\n"


def test_gbk_file_decodes_and_round_trips():
    data = GSK_TEXT.encode("gbk")
    src = decode_program(data)
    assert src.encoding == "gb18030" and src.text == GSK_TEXT
    assert encode_program(src) == data
    doc = ParsedDocument(src.text)
    assert doc.blocks[0].title == "刀具磨损补偿"
    assert doc.blocks[1].word("P").name == "螺纹切削"


def test_undecodable_bytes_are_kept():
    data = b"G00 X0 (\xff\xfe\x80)\n"
    src = decode_program(data)
    assert encode_program(src) == data


def test_crlf_and_lone_cr_line_breaks():
    assert split_lines("G00\r\nG01\rG02\nG03") == ["G00", "G01", "G02", "G03"]
    doc = ParsedDocument("N1 G00\r\nN2 G01\r\n")
    assert doc.program.labels == {1: [0], 2: [1]}


def test_binary_file_is_refused():
    with pytest.raises(BinaryFileError) as e:
        decode_program(b"\x7fELF\x02\x01\x01\x00\x00")
    assert e.value.offset == 7
    with pytest.raises(BinaryFileError):
        decode_program(bytes(range(1, 32)) * 20)


def test_utf16_program_with_bom_is_read():
    text = "O0100 (刀具磨损补偿)\nG00 X10.\nM30\n"
    src = decode_program(text.encode("utf-16"))
    assert src.encoding == "utf-16" and src.text == text
    assert encode_program(src) == text.encode("utf-16")


def test_binary_file_starting_like_utf16_is_refused():
    """Binary data whose first two bytes happen to be a UTF-16 byte-order mark is still binary."""
    with pytest.raises(BinaryFileError):
        decode_program(b"\xff\xfe" + bytes(range(256)) * 4)
    with pytest.raises(BinaryFileError):
        decode_program(b"\xff\xfe" + "图像数据".encode("utf-16-le") * 50)
    with pytest.raises(BinaryFileError):
        decode_program(b"\xff\xfe\x00\xd8")  # a lone surrogate


def test_text_file_is_not_binary():
    assert decode_program(b"G00 X0\tY0\n\x1a").text.startswith("G00")


def test_program_files_by_ending_or_o_number(tmp_path):
    for name in ["a.NC", "b.cnc", "O1234", "c.txt", "readme", ".hidden.nc"]:
        (tmp_path / name).write_text("M30\n")
    assert is_program_file(tmp_path / "O1234") and not is_program_file(tmp_path / "readme")
    names = [p.name for p in find_program_files(tmp_path)]
    assert names == ["O1234", "a.NC", "b.cnc"]


def test_a_name_spells_a_program_number_with_an_o_and_one_to_eight_digits():
    """``P[O1004]`` and a file ``O1004.nc`` name O1004; the file ``1004.nc`` does too, a bracketed
    ``P[1004]`` does not (it is a file name); a name of nine digits is a program file, not a number."""
    assert o_number("O1004") == o_number("o01004") == o_number("1004", bare=True) == 1004
    assert o_number("O12345678") == 12345678 and o_number("O123456789") is None
    assert o_number("1004") is None and o_number("O") is None and o_number("O12A") is None
    assert o_number("O1004 ") is None and o_number("OO1004", bare=True) is None
    assert is_program_file(Path("O123456789")) and is_program_file(Path("o7"))
    assert not is_program_file(Path("1234")) and not is_program_file(Path("O")) and not is_program_file(Path("O12.3"))
