; atlas3.polar.singular-values L25.blend-order-changes
(set-logic QF_NRA)
(declare-const a Real)
(declare-const b Real)
(declare-const t Real)
(assert (and (> b 0) (> (+ a (* (- 1) b)) 0) (> t 0) (<= (+ (- 1) t) 0) (<= (+ (* a t) (* (- 1) b t)) 0)))
(check-sat)
