; thesis.ex-2.2.4 polar-not-good-norm
(set-logic QF_NRA)
(declare-const r3 Real)
(declare-const v1 Real)
(declare-const v2 Real)
(assert (and (= (+ (- 3) (* r3 r3)) 0) (> r3 0) (= (+ (- 1) (* v1 v1) (* v2 v2)) 0) (or (and (< (+ (* (- 1) r3 v1 v2) (* (/ 1 2) v1 v1) (* (/ 3 2) v2 v2)) 0) (> (+ (* (- 2) r3 v1 v2) (* (/ 1 8) r3 r3 v1 v1) (* (/ 1 8) r3 r3 v2 v2) (* (/ 5 8) v1 v1) (* (/ 21 8) v2 v2)) 0)) (and (> (+ (* (- 1) r3 v1 v2) (* (/ 1 2) v1 v1) (* (/ 3 2) v2 v2)) 0) (< (+ (* (- 2) r3 v1 v2) (* (/ 1 8) r3 r3 v1 v1) (* (/ 1 8) r3 r3 v2 v2) (* (/ 5 8) v1 v1) (* (/ 21 8) v2 v2)) 0)))))
(check-sat)
