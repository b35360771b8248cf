; thesis.ex-2.2.4 decompositions-wrong
(set-logic QF_NRA)
(declare-const r3 Real)
(assert (and (= (+ (- 3) (* r3 r3)) 0) (> r3 0) (or (not (= (+ (/ 3 4) (* (- (/ 1 4)) r3 r3)) 0)) (not (= (+ (/ 3 2) (* (- (/ 1 2)) r3 r3)) 0)) (not (= (+ (- (/ 3 8)) (* (/ 1 8) r3 r3)) 0)) (not (= (+ (/ 3 8) (* (- (/ 1 8)) r3 r3)) 0)) (<= (+ (/ 35 16) (* (- (/ 1 16)) r3 r3)) 0))))
(check-sat)
