;; SYNTAX TEST "source.cnc-macro" "alarm and operator messages: #3000 and #3006 texts, DPRNT output"
#3000=1(TEXT)
;; <- variable.language.system.cnc-macro punctuation.definition.variable.cnc-macro
;; <~---- variable.language.system.cnc-macro
;;   ^ keyword.operator.assignment.cnc-macro
;;    ^ constant.numeric.integer.cnc-macro
;;     ^ string.quoted.other.message.cnc-macro punctuation.definition.string.begin.cnc-macro
;;      ^^^^ string.quoted.other.message.cnc-macro - comment.line.parenthesized.cnc-macro
;;          ^ string.quoted.other.message.cnc-macro punctuation.definition.string.end.cnc-macro
IF[#24 EQ #0] THEN #3000=1(X MISSING)
;; <-- keyword.control.conditional.cnc-macro
;;            ^^^^ keyword.control.conditional.cnc-macro
;;                 ^^^^^ variable.language.system.cnc-macro
;;                         ^^^^^^^^^ string.quoted.other.message.cnc-macro
N941#3000=1(MSG)
;; <---- entity.name.tag.label.cnc-macro
;;  ^^^^^ variable.language.system.cnc-macro
;;          ^^^ string.quoted.other.message.cnc-macro
#3006=1(CHECK THE PART)
;; <----- variable.language.system.cnc-macro
;;      ^^^^^^^^^^^^^^ string.quoted.other.message.cnc-macro
#3000=1(ROUGH DEPTH MUST BE > 0 粗车切深必须大于 0)
;;      ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^^ string.quoted.other.message.cnc-macro
#3000=2(UNCLOSED MESSAGE
;;      ^^^^^^^^^^^^^^^^ string.quoted.other.message.unclosed.cnc-macro
#1=#3001 (A TIMER READ IS NOT A MESSAGE)
;; ^^^^^ variable.language.system.cnc-macro
;;        ^^^^^^^^^^^^^^^^^^^^^^^^^^^^^ comment.line.parenthesized.cnc-macro - string.quoted.other.message.cnc-macro
POPEN
;; <----- support.function.output.cnc-macro
DPRNT[X*ERROR*#141[2 3]]
;; <----- support.function.output.cnc-macro
;;   ^ punctuation.section.brackets.begin.cnc-macro
;;    ^ string.unquoted.output.cnc-macro - support.type.address.cnc-macro
;;     ^ constant.character.space.cnc-macro
;;      ^^^^^ string.unquoted.output.cnc-macro
;;            ^ punctuation.definition.variable.cnc-macro
;;             ^^^ variable.other.common.cnc-macro
;;                 ^ constant.numeric.integer.format.cnc-macro
;;                   ^ constant.numeric.integer.format.cnc-macro
;;                    ^ meta.output.cnc-macro punctuation.section.brackets.end.cnc-macro
DPRNT[X#2[53]**Y#5[53]]
;;     ^ punctuation.definition.variable.cnc-macro
;;      ^ variable.other.local.cnc-macro
;;        ^ constant.numeric.integer.format.cnc-macro
;;           ^^ constant.character.space.cnc-macro
;;             ^ string.unquoted.output.cnc-macro
N41 DPRNT[PROBE*REPORT*O1001]
;; <--- entity.name.tag.label.cnc-macro
;;        ^^^^^ string.unquoted.output.cnc-macro - support.function.math.cnc-macro
;;                     ^^^^^ string.unquoted.output.cnc-macro - entity.name.function.program.cnc-macro
DPRNT[PART*#100[40]](COUNT)
;;         ^ punctuation.definition.variable.cnc-macro
;;          ^^^ variable.other.common.cnc-macro
;;                ^ punctuation.section.brackets.end.cnc-macro
;;                  ^^^^^^^ comment.line.parenthesized.cnc-macro - string.unquoted.output.cnc-macro
DPRNT[A(NOTE)B]
;;     ^^^^^^ comment.line.parenthesized.cnc-macro
;;           ^ string.unquoted.output.cnc-macro
PCLOS
;; <----- support.function.output.cnc-macro
BPRNT[C**X#100[3]]
;; <----- support.function.output.cnc-macro
