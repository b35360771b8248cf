(* Small steps: where a perturbation argument needs an explicit eps (L8, L9, SentencesDirections.v). *)
Require Import Reals Lra Psatz.
Open Scope R_scope.

(* Small perturbations: a1 eps + b1 eps^2 < 0 < c + a2 eps + b2 eps^2 for some eps in (0, 1], if a1 < 0 < c. *)
Lemma small_eps (a1 b1 c a2 b2 : R) :
  a1 < 0 -> 0 < c -> exists e, 0 < e <= 1 /\ a1 * e + b1 * e ^ 2 < 0 /\ 0 < c + a2 * e + b2 * e ^ 2.
Proof.
  intros Ha Hc.
  set (e := Rmin 1 (Rmin (- a1 / (2 * (Rabs b1 + 1))) (c / (2 * (Rabs a2 + Rabs b2 + 1))))).
  pose proof (Rabs_pos b1). pose proof (Rabs_pos a2). pose proof (Rabs_pos b2).
  assert (He1 : e <= 1) by apply Rmin_l.
  assert (He2 : e <= - a1 / (2 * (Rabs b1 + 1))) by (eapply Rle_trans; [apply Rmin_r | apply Rmin_l]).
  assert (He3 : e <= c / (2 * (Rabs a2 + Rabs b2 + 1))) by (eapply Rle_trans; [apply Rmin_r | apply Rmin_r]).
  assert (He0 : 0 < e).
  { unfold e. repeat apply Rmin_pos; try lra; apply Rdiv_lt_0_compat; lra. }
  exists e. split; [lra |].
  assert (Ee : 0 <= e ^ 2 <= e) by (split; [apply pow2_ge_0 | nra]).
  pose proof (Rle_abs b1).
  assert (- a2 <= Rabs a2) by (rewrite <- Rabs_Ropp; apply Rle_abs).
  assert (- b2 <= Rabs b2) by (rewrite <- Rabs_Ropp; apply Rle_abs).
  assert (Hb1 : b1 * e ^ 2 <= e * (Rabs b1 * e)).
  { replace (e * (Rabs b1 * e)) with (Rabs b1 * e ^ 2) by ring. apply Rmult_le_compat_r; lra. }
  assert (Hkey : Rabs b1 * e <= - a1 / 2).
  { assert (e * (2 * (Rabs b1 + 1)) <= - a1).
    { apply (Rmult_le_compat_r (2 * (Rabs b1 + 1))) in He2; [| lra].
      unfold Rdiv in He2. rewrite Rmult_assoc, Rinv_l in He2 by lra. lra. }
    lra. }
  assert (e * (Rabs b1 * e) <= e * (- a1 / 2)) by (apply Rmult_le_compat_l; lra).
  assert (Ha2 : - (Rabs a2 * e) <= a2 * e).
  { rewrite Ropp_mult_distr_l. apply Rmult_le_compat_r; lra. }
  assert (Hb2 : - (Rabs b2 * e) <= b2 * e ^ 2).
  { apply Rle_trans with (- Rabs b2 * e ^ 2).
    - assert (Rabs b2 * e ^ 2 <= Rabs b2 * e) by (apply Rmult_le_compat_l; lra). lra.
    - apply Rmult_le_compat_r; lra. }
  assert (Hc' : e * (2 * (Rabs a2 + Rabs b2 + 1)) <= c).
  { apply (Rmult_le_compat_r (2 * (Rabs a2 + Rabs b2 + 1))) in He3; [| lra].
    unfold Rdiv in He3. rewrite Rmult_assoc, Rinv_l in He3 by lra. lra. }
  split; [nra | lra].
Qed.

