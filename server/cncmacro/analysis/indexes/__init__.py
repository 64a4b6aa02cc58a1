"""Where things are: the facts of each block found once (``block_memo.py``), the jumps, variables
and calls a block mentions (``sites.py``, ``call_sites.py``), kept per document across edits
(``site_index.py``), the workspace's program files (``workspace_index.py``) and who calls whom on
disk (``call_index.py``, ``caller_entries.py``, ``disk_callers.py``, ``open_programs.py``).
"""
