"""The debug adapter (``cncmacro dap``): the Debug Adapter Protocol over standard input and
output, mapped onto the debugger (``debugging/``) and the interpreter (docs/design.md "The
debugger").

``protocol`` frames and types the messages, ``launch`` sets up a machine from a launch
configuration, ``presentation`` shows frames, scopes and variables, and ``session`` answers
each request, with ``debugging.breakpoints`` deciding where a run stops, ``debugging.stepping``
running the machine until it should and ``debugging.history`` taking it back for step back.
Neither the debugger nor the interpreter knows anything of DAP.
"""
