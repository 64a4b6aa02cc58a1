;; SYNTAX TEST "source.cnc-macro" "control flow: IF GOTO THEN WHILE DO END, glued and lower case"
IF [#1 GT #2] GOTO 10
;; <-- keyword.control.conditional.cnc-macro
;; ^ punctuation.section.brackets.begin.cnc-macro
;;     ^^ keyword.operator.comparison.cnc-macro
;;          ^ punctuation.section.brackets.end.cnc-macro
;;            ^^^^ keyword.control.goto.cnc-macro
;;                 ^^ entity.name.tag.label.reference.cnc-macro
IF[#1GT#2]GOTO10
;; <-- keyword.control.conditional.cnc-macro
;; ^^ variable.other.local.cnc-macro
;;   ^^ keyword.operator.comparison.cnc-macro - keyword.other.g-code.cnc-macro
;;     ^^ variable.other.local.cnc-macro
;;        ^^^^ keyword.control.goto.cnc-macro - keyword.other.g-code.cnc-macro
;;            ^^ entity.name.tag.label.reference.cnc-macro - entity.name.function.program.cnc-macro
IF[#1 EQ #0] THEN #1=0
;;           ^^^^ keyword.control.conditional.cnc-macro
;;                ^^ variable.other.local.cnc-macro
;;                  ^ keyword.operator.assignment.cnc-macro
;;                   ^ constant.numeric.integer.cnc-macro
WHILE[#1LE10]DO1
;; <----- keyword.control.loop.cnc-macro
;;    ^^ variable.other.local.cnc-macro
;;      ^^ keyword.operator.comparison.cnc-macro
;;        ^^ constant.numeric.integer.cnc-macro
;;           ^^ keyword.control.loop.cnc-macro
;;             ^ constant.numeric.integer.loop-number.cnc-macro
WHILE [#20 LE #11] DO 2
;; <----- keyword.control.loop.cnc-macro
;;                 ^^ keyword.control.loop.cnc-macro
;;                    ^ constant.numeric.integer.loop-number.cnc-macro
END1
;; <--- keyword.control.loop.cnc-macro
;; ^ constant.numeric.integer.loop-number.cnc-macro
END 2
;; <--- keyword.control.loop.cnc-macro
;;  ^ constant.numeric.integer.loop-number.cnc-macro
DO3
;; <-- keyword.control.loop.cnc-macro - support.type.address.cnc-macro
;; <~~- constant.numeric.integer.loop-number.cnc-macro
GOTO #10
;; <---- keyword.control.goto.cnc-macro
;;   ^^^ variable.other.local.cnc-macro
GOTO[#10+1]
;; <---- keyword.control.goto.cnc-macro
;;  ^ punctuation.section.brackets.begin.cnc-macro
;;   ^^^ variable.other.local.cnc-macro
IF[[#1 EQ #0] OR [#2 LT 0]] GOTO 99
;; <-- keyword.control.conditional.cnc-macro
;; <~~- punctuation.section.brackets.begin.cnc-macro
;; ^ punctuation.section.brackets.begin.cnc-macro
;;     ^^ keyword.operator.comparison.cnc-macro
;;        ^^ constant.language.vacant.cnc-macro
;;          ^ punctuation.section.brackets.end.cnc-macro
;;            ^^ keyword.operator.logical.cnc-macro
;;                   ^^ keyword.operator.comparison.cnc-macro
;;                      ^ constant.numeric.integer.cnc-macro
;;                       ^ punctuation.section.brackets.end.cnc-macro
;;                        ^ punctuation.section.brackets.end.cnc-macro
;;                               ^^ entity.name.tag.label.reference.cnc-macro
if[#1 ne #2] goto 5
;; <-- keyword.control.conditional.cnc-macro
;;    ^^ keyword.operator.comparison.cnc-macro
;;           ^^^^ keyword.control.goto.cnc-macro
;;                ^ entity.name.tag.label.reference.cnc-macro
while[#3 lt 4] do1
;; <----- keyword.control.loop.cnc-macro
;;       ^^ keyword.operator.comparison.cnc-macro
;;             ^^ keyword.control.loop.cnc-macro
;;               ^ constant.numeric.integer.loop-number.cnc-macro
end1
;; <--- keyword.control.loop.cnc-macro
;; ^ constant.numeric.integer.loop-number.cnc-macro
N10 WHILE[#1 LT 3] DO1 (LOOP)
;; <--- entity.name.tag.label.cnc-macro
;;  ^^^^^ keyword.control.loop.cnc-macro
;;                 ^^ keyword.control.loop.cnc-macro
;;                     ^^^^^^ comment.line.parenthesized.cnc-macro
DO1 (WITHOUT WHILE: FOREVER)
;; <-- keyword.control.loop.cnc-macro
;; <~~- constant.numeric.integer.loop-number.cnc-macro
