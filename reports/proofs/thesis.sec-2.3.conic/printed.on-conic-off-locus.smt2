; thesis.sec-2.3.conic printed.on-conic-off-locus
(set-logic QF_NRA)
(declare-const x Real)
(declare-const y Real)
(assert (and (= (+ (- (/ 1 4)) x (* (- 4) x y) (* x x) y (* y y)) 0) (not (= (+ (* (- (/ 1 3)) x) (* (/ 4 3) x y) (* (- (/ 1 3)) x x) (* (- (/ 1 3)) y) (* (- (/ 1 3)) y y)) 0))))
(check-sat)
