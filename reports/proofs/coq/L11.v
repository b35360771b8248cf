(* L11: the polar factor of A = R_alpha D R_beta (LEMMAS.md, L11). *)
Require Import Reals Lra Psatz.
Require Import Affinterp.Defs Affinterp.L5 Affinterp.L13.
Open Scope R_scope.

Definition A_svd (x y alpha beta : R) : mat := mmul (rot alpha) (mmul (Mat x 0 0 y) (rot beta)).
Definition S_polar (x y beta : R) : mat := mmul (transpose (rot beta)) (mmul (Mat x 0 0 y) (rot beta)).

Lemma rot_gram (b : R) : mmul (rot b) (transpose (rot b)) = Id2 /\ mmul (transpose (rot b)) (rot b) = Id2.
Proof.
  pose proof (sin2_cos2 b) as E. unfold Rsqr in E.
  unfold mmul, transpose, rot, Id2; simpl; split; f_equal; nra.
Qed.

Lemma mmul_assoc (A B C : mat) : mmul A (mmul B C) = mmul (mmul A B) C.
Proof. destruct A, B, C; unfold mmul; simpl; f_equal; ring. Qed.

Lemma mmul_id_l (A : mat) : mmul Id2 A = A.
Proof. destruct A; unfold mmul, Id2; simpl; f_equal; ring. Qed.

(* Identity L11.polar-factor: A = (R_alpha R_beta)(R_beta^T D R_beta). *)
Theorem L11_polar_factor (x y alpha beta : R) :
  A_svd x y alpha beta = mmul (mmul (rot alpha) (rot beta)) (S_polar x y beta).
Proof.
  unfold A_svd, S_polar. rewrite <- mmul_assoc, (mmul_assoc (rot beta)), (proj1 (rot_gram beta)), mmul_id_l.
  reflexivity.
Qed.

(* R_alpha R_beta is a rotation; S = R_beta^T D R_beta is symmetric, positive definite, with tr S = tr D and
   det S = det D (identity L11.trace-det). *)
Theorem L11_factors (x y alpha beta : R) :
  0 < x -> 0 < y ->
  is_rotation (mmul (rot alpha) (rot beta)) /\ symmetric (S_polar x y beta) /\ pd (S_polar x y beta) /\
  tr (S_polar x y beta) = x + y /\ det (S_polar x y beta) = x * y.
Proof.
  intros Hx Hy.
  pose proof (sin2_cos2 alpha) as Ea. pose proof (sin2_cos2 beta) as Eb. unfold Rsqr in Ea, Eb.
  assert (Htr : tr (S_polar x y beta) = x + y).
  { unfold tr, S_polar, mmul, transpose, rot; simpl. nra. }
  assert (Hdet : det (S_polar x y beta) = x * y).
  { assert (Dt : det (transpose (rot beta)) = 1) by (unfold det, transpose, rot; simpl; lra).
    unfold S_polar. rewrite !L5_det_product, Dt, L5_det_rotation. unfold det; simpl. ring. }
  assert (Hsym : symmetric (S_polar x y beta)) by (unfold symmetric, S_polar, mmul, transpose, rot; simpl; ring).
  split; [| split; [exact Hsym | split; [| split; assumption]]].
  - split.
    + unfold mmul, transpose, rot, Id2; simpl. f_equal; nra.
    + rewrite L5_det_product, !L5_det_rotation. ring.
  - destruct (S_polar x y beta) as [a b c d] eqn:ES. unfold symmetric in Hsym; simpl in Hsym. subst c.
    unfold tr, det in Htr, Hdet; simpl in Htr, Hdet.
    apply (proj2 (L13_pd a b d x y ltac:(lra) ltac:(lra))). split; assumption.
Qed.

(* A positive definite symmetric 2x2 matrix is fixed by its square: by Cayley-Hamilton tr(S) S = S^2 + det(S) I,
   det S = sqrt(det S^2) and tr S = sqrt(tr S^2 + 2 det S). *)
