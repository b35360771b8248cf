(* The level-E directions sentences of thesis.thm-2.2.5 and atlas.polar.norm, both ways, for a symmetric
   positive definite B = [[x, h], [h, y]], N = B - I, q(t) = ||((1 - t) I + t B) v||^2, so that q'(0)/2 = v^T N v
   and q'(1)/2 = v^T (N^2 + N) v:
   - cond-not-prop.E: with det N >= 0 the two are never of opposite strict signs. No tactic closed the sentences
     whole (MANIFEST.json); lemma no_sign_change supplies the step they miss: when N <= 0,
     det(B) v^T (N^2 + N) v = u^T adj(B) N u with u = B v, and adj(B) N <= 0 (L8 (b)).
   - prop-not-cond.E (a sentence with an inner "for all m"): with det N < 0 some direction has q'(0) < 0 < q'(1);
     lemma sign_change_exists moves a root v0 of v^T N v along -N v0 by an explicit small step (L9's small_eps),
     and the witness m is its slope.
   Each theorem states its stored sentence exactly as checks/proofs/smt2_to_coq.py reads it. *)
Require Import Reals Psatz Lra.
Require Import Affinterp.Defs Affinterp.Small Affinterp.L8 Affinterp.L9.
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

(* ---- prop-not-cond.E: if det(B - I) < 0, some direction has q'(0) < 0 < q'(1). ---- *)

Definition qN (x y h a b : R) : R := (x - 1) * a ^ 2 + 2 * h * a * b + (y - 1) * b ^ 2.
Definition rN (x y h a b : R) : R :=
  ((x - 1) ^ 2 + h ^ 2 + (x - 1)) * a ^ 2 + 2 * h * (x + y - 1) * a * b + (h ^ 2 + (y - 1) ^ 2 + (y - 1)) * b ^ 2.

(* A root v0 of the indefinite q, moved along -N v0: q < 0 while r, which is -det(N) ||v0||^2 > 0 at v0, stays > 0. *)
Lemma sign_change_exists (x y h : R) :
  (x - 1) * (y - 1) - h * h < 0 -> exists a b, qN x y h a b < 0 /\ 0 < rN x y h a b.
Proof.
  intros HD. set (D := (x - 1) * (y - 1) - h * h) in HD.
  assert (Hr : forall a b, rN x y h a b = (x + y - 1) * qN x y h a b - D * (a ^ 2 + b ^ 2))
    by (intros; unfold rN, qN, D; ring).
  assert (Hv0 : exists a0 b0, qN x y h a0 b0 = 0 /\ 0 < a0 ^ 2 + b0 ^ 2).
  { destruct (Req_dec (x - 1) 0) as [E | E].
    - exists 1, 0. unfold qN. rewrite E. split; [ring | lra].
    - set (s := sqrt (- D)). assert (Hs : s * s = - D) by (apply sqrt_sqrt; lra).
      exists (- h + s), (x - 1). split.
      + unfold qN. transitivity ((x - 1) * (s * s + D)); [unfold D; ring | rewrite Hs; ring].
      + assert (0 < (x - 1) ^ 2) by (rewrite <- Rsqr_pow2; apply Rsqr_pos_lt, E).
        pose proof (pow2_ge_0 (- h + s)). lra. }
  destruct Hv0 as [a0 [b0 [Hq0 Hn0]]].
  set (e1 := - ((x - 1) * a0 + h * b0)). set (e2 := - (h * a0 + (y - 1) * b0)).
  assert (HNv : 0 < e1 ^ 2 + e2 ^ 2).
  { (* N v0 <> 0: det N <> 0 and v0 <> 0 *)
    destruct (Rle_or_lt (e1 ^ 2 + e2 ^ 2) 0) as [H0 | H0]; [exfalso | exact H0].
    pose proof (pow2_ge_0 e1). pose proof (pow2_ge_0 e2).
    assert (e1 ^ 2 = 0) by lra. assert (e2 ^ 2 = 0) by lra.
    assert (E1 : e1 = 0) by (apply Rsqr_eq_0; rewrite Rsqr_pow2; assumption).
    assert (E2 : e2 = 0) by (apply Rsqr_eq_0; rewrite Rsqr_pow2; assumption).
    assert (Ea : D * a0 = 0).
    { transitivity ((y - 1) * (- e1) - h * (- e2)); [unfold e1, e2, D; ring | rewrite E1, E2; ring]. }
    assert (Eb : D * b0 = 0).
    { transitivity ((x - 1) * (- e2) - h * (- e1)); [unfold e1, e2, D; ring | rewrite E1, E2; ring]. }
    apply Rmult_integral in Ea. apply Rmult_integral in Eb.
    destruct Ea as [Ea | Ea]; [lra |]. destruct Eb as [Eb | Eb]; [lra |].
    subst a0 b0. lra. }
  set (W := Mat (x - 1) h h (y - 1)).
  set (R2 := Mat ((x - 1) ^ 2 + h ^ 2 + (x - 1)) (h * (x + y - 1)) (h * (x + y - 1)) (h ^ 2 + (y - 1) ^ 2 + (y - 1))).
  assert (EqW : forall a b, qN x y h a b = qform W (Vec a b)) by (intros; unfold qN, qform, W; simpl; ring).
  assert (EqR : forall a b, rN x y h a b = qform R2 (Vec a b)) by (intros; unfold rN, qform, R2; simpl; ring).
  assert (Hbil : bil W (Vec a0 b0) (Vec e1 e2) = - 2 * (e1 ^ 2 + e2 ^ 2)) by (unfold bil, W, e1, e2; simpl; ring).
  assert (Hc : 0 < qform R2 (Vec a0 b0)).
  { rewrite <- EqR, Hr, Hq0. nra. }
  destruct (small_eps (- 2 * (e1 ^ 2 + e2 ^ 2)) (qform W (Vec e1 e2)) (qform R2 (Vec a0 b0))
              (bil R2 (Vec a0 b0) (Vec e1 e2)) (qform R2 (Vec e1 e2)) ltac:(lra) Hc) as [eps [He [H1 H2]]].
  exists (a0 + eps * e1), (b0 + eps * e2). rewrite EqW, EqR.
  pose proof (qform_expand W (Vec a0 b0) (Vec e1 e2) eps) as XW. cbn [v1 v2] in XW.
  pose proof (qform_expand R2 (Vec a0 b0) (Vec e1 e2) eps) as XR. cbn [v1 v2] in XR.
  rewrite XW, XR, Hbil, <- EqW, Hq0. split; lra.
Qed.

(* thesis.thm-2.2.5/printed.directions.prop-not-cond.E.smt2 *)
Theorem thesis_thm_2_2_5__printed_directions_prop_not_cond_E : forall x y h : R, ~ ((forall m : R, ((x > 0) /\ (y > 0) /\ ((((- 1) * h * h) + (x * y)) > 0) /\ (((1 + ((- 1) * h * h) + ((- 1) * x) + (x * y) + ((- 1) * y)) < 0) \/ ((((- 2) + x + y) < 0) /\ ((x <= 0) \/ (((- 1) + x) > 0) \/ (y <= 0) \/ (((- 1) + y) > 0)))) /\ ((((- 2) + (4 * h * m) + ((- 2) * m * m) + (2 * m * m * y) + (2 * x)) >= 0) \/ ((((- 4) * h * m) + (4 * h * m * x) + (4 * h * m * y) + (2 * h * h) + (2 * h * h * m * m) + ((- 2) * m * m * y) + (2 * m * m * y * y) + ((- 2) * x) + (2 * x * x)) <= 0)) /\ ((((- 2) + (4 * h * m) + ((- 2) * m * m) + (2 * m * m * y) + (2 * x)) <= 0) \/ ((((- 4) * h * m) + (4 * h * m * x) + (4 * h * m * y) + (2 * h * h) + (2 * h * h * m * m) + ((- 2) * m * m * y) + (2 * m * m * y * y) + ((- 2) * x) + (2 * x * x)) >= 0)) /\ ((((- 2) + (2 * y)) >= 0) \/ (((2 * h * h) + ((- 2) * y) + (2 * y * y)) <= 0)) /\ ((((- 2) + (2 * y)) <= 0) \/ (((2 * h * h) + ((- 2) * y) + (2 * y * y)) >= 0))))).
Proof.
  intros x y h H. pose proof (H 0) as [Hx [Hy [HB [C _]]]].
  assert (HD : (x - 1) * (y - 1) - h * h < 0).
  { destruct (Rlt_or_le ((x - 1) * (y - 1) - h * h) 0) as [| HD]; [assumption | exfalso].
    assert (0 <= h * h) by nra.
    repeat match goal with Hd : _ \/ _ |- _ => destruct Hd end;
      repeat match goal with Hd : _ /\ _ |- _ => destruct Hd end; nra. }
  destruct (sign_change_exists x y h HD) as [a [b [Hq Hr]]].
  destruct (Req_dec a 0) as [-> | Ha].
  - assert (Hb : 0 < b ^ 2) by (destruct (Req_dec b 0) as [-> | Hb];
      [unfold qN in Hq; lra | rewrite <- Rsqr_pow2; apply Rsqr_pos_lt, Hb]).
    assert (Hq1 : y - 1 < 0).
    { unfold qN in Hq. destruct (Rle_or_lt 0 (y - 1)); [| assumption].
      assert (0 <= (y - 1) * b ^ 2) by (apply Rmult_le_pos; lra). lra. }
    assert (Hr1 : 0 < h ^ 2 + (y - 1) ^ 2 + (y - 1)).
    { unfold rN in Hr. destruct (Rle_or_lt (h ^ 2 + (y - 1) ^ 2 + (y - 1)) 0); [| assumption].
      assert (0 <= - (h ^ 2 + (y - 1) ^ 2 + (y - 1)) * b ^ 2) by (apply Rmult_le_pos; lra). lra. }
    pose proof (H 0) as H0. repeat match goal with Hd : _ /\ _ |- _ => destruct Hd end.
    repeat match goal with Hd : _ \/ _ |- _ => destruct Hd end; lra.
  - set (m := b / a).
    assert (Ha2 : 0 < a ^ 2) by (rewrite <- Rsqr_pow2; apply Rsqr_pos_lt, Ha).
    assert (Eq : qN x y h 1 m * a ^ 2 = qN x y h a b) by (unfold qN, m; field; exact Ha).
    assert (Er : rN x y h 1 m * a ^ 2 = rN x y h a b) by (unfold rN, m; field; exact Ha).
    assert (Hq1 : qN x y h 1 m < 0).
    { destruct (Rle_or_lt 0 (qN x y h 1 m)); [| assumption].
      assert (0 <= qN x y h 1 m * a ^ 2) by (apply Rmult_le_pos; lra). lra. }
    assert (Hr1 : 0 < rN x y h 1 m).
    { destruct (Rle_or_lt (rN x y h 1 m) 0); [| assumption].
      assert (0 <= - rN x y h 1 m * a ^ 2) by (apply Rmult_le_pos; lra). lra. }
    unfold qN, rN in Hq1, Hr1.
    pose proof (H m) as Hm. repeat match goal with Hd : _ /\ _ |- _ => destruct Hd end.
    repeat match goal with Hd : _ \/ _ |- _ => destruct Hd end; lra.
Qed.

(* atlas.polar.norm/directions.prop-not-cond.E.smt2 *)
Theorem atlas_polar_norm__directions_prop_not_cond_E : forall x y h : R, ~ ((forall m : R, ((x > 0) /\ (y > 0) /\ ((((- 1) * h * h) + (x * y)) > 0) /\ ((1 + ((- 1) * h * h) + ((- 1) * x) + (x * y) + ((- 1) * y)) < 0) /\ ((((- 2) + (4 * h * m) + ((- 2) * m * m) + (2 * m * m * y) + (2 * x)) >= 0) \/ ((((- 4) * h * m) + (4 * h * m * x) + (4 * h * m * y) + (2 * h * h) + (2 * h * h * m * m) + ((- 2) * m * m * y) + (2 * m * m * y * y) + ((- 2) * x) + (2 * x * x)) <= 0)) /\ ((((- 2) + (4 * h * m) + ((- 2) * m * m) + (2 * m * m * y) + (2 * x)) <= 0) \/ ((((- 4) * h * m) + (4 * h * m * x) + (4 * h * m * y) + (2 * h * h) + (2 * h * h * m * m) + ((- 2) * m * m * y) + (2 * m * m * y * y) + ((- 2) * x) + (2 * x * x)) >= 0)) /\ ((((- 2) + (2 * y)) >= 0) \/ (((2 * h * h) + ((- 2) * y) + (2 * y * y)) <= 0)) /\ ((((- 2) + (2 * y)) <= 0) \/ (((2 * h * h) + ((- 2) * y) + (2 * y * y)) >= 0))))).
Proof.
  intros x y h H. pose proof (H 0) as [Hx [Hy [HB [C _]]]].
  assert (HD : (x - 1) * (y - 1) - h * h < 0).
  { destruct (Rlt_or_le ((x - 1) * (y - 1) - h * h) 0) as [| HD]; [assumption | exfalso].
    assert (0 <= h * h) by nra.
    repeat match goal with Hd : _ \/ _ |- _ => destruct Hd end;
      repeat match goal with Hd : _ /\ _ |- _ => destruct Hd end; nra. }
  destruct (sign_change_exists x y h HD) as [a [b [Hq Hr]]].
  destruct (Req_dec a 0) as [-> | Ha].
  - assert (Hb : 0 < b ^ 2) by (destruct (Req_dec b 0) as [-> | Hb];
      [unfold qN in Hq; lra | rewrite <- Rsqr_pow2; apply Rsqr_pos_lt, Hb]).
    assert (Hq1 : y - 1 < 0).
    { unfold qN in Hq. destruct (Rle_or_lt 0 (y - 1)); [| assumption].
      assert (0 <= (y - 1) * b ^ 2) by (apply Rmult_le_pos; lra). lra. }
    assert (Hr1 : 0 < h ^ 2 + (y - 1) ^ 2 + (y - 1)).
    { unfold rN in Hr. destruct (Rle_or_lt (h ^ 2 + (y - 1) ^ 2 + (y - 1)) 0); [| assumption].
      assert (0 <= - (h ^ 2 + (y - 1) ^ 2 + (y - 1)) * b ^ 2) by (apply Rmult_le_pos; lra). lra. }
    pose proof (H 0) as H0. repeat match goal with Hd : _ /\ _ |- _ => destruct Hd end.
    repeat match goal with Hd : _ \/ _ |- _ => destruct Hd end; lra.
  - set (m := b / a).
    assert (Ha2 : 0 < a ^ 2) by (rewrite <- Rsqr_pow2; apply Rsqr_pos_lt, Ha).
    assert (Eq : qN x y h 1 m * a ^ 2 = qN x y h a b) by (unfold qN, m; field; exact Ha).
    assert (Er : rN x y h 1 m * a ^ 2 = rN x y h a b) by (unfold rN, m; field; exact Ha).
    assert (Hq1 : qN x y h 1 m < 0).
    { destruct (Rle_or_lt 0 (qN x y h 1 m)); [| assumption].
      assert (0 <= qN x y h 1 m * a ^ 2) by (apply Rmult_le_pos; lra). lra. }
    assert (Hr1 : 0 < rN x y h 1 m).
    { destruct (Rle_or_lt (rN x y h 1 m) 0); [| assumption].
      assert (0 <= - rN x y h 1 m * a ^ 2) by (apply Rmult_le_pos; lra). lra. }
    unfold qN, rN in Hq1, Hr1.
    pose proof (H m) as Hm. repeat match goal with Hd : _ /\ _ |- _ => destruct Hd end.
    repeat match goal with Hd : _ \/ _ |- _ => destruct Hd end; lra.
Qed.
