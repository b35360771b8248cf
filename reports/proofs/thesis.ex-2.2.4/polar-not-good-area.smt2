; thesis.ex-2.2.4 polar-not-good-area
(set-logic QF_NRA)
(declare-const r3 Real)
(declare-const t Real)
(declare-const t1 Real)
(declare-const t2 Real)
(assert (and (= (+ (- 3) (* r3 r3)) 0) (> r3 0) (or (and (>= t 0) (<= (+ (- 1) t) 0) (<= (+ 1 (* (- (/ 1 16)) r3 r3 t t) t (* (/ 3 16) t t)) 0)) (and (>= t1 0) (<= (+ (- 1) t1) 0) (< (+ 1 (* (- (/ 1 8)) r3 r3 t1) (* (/ 3 8) t1)) 0) (>= t2 0) (<= (+ (- 1) t2) 0) (> (+ 1 (* (- (/ 1 8)) r3 r3 t2) (* (/ 3 8) t2)) 0)))))
(check-sat)
