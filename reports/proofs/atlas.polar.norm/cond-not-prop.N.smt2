; atlas.polar.norm cond-not-prop.N
(set-logic NRA)
(declare-const x Real)
(declare-const y Real)
(declare-const h Real)
(assert (forall ((nu Real)) (and (> x 0) (> y 0) (> (+ (* (- 1) h h) (* x y)) 0) (>= (+ 1 (* (- 1) h h) (* (- 1) x) (* x y) (* (- 1) y)) 0) (or (< (+ (* (- 1) h h) x (* (- 1) x x)) 0) (< (+ (* (- 1) h h) y (* (- 1) y y)) 0) (< (+ (* (- 1) h h) (* h h x) (* (- 2) h h x y) (* h h y) (* h h h h) (* x y) (* (- 1) x y y) (* (- 1) x x y) (* x x y y)) 0)) (or (< nu 0) (< (+ (- 1) (* (- 1) h h nu) (* nu x) (* (- 1) nu x x) x) 0) (< (+ (- 1) (* (- 1) h h nu) (* nu y) (* (- 1) nu y y) y) 0) (< (+ 1 (* (- 1) h h) (* h h nu x) (* h h nu y) (* (- 1) h h nu nu) (* h h nu nu x) (* (- 2) h h nu nu x y) (* h h nu nu y) (* h h h h nu nu) (* (- 1) nu x) (* 2 nu x y) (* (- 1) nu x y y) (* nu x x) (* (- 1) nu x x y) (* (- 1) nu y) (* nu y y) (* nu nu x y) (* (- 1) nu nu x y y) (* (- 1) nu nu x x y) (* nu nu x x y y) (* (- 1) x) (* x y) (* (- 1) y)) 0)))))
(check-sat)
