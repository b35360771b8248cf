(* L24: the minimiser at t = 1 with the printed and the intended [ACOL00] constraint (LEMMAS.md, L24), under
   L23's hypotheses (a mesh with source positions p, target positions q, the constraint on vertex k). *)
Require Import Reals Lra Psatz List FunctionalExtensionality.
Require Import Affinterp.Defs Affinterp.L10 Affinterp.L23.
Open Scope R_scope.

(* Every homotopy gives A(1) = A: linear, polar R_{t theta}((1 - t) I + t S), SVD R_{t alpha}((1 - t) I + t D)
   R_{t beta}, and exp-log R_{t theta} S^t with S = R_q diag(l1, l2) R_q^T (L10). *)
Theorem L24_linear_at_1 (A : mat) : blend A 1 = A.
Proof. destruct A; unfold blend, madd, mscale, Id2; simpl; f_equal; ring. Qed.

Theorem L24_polar_at_1 (theta : R) (S : mat) : mmul (rot (1 * theta)) (blend S 1) = mmul (rot theta) S.
Proof. rewrite L24_linear_at_1, Rmult_1_l. reflexivity. Qed.

Theorem L24_svd_at_1 (alpha beta : R) (D : mat) :
  mmul (rot (1 * alpha)) (mmul (blend D 1) (rot (1 * beta))) = mmul (rot alpha) (mmul D (rot beta)).
Proof. rewrite L24_linear_at_1, !Rmult_1_l. reflexivity. Qed.

Theorem L24_exp_at_1 (theta q l1 l2 : R) :
  0 < l1 -> 0 < l2 ->
  A_E theta q l1 l2 1 = mmul (rot theta) (mmul (rot q) (mmul (Mat l1 0 0 l2) (transpose (rot q)))).
Proof. intros H1 H2. unfold A_E, S_pow. rewrite !Rpower_1 by assumption. rewrite Rmult_1_l. reflexivity. Qed.

(* A_i, the linear part of the affine map of the triangle onto its target (p_a, p_b, p_c to q_a, q_b, q_c): it
   maps the source edges to the target edges. It is Q_i D_i. *)
Definition linear_part (p q : nat -> vec) (T : tri) (A : mat) : Prop :=
  mvec A (vsub (p (ib T)) (p (ia T))) = vsub (q (ib T)) (q (ia T)) /\
  mvec A (vsub (p (ic T)) (p (ia T))) = vsub (q (ic T)) (q (ia T)).

Theorem L24_linear_part (p q : nat -> vec) (T : tri) (A : mat) :
  is_operator p T -> linear_part p q T A -> A = VD q T.
Proof.
  intros (P1 & P2 & Q1 & Q2 & S1 & S2) [Eb Ec].
  destruct A as [x11 x12 x21 x22]. unfold VD, mvec, vsub in *; simpl in *.
  injection Eb as Eb1 Eb2. injection Ec as Ec1 Ec2.
  set (pa := p (ia T)) in *. set (pb := p (ib T)) in *. set (pc := p (ic T)) in *.
  set (qa := q (ia T)) in *. set (qb := q (ib T)) in *. set (qc := q (ic T)) in *.
  assert (Ha1 : da1 T = - db1 T - dc1 T) by lra. assert (Ha2 : da2 T = - db2 T - dc2 T) by lra.
  rewrite Ha1, Ha2 in *.
  (* q_j = q_a + A (p_j - p_a), and P_hat D = [I; 0] with the edges gives A back *)
  f_equal.
  - replace (v1 qb) with (v1 qa + (x11 * (v1 pb - v1 pa) + x12 * (v2 pb - v2 pa))) by lra.
    replace (v1 qc) with (v1 qa + (x11 * (v1 pc - v1 pa) + x12 * (v2 pc - v2 pa))) by lra.
    transitivity (x11 * (v1 pa * (- db1 T - dc1 T) + v1 pb * db1 T + v1 pc * dc1 T)
                  + x12 * (v2 pa * (- db1 T - dc1 T) + v2 pb * db1 T + v2 pc * dc1 T)); [rewrite P1, Q1; ring | ring].
  - replace (v1 qb) with (v1 qa + (x11 * (v1 pb - v1 pa) + x12 * (v2 pb - v2 pa))) by lra.
    replace (v1 qc) with (v1 qa + (x11 * (v1 pc - v1 pa) + x12 * (v2 pc - v2 pa))) by lra.
    transitivity (x11 * (v1 pa * (- db2 T - dc2 T) + v1 pb * db2 T + v1 pc * dc2 T)
                  + x12 * (v2 pa * (- db2 T - dc2 T) + v2 pb * db2 T + v2 pc * dc2 T)); [rewrite P2, Q2; ring | ring].
  - replace (v2 qb) with (v2 qa + (x21 * (v1 pb - v1 pa) + x22 * (v2 pb - v2 pa))) by lra.
    replace (v2 qc) with (v2 qa + (x21 * (v1 pc - v1 pa) + x22 * (v2 pc - v2 pa))) by lra.
    transitivity (x21 * (v1 pa * (- db1 T - dc1 T) + v1 pb * db1 T + v1 pc * dc1 T)
                  + x22 * (v2 pa * (- db1 T - dc1 T) + v2 pb * db1 T + v2 pc * dc1 T)); [rewrite P1, Q1; ring | ring].
  - replace (v2 qb) with (v2 qa + (x21 * (v1 pb - v1 pa) + x22 * (v2 pb - v2 pa))) by lra.
    replace (v2 qc) with (v2 qa + (x21 * (v1 pc - v1 pa) + x22 * (v2 pc - v2 pa))) by lra.
    transitivity (x21 * (v1 pa * (- db2 T - dc2 T) + v1 pb * db2 T + v1 pc * dc2 T)
                  + x22 * (v2 pa * (- db2 T - dc2 T) + v2 pb * db2 T + v2 pc * dc2 T)); [rewrite P2, Q2; ring | ring].
Qed.

(* The E^F energy at t = 1, A_i(1) = A_i, vanishes at v = Q, and at every translate of Q. *)
Definition translate (v : nat -> vec) (d : vec) : nat -> vec := fun j => Vec (v1 (v j) + v1 d) (v2 (v j) + v2 d).

Lemma VD_translate (p v : nat -> vec) (d : vec) (T : tri) : is_operator p T -> VD (translate v d) T = VD v T.
Proof.
  intros (_ & _ & _ & _ & S1 & S2). unfold VD, translate; simpl. f_equal;
  [transitivity (v1 (v (ia T)) * da1 T + v1 (v (ib T)) * db1 T + v1 (v (ic T)) * dc1 T + v1 d * (da1 T + db1 T + dc1 T))
  | transitivity (v1 (v (ia T)) * da2 T + v1 (v (ib T)) * db2 T + v1 (v (ic T)) * dc2 T + v1 d * (da2 T + db2 T + dc2 T))
  | transitivity (v2 (v (ia T)) * da1 T + v2 (v (ib T)) * db1 T + v2 (v (ic T)) * dc1 T + v2 d * (da1 T + db1 T + dc1 T))
  | transitivity (v2 (v (ia T)) * da2 T + v2 (v (ib T)) * db2 T + v2 (v (ic T)) * dc2 T + v2 d * (da2 T + db2 T + dc2 T))];
  try ring; rewrite ?S1, ?S2; ring.
Qed.

Theorem L24_EF_vanishes (n : nat) (p q : nat -> vec) (tris : list tri) (A : tri -> mat) (d : vec) :
  mesh n p tris -> (forall T, In T tris -> linear_part p q T (A T)) ->
  forall T, In T tris -> frob2 (msub (VD (translate q d) T) (A T)) = 0.
Proof.
  intros M HA T HT. rewrite (VD_translate p q d T (operators _ _ _ M T HT)).
  rewrite <- (L24_linear_part p q T (A T) (operators _ _ _ M T HT) (HA T HT)).
  destruct (A T); unfold frob2, msub; simpl. ring.
Qed.

Lemma energy_nonneg (tris : list tri) (A : tri -> mat) (v : nat -> vec) :
  (forall T, In T tris -> 0 < weight T) -> 0 <= energy tris A v.
Proof.
  induction tris as [| T rest IH]; intros W; unfold energy in *; simpl; [lra |].
  pose proof (W T (or_introl eq_refl)). pose proof (frob2_nonneg (msub (VD v T) (A T))).
  pose proof (IH (fun U H => W U (or_intror H))). nra.
Qed.

Lemma energy_zero (tris : list tri) (A : tri -> mat) (v : nat -> vec) :
  (forall T, In T tris -> frob2 (msub (VD v T) (A T)) = 0) -> energy tris A v = 0.
Proof.
  induction tris as [| T rest IH]; intros Z; unfold energy in *; simpl; [reflexivity |].
  rewrite (Z T (or_introl eq_refl)), IH by (intros U H; apply Z; right; exact H). ring.
Qed.

(* The constraint's point at time t: (1 - t) a + t b. *)
Definition along (a b : vec) (t : R) : vec := Vec ((1 - t) * v1 a + t * v1 b) ((1 - t) * v2 a + t * v2 b).

(* A translate of Q at whose vertex k the constraint vanishes is the unique minimiser at t = 1. *)
Lemma translate_minimiser (n : nat) (p q : nat -> vec) (tris : list tri) (A : tri -> mat) (k : nat) (u d : vec) :
  mesh n p tris -> (k < n)%nat -> (forall T, In T tris -> linear_part p q T (A T)) ->
  translate q d k = u ->
  let F := pinned tris A k 1 u in
  (forall x, F (translate q d) <= F x) /\
  (forall v, (forall x, F v <= F x) -> forall j, (j < n)%nat -> v j = translate q d j).
Proof.
  intros M Hk HA Hu F.
  assert (F0 : F (translate q d) = 0).
  { unfold F, pinned. rewrite (energy_zero tris A _ (L24_EF_vanishes n p q tris A d M HA)), Hu.
    unfold norm2, vsub; simpl. ring. }
  assert (Fmin : forall x, F (translate q d) <= F x).
  { intros x. rewrite F0. unfold F, pinned.
    pose proof (energy_nonneg tris A x (positive_weights _ _ _ M)).
    assert (0 <= norm2 (vsub (x k) u)) by (unfold norm2; nra). lra. }
  split; [exact Fmin |].
  intros v Hv. apply (L23_unique_minimiser n p tris A k 1 u v (translate q d) M Hk ltac:(lra) Hv Fmin).
Qed.

(* With the intended constraint ||(1 - t) p_k + t q_k - v_k(t)||^2 the unique minimiser at t = 1 is Q. *)
Theorem L24_intended (n : nat) (p q : nat -> vec) (tris : list tri) (A : tri -> mat) (k : nat) :
  mesh n p tris -> (k < n)%nat -> (forall T, In T tris -> linear_part p q T (A T)) ->
  let F := pinned tris A k 1 (along (p k) (q k) 1) in
  (forall x, F q <= F x) /\ (forall v, (forall x, F v <= F x) -> forall j, (j < n)%nat -> v j = q j).
Proof.
  intros M Hk HA F.
  assert (Eq : translate q (Vec 0 0) = q) by (extensionality j; unfold translate; destruct (q j); simpl; f_equal; ring).
  rewrite <- Eq. apply (translate_minimiser n p q tris A k); try assumption.
  unfold translate, along; simpl. destruct (q k), (p k); simpl. f_equal; ring.
Qed.

(* With the printed ||(1 - t) p_k + t p_k - v_k(t)||^2 it is Q + (p_k - q_k) 1^T, which is not Q when
   p_k <> q_k. *)
Theorem L24_printed (n : nat) (p q : nat -> vec) (tris : list tri) (A : tri -> mat) (k : nat) :
  mesh n p tris -> (k < n)%nat -> (forall T, In T tris -> linear_part p q T (A T)) ->
  let F := pinned tris A k 1 (along (p k) (p k) 1) in
  let Q' := translate q (vsub (p k) (q k)) in
  (forall x, F Q' <= F x) /\ (forall v, (forall x, F v <= F x) -> forall j, (j < n)%nat -> v j = Q' j) /\
  (p k <> q k -> Q' k <> q k).
Proof.
  intros M Hk HA F Q'.
  destruct (translate_minimiser n p q tris A k (along (p k) (p k) 1) (vsub (p k) (q k)) M Hk HA) as [H1 H2].
  - unfold translate, along, vsub; simpl. destruct (q k), (p k); simpl. f_equal; ring.
  - split; [exact H1 | split; [exact H2 |]].
    intros Hpq E. apply Hpq. unfold Q', translate, vsub in E. destruct (p k) as [a b], (q k) as [c d].
    simpl in E. injection E as E1 E2. f_equal; lra.
Qed.
