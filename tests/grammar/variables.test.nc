;; SYNTAX TEST "source.cnc-macro" "variables: one scope per class, indirection"
#1=#33
;; <- variable.other.local.cnc-macro punctuation.definition.variable.cnc-macro
;; <~- variable.other.local.cnc-macro
;; <~~- keyword.operator.assignment.cnc-macro
;; ^^^ variable.other.local.cnc-macro
#100=#199+#499
;; <---- variable.other.common.cnc-macro
;;   ^^^^ variable.other.common.cnc-macro
;;        ^^^^ variable.other.common.cnc-macro
#500=#999
;; <---- variable.other.persistent.cnc-macro
;;   ^^^^ variable.other.persistent.cnc-macro
#24=#5001
;; <--- variable.other.local.cnc-macro
;;  ^^^^^ variable.language.system.cnc-macro
#1=#3011+#10001
;; ^^^^^ variable.language.system.cnc-macro
;;       ^^^^^^ variable.language.system.cnc-macro
IF[#24 EQ #0] GOTO 1
;; ^^^ variable.other.local.cnc-macro
;;        ^^ constant.language.vacant.cnc-macro - variable.other.local.cnc-macro
#50=1
;; <--- invalid.illegal.variable-number.cnc-macro
# 100=1
;; <----- variable.other.common.cnc-macro
#[#100]=#[#1+1]
;; <- variable.other.indirect.cnc-macro punctuation.definition.variable.cnc-macro
;; <~- punctuation.section.brackets.begin.cnc-macro
;; <~~---- variable.other.common.cnc-macro
;;    ^ punctuation.section.brackets.end.cnc-macro
;;     ^ keyword.operator.assignment.cnc-macro
;;      ^ variable.other.indirect.cnc-macro
;;        ^^ variable.other.local.cnc-macro
;;          ^ keyword.operator.arithmetic.cnc-macro
;;           ^ constant.numeric.integer.cnc-macro
X#[#100]
;; <- support.type.address.cnc-macro
;; <~- variable.other.indirect.cnc-macro
#9100=#9502
;; <----- variable.other.indirect.cnc-macro
;;    ^^^^^ variable.other.indirect.cnc-macro
#1GT#2
;; <-- variable.other.local.cnc-macro
;; <~~-- keyword.operator.comparison.cnc-macro
;;  ^^ variable.other.local.cnc-macro
#1=#2(COMMENT)
;; ^^ variable.other.local.cnc-macro
;;   ^^^^^^^^^ comment.line.parenthesized.cnc-macro
