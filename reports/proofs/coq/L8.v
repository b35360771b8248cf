(* L8: Dines' theorem in the form used (level N), and how W >= 0 is written (LEMMAS.md, L8). *)
Require Import Reals Lra Psatz.
Require Import Affinterp.Defs.
Open Scope R_scope.

(* Identity L8.psd-completed-square: x v^T W v = (x v1 + h v2)^2 + det W v2^2. *)
Theorem L8_psd_completed_square (x h y : R) (v : vec) :
  x * qform (Mat x h h y) v = (x * v1 v + h * v2 v) ^ 2 + det (Mat x h h y) * v2 v ^ 2.
Proof. destruct v; unfold qform, det; simpl; ring. Qed.

(* (b) W = [[x, h], [h, y]] is >= 0 iff x >= 0, y >= 0 and det W = x y - h^2 >= 0. *)
Theorem L8b_psd_iff (x h y : R) :
  psd (Mat x h h y) <-> 0 <= x /\ 0 <= y /\ 0 <= x * y - h * h.
Proof.
  unfold psd. split.
  - intros H. pose proof (H (Vec 1 0)) as Hx. pose proof (H (Vec 0 1)) as Hy.
    unfold qform in Hx, Hy; simpl in Hx, Hy.
    repeat split; [nra | nra |].
    destruct (Req_dec x 0) as [-> | Hx0].
    + pose proof (H (Vec (y + 1) (- h))) as Hv. unfold qform in Hv; simpl in Hv. nra.
    + pose proof (H (Vec (- h) x)) as Hv. unfold qform in Hv; simpl in Hv.
      assert (0 < x) by lra. nra.
  - intros [Hx [Hy Hd]] v. pose proof (L8_psd_completed_square x h y v) as E.
    unfold det in E; simpl in E.
    destruct (Req_dec x 0) as [-> | Hx0].
    + assert (h = 0) by nra. subst. destruct v; unfold qform; simpl. nra.
    + assert (0 < x) by lra.
      assert (0 <= (x * v1 v + h * v2 v) ^ 2) by apply pow2_ge_0.
      assert (0 <= (x * y - h * h) * v2 v ^ 2) by (apply Rmult_le_pos; [lra | apply pow2_ge_0]).
      apply (Rmult_le_reg_l x); [assumption |]. rewrite Rmult_0_r, E. lra.
Qed.

Theorem L8b_nsd_iff (x h y : R) :
  nsd (Mat x h h y) <-> x <= 0 /\ y <= 0 /\ 0 <= x * y - h * h.
Proof.
  assert (E : forall v, qform (Mat x h h y) v = - qform (Mat (- x) (- h) (- h) (- y)) v).
  { intros v. destruct v; unfold qform; simpl; ring. }
  unfold nsd. setoid_rewrite E.
  assert (I : (forall v, - qform (Mat (- x) (- h) (- h) (- y)) v <= 0) <-> psd (Mat (- x) (- h) (- h) (- y))).
  { unfold psd. split; intros H v; specialize (H v); lra. }
  rewrite I, L8b_psd_iff. split; intros [H1 [H2 H3]]; repeat split; nra.
Qed.

(* The statement used, direction (<=): Q <= 0, or P - nu Q >= 0 for some nu >= 0, leaves no v with
   P(v) < 0 < Q(v). *)
Theorem L8_sufficient (P Q : mat) :
  (nsd Q \/ exists nu, 0 <= nu /\ psd (madd P (mscale (- nu) Q))) ->
  ~ exists v, qform P v < 0 < qform Q v.
Proof.
  intros [HQ | [nu [Hnu HPQ]]] [v [HP HQv]].
  - specialize (HQ v). lra.
  - specialize (HPQ v).
    assert (E : qform (madd P (mscale (- nu) Q)) v = qform P v - nu * qform Q v).
    { destruct P, Q, v; unfold qform, madd, mscale; simpl; ring. }
    rewrite E in HPQ. nra.
Qed.
