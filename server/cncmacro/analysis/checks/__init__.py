"""The static checks: what the analysis decides without running the program.

Per line (``line_facts.py`` and the checks of statements, calls, variables and corner words),
across lines (labels, loops, O programs, call targets, the tape's end), kept per line across
edits (``static_lines.py``) and gathered for a file (``static_checks.py``), with the parser's
problems (``syntax_check.py``) and the profile a file seems written for (``profile_suggestion.py``).
"""
