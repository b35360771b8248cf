; thesis.viete eigen.k-outside-unit-interval
(set-logic QF_NRA)
(declare-const m1 Real)
(declare-const m2 Real)
(declare-const m3 Real)
(assert (> (+ (* 2 m1 m2 m3 m3 m3 m3) (* (- 2) m1 m2 m2 m3 m3 m3) (* (- 2) m1 m2 m2 m2 m3 m3) (* 2 m1 m2 m2 m2 m2 m3) (* (- 2) m1 m1 m2 m3 m3 m3) (* 6 m1 m1 m2 m2 m3 m3) (* (- 2) m1 m1 m2 m2 m2 m3) (* (- 1) m1 m1 m2 m2 m2 m2) (* (- 1) m1 m1 m3 m3 m3 m3) (* (- 2) m1 m1 m1 m2 m3 m3) (* (- 2) m1 m1 m1 m2 m2 m3) (* 2 m1 m1 m1 m2 m2 m2) (* 2 m1 m1 m1 m3 m3 m3) (* 2 m1 m1 m1 m1 m2 m3) (* (- 1) m1 m1 m1 m1 m2 m2) (* (- 1) m1 m1 m1 m1 m3 m3) (* (- 1) m2 m2 m3 m3 m3 m3) (* 2 m2 m2 m2 m3 m3 m3) (* (- 1) m2 m2 m2 m2 m3 m3)) 0))
(check-sat)
