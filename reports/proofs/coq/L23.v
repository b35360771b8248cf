(* L23: the E^F system's kernel is the translations, on a connected mesh (LEMMAS.md, L23).
   A mesh has the vertices 0, ..., n - 1, each a corner of some triangle, and a list of triangles; a triangle
   carries its corners a, b, c, its weight w and its operator D (3 x 2, rows a, b, c). Vertex positions are
   functions nat -> vec; V D is the 2 x 2 matrix of the triangle's positions V (2 x 3) times D. *)
Require Import Reals Lra Psatz List.
Require Import Affinterp.Defs.
Import ListNotations.
Open Scope R_scope.

Record tri := Tri {
  ia : nat; ib : nat; ic : nat; weight : R;
  da1 : R; da2 : R; db1 : R; db2 : R; dc1 : R; dc2 : R }.

Definition corner (k : nat) (T : tri) : Prop := k = ia T \/ k = ib T \/ k = ic T.

(* P_hat = [[pa_x, pb_x, pc_x], [pa_y, pb_y, pc_y], [1, 1, 1]] of the source positions p. *)
Definition nondegenerate (p : nat -> vec) (T : tri) : Prop :=
  (v1 (p (ib T)) - v1 (p (ia T))) * (v2 (p (ic T)) - v2 (p (ia T)))
  - (v1 (p (ic T)) - v1 (p (ia T))) * (v2 (p (ib T)) - v2 (p (ia T))) <> 0.

(* P_hat D = [I; 0]. *)
Definition is_operator (p : nat -> vec) (T : tri) : Prop :=
  v1 (p (ia T)) * da1 T + v1 (p (ib T)) * db1 T + v1 (p (ic T)) * dc1 T = 1 /\
  v1 (p (ia T)) * da2 T + v1 (p (ib T)) * db2 T + v1 (p (ic T)) * dc2 T = 0 /\
  v2 (p (ia T)) * da1 T + v2 (p (ib T)) * db1 T + v2 (p (ic T)) * dc1 T = 0 /\
  v2 (p (ia T)) * da2 T + v2 (p (ib T)) * db2 T + v2 (p (ic T)) * dc2 T = 1 /\
  da1 T + db1 T + dc1 T = 0 /\ da2 T + db2 T + dc2 T = 0.

(* V D for the positions v. *)
Definition VD (v : nat -> vec) (T : tri) : mat :=
  Mat (v1 (v (ia T)) * da1 T + v1 (v (ib T)) * db1 T + v1 (v (ic T)) * dc1 T)
      (v1 (v (ia T)) * da2 T + v1 (v (ib T)) * db2 T + v1 (v (ic T)) * dc2 T)
      (v2 (v (ia T)) * da1 T + v2 (v (ib T)) * db1 T + v2 (v (ic T)) * dc1 T)
      (v2 (v (ia T)) * da2 T + v2 (v (ib T)) * db2 T + v2 (v (ic T)) * dc2 T).

Definition frob2 (M : mat) : R := m11 M ^ 2 + m12 M ^ 2 + m21 M ^ 2 + m22 M ^ 2.

(* v^T G v = sum_i w_i ||V_i D_i||_F^2. *)
Definition form (tris : list tri) (v : nat -> vec) : R :=
  fold_right (fun T acc => weight T * frob2 (VD v T) + acc) 0 tris.

(* Any two triangles are joined by a chain of triangles of the mesh, each sharing a vertex with the next. *)
Inductive chain (tris : list tri) : tri -> tri -> Prop :=
  | chain_refl T : In T tris -> chain tris T T
  | chain_step T U W : chain tris T U -> In W tris -> (exists k, corner k U /\ corner k W) -> chain tris T W.

Record mesh (n : nat) (p : nat -> vec) (tris : list tri) : Prop := {
  corners_are_vertices : forall T k, In T tris -> corner k T -> (k < n)%nat;
  vertices_are_corners : forall k, (k < n)%nat -> exists T, In T tris /\ corner k T;
  positive_weights : forall T, In T tris -> 0 < weight T;
  nondegenerate_source : forall T, In T tris -> nondegenerate p T;
  operators : forall T, In T tris -> is_operator p T;
  connected : forall T U, In T tris -> In U tris -> chain tris T U }.

Lemma chain_last (tris : list tri) (T U : tri) : chain tris T U -> In U tris.
Proof. intros C; destruct C; assumption. Qed.

(* One triangle: V D = 0 iff its three corners coincide (1^T D = 0, and D has rank 2). *)
Lemma row_kernel (pa pb pc xa xb xc d1 d2 d3 e1 e2 e3 qa qb qc : R) :
  pa * d1 + pb * d2 + pc * d3 = 1 -> pa * e1 + pb * e2 + pc * e3 = 0 ->
  qa * d1 + qb * d2 + qc * d3 = 0 -> qa * e1 + qb * e2 + qc * e3 = 1 ->
  d1 + d2 + d3 = 0 -> e1 + e2 + e3 = 0 ->
  xa * d1 + xb * d2 + xc * d3 = 0 -> xa * e1 + xb * e2 + xc * e3 = 0 -> xb = xa /\ xc = xa.
Proof.
  intros P1 P2 Q1 Q2 S1 S2 X1 X2.
  assert (Hd1 : d1 = - d2 - d3) by lra. assert (He1 : e1 = - e2 - e3) by lra. subst d1 e1.
  (* E M = I with E the edge matrix and M = [[d2, e2], [d3, e3]]: det E det M = 1 *)
  assert (Hdet : ((pb - pa) * (qc - qa) - (pc - pa) * (qb - qa)) * (d2 * e3 - e2 * d3) = 1).
  { transitivity (((pb - pa) * d2 + (pc - pa) * d3) * ((qb - qa) * e2 + (qc - qa) * e3)
                  - ((pb - pa) * e2 + (pc - pa) * e3) * ((qb - qa) * d2 + (qc - qa) * d3)); [ring |].
    replace ((pb - pa) * d2 + (pc - pa) * d3) with 1 by lra.
    replace ((qb - qa) * e2 + (qc - qa) * e3) with 1 by lra.
    replace ((pb - pa) * e2 + (pc - pa) * e3) with 0 by lra. ring. }
  assert (HM : d2 * e3 - e2 * d3 <> 0) by (intros E; rewrite E in Hdet; lra).
  assert (B : (xb - xa) * (d2 * e3 - e2 * d3) = 0).
  { transitivity (e3 * (xa * (- d2 - d3) + xb * d2 + xc * d3) - d3 * (xa * (- e2 - e3) + xb * e2 + xc * e3));
      [ring | rewrite X1, X2; ring]. }
  assert (C : (xc - xa) * (d2 * e3 - e2 * d3) = 0).
  { transitivity (d2 * (xa * (- e2 - e3) + xb * e2 + xc * e3) - e2 * (xa * (- d2 - d3) + xb * d2 + xc * d3));
      [ring | rewrite X1, X2; ring]. }
  apply Rmult_integral in B. apply Rmult_integral in C. destruct B, C; split; lra.
Qed.

Lemma triangle_kernel (p v : nat -> vec) (T : tri) :
  is_operator p T -> (VD v T = Mat 0 0 0 0 <-> v (ib T) = v (ia T) /\ v (ic T) = v (ia T)).
Proof.
  intros (P1 & P2 & Q1 & Q2 & S1 & S2). split.
  - intros E. unfold VD in E. injection E as X1 X2 Y1 Y2.
    destruct (row_kernel _ _ _ _ _ _ _ _ _ _ _ _ _ _ _ P1 P2 Q1 Q2 S1 S2 X1 X2) as [Xb Xc].
    destruct (row_kernel _ _ _ _ _ _ _ _ _ _ _ _ _ _ _ P1 P2 Q1 Q2 S1 S2 Y1 Y2) as [Yb Yc].
    destruct (v (ia T)), (v (ib T)), (v (ic T)); simpl in *; subst; split; reflexivity.
  - intros [Eb Ec]. unfold VD. rewrite Eb, Ec.
    f_equal; [transitivity (v1 (v (ia T)) * (da1 T + db1 T + dc1 T)) | transitivity (v1 (v (ia T)) * (da2 T + db2 T + dc2 T))
      | transitivity (v2 (v (ia T)) * (da1 T + db1 T + dc1 T)) | transitivity (v2 (v (ia T)) * (da2 T + db2 T + dc2 T))];
      try ring; rewrite ?S1, ?S2; ring.
Qed.

Lemma frob2_nonneg (M : mat) : 0 <= frob2 M.
Proof. unfold frob2. pose proof (pow2_ge_0 (m11 M)). pose proof (pow2_ge_0 (m12 M)).
  pose proof (pow2_ge_0 (m21 M)). pose proof (pow2_ge_0 (m22 M)). lra. Qed.

Lemma frob2_zero (M : mat) : frob2 M = 0 -> M = Mat 0 0 0 0.
Proof.
  destruct M as [a b c d]. unfold frob2; simpl. intros E.
  pose proof (pow2_ge_0 a). pose proof (pow2_ge_0 b). pose proof (pow2_ge_0 c). pose proof (pow2_ge_0 d).
  assert (a ^ 2 = 0 /\ b ^ 2 = 0 /\ c ^ 2 = 0 /\ d ^ 2 = 0) as (A & B & C & D) by lra.
  assert (a = 0) by nra. assert (b = 0) by nra. assert (c = 0) by nra. assert (d = 0) by nra.
  subst. reflexivity.
Qed.

Theorem L23_form_nonneg (tris : list tri) (v : nat -> vec) :
  (forall T, In T tris -> 0 < weight T) -> 0 <= form tris v.
Proof.
  induction tris as [| T rest IH]; intros W; simpl; [lra |].
  pose proof (W T (or_introl eq_refl)). pose proof (frob2_nonneg (VD v T)).
  pose proof (IH (fun U H => W U (or_intror H))). nra.
Qed.

(* The sum of non-negative terms vanishes iff every term does. *)
Lemma form_zero (tris : list tri) (v : nat -> vec) :
  (forall T, In T tris -> 0 < weight T) ->
  (form tris v = 0 <-> forall T, In T tris -> VD v T = Mat 0 0 0 0).
Proof.
  induction tris as [| T rest IH]; intros W; simpl.
  - split; [intros _ U [] | reflexivity].
  - pose proof (W T (or_introl eq_refl)) as WT. pose proof (frob2_nonneg (VD v T)) as F.
    assert (Wr : forall U, In U rest -> 0 < weight U) by (intros U HU; apply W; right; exact HU).
    pose proof (L23_form_nonneg rest v Wr) as R. split.
    + intros E U [<- | HU].
      * apply frob2_zero. nra.
      * apply (proj1 (IH Wr)); [nra | exact HU].
    + intros HZ. rewrite (proj2 (IH Wr) (fun U HU => HZ U (or_intror HU))).
      rewrite (HZ T (or_introl eq_refl)). unfold frob2; simpl. ring.
Qed.

Theorem L23_kernel (n : nat) (p : nat -> vec) (tris : list tri) (v : nat -> vec) :
  mesh n p tris -> (form tris v = 0 <-> exists c, forall k, (k < n)%nat -> v k = c).
Proof.
  intros M. rewrite (form_zero tris v (positive_weights _ _ _ M)). split.
  - intros H.
    assert (Hc : forall T k, In T tris -> corner k T -> v k = v (ia T)).
    { intros T k HT [-> | [-> | ->]]; [reflexivity | |];
        apply (proj1 (triangle_kernel p v T (operators _ _ _ M T HT))); apply H; exact HT. }
    assert (Hchain : forall T U, chain tris T U -> v (ia T) = v (ia U)).
    { intros T U C. induction C as [T _ | T U W C IH HW [k [Hk1 Hk2]]]; [reflexivity |].
      rewrite IH, <- (Hc U k (chain_last _ _ _ C) Hk1). apply (Hc W k HW Hk2). }
    exists (v 0%nat). intros k Hk.
    destruct (vertices_are_corners _ _ _ M k Hk) as [T [HT Hk']].
    destruct (vertices_are_corners _ _ _ M 0%nat ltac:(lia)) as [T0 [HT0 H0]].
    rewrite (Hc T k HT Hk'), (Hc T0 0%nat HT0 H0).
    apply Hchain, (connected _ _ _ M); assumption.
  - intros [c Hc] T HT. apply (triangle_kernel p v T (operators _ _ _ M T HT)).
    assert (forall k, corner k T -> v k = c) by (intros k Hk; apply Hc, (corners_are_vertices _ _ _ M T k HT Hk)).
    rewrite !H by (unfold corner; tauto). split; reflexivity.
Qed.

(* The pinned energy: sum_i w_i E^F_i with E^F_i = ||V_i D_i - A_i||_F^2 for any targets A_i (one matrix per
   triangle, at any time t), plus c_k ||v_k - u||^2, c_k > 0. *)
Definition msub (A B : mat) : mat := Mat (m11 A - m11 B) (m12 A - m12 B) (m21 A - m21 B) (m22 A - m22 B).
Definition vsub (a b : vec) : vec := Vec (v1 a - v1 b) (v2 a - v2 b).

Definition energy (tris : list tri) (A : tri -> mat) (v : nat -> vec) : R :=
  fold_right (fun T acc => weight T * frob2 (msub (VD v T) (A T)) + acc) 0 tris.

Definition pinned (tris : list tri) (A : tri -> mat) (k : nat) (ck : R) (u : vec) (v : nat -> vec) : R :=
  energy tris A v + ck * norm2 (vsub (v k) u).

Definition midpoint (v w : nat -> vec) : nat -> vec :=
  fun j => Vec ((v1 (v j) + v1 (w j)) / 2) ((v2 (v j) + v2 (w j)) / 2).
Definition difference (v w : nat -> vec) : nat -> vec := fun j => vsub (v j) (w j).

Lemma energy_midpoint (tris : list tri) (A : tri -> mat) (v w : nat -> vec) :
  energy tris A (midpoint v w) = (energy tris A v + energy tris A w) / 2 - form tris (difference v w) / 4.
Proof.
  induction tris as [| T rest IH]; unfold energy, form in *; simpl; [field |].
  rewrite IH. unfold frob2, msub, VD, midpoint, difference, vsub; simpl. field.
Qed.

(* The form is positive definite on differences once pinned: it vanishes only where delta = 0. *)
Theorem L23_pin_definite (n : nat) (p : nat -> vec) (tris : list tri) (k : nat) (ck : R) (delta : nat -> vec) :
  mesh n p tris -> (k < n)%nat -> 0 < ck ->
  0 <= form tris delta + ck * norm2 (delta k) /\
  (form tris delta + ck * norm2 (delta k) = 0 -> forall j, (j < n)%nat -> delta j = Vec 0 0).
Proof.
  intros M Hk Hck.
  pose proof (L23_form_nonneg tris delta (positive_weights _ _ _ M)) as F.
  assert (N : 0 <= norm2 (delta k)) by (unfold norm2; nra).
  split; [nra |]. intros E j Hj.
  assert (F0 : form tris delta = 0) by nra.
  assert (N0 : norm2 (delta k) = 0) by nra.
  destruct (proj1 (L23_kernel n p tris delta M) F0) as [c Hc].
  assert (Hc0 : c = Vec 0 0).
  { rewrite <- (Hc k Hk). destruct (delta k) as [a b]. unfold norm2 in N0; simpl in N0.
    assert (a = 0) by nra. assert (b = 0) by nra. subst. reflexivity. }
  rewrite Hc by exact Hj. exact Hc0.
Qed.

(* So the minimiser of the pinned energy is unique (on the vertices 0, ..., n - 1). *)
Theorem L23_unique_minimiser (n : nat) (p : nat -> vec) (tris : list tri) (A : tri -> mat) (k : nat) (ck : R)
  (u : vec) (v w : nat -> vec) :
  mesh n p tris -> (k < n)%nat -> 0 < ck ->
  (forall x, pinned tris A k ck u v <= pinned tris A k ck u x) ->
  (forall x, pinned tris A k ck u w <= pinned tris A k ck u x) ->
  forall j, (j < n)%nat -> v j = w j.
Proof.
  intros M Hk Hck Hv Hw j Hj.
  pose proof (Hv w). pose proof (Hw v). pose proof (Hv (midpoint v w)) as Hm.
  unfold pinned in *. rewrite energy_midpoint in Hm.
  assert (Hpin : norm2 (vsub (midpoint v w k) u)
                 = (norm2 (vsub (v k) u) + norm2 (vsub (w k) u)) / 2 - norm2 (difference v w k) / 4)
    by (unfold norm2, vsub, midpoint, difference, vsub; simpl; field).
  rewrite Hpin in Hm.
  destruct (L23_pin_definite n p tris k ck (difference v w) M Hk Hck) as [Pos Zero].
  assert (E : form tris (difference v w) + ck * norm2 (difference v w k) = 0) by nra.
  pose proof (Zero E j Hj) as D. unfold difference, vsub in D.
  destruct (v j) as [a b], (w j) as [c d]; simpl in D. injection D as D1 D2. f_equal; lra.
Qed.
