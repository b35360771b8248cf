; atlas.svd.area prop-not-cond.L
(set-logic NRA)
(declare-const x Real)
(declare-const y Real)
(assert (forall ((t Real) (ts Real) (tt Real) (ts1 Real) (tt1 Real)) (and (> x 0) (> y 0) (or (> (+ (* (- 1) x) (* 2 x y) (* (- 1) y)) 0) (> (+ (- 2) x y) 0)) (or (> (+ 2 (* (- 1) x) (* (- 1) y)) 0) (> (+ x (* (- 2) x y) y) 0)) (or (< t 0) (> (+ (- 1) t) 0) (> (+ 1 (* (- 2) t) (* t x) (* t y) (* t t) (* (- 1) t t x) (* t t x y) (* (- 1) t t y)) 0)) (or (< ts 0) (> (+ ts (* (- 1) tt)) 0) (> (+ (- 1) tt) 0) (<= (+ (* (- 2) ts) (* ts x) (* ts y) (* ts ts) (* (- 1) ts ts x) (* ts ts x y) (* (- 1) ts ts y) (* 2 tt) (* (- 1) tt x) (* (- 1) tt y) (* (- 1) tt tt) (* tt tt x) (* (- 1) tt tt x y) (* tt tt y)) 0) (< ts1 0) (> (+ ts1 (* (- 1) tt1)) 0) (> (+ (- 1) tt1) 0) (>= (+ (* (- 2) ts1) (* ts1 x) (* ts1 y) (* ts1 ts1) (* (- 1) ts1 ts1 x) (* ts1 ts1 x y) (* (- 1) ts1 ts1 y) (* 2 tt1) (* (- 1) tt1 x) (* (- 1) tt1 y) (* (- 1) tt1 tt1) (* tt1 tt1 x) (* (- 1) tt1 tt1 x y) (* tt1 tt1 y)) 0)))))
(check-sat)
