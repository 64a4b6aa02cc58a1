;; SYNTAX TEST "source.cnc-macro" "NC words: G and M codes, addresses and their values"
G00 G01 G02 G03 G0 G1
;; <--- keyword.other.g-code.motion.cnc-macro
;;  ^^^ keyword.other.g-code.motion.cnc-macro
;;      ^^^ keyword.other.g-code.motion.cnc-macro
;;          ^^^ keyword.other.g-code.motion.cnc-macro
;;              ^^ keyword.other.g-code.motion.cnc-macro
;;                 ^^ keyword.other.g-code.motion.cnc-macro
G90 G54 G54.1 G17
;; <--- keyword.other.g-code.cnc-macro - keyword.other.g-code.motion.cnc-macro
;;  ^^^ keyword.other.g-code.cnc-macro
;;      ^^^^^ keyword.other.g-code.cnc-macro
;;            ^^^ keyword.other.g-code.cnc-macro
G01X10.Y-#5
;; <--- keyword.other.g-code.motion.cnc-macro
;; ^ support.type.address.cnc-macro
;;  ^^^ constant.numeric.decimal.cnc-macro
;;     ^ support.type.address.cnc-macro
;;      ^ keyword.operator.arithmetic.cnc-macro
;;       ^^ variable.other.local.cnc-macro
X10.5 Z-3.25 F200 S1200 T0101
;; <- support.type.address.cnc-macro
;; <~---- constant.numeric.decimal.cnc-macro
;;    ^ support.type.address.cnc-macro
;;     ^^^^^ constant.numeric.decimal.cnc-macro
;;           ^ support.type.address.cnc-macro
;;            ^^^ constant.numeric.integer.cnc-macro
;;                ^ support.type.address.cnc-macro
;;                 ^^^^ constant.numeric.integer.cnc-macro
;;                      ^ support.type.address.cnc-macro
;;                       ^^^^ constant.numeric.integer.cnc-macro
X-#5 Z-[#1]
;; <- support.type.address.cnc-macro
;; <~- keyword.operator.arithmetic.cnc-macro
;; <~~-- variable.other.local.cnc-macro
;;   ^ support.type.address.cnc-macro
;;    ^ keyword.operator.arithmetic.cnc-macro
;;     ^ punctuation.section.brackets.begin.cnc-macro
x5y.5
;; <- support.type.address.cnc-macro
;; <~- constant.numeric.integer.cnc-macro
;; <~~- support.type.address.cnc-macro
;; ^^ constant.numeric.decimal.cnc-macro
X 10
;; <- support.type.address.cnc-macro
;; <~~-- constant.numeric.integer.cnc-macro
M03 M06 M08
;; <--- keyword.other.m-code.cnc-macro
;;  ^^^ keyword.other.m-code.cnc-macro
;;      ^^^ keyword.other.m-code.cnc-macro
M30
;; <--- keyword.control.end-program.cnc-macro - keyword.other.m-code.cnc-macro
M02
;; <--- keyword.control.end-program.cnc-macro
M2
;; <-- keyword.control.end-program.cnc-macro
G#27 G#28
;; <- support.type.address.cnc-macro
;; <~--- variable.other.local.cnc-macro
G43 Z50. H01 M08
;; <--- keyword.other.g-code.cnc-macro
;;  ^ support.type.address.cnc-macro
;;   ^^^ constant.numeric.decimal.cnc-macro
;;       ^ support.type.address.cnc-macro
;;        ^^ constant.numeric.integer.cnc-macro
;;           ^^^ keyword.other.m-code.cnc-macro
G81 X#32 Y#33 Z#26 R#3 F#9
;; <--- keyword.other.g-code.cnc-macro
;;  ^ support.type.address.cnc-macro
;;   ^^^ variable.other.local.cnc-macro
;;                 ^ support.type.address.cnc-macro
;;                  ^^ variable.other.local.cnc-macro
G31 Z-10. F100
;; <--- keyword.other.g-code.motion.cnc-macro
G01 X50. ,R5. F500.
;;       ^ punctuation.separator.corner.cnc-macro
;;        ^ support.type.address.corner.cnc-macro
;;         ^^ constant.numeric.decimal.cnc-macro
;;            ^ support.type.address.cnc-macro - support.type.address.corner.cnc-macro
Y50.,C#1
;;  ^ punctuation.separator.corner.cnc-macro
;;   ^ support.type.address.corner.cnc-macro
;;    ^^ variable.other.local.cnc-macro
G01 X20 Y30 ,C3
;;          ^ punctuation.separator.corner.cnc-macro
;;           ^ support.type.address.corner.cnc-macro
;;            ^ constant.numeric.integer.cnc-macro
#1=POW[2,3]
;;      ^ - punctuation.separator.corner.cnc-macro
