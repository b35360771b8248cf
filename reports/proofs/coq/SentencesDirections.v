(* The directions sentences cond-not-prop.E of thesis.thm-2.2.5 and atlas.polar.norm: for a symmetric positive
   definite B = [[x, h], [h, y]] with det(B - I) >= 0, q'(0)/2 = v^T N v and q'(1)/2 = v^T (N^2 + N) v
   (N = B - I, q(t) = ||((1 - t) I + t B) v||^2) are never of opposite strict signs. No tactic found a
   certificate for the sentences whole (MANIFEST.json); this proof supplies the one step they miss: when N <= 0,
   det(B) v^T (N^2 + N) v = u^T adj(B) N u with u = B v, and adj(B) N <= 0 (L8 (b)). Each theorem states its
   stored sentence exactly as checks/proofs/smt2_to_coq.py reads it. *)
Require Import Reals Psatz Lra.
Require Import Affinterp.Defs Affinterp.L8.
Open Scope R_scope.

Lemma no_sign_change (x y h a b : R) :
  0 < x -> 0 < y -> 0 < x * y - h * h -> 0 <= (x - 1) * (y - 1) - h * h ->
  let q := (x - 1) * a ^ 2 + 2 * h * a * b + (y - 1) * b ^ 2 in
  let r := ((x - 1) ^ 2 + h ^ 2 + (x - 1)) * a ^ 2 + 2 * h * (x + y - 1) * a * b
           + (h ^ 2 + (y - 1) ^ 2 + (y - 1)) * b ^ 2 in
  ~ (q < 0 /\ 0 < r) /\ ~ (0 < q /\ r < 0).
Proof.
  intros Hx Hy HB HD q r.
  assert (Hq : q = qform (Mat (x - 1) h h (y - 1)) (Vec a b)) by (unfold q, qform; simpl; ring).
  assert (Hsame : (0 <= x - 1 /\ 0 <= y - 1) \/ (x - 1 <= 0 /\ y - 1 <= 0)).
  { assert (0 <= h * h) by nra.
    destruct (Rlt_or_le 0 (x - 1)); [left; split; nra |].
    destruct (Rlt_or_le 0 (y - 1)); [left; split; nra | right; split; lra]. }
  destruct Hsame as [[H1 H2] | [H1 H2]].
  - (* N >= 0: q >= 0 and r = ||N v||^2 + q >= q *)
    assert (0 <= q) by (rewrite Hq; apply (proj2 (L8b_psd_iff _ _ _)); repeat split; lra).
    assert (r - q = ((x - 1) * a + h * b) ^ 2 + (h * a + (y - 1) * b) ^ 2) by (unfold r, q; ring).
    assert (0 <= ((x - 1) * a + h * b) ^ 2 + (h * a + (y - 1) * b) ^ 2)
      by (pose proof (pow2_ge_0 ((x - 1) * a + h * b)); pose proof (pow2_ge_0 (h * a + (y - 1) * b)); lra).
    split; intros [Ha Hb]; lra.
  - (* N <= 0: q <= 0 and det(B) r = u^T adj(B) N u <= 0 *)
    assert (0 <= - q).
    { assert (E : - q = qform (Mat (- (x - 1)) (- h) (- h) (- (y - 1))) (Vec a b)) by (unfold q, qform; simpl; ring).
      rewrite E. apply (proj2 (L8b_psd_iff _ _ _)). repeat split; nra. }
    set (M := Mat (y * (x - 1) - h * h) h h (x * (y - 1) - h * h)).
    assert (Er : (x * y - h * h) * r = qform M (Vec (x * a + h * b) (h * a + y * b))) by (unfold r, M, qform; simpl; ring).
    assert (HM : qform M (Vec (x * a + h * b) (h * a + y * b)) <= 0).
    { apply (proj2 (L8b_nsd_iff _ _ _)). repeat split; [nra | nra |].
      replace ((y * (x - 1) - h * h) * (x * (y - 1) - h * h) - h * h)
        with ((x * y - h * h) * ((x - 1) * (y - 1) - h * h)) by ring.
      apply Rmult_le_pos; lra. }
    assert (r <= 0).
    { destruct (Rle_or_lt r 0) as [| Hr]; [assumption |].
      assert (0 < (x * y - h * h) * r) by (apply Rmult_lt_0_compat; lra). lra. }
    split; intros [Ha Hb]; lra.
Qed.

