(* L7: conjugating the linear homotopy by a rotation (LEMMAS.md, L7). A rotation is a matrix O with
   O^T O = I and det O = 1 (L13's is_rotation). *)
Require Import Reals Lra Psatz.
Require Import Affinterp.Defs Affinterp.L5 Affinterp.L11 Affinterp.L13.
Open Scope R_scope.

Definition conj (O A : mat) : mat := mmul (transpose O) (mmul A O).

(* O^T O = I gives O O^T = I for a 2x2 O with det O = 1 (O^T is O's adjugate). *)
Lemma rotation_right_inverse (O : mat) : is_rotation O -> mmul O (transpose O) = Id2.
Proof.
  intros [HO Hd]. set (adj := Mat (m22 O) (- m12 O) (- m21 O) (m11 O)).
  assert (K1 : mmul O adj = mscale (det O) Id2) by (destruct O; unfold mmul, adj, mscale, det, Id2; simpl; f_equal; ring).
  assert (K2 : transpose O = adj).
  { transitivity (mmul (mmul (transpose O) O) adj).
    - rewrite <- mmul_assoc, K1, Hd. destruct O; unfold mmul, mscale, transpose, Id2; simpl; f_equal; ring.
    - rewrite HO, mmul_id_l. reflexivity. }
  rewrite K2, K1, Hd. unfold mscale, Id2; simpl; f_equal; ring.
Qed.

Lemma rotation_transpose (O : mat) : is_rotation O -> is_rotation (transpose O).
Proof.
  intros HO. split.
  - replace (transpose (transpose O)) with O by (destruct O; reflexivity). apply rotation_right_inverse, HO.
  - destruct HO as [_ Hd]. rewrite <- Hd. destruct O; unfold det, transpose; simpl; ring.
Qed.

Lemma mvec_transpose_cancel (O : mat) (v : vec) : is_rotation O -> mvec O (mvec (transpose O) v) = v.
Proof.
  intros HO. rewrite <- mvec_mmul, (rotation_right_inverse O HO).
  destruct v; unfold mvec, Id2; simpl; f_equal; ring.
Qed.

Lemma norm_rotation (O : mat) (w : vec) : is_rotation O -> norm (mvec O w) = norm w.
Proof.
  intros [HO _]. unfold norm. f_equal.
  transitivity (qform (mmul (transpose O) O) w); [destruct O, w; unfold norm2, qform, mvec, mmul, transpose; simpl; ring |].
  rewrite HO. destruct w; unfold norm2, qform, Id2; simpl; ring.
Qed.

(* Identity L7.conjugated-blend: (1 - t) I + t O^T A O = O^T ((1 - t) I + t A) O when O^T O = I. *)
Theorem L7_conjugated_blend (O A : mat) (t : R) :
  is_rotation O -> blend (conj O A) t = conj O (blend A t).
Proof.
  intros [HO _]. transitivity (madd (mscale (1 - t) (mmul (transpose O) O)) (mscale t (conj O A))).
  - rewrite HO. reflexivity.
  - destruct O, A; unfold blend, conj, madd, mscale, mmul, transpose, Id2; simpl; f_equal; ring.
Qed.

(* (a) (1 - t) I + t A' is good for norm iff (1 - t) I + t A is. *)
Theorem L7a (O A : mat) : is_rotation O -> (good_for_norm (blend (conj O A)) <-> good_for_norm (blend A)).
Proof.
  intros HO.
  assert (N : forall t v, norm (mvec (blend (conj O A) t) v) = norm (mvec (blend A t) (mvec O v))).
  { intros t v. rewrite L7_conjugated_blend by exact HO. unfold conj. rewrite !mvec_mmul.
    apply norm_rotation, rotation_transpose, HO. }
  assert (U : forall v, is_unit v -> is_unit (mvec O v)).
  { intros v Hv. unfold is_unit in *. pose proof (norm_rotation O v HO) as E. unfold norm in E.
    apply sqrt_inj in E; [lra | unfold norm2; nra | unfold norm2; nra]. }
  unfold good_for_norm. split.
  - intros H v Hv.
    assert (Hu : is_unit (mvec (transpose O) v)).
    { unfold is_unit in *. pose proof (norm_rotation _ v (rotation_transpose O HO)) as E. unfold norm in E.
      apply sqrt_inj in E; [lra | unfold norm2; nra | unfold norm2; nra]. }
    apply (monotone01_ext (fun t => norm (mvec (blend (conj O A) t) (mvec (transpose O) v)))).
    + intros t. rewrite N, mvec_transpose_cancel by exact HO. reflexivity.
    + apply H, Hu.
  - intros H v Hv. apply (monotone01_ext (fun t => norm (mvec (blend A t) (mvec O v)))).
    + intros t. symmetry. apply N.
    + apply H, U, Hv.
Qed.

Lemma qform_conj (O W : mat) (v : vec) : qform (conj O W) v = qform W (mvec O v).
Proof. destruct O, W, v; unfold qform, conj, mmul, mvec, transpose; simpl; ring. Qed.

Lemma psd_conj (O W : mat) : is_rotation O -> (psd (conj O W) <-> psd W).
Proof.
  intros HO. unfold psd. setoid_rewrite qform_conj. split; [| intros H v; apply H].
  intros H v. rewrite <- (mvec_transpose_cancel O v HO). apply H.
Qed.

Lemma conj_lin (O X Y : mat) (k : R) :
  conj O (madd X (mscale k Y)) = madd (conj O X) (mscale k (conj O Y)).
Proof. destruct O, X, Y; unfold conj, madd, mscale, mmul, transpose; simpl; f_equal; ring. Qed.

Lemma conj_id (O : mat) : is_rotation O -> conj O Id2 = Id2.
Proof.
  intros [HO _]. rewrite <- HO at 2. destruct O; unfold conj, mmul, transpose, Id2; simpl; f_equal; ring.
Qed.

(* Identity L7.sym-and-gram: sym(A') = O^T sym(A) O and A'^T A' = O^T A^T A O. *)
Theorem L7_sym_and_gram (O A : mat) :
  is_rotation O ->
  sym (conj O A) = conj O (sym A) /\ mmul (transpose (conj O A)) (conj O A) = conj O (mmul (transpose A) A).
Proof.
  intros HO. split.
  - destruct O, A; unfold sym, conj, madd, mscale, mmul, transpose; simpl; f_equal; field.
  - transitivity (mmul (transpose O) (mmul (transpose A) (mmul (mmul O (transpose O)) (mmul A O)))).
    + destruct O, A; unfold conj, mmul, transpose; simpl; f_equal; ring.
    + rewrite (rotation_right_inverse O HO). destruct O, A; unfold conj, mmul, transpose, Id2; simpl; f_equal; ring.
Qed.

(* The condition of atlas.linear.norm: sym(A) >= I or A^T A <= sym(A), and det A > 0. *)
Definition linear_norm_condition (A : mat) : Prop :=
  (psd (madd (sym A) (mscale (-1) Id2)) \/ psd (madd (sym A) (mscale (-1) (mmul (transpose A) A)))) /\
  0 < det A.

(* (b) The condition holds for A' iff it holds for A. *)
Theorem L7b (O A : mat) : is_rotation O -> (linear_norm_condition (conj O A) <-> linear_norm_condition A).
Proof.
  intros HO. destruct (L7_sym_and_gram O A HO) as [Hs Hg].
  assert (Hd : det (conj O A) = det A).
  { destruct HO as [_ Hdet]. unfold conj. rewrite !L5_det_product.
    replace (det (transpose O)) with (det O) by (destruct O; unfold det, transpose; simpl; ring).
    rewrite Hdet. ring. }
  unfold linear_norm_condition. rewrite Hs, Hg, Hd.
  rewrite <- (conj_id O HO) at 1. rewrite <- conj_lin, psd_conj by exact HO.
  rewrite <- conj_lin, psd_conj by exact HO. tauto.
Qed.

(* (c) Identities L7.skew-part and L7.skew-commutes, and L13: for the rotation O diagonalising sym(A),
   A' = [[p, -k], [k, r]] with p, r the eigenvalues of sym(A) and k = (c - b)/2. *)
Definition J : mat := Mat 0 (-1) 1 0.

Theorem L7_skew_part (A : mat) : A = madd (sym A) (mscale ((m21 A - m12 A) / 2) J).
Proof. destruct A; unfold sym, madd, mscale, transpose, J; simpl; f_equal; field. Qed.

Theorem L7_skew_commutes (O : mat) : conj O J = mscale (det O) J.
Proof. destruct O; unfold conj, mmul, transpose, J, mscale, det; simpl; f_equal; ring. Qed.

Theorem L7c (A : mat) :
  let k := (m21 A - m12 A) / 2 in
  exists p r O, p + r = tr (sym A) /\ p * r = det (sym A) /\ is_rotation O /\ conj O A = Mat p (- k) k r.
Proof.
  intros k. set (h := (m12 A + m21 A) / 2).
  assert (Hsym : sym A = Mat (m11 A) h h (m22 A)).
  { unfold h. destruct A; unfold sym, madd, mscale, transpose; simpl; f_equal; field. }
  destruct (L13_eigenvalues_real (m11 A) h (m22 A)) as [p [r [Hs Hp]]].
  destruct (L13_spectral _ _ _ p r Hs Hp) as [O [HO Hdiag]].
  exists p, r, O.
  split; [rewrite Hsym; unfold tr; simpl; lra |]. split; [rewrite Hsym; unfold det; simpl; lra |].
  split; [exact HO |].
  rewrite (L7_skew_part A) at 1. rewrite conj_lin, L7_skew_commutes.
  destruct HO as [HO Hdet]. rewrite Hdet. fold k.
  replace (conj O (sym A)) with (diag p r).
  - unfold diag, madd, mscale, J; simpl; f_equal; ring.
  - rewrite Hsym, Hdiag. unfold conj.
    transitivity (mmul (mmul (transpose O) O) (mmul (diag p r) (mmul (transpose O) O))).
    + rewrite HO, mmul_id_l. unfold diag, mmul, Id2; simpl; f_equal; ring.
    + destruct O; unfold mmul, transpose, diag; simpl; f_equal; ring.
Qed.
