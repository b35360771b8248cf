; thesis.ex-2.2.4 linear-good-area
(set-logic NRA)
(declare-const r3 Real)
(assert (forall ((t Real) (t1 Real) (t2 Real)) (and (= (+ (- 3) (* r3 r3)) 0) (> r3 0) (or (< t 0) (> (+ (- 1) t) 0) (> (+ 1 (* (/ 9 16) r3 r3 t t) (* (- (/ 7 2)) t) (* (/ 45 16) t t)) 0)) (or (< t1 0) (> (+ (- 1) t1) 0) (>= (+ (- (/ 7 2)) (* (/ 9 8) r3 r3 t1) (* (/ 45 8) t1)) 0) (< t2 0) (> (+ (- 1) t2) 0) (<= (+ (- (/ 7 2)) (* (/ 9 8) r3 r3 t2) (* (/ 45 8) t2)) 0)))))
(check-sat)
