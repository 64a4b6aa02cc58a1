"""The machine file's ``part_system_commons`` (docs/machine-file.md "part_system_commons"): on a
multi-path control (a Mitsubishi M70/M80 with two part systems) parameters decide which commons
each path keeps its own and which the paths share. The key names the ranges each part system
keeps; the profile the machine file makes answers whether a common is shared (what the editor's
hover on the variable says), and a range outside the machine's commons names the key."""

from __future__ import annotations

import pytest

from cncmacro.library.machine_file import MachineFileError, settings_from_mapping
from cncmacro.library.profiles import machine_profile


def test_part_system_commons_says_which_commons_each_path_keeps() -> None:
    settings = settings_from_mapping({"base": "mitsubishi-m70", "part_system_commons": [[100, 149], [500, 549]]})
    profile = machine_profile(None, settings)
    assert profile.name == "mitsubishi-m70" and profile.part_system_commons == ((100, 149), (500, 549))
    assert [profile.shared_common(n) for n in (100, 149, 150, 199, 549, 550, 999)] == [
        False, False, True, True, False, True, True,
    ]  # fmt: skip


def test_without_the_key_nothing_is_said_of_sharing() -> None:
    profile = machine_profile(None, settings_from_mapping({"base": "mitsubishi-m70"}))
    assert profile.shared_common(100) is None


@pytest.mark.parametrize(
    "value",
    [[[100, 299]], [[150, 100]], [[1000, 1010]], "100-149", [[100]], [[100, 149.5]]],
)
def test_part_system_commons_outside_the_machines_commons_names_the_key(value: object) -> None:
    # mitsubishi-m70's commons are #100-#199 and #500-#999: #200-#299 is none of them
    with pytest.raises(MachineFileError) as bad:
        settings_from_mapping({"base": "mitsubishi-m70", "part_system_commons": value}, "shop.toml")
    assert bad.value.key == "part_system_commons"
    assert "each inside the machine's commons (#100-#199, #500-#999)" in str(bad.value)


def test_part_system_commons_are_judged_against_the_machine_files_common() -> None:
    # a fanuc-0i whose machine has #100-#499: #300 may be kept per path there
    settings = settings_from_mapping({"common": [[100, 499], [500, 999]], "part_system_commons": [[300, 399]]})
    assert machine_profile(None, settings).shared_common(300) is False
    with pytest.raises(MachineFileError):
        settings_from_mapping({"common": [[100, 199], [500, 999]], "part_system_commons": [[300, 399]]})
