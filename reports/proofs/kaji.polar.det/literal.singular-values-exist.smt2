; kaji.polar.det literal.singular-values-exist
(set-logic NRA)
(declare-const x Real)
(declare-const y Real)
(declare-const h Real)
(declare-const c Real)
(declare-const s Real)
(assert (forall ((l1 Real) (l2 Real)) (and (> x 0) (> y 0) (> (+ (* (- 1) h h) (* x y)) 0) (= (+ (- 1) (* c c) (* s s)) 0) (or (< l1 0) (< l2 0) (not (= (+ (* (- 2) c c h h) (* (- 1) c c x x) (* (- 1) c c y y) (* (- 2) h h s s) (* l1 l1) (* l2 l2) (* (- 1) s s x x) (* (- 1) s s y y)) 0)) (not (= (+ (* 4 c c h h s s x y) (* (- 2) c c h h h h s s) (* (- 2) c c s s x x y y) (* 2 c c c c h h x y) (* (- 1) c c c c h h h h) (* (- 1) c c c c x x y y) (* 2 h h s s s s x y) (* (- 1) h h h h s s s s) (* l1 l1 l2 l2) (* (- 1) s s s s x x y y)) 0))))))
(check-sat)
