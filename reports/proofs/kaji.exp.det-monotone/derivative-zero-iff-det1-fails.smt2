; kaji.exp.det-monotone derivative-zero-iff-det1-fails
(set-logic QF_NRA)
(declare-const c Real)
(declare-const L Real)
(declare-const E Real)
(assert (and (> c 0) (> E 0) (or (and (> L 0) (> (+ (- 1) c) 0)) (and (<= L 0) (<= (+ (- 1) c) 0))) (or (and (= L 0) (= (+ (- 1) c) 0)) (and (not (= L 0)) (not (= (+ (- 1) c) 0)))) (or (and (< L 0) (< (+ (- 1) c) 0)) (and (>= L 0) (>= (+ (- 1) c) 0))) (or (not (= (* E L) 0)) (not (= (+ (- 1) c) 0))) (or (= (* E L) 0) (= (+ (- 1) c) 0))))
(check-sat)
