; thesis.sec-2.3.min-energy hessian-not-positive-definite
(set-logic QF_NRA)
(declare-const x Real)
(declare-const y Real)
(assert (or (<= (+ 6 (* (- 4) x) (* 4 x y) (* 2 x x) (* (- 4) y) (* 2 y y)) 0) (<= (+ 32 (* (- 16) x) (* 32 x y) (* (- 24) x y y) (* 8 x y y y) (* 12 x x) (* (- 8) x x y) (* 4 x x y y) (* (- 48) y) (* 40 y y) (* (- 16) y y y) (* 4 y y y y)) 0) (<= (+ 160 (* (- 192) x) (* 224 x y) (* (- 128) x y y) (* 32 x y y y) (* 160 x x) (* (- 128) x x y) (* 32 x x y y) (* (- 64) x x x) (* 32 x x x y) (* 16 x x x x) (* (- 192) y) (* 160 y y) (* (- 64) y y y) (* 16 y y y y)) 0) (<= (+ 192 (* (- 128) x) (* 128 x y) (* 64 x x) (* (- 128) y) (* 64 y y)) 0)))
(check-sat)
