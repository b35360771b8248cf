(* L5: rotations leave det and the norm alone (LEMMAS.md, L5). *)
Require Import Reals Lra Psatz.
Require Import Affinterp.Defs.
Open Scope R_scope.

Theorem L5_det_rotation (theta : R) : det (rot theta) = 1.
Proof. unfold det, rot; simpl. pose proof (sin2_cos2 theta). unfold Rsqr in *. lra. Qed.

Theorem L5_norm_rotation (theta : R) (w : vec) : norm2 (mvec (rot theta) w) = norm2 w.
Proof.
  destruct w; unfold norm2, mvec, rot; simpl. pose proof (sin2_cos2 theta). unfold Rsqr in *. nra.
Qed.

Theorem L5_det_product (W B : mat) : det (mmul W B) = det W * det B.
Proof. destruct W, B; unfold det, mmul; simpl; ring. Qed.

(* det(U ((1 - t) I + t B) V) = det((1 - t) I + t B) for rotations U, V. *)
Theorem L5_det_homotopy (alpha beta : R) (B : mat) (t : R) :
  det (mmul (rot alpha) (mmul (blend B t) (rot beta))) = det (blend B t).
Proof. rewrite !L5_det_product, !L5_det_rotation. ring. Qed.

Lemma mvec_mmul (U W : mat) (v : vec) : mvec (mmul U W) v = mvec U (mvec W v).
Proof. destruct U, W, v; unfold mvec, mmul; simpl; f_equal; ring. Qed.

(* ||U W v|| = ||W v||: a rotation on the left drops out of Def 2.2.2. *)
Theorem L5_norm_left_rotation (theta : R) (W : mat) (v : vec) :
  norm (mvec (mmul (rot theta) W) v) = norm (mvec W v).
Proof. unfold norm. rewrite mvec_mmul, L5_norm_rotation. reflexivity. Qed.
