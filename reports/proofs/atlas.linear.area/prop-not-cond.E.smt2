; atlas.linear.area prop-not-cond.E
(set-logic QF_NRA)
(declare-const a Real)
(declare-const b Real)
(declare-const c Real)
(declare-const d Real)
(assert (and (> (+ (* a d) (* (- 1) b c)) 0) (or (> (+ (* (- 1) a) (* 2 a d) (* (- 2) b c) (* (- 1) d)) 0) (> (+ (- 2) a d) 0)) (or (> (+ 2 (* (- 1) a) (* (- 1) d)) 0) (> (+ a (* (- 2) a d) (* 2 b c) d) 0)) (> (+ (* a d) (* (- 1) b c)) 0) (or (>= (+ (- 2) a d) 0) (<= (+ (* (- 1) a) (* 2 a d) (* (- 2) b c) (* (- 1) d)) 0)) (or (<= (+ (- 2) a d) 0) (>= (+ (* (- 1) a) (* 2 a d) (* (- 2) b c) (* (- 1) d)) 0))))
(check-sat)
