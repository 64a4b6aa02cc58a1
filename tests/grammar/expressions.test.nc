;; SYNTAX TEST "source.cnc-macro" "expressions: operators, functions, numbers"
#1=#2+#3-#4*#5/#6
;; <~~- keyword.operator.assignment.cnc-macro
;;   ^ keyword.operator.arithmetic.cnc-macro
;;      ^ keyword.operator.arithmetic.cnc-macro
;;         ^ keyword.operator.arithmetic.cnc-macro
;;            ^ keyword.operator.arithmetic.cnc-macro
#1=#2 MOD 3
;;    ^^^ keyword.operator.arithmetic.cnc-macro - keyword.other.m-code.cnc-macro
#1=#2 AND #3 OR #4 XOR #5
;;    ^^^ keyword.operator.logical.cnc-macro
;;           ^^ keyword.operator.logical.cnc-macro
;;                 ^^^ keyword.operator.logical.cnc-macro - support.type.address.cnc-macro
IF[#1 EQ 1] GOTO1
;;    ^^ keyword.operator.comparison.cnc-macro
IF[#1 NE 1] GOTO1
;;    ^^ keyword.operator.comparison.cnc-macro - entity.name.tag.label.cnc-macro
IF[#1 GT 1] GOTO1
;;    ^^ keyword.operator.comparison.cnc-macro
IF[#1 GE 1] GOTO1
;;    ^^ keyword.operator.comparison.cnc-macro
IF[#1 LT 1] GOTO1
;;    ^^ keyword.operator.comparison.cnc-macro
IF[#1 LE 1] GOTO1
;;    ^^ keyword.operator.comparison.cnc-macro
#1=SIN[30]+COS[#2]+TAN[#3]
;; ^^^ support.function.math.cnc-macro
;;    ^ punctuation.section.brackets.begin.cnc-macro
;;     ^^ constant.numeric.integer.cnc-macro
;;       ^ punctuation.section.brackets.end.cnc-macro
;;         ^^^ support.function.math.cnc-macro
;;                 ^^^ support.function.math.cnc-macro
#1=ASIN[#2]+ACOS[#3]+ATAN[#4]/[#5]
;; ^^^^ support.function.math.cnc-macro
;;          ^^^^ support.function.math.cnc-macro
;;                   ^^^^ support.function.math.cnc-macro
;;                           ^ keyword.operator.arithmetic.cnc-macro
#1=SQRT[#2]+ABS[#3]+LN[#4]+EXP[#5]
;; ^^^^ support.function.math.cnc-macro
;;          ^^^ support.function.math.cnc-macro
;;                  ^^ support.function.math.cnc-macro
;;                         ^^^ support.function.math.cnc-macro
#1=ROUND[#2]+FIX[#3]+FUP[#4]
;; ^^^^^ support.function.math.cnc-macro
;;           ^^^ support.function.math.cnc-macro - support.type.address.cnc-macro
;;                   ^^^ support.function.math.cnc-macro
#1=BIN[#2]+BCD[#3]
;; ^^^ support.function.conversion.cnc-macro
;;         ^^^ support.function.conversion.cnc-macro
#1=round[#2]*sqrt[2]
;; ^^^^^ support.function.math.cnc-macro
;;           ^^^^ support.function.math.cnc-macro
#1=10+10.+.5-3.25
;; ^^ constant.numeric.integer.cnc-macro
;;    ^^^ constant.numeric.decimal.cnc-macro
;;        ^^ constant.numeric.decimal.cnc-macro
;;          ^ keyword.operator.arithmetic.cnc-macro
;;           ^^^^ constant.numeric.decimal.cnc-macro
#1=-#2
;; ^ keyword.operator.arithmetic.cnc-macro
;;  ^^ variable.other.local.cnc-macro
#12=ROUND[#3/#11*1000]/1000
;;  ^^^^^ support.function.math.cnc-macro
;;               ^^^^ constant.numeric.integer.cnc-macro
;;                   ^ punctuation.section.brackets.end.cnc-macro
;;                    ^ keyword.operator.arithmetic.cnc-macro
;;                     ^^^^ constant.numeric.integer.cnc-macro
#1=#2*[#3-1]
;;    ^ punctuation.section.brackets.begin.cnc-macro
;;       ^ keyword.operator.arithmetic.cnc-macro
;;         ^ punctuation.section.brackets.end.cnc-macro
