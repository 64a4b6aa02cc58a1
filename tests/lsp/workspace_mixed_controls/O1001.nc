O1001 (cncmacro: dialect=fanuc-0i)
#100=#100+1
#500=#500+#100
M99
