"""The words the language server itself shows (hover headings and texts, hint labels, quick fix
titles, progress and messages), in English and simplified Chinese: the one place of the editor's
own texts, each key with both (no other module of ``lsp/`` writes Chinese). What a code or variable
means comes from the dialect tables, what a check finds from the analysis, not from here."""

from __future__ import annotations

from ..bilingual import pick

TEXTS: dict[str, tuple[str, str]] = {
    "unknown_dialect_near": (
        "cncMacro.dialect: '{name}' is not a profile, so the setting is passed over. Did you mean '{near}'? "
        "(profiles: {names})",
        "cncMacro.dialect：'{name}' 不是系统类型，该设置被忽略。是否应为 '{near}'？（可用：{names}）",
    ),
    "unknown_dialect": (
        "cncMacro.dialect: '{name}' is not a profile, so the setting is passed over (profiles: {names})",
        "cncMacro.dialect：'{name}' 不是系统类型，该设置被忽略（可用：{names}）",
    ),
    "setting_refused": ("{text}", "设置被忽略：{text}"),  # a setting's own message (check_overrides), passed over
    "local": ("Local variable", "局部变量"),
    "common": ("Common variable (cleared at power-off)", "公共变量（断电清除）"),
    "persistent": ("Common variable (kept at power-off)", "公共变量（断电保持）"),
    "part_system_own": (
        "Each part system (path) keeps its own (the machine file's part_system_commons)",
        "每个系统（通道）各有一个（机床设置文件的 part_system_commons）",
    ),
    "part_system_shared": (
        "Shared by every part system (path) of the machine (not in the machine file's part_system_commons)",
        "机床的各系统（通道）共用（不在机床设置文件的 part_system_commons 之内）",
    ),
    "symbol_read": ("`{symbol}` is {word}, as this control reads it.", "`{symbol}` 即 {word}，本系统可以这样写。"),
    "symbol_refused": (
        "`{symbol}` stands for {word} on some controls; this one does not read it: write {word}.",
        "`{symbol}` 在部分系统中表示 {word}；本系统不识别，应写 {word}。",
    ),
    "system": ("System variable", "系统变量"),
    "null": ("Always vacant, read-only", "总是空，只读"),
    "undefined": ("No such variable in this dialect ({alarm})", "该系统中不存在此变量（{alarm}）"),
    "name": ("System variable name", "系统变量名"),
    "no_names": ("This dialect has no system variable names ({alarm})", "该系统不支持系统变量名（{alarm}）"),
    "r": ("read-only", "只读"),
    "w": ("write-only", "只写"),
    "rw": ("read/write", "可读写"),
    "unit": ("unit", "单位"),
    "axis": ("axis", "轴"),
    "access": ("access", "读写"),
    "spec1": ("argument specification I", "自变量指定I"),
    "spec2": ("argument specification II", "自变量指定II"),
    "filled_by": ("filled by the G65/G66 argument", "由G65/G66自变量赋值"),
    "no_argument": ("no argument fills it; set it in the macro", "没有自变量对其赋值，需在宏程序中赋值"),
    "written_at": ("written at", "赋值位置"),
    "not_written": ("not written in the workspace", "工作区内没有对其赋值"),
    "being_found": (
        "still being found in {files} (a long file, being read or indexed); hover again in a moment",
        "仍在 {files} 中查找（长文件，正在读取或建立索引），请稍后再次悬停",
    ),
    "label": ("Sequence number", "顺序号"),
    "jumps": ("jumps to it", "跳转到此处"),
    "no_jumps": ("no jump names it", "没有跳转指向此处"),
    "target": ("target", "目标"),
    "not_found": ("not found", "未找到"),
    "returns_to": ("M99 P{label} returns to N{label} of the calling program", "M99 P{label} 返回调用程序的 N{label}"),
    "callers_unknown": (
        "M99 P{label} returns to N{label} of the program that calls {name}: no call of {name} was found in the "
        "workspace, so where it lands is known only when it runs",
        "M99 P{label} 返回调用 {name} 的程序中的 N{label}：工作区中未找到对 {name} 的调用，落点在运行时才能确定",
    ),
    "main_return": (
        "Nothing in the workspace calls {name}: as a main program, M99 P{label} goes on from its own N{label}",
        "工作区中没有程序调用 {name}：作为主程序，M99 P{label} 从其自身的 N{label} 继续执行",
    ),
    "on_control": (
        "kept on the control ({title} keeps {ranges} there: programs_on_control of its profile or of the "
        "machine file); the run returns from it at once. "
        "A file with this number in the workspace would be run in its place, to set what the caller reads.",
        "存放在数控系统内（{title} 的 {ranges} 存放在系统内：由配置或机床设置文件的 programs_on_control 决定）；"
        "分析运行时调用后立即返回。若工作区中有同号的程序文件，则运行该文件，用它设定调用者要读取的变量。",
    ),
    "program": ("Program", "程序"),
    "arguments": ("Arguments", "自变量"),
    "results": ("Results it writes", "写入的结果变量"),
    "given": ("given in this call", "本次调用已给出"),
    "file": ("file", "文件"),
    "line": ("line", "行"),
    "modal": ("modal group", "模态组"),
    "one_shot": ("one-shot", "非模态"),
    "fills": ("fills", "赋值给"),
    "reads": ("reads", "读取"),
    "this_block": ("this block", "本程序段"),
    "skip_stores": (
        "Where the skip signal comes on, the absolute position is stored in {places}",
        "跳转信号变为“1”时，绝对坐标位置被存储在 {places}",
    ),
    "skip_clamp": ("a faster feed is clamped at {feed:g} mm/min", "进给速度超过 {feed:g} mm/min 时被箝制在该速度"),
    "skip_common": (
        "{code} stores here the absolute {axis} position where the skip signal came on (until then it keeps its value)",
        "{code} 跳转信号变为“1”时，在此存储 {axis} 轴的绝对坐标位置（此前保持原值）",
    ),
    "more": ("more", "更多"),
    "not_here": ("this dialect does not read abbreviations", "本系统不支持关键字缩写"),
    "short_for": ("**{text}** — short for **{word}**", "**{text}** — **{word}** 的缩写"),
    # hover on a corner word (``,C`` ``,R`` ``,A``)
    "corner_C": (
        "chamfer: a straight cut of this length across the corner between this move and the next",
        "倒角：在本段与下一段移动之间的拐角处切出此长度的直线",
    ),
    "corner_R": (
        "corner radius: an arc of this radius rounds the corner between this move and the next",
        "拐角圆弧：以此半径的圆弧连接本段与下一段移动之间的拐角",
    ),
    "corner_A": ("angle of the move (direct drawing dimension programming)", "移动的角度（图纸尺寸直接输入）"),
    "corner_run": (
        "The simulator runs the move as written: the toolpath shows the sharp corner.",
        "模拟器按所写路径运行：刀路显示未倒角的尖角。",
    ),
    "corner_not_in_manual": (
        "Not in the manual of *{title}*, which writes chamfers as L and corner arcs as D.",
        "*{title}* 的说明书中没有此写法，其倒角写作 L（直线）和 D（圆弧）。",
    ),
    # hover on the M99 of a conditional jump (Haas)
    "conditional_m99": (
        "**[cond] M99 P n** — Conditional jump (Haas): to block Nn when the condition holds, otherwise on to "
        "the next block; the same as IF [cond] GOTO n",
        "**[条件] M99 P n** — 条件跳转（哈斯）：条件成立时转到 Nn 程序段，否则继续执行下一段；等同于 IF [条件] GOTO n",
    ),
    "conditional_m99_refused": (
        "{title} does not read it: the control stops at this block with {alarm}",
        "{title} 不接受这种写法：执行到此程序段时{alarm}",
    ),
    # hover: the cycle time
    "starts_at": (
        "Cycle time: this block starts at ≈ {shown} (the first time it runs)",
        "加工时间：本程序段约在 {shown}时开始（首次执行时）",
    ),
    # inlay hints
    "vacant": ("<vacant>", "<空>"),
    "unknown": ("<unknown>", "<未知>"),  # a value only the machine has (docs/semantics.md §2)
    # quick fixes
    "fix_comment": (
        "Read this file as {title}: add (cncmacro: dialect={name})",
        "按 {title} 读取此文件：加上 (cncmacro: dialect={name})",
    ),
    "fix_machine": (
        'Set base = "{name}" in .cncmacro.toml (every file of the workspace)',
        '在 .cncmacro.toml 中设定 base = "{name}"（对工作区所有文件生效）',
    ),
    "fix_machine_lathe": (
        "Set lathe = true in .cncmacro.toml: a {title} (every file of the workspace)",
        "在 .cncmacro.toml 中设定 lathe = true：{title}（对工作区所有文件生效）",
    ),
    "fix_split": ("Split: move {words} to a block before the {name}", "拆分：把 {words} 移到 {name} 之前的单独程序段"),
    "fix_clamp": ("Clamp the repeat count to {value}", "把重复次数改为 {value}"),
    "fix_expand": ("Write {word} in full", "把 {text} 写全为 {word}"),
    "fix_if_goto": ("Write it as {text}", "改写为 {text}"),
    # the sequence-number commands
    "renumber": ("Renumber sequence numbers", "重新编排顺序号"),
    "add_numbers": ("Add missing sequence numbers", "补上缺少的顺序号"),
    "remove_numbers": ("Remove unused sequence numbers", "删除无用的顺序号"),
    "keep_labels": ("Keep those labels unchanged", "保留这些顺序号不变"),
    "cancel": ("Cancel", "取消"),
    "and_more": ("; and {more} more", "；另有 {more} 处"),
    "refused": ("{label}: refused. {text}", "{label}：已拒绝。{text}"),
    "nothing_to_change": ("Nothing to change.", "没有需要修改的地方。"),
    "labels_kept": (
        "{label}: kept the labels on lines {lines}: a jump whose label is computed, or a jump of another file, "
        "may land on them.",
        "{label}：第 {lines} 行的顺序号保持不变：运算得出顺序号的跳转或其他文件的跳转可能落在这些顺序号上。",
    ),
    # work done progress of an analysis
    "reading_lines": ("reading {lines:,} lines", "读取 {lines:,} 行"),
    "analysing_lines": ("analysing {lines:,} lines", "分析 {lines:,} 行"),
    "stopped": ("stopped", "已停止"),
    "done": ("done", "完成"),
    # folders and files the workspace scan did not read
    "not_read_one": (
        "cncmacro: 1 folder or file in the workspace was not read: {named}",
        "cncmacro：工作区中有 1 个文件夹或文件未读取：{named}",
    ),
    "not_read": (
        "cncmacro: {count} folders or files in the workspace were not read: {named}",
        "cncmacro：工作区中有 {count} 个文件夹或文件未读取：{named}",
    ),
    "more_in_output": ("; {more} more in the output", "；其余 {more} 个见输出窗口"),
    "more_not_read": ("... and {more} more folders or files not read", "……另有 {more} 个文件夹或文件未读取"),
}


def t(key: str, locale: str | None, **values: object) -> str:
    """The text ``key`` in the language of ``locale``, its ``{name}`` places filled from ``values``."""
    en, zh = TEXTS[key]
    text = pick(locale, en, zh)
    return text.format(**values) if values else text
