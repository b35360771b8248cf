; atlas.linear.area prop-not-cond.L
(set-logic NRA)
(declare-const a Real)
(declare-const b Real)
(declare-const c Real)
(declare-const d Real)
(assert (forall ((t Real) (ts Real) (tt Real) (ts1 Real) (tt1 Real)) (and (> (+ (* a d) (* (- 1) b c)) 0) (or (> (+ (* (- 1) a) (* 2 a d) (* (- 2) b c) (* (- 1) d)) 0) (> (+ (- 2) a d) 0)) (or (> (+ 2 (* (- 1) a) (* (- 1) d)) 0) (> (+ a (* (- 2) a d) (* 2 b c) d) 0)) (or (< t 0) (> (+ (- 1) t) 0) (> (+ 1 (* a d t t) (* a t) (* (- 1) a t t) (* (- 1) b c t t) (* d t) (* (- 1) d t t) (* (- 2) t) (* t t)) 0)) (or (< ts 0) (> (+ ts (* (- 1) tt)) 0) (> (+ (- 1) tt) 0) (<= (+ (* a d ts ts) (* (- 1) a d tt tt) (* a ts) (* (- 1) a ts ts) (* (- 1) a tt) (* a tt tt) (* (- 1) b c ts ts) (* b c tt tt) (* d ts) (* (- 1) d ts ts) (* (- 1) d tt) (* d tt tt) (* (- 2) ts) (* ts ts) (* 2 tt) (* (- 1) tt tt)) 0) (< ts1 0) (> (+ ts1 (* (- 1) tt1)) 0) (> (+ (- 1) tt1) 0) (>= (+ (* a d ts1 ts1) (* (- 1) a d tt1 tt1) (* a ts1) (* (- 1) a ts1 ts1) (* (- 1) a tt1) (* a tt1 tt1) (* (- 1) b c ts1 ts1) (* b c tt1 tt1) (* d ts1) (* (- 1) d ts1 ts1) (* (- 1) d tt1) (* d tt1 tt1) (* (- 2) ts1) (* ts1 ts1) (* 2 tt1) (* (- 1) tt1 tt1)) 0)))))
(check-sat)
