;; SYNTAX TEST "source.cnc-macro" "Haas's conditional jump [cond] M99 P n"
N50 [#100 LT 10] M99 P10
;; <--- entity.name.tag.label.cnc-macro
;;  ^ punctuation.section.brackets.begin.cnc-macro
;;        ^^ keyword.operator.comparison.cnc-macro
;;             ^ punctuation.section.brackets.end.cnc-macro
;;               ^^^ keyword.control.return.cnc-macro
;;                   ^ support.type.address.cnc-macro
;;                    ^^ entity.name.tag.label.reference.cnc-macro
[#1 EQ #0]M99P10
;; <- punctuation.section.brackets.begin.cnc-macro
;;  ^^ keyword.operator.comparison.cnc-macro
;;       ^ punctuation.section.brackets.end.cnc-macro
;;        ^^^ keyword.control.return.cnc-macro
;;            ^^ entity.name.tag.label.reference.cnc-macro
