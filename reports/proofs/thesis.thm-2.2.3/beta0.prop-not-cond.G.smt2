; thesis.thm-2.2.3 beta0.prop-not-cond.G
(set-logic NRA)
(declare-const x Real)
(declare-const y Real)
(assert (forall ((t Real)) (and (> x 0) (> y 0) (or (< (+ (- 1) x) 0) (< (+ (- 1) y) 0)) (or (<= x 0) (> (+ (- 1) x) 0) (<= y 0) (> (+ (- 1) y) 0)) (or (< t 0) (> (+ (- 1) t) 0) (>= (+ 4 (* (- 8) t) (* 12 t x) (* (- 16) t x y) (* 4 t x y y) (* (- 4) t x x) (* 4 t x x y) (* 12 t y) (* (- 4) t y y) (* 4 t t) (* (- 8) t t x) (* 16 t t x y) (* (- 8) t t x y y) (* 4 t t x x) (* (- 8) t t x x y) (* 4 t t x x y y) (* (- 8) t t y) (* 4 t t y y) (* (- 4) x) (* 4 x y) (* (- 4) y)) 0)))))
(check-sat)
