"""Generated CAM-style programs for the benchmarks (and for tests that want realistic lines).

A program is 90% plain motion blocks (G00/G01/G02/G03 with coordinates, feeds, arcs), an N
number every 10 lines, and 10% macro statements: assignments with arithmetic and functions,
IF..GOTO to a later label, and short WHILE loops. Output is deterministic for a seed.
"""

from __future__ import annotations

import random


def cam_program(lines: int, seed: int = 1) -> str:
    """A FANUC program of about ``lines`` lines that runs to M30 without an alarm."""
    rnd = random.Random(seed)
    out = ["%", "O0001 (GENERATED CAM PROGRAM)", "G21 G17 G40 G49 G80 G90", "#100=0", "#101=1.5"]
    label = 0
    x = y = 0.0
    while len(out) < lines - 3:
        k = len(out)
        prefix = ""
        if k % 10 == 0:
            label += 1
            prefix = f"N{label} "
        if rnd.random() < 0.10:
            out.append(prefix + _macro_statement(rnd, label))
            continue
        x = round(x + rnd.uniform(-5, 5), 3)
        y = round(y + rnd.uniform(-5, 5), 3)
        r = rnd.random()
        if r < 0.05:
            out.append(f"{prefix}G00 X{x:.3f} Y{y:.3f} Z{rnd.uniform(1, 5):.3f}")
        elif r < 0.15:
            g = rnd.choice(("G02", "G03"))
            out.append(f"{prefix}{g} X{x:.3f} Y{y:.3f} I{rnd.uniform(-9, 9):.4f} J{rnd.uniform(-9, 9):.4f}")
        elif r < 0.20:
            out.append(f"{prefix}G01 X{x:.3f} Y{y:.3f} Z{rnd.uniform(-3, 0):.3f} F{rnd.randint(100, 900)}.")
        else:
            out.append(f"{prefix}X{x:.3f} Y{y:.3f}")
    out += ["M05", "M30", "%"]
    return "\n".join(out) + "\n"


def _macro_statement(rnd: random.Random, label: int) -> str:
    a = rnd.randint(102, 149)
    b = rnd.randint(102, 149)
    c = round(rnd.uniform(0.5, 99), 3)
    r = rnd.random()
    if r < 0.35:
        return f"#{a}=#{b}+{c}"
    if r < 0.55:
        return f"#{a}=[#{b}*COS[#{rnd.randint(102, 149)}]+{c}]/2"
    if r < 0.70:
        return f"#{a}=ROUND[#{b}*1000]/1000+SIN[{c}]"
    if r < 0.85:
        return f"IF[#{a} GT {c}]GOTO{label + 1}"
    return f"#{a}=#{a}+#101*{c}-ABS[#{b}]"
