; kaji.exp.det-monotone derivative-sign-changes
(set-logic QF_NRA)
(declare-const c Real)
(declare-const L Real)
(declare-const E Real)
(declare-const E2 Real)
(assert (and (> c 0) (> E 0) (> E2 0) (or (and (> L 0) (> (+ (- 1) c) 0)) (and (<= L 0) (<= (+ (- 1) c) 0))) (or (and (= L 0) (= (+ (- 1) c) 0)) (and (not (= L 0)) (not (= (+ (- 1) c) 0)))) (or (and (< L 0) (< (+ (- 1) c) 0)) (and (>= L 0) (>= (+ (- 1) c) 0))) (< (* E L) 0) (> (* E2 L) 0)))
(check-sat)
