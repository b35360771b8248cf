; atlas3.svd.singular-values L25.blend-not-positive
(set-logic QF_NRA)
(declare-const a Real)
(declare-const t Real)
(assert (and (> a 0) (>= t 0) (<= (+ (- 1) t) 0) (<= (+ 1 (* a t) (* (- 1) t)) 0)))
(check-sat)
