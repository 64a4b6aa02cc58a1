"""Edits and views the editor asks the analysis for: renumbering N labels so that every jump still
lands where it landed (``sequence_numbers.py``, with the jumps of other files, ``outside_jumps.py``)
and who calls whom for the call hierarchy (``call_hierarchy.py``).
"""
