; thesis.thm-2.2.6 polar-good-svd-not.E
(set-logic QF_NRA)
(declare-const x Real)
(declare-const y Real)
(declare-const c Real)
(declare-const s Real)
(assert (and (> x 0) (> y 0) (= (+ (- 1) (* c c) (* s s)) 0) (or (<= (* x y) 0) (and (< (+ (- 2) x y) 0) (> (+ (* (- 1) x) (* 2 x y) (* (- 1) y)) 0)) (and (> (+ (- 2) x y) 0) (< (+ (* (- 1) x) (* 2 x y) (* (- 1) y)) 0))) (> (+ (* 2 c c s s x y) (* c c c c x y) (* s s s s x y)) 0) (or (>= (+ (- 2) (* c c x) (* c c y) (* s s x) (* s s y)) 0) (<= (+ (* 4 c c s s x y) (* (- 1) c c x) (* (- 1) c c y) (* 2 c c c c x y) (* (- 1) s s x) (* (- 1) s s y) (* 2 s s s s x y)) 0)) (or (<= (+ (- 2) (* c c x) (* c c y) (* s s x) (* s s y)) 0) (>= (+ (* 4 c c s s x y) (* (- 1) c c x) (* (- 1) c c y) (* 2 c c c c x y) (* (- 1) s s x) (* (- 1) s s y) (* 2 s s s s x y)) 0))))
(check-sat)
