; thesis.ex-2.2.4 linear-good-norm
(set-logic NRA)
(declare-const r3 Real)
(assert (forall ((v1 Real) (v2 Real)) (and (= (+ (- 3) (* r3 r3)) 0) (> r3 0) (or (not (= (+ (- 1) (* v1 v1) (* v2 v2)) 0)) (and (or (>= (+ (* (- (/ 5 2)) v1 v1) (* (- (/ 9 2)) v2 v2)) 0) (<= (+ (* (- 3) r3 v1 v2) (* (/ 9 8) r3 r3 v1 v1) (* (/ 9 8) r3 r3 v2 v2) (* (/ 5 8) v1 v1) (* (/ 45 8) v2 v2)) 0)) (or (<= (+ (* (- (/ 5 2)) v1 v1) (* (- (/ 9 2)) v2 v2)) 0) (>= (+ (* (- 3) r3 v1 v2) (* (/ 9 8) r3 r3 v1 v1) (* (/ 9 8) r3 r3 v2 v2) (* (/ 5 8) v1 v1) (* (/ 45 8) v2 v2)) 0)))))))
(check-sat)
