"""What the analysis finds by running: bounded, resumable runs of the machine from each entry point.

``run_checks.py`` (``EntryRun``, the run's observer), the runs of a workspace kept across edits
(``entry_runs.py``, taken back after an edit by ``run_rewind.py``, resumed by
``run_convergence.py``), what no run reached (``unreached.py``), the cycle time the runs measured
(``cycle_lenses.py``, ``cycle_summary.py``), which file may read the clock (``clock_reads.py``) and
what to say of a subprogram run on its own (``subprogram_alone.py``).
"""
