(* The notions LEMMAS.md's "Notation" section uses, over Coq's real numbers.
   "Monotone" is weak and on all of [0, 1]: non-decreasing or non-increasing there. *)
Require Import Reals Lra.
Open Scope R_scope.

Definition nondecreasing01 (f : R -> R) : Prop :=
  forall s t, 0 <= s -> s <= t -> t <= 1 -> f s <= f t.

Definition nonincreasing01 (f : R -> R) : Prop :=
  forall s t, 0 <= s -> s <= t -> t <= 1 -> f t <= f s.

Definition monotone01 (f : R -> R) : Prop := nondecreasing01 f \/ nonincreasing01 f.

(* 2x2 matrices [[a, b], [c, d]] and vectors in R^2, written by their entries. *)
Record mat := Mat { m11 : R; m12 : R; m21 : R; m22 : R }.
Record vec := Vec { v1 : R; v2 : R }.

Definition mmul (A B : mat) : mat :=
  Mat (m11 A * m11 B + m12 A * m21 B) (m11 A * m12 B + m12 A * m22 B)
      (m21 A * m11 B + m22 A * m21 B) (m21 A * m12 B + m22 A * m22 B).
Definition mvec (A : mat) (v : vec) : vec :=
  Vec (m11 A * v1 v + m12 A * v2 v) (m21 A * v1 v + m22 A * v2 v).
Definition det (A : mat) : R := m11 A * m22 A - m12 A * m21 A.
Definition tr (A : mat) : R := m11 A + m22 A.
Definition transpose (A : mat) : mat := Mat (m11 A) (m21 A) (m12 A) (m22 A).
Definition madd (A B : mat) : mat :=
  Mat (m11 A + m11 B) (m12 A + m12 B) (m21 A + m21 B) (m22 A + m22 B).
Definition mscale (k : R) (A : mat) : mat := Mat (k * m11 A) (k * m12 A) (k * m21 A) (k * m22 A).
Definition Id2 : mat := Mat 1 0 0 1.

(* The squared norm and the norm ||w||. *)
Definition norm2 (w : vec) : R := v1 w * v1 w + v2 w * v2 w.
Definition norm (w : vec) : R := sqrt (norm2 w).
Definition is_unit (v : vec) : Prop := norm2 v = 1.

(* The quadratic form v^T W v, and the Loewner order W >= 0 on symmetric matrices. *)
Definition qform (W : mat) (v : vec) : R :=
  v1 v * (m11 W * v1 v + m12 W * v2 v) + v2 v * (m21 W * v1 v + m22 W * v2 v).
Definition psd (W : mat) : Prop := forall v, 0 <= qform W v.
Definition nsd (W : mat) : Prop := forall v, qform W v <= 0.
Definition symmetric (W : mat) : Prop := m12 W = m21 W.
Definition sym (B : mat) : mat := mscale (/2) (madd B (transpose B)).

(* The rotation R_theta, and the linear blend (1 - t) I + t B. *)
Definition rot (theta : R) : mat := Mat (cos theta) (- sin theta) (sin theta) (cos theta).
Definition blend (B : mat) (t : R) : mat := madd (mscale (1 - t) Id2) (mscale t B).

(* Def 2.2.1 and Def 2.2.2 of the thesis for a path A(t). *)
Definition good_for_area (A : R -> mat) : Prop :=
  monotone01 (fun t => det (A t)) /\ forall t, 0 <= t <= 1 -> 0 < det (A t).
Definition good_for_norm (A : R -> mat) : Prop :=
  forall v, is_unit v -> monotone01 (fun t => norm (mvec (A t) v)).

Lemma monotone01_ext (f g : R -> R) : (forall t, f t = g t) -> monotone01 f -> monotone01 g.
Proof.
  intros E [H | H]; [left | right]; intros s t Hs Hst Ht; rewrite <- !E; apply H; assumption.
Qed.
