O8000 (LOCAL WATCH)
(cncmacro: dialect=fanuc-0i)
#1=111
G65 P8001 A1.
#1=#1+1
M30
