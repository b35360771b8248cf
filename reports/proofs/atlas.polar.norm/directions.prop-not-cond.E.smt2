; atlas.polar.norm directions.prop-not-cond.E
(set-logic NRA)
(declare-const x Real)
(declare-const y Real)
(declare-const h Real)
(assert (forall ((m Real)) (and (> x 0) (> y 0) (> (+ (* (- 1) h h) (* x y)) 0) (< (+ 1 (* (- 1) h h) (* (- 1) x) (* x y) (* (- 1) y)) 0) (or (>= (+ (- 2) (* 4 h m) (* (- 2) m m) (* 2 m m y) (* 2 x)) 0) (<= (+ (* (- 4) h m) (* 4 h m x) (* 4 h m y) (* 2 h h) (* 2 h h m m) (* (- 2) m m y) (* 2 m m y y) (* (- 2) x) (* 2 x x)) 0)) (or (<= (+ (- 2) (* 4 h m) (* (- 2) m m) (* 2 m m y) (* 2 x)) 0) (>= (+ (* (- 4) h m) (* 4 h m x) (* 4 h m y) (* 2 h h) (* 2 h h m m) (* (- 2) m m y) (* 2 m m y y) (* (- 2) x) (* 2 x x)) 0)) (or (>= (+ (- 2) (* 2 y)) 0) (<= (+ (* 2 h h) (* (- 2) y) (* 2 y y)) 0)) (or (<= (+ (- 2) (* 2 y)) 0) (>= (+ (* 2 h h) (* (- 2) y) (* 2 y y)) 0)))))
(check-sat)
