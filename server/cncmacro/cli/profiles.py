"""``cncmacro profiles``: the control profiles this version knows, and the ``--dialect`` option
that picks one by its name or an alias (``fanuc`` is ``fanuc-0i``)."""

from __future__ import annotations

import argparse
import sys
from typing import Any

from ..dialects import DEFAULT_DIALECT, DIALECTS, normalise_dialect
from ..dialects.registry import profile_facts
from .terminal import json_text


def profile_argument(text: str) -> str:
    """argparse ``type`` for ``--dialect``: the profile's name, from its name or an alias."""
    name = normalise_dialect(text)
    if name is None:
        raise argparse.ArgumentTypeError(f"unknown profile {text!r}; choose one of {', '.join(DIALECTS)}")
    return name


def add_dialect_option(parser: argparse.ArgumentParser, when: str) -> None:
    parser.add_argument(
        "--dialect", type=profile_argument, metavar="PROFILE",
        help=f"control profile {when}: {', '.join(DIALECTS)} (default {DEFAULT_DIALECT}; see 'cncmacro profiles')",
    )  # fmt: skip


def add_profiles_parser(sub: Any) -> None:
    p = sub.add_parser("profiles", help="list the control profiles", description="List the control profiles.")
    p.add_argument("--json", action="store_true", help="print them as JSON")
    p.set_defaults(handler=main_profiles)


def main_profiles(args: argparse.Namespace) -> int:
    facts = profile_facts()
    if args.json:
        sys.stdout.write(json_text(facts, indent=1) + "\n")
        return 0
    width = max(len(f["name"]) for f in facts) + 1
    for f in facts:
        kind = "lathe" if f["lathe"] else "mill"
        also = f" (also: {', '.join(f['aliases'])})" if f["aliases"] else ""
        default = " [default]" if f["default"] else ""
        print(f"{f['name']:<{width}} {f['title']} — {f['summary']}; {kind}{default}{also}")
    return 0
