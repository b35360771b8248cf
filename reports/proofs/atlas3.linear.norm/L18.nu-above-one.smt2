; atlas3.linear.norm L18.nu-above-one
(set-logic QF_NRA)
(declare-const nu Real)
(declare-const p Real)
(declare-const d Real)
(assert (and (> (+ (- 1) nu) 0) (>= d 0) (>= (+ (* (- 1) d nu) (* (- 1) nu p) p) 0) (> (+ d p) 0)))
(check-sat)
