(* L21: Viete's trigonometric roots are the eigenvalues of a symmetric 3x3 S, with multiplicity (LEMMAS.md,
   L21). "With multiplicity" is read as chi(z) = (z - l0)(z - l1)(z - l2) for every z, chi(z) = det(zE - S). *)
Require Import Reals Lra Psatz.
Require Import Affinterp.Defs3.
Open Scope R_scope.

Definition chi (S : mat3) (z : R) : R := det3 (madd3 (mscale3 z Id3) (mscale3 (-1) S)).

(* p and q as the thesis prints them (theory/sym3/viete.hpp, viete_pq). *)
Definition viete_p (S : mat3) : R := (tr3 S ^ 2 - 3 * frob2 S) / 6.
Definition viete_q (S : mat3) : R := 5 / 54 * tr3 S ^ 3 - 1 / 6 * tr3 S * frob2 S - det3 S.

(* w_j = cos((arccos k + 2 pi j)/3) and lambda_j = (r w_j + tr S)/3, j = 0, 1, 2. *)
Definition viete_w (k : R) (j : nat) : R := cos ((acos k + 2 * PI * INR j) / 3).
Definition viete_lambda (S : mat3) (r k : R) (j : nat) : R := (r * viete_w k j + tr3 S) / 3.

(* 27 chi((u + tr S)/3) = u^3 + 9 p u + 27 q for every symmetric S: the ideal certificate of thesis.viete with
   r w = u, its terms in r^2 + 12p and r^3 k + 108q collected. *)
Lemma chi_shift (S : mat3) (z : R) :
  symmetric3 S -> 27 * chi S z = (3 * z - tr3 S) ^ 3 + 9 * viete_p S * (3 * z - tr3 S) + 27 * viete_q S.
Proof.
  intros [E12 [E13 E23]]. destruct S; simpl in *. subst.
  unfold chi, viete_p, viete_q, det3, tr3, frob2, madd3, mscale3, Id3; simpl. field.
Qed.

(* The three w_j for w_0 = cos th, k = cos (3 th): sum 0, pairwise products -3/4, product k/4. *)
Lemma w_symmetric_functions (k : R) :
  -1 <= k <= 1 ->
  let w0 := viete_w k 0 in let w1 := viete_w k 1 in let w2 := viete_w k 2 in
  w0 + w1 + w2 = 0 /\ w0 * w1 + w0 * w2 + w1 * w2 = - 3 / 4 /\ w0 * w1 * w2 = k / 4.
Proof.
  intros Hk w0 w1 w2.
  set (th := acos k / 3).
  assert (Hk3 : cos (3 * th) = k) by (unfold th; replace (3 * (acos k / 3)) with (acos k) by field;
                                      apply cos_acos; exact Hk).
  set (c := cos th). set (s := sin th).
  assert (Hcs : c ^ 2 + s ^ 2 = 1) by (unfold c, s; pose proof (sin2_cos2 th); unfold Rsqr in *; lra).
  assert (Htriple : k = 4 * c ^ 3 - 3 * c).
  { rewrite <- Hk3. replace (3 * th) with (2 * th + th) by ring.
    rewrite cos_plus, cos_2a, sin_2a. fold c s.
    transitivity (4 * c ^ 3 - 3 * c - 3 * c * (c ^ 2 + s ^ 2 - 1)); [ring | rewrite Hcs; ring]. }
  set (t3 := sqrt 3).
  assert (Ht3 : t3 * t3 = 3) by (unfold t3; apply sqrt_sqrt; lra).
  assert (Hc23 : cos (2 * (PI / 3)) = - 1 / 2) by exact cos_2PI3.
  assert (Hs23 : sin (2 * (PI / 3)) = t3 / 2) by exact sin_2PI3.
  assert (Hw0 : w0 = c) by (unfold w0, viete_w, c, th; f_equal; simpl; field).
  assert (Hw1 : w1 = - c / 2 - t3 / 2 * s).
  { unfold w1, viete_w. replace ((acos k + 2 * PI * INR 1) / 3) with (th + 2 * (PI / 3))
      by (unfold th; simpl; field).
    rewrite cos_plus, Hc23, Hs23. fold c s. field. }
  assert (Hw2 : w2 = - c / 2 + t3 / 2 * s).
  { unfold w2, viete_w. replace ((acos k + 2 * PI * INR 2) / 3) with (th + 2 * (2 * (PI / 3)))
      by (unfold th; simpl; field).
    rewrite cos_plus, (cos_2a (2 * (PI / 3))), (sin_2a (2 * (PI / 3))), Hc23, Hs23. fold c s.
    transitivity (c * (1 / 4 - t3 * t3 / 4) + s * (t3 / 2)); [field |]. rewrite Ht3. field. }
  rewrite Hw0, Hw1, Hw2. clearbody c s t3. repeat split.
  - field.
  - transitivity (- 3 / 4 * c ^ 2 - t3 * t3 / 4 * s ^ 2); [field |]. rewrite Ht3. lra.
  - transitivity (c ^ 3 / 4 - t3 * t3 / 4 * c * s ^ 2); [field |]. rewrite Ht3, Htriple.
    replace (s ^ 2) with (1 - c ^ 2) by lra. field.
Qed.

Theorem L21 (S : mat3) (r k : R) :
  symmetric3 S -> r ^ 2 = -12 * viete_p S -> r ^ 3 * k = -108 * viete_q S -> 0 < r -> Rabs k <= 1 ->
  forall z, chi S z = (z - viete_lambda S r k 0) * (z - viete_lambda S r k 1) * (z - viete_lambda S r k 2).
Proof.
  intros HS Hp Hq Hr Hk z.
  assert (Hk' : -1 <= k <= 1) by (unfold Rabs in Hk; destruct (Rcase_abs k); lra).
  destruct (w_symmetric_functions k Hk') as [Hsum [Hpair Hprod]].
  apply (Rmult_eq_reg_l 27); [| lra]. rewrite (chi_shift S z HS).
  unfold viete_lambda.
  set (u := 3 * z - tr3 S). set (w0 := viete_w k 0). set (w1 := viete_w k 1). set (w2 := viete_w k 2).
  fold w0 w1 w2 in Hsum, Hpair, Hprod.
  transitivity (u ^ 3 - r * (w0 + w1 + w2) * u ^ 2 + r ^ 2 * (w0 * w1 + w0 * w2 + w1 * w2) * u
                - r ^ 3 * (w0 * w1 * w2)).
  - rewrite Hsum, Hpair, Hprod.
    replace (9 * viete_p S * u) with (- 3 / 4 * (-12 * viete_p S) * u) by field.
    replace (27 * viete_q S) with (- (-108 * viete_q S) / 4) by field.
    rewrite <- Hp, <- Hq. field.
  - unfold u. field.
Qed.

(* Each lambda_j is an eigenvalue: det(lambda_j E - S) = 0. *)
Corollary L21_eigenvalues (S : mat3) (r k : R) :
  symmetric3 S -> r ^ 2 = -12 * viete_p S -> r ^ 3 * k = -108 * viete_q S -> 0 < r -> Rabs k <= 1 ->
  forall j, (j <= 2)%nat -> chi S (viete_lambda S r k j) = 0.
Proof.
  intros HS Hp Hq Hr Hk j Hj. rewrite (L21 S r k HS Hp Hq Hr Hk).
  destruct j as [| [| [| j]]]; [ring | ring | ring | lia].
Qed.