Lemma pd_sqrt_unique (a b c a' b' c' : R) :
  pd (Mat a b b c) -> pd (Mat a' b' b' c') -> mmul (Mat a b b c) (Mat a b b c) = mmul (Mat a' b' b' c') (Mat a' b' b' c') ->
  Mat a b b c = Mat a' b' b' c'.
Proof.
  intros H1 H2 Hsq. unfold mmul in Hsq; simpl in Hsq. injection Hsq as E11 E12 E21 E22.
  assert (P : forall a b c, pd (Mat a b b c) -> 0 < a /\ 0 < c /\ 0 < a * c - b * b).
  { intros p q r H.
    pose proof (H (Vec 1 0) ltac:(intros E; injection E; lra)) as Hp.
    pose proof (H (Vec 0 1) ltac:(intros E; injection E; lra)) as Hr.
    unfold qform in Hp, Hr; simpl in Hp, Hr.
    destruct (L13_eigenvalues_real p q r) as [l1 [l2 [Hs Hpr]]].
    apply (L13_pd p q r l1 l2 Hs Hpr) in H. destruct H as [Hl1 Hl2].
    assert (0 < l1 * l2) by (apply Rmult_lt_0_compat; assumption).
    repeat split; lra. }
  destruct (P a b c H1) as [Ha [Hc Hd]]. destruct (P a' b' c' H2) as [Ha' [Hc' Hd']].
  (* det S^2 = (det S)^2, so det S = det S' *)
  assert (Edet2 : (a * c - b * b) ^ 2 = (a' * c' - b' * b') ^ 2).
  { transitivity ((a * a + b * b) * (b * b + c * c) - (a * b + b * c) * (b * a + c * b)); [ring |].
    rewrite E11, E12, E21, E22. ring. }
  assert (Edet : a * c - b * b = a' * c' - b' * b').
  { apply Rsqr_inj; [lra | lra | rewrite !Rsqr_pow2; exact Edet2]. }
  assert (Etr2 : (a + c) ^ 2 = (a' + c') ^ 2).
  { transitivity ((a * a + b * b) + (b * b + c * c) + 2 * (a * c - b * b)); [ring |].
    rewrite E11, E22, Edet. ring. }
  assert (Etr : a + c = a' + c') by (apply Rsqr_inj; [lra | lra | rewrite !Rsqr_pow2; exact Etr2]).
  (* Cayley-Hamilton: (a + c) S = S^2 + det(S) I, entry by entry *)
  assert (Ca : a = ((a * a + b * b) + (a * c - b * b)) / (a + c)) by (field; lra).
  assert (Cb : b = (a * b + b * c) / (a + c)) by (field; lra).
  assert (Cc : c = ((b * b + c * c) + (a * c - b * b)) / (a + c)) by (field; lra).
  assert (Ca' : a' = ((a' * a' + b' * b') + (a' * c' - b' * b')) / (a' + c')) by (field; lra).
  assert (Cb' : b' = (a' * b' + b' * c') / (a' + c')) by (field; lra).
  assert (Cc' : c' = ((b' * b' + c' * c') + (a' * c' - b' * b')) / (a' + c')) by (field; lra).
  f_equal.
  - rewrite Ca, Ca', E11, Edet, Etr. reflexivity.
  - rewrite Cb, Cb', E12, Etr. reflexivity.
  - rewrite Cb, Cb', E12, Etr. reflexivity.
  - rewrite Cc, Cc', E22, Edet, Etr. reflexivity.
Qed.

Lemma transpose_mmul (A B : mat) : transpose (mmul A B) = mmul (transpose B) (transpose A).
Proof. destruct A, B; unfold transpose, mmul; simpl; f_equal; ring. Qed.

Lemma mmul_id_r (A : mat) : mmul A Id2 = A.
Proof. destruct A; unfold mmul, Id2; simpl; f_equal; ring. Qed.

(* A^T A = S^2 for A = U S with U^T U = I and S symmetric. *)
Lemma gram_of_product (U S : mat) :
  mmul (transpose U) U = Id2 -> symmetric S -> mmul (transpose (mmul U S)) (mmul U S) = mmul S S.
Proof.
  intros HU HS. rewrite transpose_mmul, <- mmul_assoc, (mmul_assoc (transpose U)), HU, mmul_id_l.
  replace (transpose S) with S; [reflexivity |].
  destruct S; unfold symmetric in HS; simpl in HS; unfold transpose; simpl; rewrite HS; reflexivity.
Qed.

Lemma mmul_cancel_r (U V S : mat) : det S <> 0 -> mmul U S = mmul V S -> U = V.
Proof.
  intros Hd E. set (adj := Mat (m22 S) (- m12 S) (- m21 S) (m11 S)).
  assert (K : forall W, mmul (mmul W S) adj = mscale (det S) W).
  { intros W. destruct W, S; unfold mmul, mscale, adj, det; simpl; f_equal; ring. }
  pose proof (K U) as KU. rewrite E, K in KU.
  destruct U, V; unfold mscale in KU; simpl in KU. injection KU as K1 K2 K3 K4.
  f_equal; apply (Rmult_eq_reg_l (det S)); auto.
Qed.

(* By hand in LEMMAS.md: the factorisation A = U S with U orthogonal and S symmetric positive definite is
   unique, so (R_alpha R_beta, R_beta^T D R_beta) is the polar decomposition of thesis Def 2.2.5. *)
Theorem L11_unique (x y alpha beta : R) (U S : mat) :
  0 < x -> 0 < y -> mmul (transpose U) U = Id2 -> symmetric S -> pd S ->
  A_svd x y alpha beta = mmul U S ->
  U = mmul (rot alpha) (rot beta) /\ S = S_polar x y beta.
Proof.
  intros Hx Hy HU HS Hpd HA.
  destruct (L11_factors x y alpha beta Hx Hy) as [[HR _] [HS0 [Hpd0 [_ Hdet0]]]].
  assert (Hsq : mmul S S = mmul (S_polar x y beta) (S_polar x y beta)).
  { rewrite <- (gram_of_product U S HU HS), <- HA, L11_polar_factor.
    apply gram_of_product; assumption. }
  assert (ES : S = S_polar x y beta).
  { destruct S as [a b b' c], (S_polar x y beta) as [a' e e' c'].
    unfold symmetric in HS, HS0; simpl in HS, HS0. subst b' e'.
    apply pd_sqrt_unique; assumption. }
  split; [| exact ES].
  apply (mmul_cancel_r _ _ (S_polar x y beta)); [rewrite Hdet0; nra |].
  rewrite <- ES, <- HA, L11_polar_factor, ES. reflexivity.
Qed.
