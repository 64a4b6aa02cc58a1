"""The words the language server itself shows (hover headings, hint labels), in English and
simplified Chinese. What a code or variable means comes from the dialect tables, not from here."""

from __future__ import annotations

from ..bilingual import pick

_TEXTS: dict[str, tuple[str, str]] = {
    "local": ("Local variable", "局部变量"),
    "common": ("Common variable (cleared at power-off)", "公共变量（断电清除）"),
    "persistent": ("Common variable (kept at power-off)", "公共变量（断电保持）"),
    "system": ("System variable", "系统变量"),
    "null": ("#0: always vacant, read-only", "#0：总是空，只读"),
    "undefined": ("No such variable in this dialect (alarm 115)", "该系统中不存在此变量（115号报警）"),
    "name": ("System variable name", "系统变量名"),
    "no_names": ("This dialect has no system variable names (alarm 114)", "该系统不支持系统变量名（114号报警）"),
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
    "more": ("more", "更多"),
    "not_here": ("this dialect does not read abbreviations", "本系统不支持关键字缩写"),
}


def t(key: str, locale: str | None) -> str:
    en, zh = _TEXTS[key]
    return pick(locale, en, zh)
