"""The debugger's logic, free of any protocol: where a run stops, how it steps, how it goes back.

``breakpoints`` decides where a run stops (line, ``N``/``O`` and data breakpoints, with their
conditions, hit counts and log messages), ``stepping`` runs the machine until it should
(continue, step in, over and out, step back and reverse continue), and ``history`` keeps the
run's past for going back. It sits on the interpreter (``machine/``) beside the analysis, and
knows nothing of DAP: ``dap/`` turns DAP's requests into calls here and what comes back into
DAP's messages.
"""
