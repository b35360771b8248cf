; thesis.thm-2.2.3 printed.prop-not-cond.inst
(set-logic QF_NRA)
(declare-const x Real)
(declare-const y Real)
(declare-const beta Real)
(assert (and (> x 0) (> y 0) (or (< (+ (- 1) x) 0) (< (+ (- 1) y) 0)) (or (<= x 0) (> (+ (- 1) x) 0) (<= y 0) (> (+ (- 1) y) 0)) (>= (+ (* 2 beta beta x x y y) (* (- 1) beta beta x x x x) (* (- 1) beta beta y y y y) (* 4 x y) (* (- 4) x y y) (* (- 4) x x y) (* 4 x x y y)) 0)))
(check-sat)
