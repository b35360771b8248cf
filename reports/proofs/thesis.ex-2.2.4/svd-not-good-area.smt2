; thesis.ex-2.2.4 svd-not-good-area
(set-logic QF_NRA)
(declare-const r3 Real)
(declare-const t Real)
(assert (and (= (+ (- 3) (* r3 r3)) 0) (> r3 0) (>= t 0) (<= (+ (- 1) t) 0) (<= (+ 1 t) 0)))
(check-sat)
