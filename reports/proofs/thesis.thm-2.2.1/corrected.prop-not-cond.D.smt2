; thesis.thm-2.2.1 corrected.prop-not-cond.D
(set-logic NRA)
(declare-const a Real)
(declare-const b Real)
(declare-const c Real)
(declare-const d Real)
(assert (forall ((t Real) (t1 Real) (t2 Real)) (and (> (+ (* a d) (* (- 1) b c)) 0) (or (> (+ (* (- 1) a) (* 2 a d) (* (- 2) b c) (* (- 1) d)) 0) (> (+ (- 2) a d) 0)) (or (> (+ 2 (* (- 1) a) (* (- 1) d)) 0) (> (+ a (* (- 2) a d) (* 2 b c) d) 0)) (or (< t 0) (> (+ (- 1) t) 0) (> (+ 1 (* a d t t) (* a t) (* (- 1) a t t) (* (- 1) b c t t) (* d t) (* (- 1) d t t) (* (- 2) t) (* t t)) 0)) (or (< t1 0) (> (+ (- 1) t1) 0) (>= (+ (- 2) a (* 2 a d t1) (* (- 2) a t1) (* (- 2) b c t1) d (* (- 2) d t1) (* 2 t1)) 0) (< t2 0) (> (+ (- 1) t2) 0) (<= (+ (- 2) a (* 2 a d t2) (* (- 2) a t2) (* (- 2) b c t2) d (* (- 2) d t2) (* 2 t2)) 0)))))
(check-sat)
