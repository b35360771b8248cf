; atlas.exp-log.norm cond-not-prop.eig
(set-logic QF_NRA)
(declare-const x Real)
(declare-const y Real)
(declare-const h Real)
(declare-const l1 Real)
(declare-const l2 Real)
(assert (and (> x 0) (> y 0) (> (+ (* (- 1) h h) (* x y)) 0) (> l1 0) (> l2 0) (= (+ l1 l2 (* (- 1) x) (* (- 1) y)) 0) (= (+ (* h h) (* l1 l2) (* (- 1) x y)) 0) (>= (+ 1 (* (- 1) h h) (* (- 1) x) (* x y) (* (- 1) y)) 0) (< (+ 1 (* (- 1) l1) (* l1 l2) (* (- 1) l2)) 0)))
(check-sat)
