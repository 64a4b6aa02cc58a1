"""The debug adapter (``cncmacro dap``): the Debug Adapter Protocol over standard input and
output, mapped onto the interpreter's stepping API (docs/design.md "The debugger").

``protocol`` frames and types the messages, ``launch`` sets up a machine from a launch
configuration, ``breakpoints`` decides where a run stops, ``stepping`` runs the machine until
it should, ``history`` takes it back for step back, ``presentation`` shows frames, scopes and
variables, and ``session`` answers each request. The interpreter knows nothing of DAP.
"""
