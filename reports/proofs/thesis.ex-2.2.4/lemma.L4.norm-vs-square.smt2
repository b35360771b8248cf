; thesis.ex-2.2.4 lemma.L4.norm-vs-square
(set-logic QF_NRA)
(declare-const a Real)
(declare-const b Real)
(assert (and (>= a 0) (>= b 0) (or (and (<= (+ a (* (- 1) b)) 0) (> (+ (* a a) (* (- 1) b b)) 0)) (and (> (+ a (* (- 1) b)) 0) (<= (+ (* a a) (* (- 1) b b)) 0)))))
(check-sat)
