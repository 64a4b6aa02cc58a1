O1001 (cncmacro: dialect=fanuc-0i)
#101=1
M99
