; thesis.ex-2.2.4 linear-good-area.L
(set-logic NRA)
(declare-const r3 Real)
(assert (forall ((t Real) (ts Real) (tt Real) (ts1 Real) (tt1 Real)) (and (= (+ (- 3) (* r3 r3)) 0) (> r3 0) (or (< t 0) (> (+ (- 1) t) 0) (> (+ 1 (* (/ 9 16) r3 r3 t t) (* (- (/ 7 2)) t) (* (/ 45 16) t t)) 0)) (or (< ts 0) (> (+ ts (* (- 1) tt)) 0) (> (+ (- 1) tt) 0) (<= (+ (* (/ 9 16) r3 r3 ts ts) (* (- (/ 9 16)) r3 r3 tt tt) (* (- (/ 7 2)) ts) (* (/ 45 16) ts ts) (* (/ 7 2) tt) (* (- (/ 45 16)) tt tt)) 0) (< ts1 0) (> (+ ts1 (* (- 1) tt1)) 0) (> (+ (- 1) tt1) 0) (>= (+ (* (/ 9 16) r3 r3 ts1 ts1) (* (- (/ 9 16)) r3 r3 tt1 tt1) (* (- (/ 7 2)) ts1) (* (/ 45 16) ts1 ts1) (* (/ 7 2) tt1) (* (- (/ 45 16)) tt1 tt1)) 0)))))
(check-sat)
