; thesis.thm-2.2.6 trace-det-differ
(set-logic QF_NRA)
(declare-const x Real)
(declare-const y Real)
(declare-const c Real)
(declare-const s Real)
(assert (and (> x 0) (> y 0) (= (+ (- 1) (* c c) (* s s)) 0) (or (not (= (+ (* c c x) (* c c y) (* s s x) (* s s y) (* (- 1) x) (* (- 1) y)) 0)) (not (= (+ (* 2 c c s s x y) (* c c c c x y) (* s s s s x y) (* (- 1) x y)) 0)))))
(check-sat)