(* thesis.thm-2.2.5/printed.directions.cond-not-prop.E.smt2 *)
Theorem thesis_thm_2_2_5__printed_directions_cond_not_prop_E : forall x y h m : R, ~ (((x > 0) /\ (y > 0) /\ ((((- 1) * h * h) + (x * y)) > 0) /\ ((1 + ((- 1) * h * h) + ((- 1) * x) + (x * y) + ((- 1) * y)) >= 0) /\ ((((- 2) + x + y) >= 0) \/ ((x > 0) /\ (((- 1) + x) <= 0) /\ (y > 0) /\ (((- 1) + y) <= 0))) /\ (((((- 2) + (4 * h * m) + ((- 2) * m * m) + (2 * m * m * y) + (2 * x)) < 0) /\ ((((- 4) * h * m) + (4 * h * m * x) + (4 * h * m * y) + (2 * h * h) + (2 * h * h * m * m) + ((- 2) * m * m * y) + (2 * m * m * y * y) + ((- 2) * x) + (2 * x * x)) > 0)) \/ ((((- 2) + (4 * h * m) + ((- 2) * m * m) + (2 * m * m * y) + (2 * x)) > 0) /\ ((((- 4) * h * m) + (4 * h * m * x) + (4 * h * m * y) + (2 * h * h) + (2 * h * h * m * m) + ((- 2) * m * m * y) + (2 * m * m * y * y) + ((- 2) * x) + (2 * x * x)) < 0)) \/ ((((- 2) + (2 * y)) < 0) /\ (((2 * h * h) + ((- 2) * y) + (2 * y * y)) > 0)) \/ ((((- 2) + (2 * y)) > 0) /\ (((2 * h * h) + ((- 2) * y) + (2 * y * y)) < 0))))).
Proof.
  intros x y h m H.
  assert (Hx : x > 0) by tauto. assert (Hy : y > 0) by tauto.
  assert (HB : 0 < x * y - h * h) by (destruct H as [_ [_ [HB _]]]; lra).
  assert (HD : 0 <= (x - 1) * (y - 1) - h * h) by (destruct H as [_ [_ [_ [HD _]]]]; lra).
  destruct (no_sign_change x y h 1 m Hx Hy HB HD) as [N1 P1].
  destruct (no_sign_change x y h 0 1 Hx Hy HB HD) as [N2 P2].
  cbv zeta in N1, P1, N2, P2.
  repeat match goal with H : _ /\ _ |- _ => destruct H end.
  repeat match goal with H : _ \/ _ |- _ => destruct H end; repeat match goal with H : _ /\ _ |- _ => destruct H end.
  all: first [apply N1 | apply P1 | apply N2 | apply P2]; split; lra.
Qed.

(* atlas.polar.norm/directions.cond-not-prop.E.smt2 *)
Theorem atlas_polar_norm__directions_cond_not_prop_E : forall x y h m : R, ~ (((x > 0) /\ (y > 0) /\ ((((- 1) * h * h) + (x * y)) > 0) /\ ((1 + ((- 1) * h * h) + ((- 1) * x) + (x * y) + ((- 1) * y)) >= 0) /\ (((((- 2) + (4 * h * m) + ((- 2) * m * m) + (2 * m * m * y) + (2 * x)) < 0) /\ ((((- 4) * h * m) + (4 * h * m * x) + (4 * h * m * y) + (2 * h * h) + (2 * h * h * m * m) + ((- 2) * m * m * y) + (2 * m * m * y * y) + ((- 2) * x) + (2 * x * x)) > 0)) \/ ((((- 2) + (4 * h * m) + ((- 2) * m * m) + (2 * m * m * y) + (2 * x)) > 0) /\ ((((- 4) * h * m) + (4 * h * m * x) + (4 * h * m * y) + (2 * h * h) + (2 * h * h * m * m) + ((- 2) * m * m * y) + (2 * m * m * y * y) + ((- 2) * x) + (2 * x * x)) < 0)) \/ ((((- 2) + (2 * y)) < 0) /\ (((2 * h * h) + ((- 2) * y) + (2 * y * y)) > 0)) \/ ((((- 2) + (2 * y)) > 0) /\ (((2 * h * h) + ((- 2) * y) + (2 * y * y)) < 0))))).
Proof.
  intros x y h m H.
  assert (Hx : x > 0) by tauto. assert (Hy : y > 0) by tauto.
  assert (HB : 0 < x * y - h * h) by (destruct H as [_ [_ [HB _]]]; lra).
  assert (HD : 0 <= (x - 1) * (y - 1) - h * h) by (destruct H as [_ [_ [_ [HD _]]]]; lra).
  destruct (no_sign_change x y h 1 m Hx Hy HB HD) as [N1 P1].
  destruct (no_sign_change x y h 0 1 Hx Hy HB HD) as [N2 P2].
  cbv zeta in N1, P1, N2, P2.
  repeat match goal with H : _ /\ _ |- _ => destruct H end.
  repeat match goal with H : _ \/ _ |- _ => destruct H end; repeat match goal with H : _ /\ _ |- _ => destruct H end.
  all: first [apply N1 | apply P1 | apply N2 | apply P2]; split; lra.
Qed.
