; atlas.linear.norm directions.cond-not-prop.E
(set-logic QF_NRA)
(declare-const a Real)
(declare-const b Real)
(declare-const c Real)
(declare-const d Real)
(declare-const m Real)
(assert (and (> (+ (* a d) (* (- 1) b c)) 0) (or (and (>= (+ (- 1) a) 0) (>= (+ (- 1) d) 0) (>= (+ 4 (* (- 4) a) (* 4 a d) (* (- 2) b c) (* (- 1) b b) (* (- 1) c c) (* (- 4) d)) 0)) (and (>= (+ a (* (- 1) a a) (* (- 1) c c)) 0) (>= (+ (* (- 1) b b) d (* (- 1) d d)) 0) (>= (+ (* 4 a b c) (* (- 8) a b c d) (* 4 a d) (* (- 4) a d d) (* (- 4) a a d) (* 4 a a d d) (* (- 2) b c) (* 4 b c d) (* (- 1) b b) (* 4 b b c c) (* (- 1) c c)) 0))) (or (and (< (+ (- 2) (* 2 a) (* 2 b m) (* 2 c m) (* 2 d m m) (* (- 2) m m)) 0) (> (+ (* (- 2) a) (* 4 a b m) (* 2 a a) (* (- 2) b m) (* 2 b b m m) (* 4 c d m) (* (- 2) c m) (* 2 c c) (* (- 2) d m m) (* 2 d d m m)) 0)) (and (> (+ (- 2) (* 2 a) (* 2 b m) (* 2 c m) (* 2 d m m) (* (- 2) m m)) 0) (< (+ (* (- 2) a) (* 4 a b m) (* 2 a a) (* (- 2) b m) (* 2 b b m m) (* 4 c d m) (* (- 2) c m) (* 2 c c) (* (- 2) d m m) (* 2 d d m m)) 0)) (and (< (+ (- 2) (* 2 d)) 0) (> (+ (* 2 b b) (* (- 2) d) (* 2 d d)) 0)) (and (> (+ (- 2) (* 2 d)) 0) (< (+ (* 2 b b) (* (- 2) d) (* 2 d d)) 0)))))
(check-sat)
