; atlas3.exp-log.singular-values L25.exponent-order-changes
(set-logic QF_NRA)
(declare-const La Real)
(declare-const Lb Real)
(declare-const t Real)
(assert (and (> (+ La (* (- 1) Lb)) 0) (> t 0) (<= (+ (- 1) t) 0) (<= (+ (* La t) (* (- 1) Lb t)) 0)))
(check-sat)
