(* thesis Thm 2.2.5 (thesis.thm-2.2.5, atlas.polar.norm) end to end: the polar interpolation
   A_p(t) = R_{t theta} ((1 - t) I + t S) of a symmetric positive definite S = [[x, h], [h, y]] is good for norm
   (Def 2.2.2) iff (x - 1)(y - 1) >= h^2 and (x + y >= 2 or 0 < x <= 1 and 0 < y <= 1); the chain of the level-E
   directions formulation, L6, L5, L4, L3, and the two lemmas of SentencesDirections.v. *)
Require Import Reals Lra Psatz FunctionalExtensionality.
Require Import Affinterp.Defs Affinterp.L3 Affinterp.L4 Affinterp.L5 Affinterp.L6 Affinterp.L13
  Affinterp.SentencesDirections.
Open Scope R_scope.

Definition A_p (theta : R) (S : mat) (t : R) : mat := mmul (rot (t * theta)) (blend S t).

Lemma pd_entries (x h y : R) : pd (Mat x h h y) -> 0 < x /\ 0 < y /\ 0 < x * y - h * h.
Proof.
  intros H. destruct (L13_eigenvalues_real x h y) as [l1 [l2 [Hs Hp]]].
  pose proof (H (Vec 1 0) ltac:(intros E; injection E; lra)) as Hx.
  pose proof (H (Vec 0 1) ltac:(intros E; injection E; lra)) as Hy.
  unfold qform in Hx, Hy; simpl in Hx, Hy.
  apply (L13_pd x h y l1 l2 Hs Hp) in H. destruct H as [H1 H2].
  assert (0 < l1 * l2) by (apply Rmult_lt_0_compat; assumption). repeat split; lra.
Qed.

Theorem thesis_thm_2_2_5 (theta x y h : R) :
  pd (Mat x h h y) ->
  (good_for_norm (A_p theta (Mat x h h y)) <->
   (x - 1) * (y - 1) >= h ^ 2 /\ (x + y >= 2 \/ (0 < x <= 1 /\ 0 < y <= 1))).
Proof.
  intros Hpd. destruct (pd_entries x h y Hpd) as [Hx [Hy HB]].
  set (S := Mat x h h y).
  (* Def 2.2.2 for every v (L6), the rotation on the left dropped (L5), the square (L4), then L3 *)
  assert (Hchain : good_for_norm (A_p theta S) <->
                   forall a b, ~ (qN x y h a b < 0 /\ 0 < rN x y h a b)).
  { unfold good_for_norm. rewrite L6_unit_vs_all.
    assert (E : forall v, (fun t => norm (mvec (A_p theta S t) v)) = (fun t => norm (mvec (blend S t) v))).
    { intros v. apply functional_extensionality. intros t. apply L5_norm_left_rotation. }
    setoid_rewrite E. setoid_rewrite L4. setoid_rewrite L3.
    assert (EP : forall a b, qform (P_of S) (Vec a b) = qN x y h a b).
    { intros. unfold qform, P_of, M_of, sym, madd, mscale, transpose, Id2, qN, S; simpl. field. }
    assert (EQ : forall a b, qform (Q_of S) (Vec a b) = rN x y h a b).
    { intros. unfold qform, Q_of, P_of, M_of, sym, madd, mscale, mmul, transpose, Id2, rN, S; simpl. field. }
    split.
    - intros H a b. rewrite <- EP, <- EQ. apply H.
    - intros H [a b]. rewrite EP, EQ. apply H. }
  rewrite Hchain. split.
  - intros H.
    assert (HD : 0 <= (x - 1) * (y - 1) - h * h).
    { destruct (Rlt_or_le ((x - 1) * (y - 1) - h * h) 0) as [HD | HD]; [exfalso | exact HD].
      destruct (sign_change_exists x y h HD) as [a [b Hab]]. exact (H a b Hab). }
    split; [nra |].
    destruct (Rlt_or_le 1 x); [left; nra |]. destruct (Rlt_or_le 1 y); [left; nra |].
    right; split; split; lra.
  - intros [HD _] a b.
    exact (proj1 (no_sign_change x y h a b Hx Hy HB ltac:(nra))).
Qed.

(* atlas.polar.norm: the region is (x - 1)(y - 1) >= h^2 alone; the thesis's second conjunct follows from it. *)
Theorem atlas_polar_norm (theta x y h : R) :
  pd (Mat x h h y) -> (good_for_norm (A_p theta (Mat x h h y)) <-> (x - 1) * (y - 1) >= h ^ 2).
Proof.
  intros Hpd. rewrite (thesis_thm_2_2_5 theta x y h Hpd). destruct (pd_entries x h y Hpd) as [Hx [Hy HB]].
  split; [tauto |]. intros HD. split; [exact HD |].
  destruct (Rlt_or_le 1 x); [left; nra |]. destruct (Rlt_or_le 1 y); [left; nra |].
  right; split; split; lra.
Qed.
