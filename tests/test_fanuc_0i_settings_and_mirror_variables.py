"""docs/semantics.md §2 "System variables": the FANUC 0i custom macro chapter lists #3005, the
setting data, read and written ("SETTING 值可用变量读和写。二进制数转换为十进制数"), and #3007,
the mirror image state of each axis set by an external switch or the setting screen, read only
("镜像：使用外部开关或SETTING 操作设置的各轴镜像状态…"). Reading them was alarm 115 on
``fanuc-0i``; the 30i had them. The simulated machine has no setting screen and no mirror switch,
so both read 0 unless the machine file gives them."""

from __future__ import annotations

from running import alarm, final, lines


def test_0i_reads_the_setting_data_and_the_mirror_image_state() -> None:
    """No alarm 115: #3005 and #3007 read their stored value, 0 on the simulated machine."""
    for dialect in ("fanuc", "fanuc-0i-lathe"):
        v = final(lines("#101=#3005", "#102=#3007", "M30"), dialect)
        assert (v[101], v[102]) == (0, 0), dialect


def test_0i_writes_the_setting_data_and_reads_it_back() -> None:
    """#3005 is read and written: a macro that switches a setting and restores it."""
    v = final(lines("#101=#3005", "#3005=4", "#102=#3005", "#3005=#101", "#103=#3005", "M30"))
    assert (v[101], v[102], v[103]) == (0, 4, 0)


def test_0i_mirror_image_state_cannot_be_written() -> None:
    """#3007 is read only: writing it is alarm 116 (write-protected variable), on line 1."""
    assert alarm(lines("#3007=1", "M30")) == (116, 1)


def test_machine_file_presets_the_settings_and_mirror_state() -> None:
    """A machine file's [variables] gives the machine's own: X mirrored (bit 0) reads 1."""
    v = final(lines("#101=#3007", "#102=#3005", "M30"), "fanuc", presets={3007: 1, 3005: 4})
    assert (v[101], v[102]) == (1, 4)
