(* L6: homogeneity in v (LEMMAS.md, L6). *)
Require Import Reals Lra Psatz.
Require Import Affinterp.Defs.
Open Scope R_scope.

Definition vscale (k : R) (v : vec) : vec := Vec (k * v1 v) (k * v2 v).

Lemma qform_scale (W : mat) (k : R) (v : vec) : qform W (vscale k v) = k ^ 2 * qform W v.
Proof. destruct W, v; unfold qform, vscale; simpl; ring. Qed.

(* ||A(t)(k v)|| = |k| ||A(t) v||; the squared form is identity L6.norm-homogeneous. *)
Theorem L6_norm_homogeneous (A : mat) (k : R) (v : vec) :
  norm (mvec A (vscale k v)) = Rabs k * norm (mvec A v).
Proof.
  unfold norm. rewrite <- sqrt_Rsqr_abs, <- sqrt_mult by (unfold Rsqr, norm2; nra).
  f_equal. destruct A, v; unfold norm2, mvec, vscale, Rsqr; simpl; ring.
Qed.

Lemma monotone01_scale (f : R -> R) (c : R) : 0 < c -> monotone01 f -> monotone01 (fun t => c * f t).
Proof.
  intros Hc [H | H]; [left | right]; intros s t Hs Hst Ht; specialize (H s t Hs Hst Ht);
    apply Rmult_le_compat_l; lra.
Qed.

Lemma norm2_pos (v : vec) : v <> Vec 0 0 -> 0 < norm2 v.
Proof.
  destruct v as [a b]; unfold norm2; simpl. intros Hv.
  destruct (Req_dec a 0), (Req_dec b 0); subst; [congruence | nra ..].
Qed.

(* ||A(t) v|| is monotone for every unit v iff it is for every v in R^2. *)
Theorem L6_unit_vs_all (A : R -> mat) :
  (forall v, is_unit v -> monotone01 (fun t => norm (mvec (A t) v))) <->
  (forall v, monotone01 (fun t => norm (mvec (A t) v))).
Proof.
  split; [| intros H v _; apply H].
  intros H v.
  destruct (Classical_Prop.classic (v = Vec 0 0)) as [-> | Hv].
  - left. intros s t _ _ _.
    replace (Vec 0 0) with (vscale 0 (Vec 0 0)) by (unfold vscale; simpl; f_equal; ring).
    rewrite !L6_norm_homogeneous, Rabs_R0. lra.
  - pose proof (norm2_pos v Hv) as Hp.
    set (r := norm v). assert (Hr : 0 < r) by (apply sqrt_lt_R0; exact Hp).
    assert (Hv' : v = vscale r (vscale (/ r) v)).
    { destruct v; unfold vscale; simpl; f_equal; field; lra. }
    assert (Hu : is_unit (vscale (/ r) v)).
    { unfold is_unit. replace (norm2 (vscale (/ r) v)) with (norm2 v / (r * r)).
      - unfold r, norm. rewrite sqrt_sqrt by lra. field. lra.
      - destruct v; unfold norm2, vscale; simpl. field. lra. }
    apply (monotone01_ext (fun t => r * norm (mvec (A t) (vscale (/ r) v)))).
    + intros t. symmetry. transitivity (norm (mvec (A t) (vscale r (vscale (/ r) v)))); [exact (f_equal (fun w => norm (mvec (A t) w)) Hv') |].
      rewrite L6_norm_homogeneous, Rabs_right; lra.
    + apply monotone01_scale; [exact Hr | apply H, Hu].
Qed.

(* {v : P(v) < 0 < Q(v)} is empty iff it contains no unit vector (it is a cone without 0). *)
Theorem L6_cone (P Q : mat) :
  (~ exists v, qform P v < 0 < qform Q v) <->
  (~ exists v, is_unit v /\ qform P v < 0 < qform Q v).
Proof.
  split; [intros H [v [_ Hv]]; apply H; exists v; exact Hv |].
  intros H [v Hv]. apply H.
  assert (Hne : v <> Vec 0 0) by (intros ->; unfold qform in Hv; simpl in Hv; lra).
  pose proof (norm2_pos v Hne) as Hp.
  set (r := sqrt (norm2 v)). assert (Hr : 0 < r) by (apply sqrt_lt_R0; exact Hp).
  exists (vscale (/ r) v). rewrite !qform_scale. split.
  - unfold is_unit. replace (norm2 (vscale (/ r) v)) with (norm2 v / (r * r)).
    + unfold r. rewrite sqrt_sqrt by lra. field. lra.
    + destruct v; unfold norm2, vscale; simpl. field. lra.
  - assert (0 < (/ r) ^ 2) by (apply pow_lt, Rinv_0_lt_compat, Hr). nra.
Qed.

(* Every unit v is a non-zero multiple of (1, m) for some real m, or of (0, 1) (sentence lemma.L6.directions). *)
Theorem L6_directions (v : vec) :
  is_unit v -> exists k m, k <> 0 /\ (v = vscale k (Vec 1 m) \/ v = vscale k (Vec 0 1)).
Proof.
  destruct v as [a b]; unfold is_unit, norm2; simpl. intros Hu.
  destruct (Req_dec a 0) as [-> | Ha].
  - exists b, 0. split; [nra | right; unfold vscale; simpl; f_equal; ring].
  - exists a, (b / a). split; [exact Ha | left; unfold vscale; simpl; f_equal; field; exact Ha].
Qed.
