(* L9: the SVD homotopy A_s(t) = R_{t alpha} ((1 - t) I + t D) R_{t beta}, D = diag(x, y), is good for norm
   iff G(t) >= 0 on [0, 1] (LEMMAS.md, L9). *)
Require Import Reals Lra Psatz.
From Coquelicot Require Import Coquelicot.
Require Import Affinterp.Defs Affinterp.Small Affinterp.L1 Affinterp.L4 Affinterp.L5 Affinterp.L6 Affinterp.L7 Affinterp.L8.
Open Scope R_scope.

Definition A_s (x y alpha beta : R) (t : R) : mat :=
  mmul (rot (t * alpha)) (mmul (blend (Mat x 0 0 y) t) (rot (t * beta))).

(* G_t = [[m1 a, beta (b^2 - a^2) / 2], [beta (b^2 - a^2) / 2, m2 b]], a = 1 + t m1, b = 1 + t m2. *)
Definition G_mat (x y beta t : R) : mat :=
  let m1 := x - 1 in let m2 := y - 1 in let a := 1 + t * m1 in let b := 1 + t * m2 in
  Mat (m1 * a) (beta * (b ^ 2 - a ^ 2) / 2) (beta * (b ^ 2 - a ^ 2) / 2) (m2 * b).

Definition G (x y beta t : R) : R :=
  4 * (x - 1) * (y - 1) * (1 + t * (x - 1)) * (1 + t * (y - 1))
  - beta ^ 2 * t ^ 2 * (x - y) ^ 2 * (2 + t * (x + y - 2)) ^ 2.

(* Identity L9.G-is-4-det. *)
Theorem L9_G_is_4_det (x y beta t : R) : 4 * det (G_mat x y beta t) = G x y beta t.
Proof. unfold det, G_mat, G; simpl. field. Qed.

(* Identities L9.norm-squared and L9.derivative: ||A_s(t) v||^2 = a^2 u1^2 + b^2 u2^2 with u = R_{t beta} v,
   and its derivative is 2 u^T G_t u. *)
Theorem L9_derivative (x y alpha beta : R) (v : vec) (t : R) :
  is_derive (fun t => norm2 (mvec (A_s x y alpha beta t) v)) t
            (2 * qform (G_mat x y beta t) (mvec (rot (t * beta)) v)).
Proof.
  apply (is_derive_ext (fun t =>
    (1 + t * (x - 1)) ^ 2 * (cos (t * beta) * v1 v - sin (t * beta) * v2 v) ^ 2 +
    (1 + t * (y - 1)) ^ 2 * (sin (t * beta) * v1 v + cos (t * beta) * v2 v) ^ 2)).
  { intros s. unfold A_s. rewrite mvec_mmul, L5_norm_rotation, mvec_mmul.
    destruct v; unfold norm2, mvec, blend, rot, madd, mscale, Id2; simpl. ring. }
  auto_derive; [exact I |].
  destruct v; unfold qform, G_mat, mvec, rot; simpl. field.
Qed.

(* G_t >= 0 from m1, m2 >= 0 and G(t) >= 0 (L8 (b)); G_t <= 0 from m1, m2 <= 0. *)
Lemma G_mat_psd (x y beta t : R) :
  0 < x -> 0 < y -> 0 <= t <= 1 -> 0 <= x - 1 -> 0 <= y - 1 -> 0 <= G x y beta t ->
  psd (G_mat x y beta t).
Proof.
  intros Hx Hy Ht H1 H2 HG. unfold G_mat; cbv zeta. rewrite L8b_psd_iff.
  rewrite <- L9_G_is_4_det in HG. unfold det, G_mat in HG; simpl in HG.
  assert (0 < 1 + t * (x - 1)) by nra. assert (0 < 1 + t * (y - 1)) by nra.
  repeat split; [apply Rmult_le_pos; lra | apply Rmult_le_pos; lra | lra].
Qed.

Lemma G_mat_nsd (x y beta t : R) :
  0 < x -> 0 < y -> 0 <= t <= 1 -> x - 1 <= 0 -> y - 1 <= 0 -> 0 <= G x y beta t ->
  nsd (G_mat x y beta t).
Proof.
  intros Hx Hy Ht H1 H2 HG. unfold G_mat; cbv zeta. rewrite L8b_nsd_iff.
  rewrite <- L9_G_is_4_det in HG. unfold det, G_mat in HG; simpl in HG.
  assert (0 < 1 + t * (x - 1)) by nra. assert (0 < 1 + t * (y - 1)) by nra.
  repeat split; [| | lra].
  - assert (0 <= - (x - 1) * (1 + t * (x - 1))) by (apply Rmult_le_pos; lra). lra.
  - assert (0 <= - (y - 1) * (1 + t * (y - 1))) by (apply Rmult_le_pos; lra). lra.
Qed.

(* L9, direction (<=): G(t) >= 0 on [0, 1] makes A_s good for norm (alpha plays no part). *)
Theorem L9_sufficient (x y alpha beta : R) :
  0 < x -> 0 < y -> (forall t, 0 <= t <= 1 -> 0 <= G x y beta t) -> good_for_norm (A_s x y alpha beta).
Proof.
  intros Hx Hy HG v _. rewrite L4.
  rewrite (L1 _ _ (fun t _ => L9_derivative x y alpha beta v t)).
  assert (H0 : 0 <= (x - 1) * (y - 1)).
  { specialize (HG 0 ltac:(lra)). unfold G in HG. nra. }
  destruct (Rle_or_lt 0 (x - 1)) as [H1 | H1].
  - destruct (Req_dec (x - 1) 0) as [E | E].
    + (* m1 = 0: G(t) >= 0 forces the off-diagonal to vanish; the sign is that of m2 *)
      destruct (Rle_or_lt 0 (y - 1)); [left | right]; intros t Ht.
      * pose proof (G_mat_psd x y beta t Hx Hy Ht H1 ltac:(lra) (HG t Ht)) as P.
        specialize (P (mvec (rot (t * beta)) v)). lra.
      * pose proof (G_mat_nsd x y beta t Hx Hy Ht ltac:(lra) ltac:(lra) (HG t Ht)) as P.
        specialize (P (mvec (rot (t * beta)) v)). lra.
    + left. intros t Ht.
      pose proof (G_mat_psd x y beta t Hx Hy Ht H1 ltac:(nra) (HG t Ht)) as P.
      specialize (P (mvec (rot (t * beta)) v)). lra.
  - right. intros t Ht.
    pose proof (G_mat_nsd x y beta t Hx Hy Ht ltac:(lra) ltac:(nra) (HG t Ht)) as P.
    specialize (P (mvec (rot (t * beta)) v)). lra.
Qed.

(* ---- Direction (=>): G(t0) < 0 for some t0 in [0, 1] gives a v whose ||A_s(t) v|| is not monotone. ---- *)

(* Half the derivative: F v t = u^T G_t u with u = R_{t beta} v, = v^T K_t v with K_t = R^T G_t R. *)
Definition F (x y beta : R) (v : vec) (t : R) : R := qform (G_mat x y beta t) (mvec (rot (t * beta)) v).
Definition K (x y beta t : R) : mat := conj (rot (t * beta)) (G_mat x y beta t).

Lemma F_is_K (x y beta : R) (v : vec) (t : R) : F x y beta v t = qform (K x y beta t) v.
Proof. unfold F, K. rewrite qform_conj. reflexivity. Qed.

Lemma K_entries (x y beta t : R) :
  let W := K x y beta t in W = Mat (m11 W) (m12 W) (m12 W) (m22 W) /\ 4 * det W = G x y beta t.
Proof.
  intros W. split.
  - unfold W, K, conj, G_mat; simpl. unfold mmul, transpose, rot; simpl. f_equal; field.
  - rewrite <- L9_G_is_4_det. unfold W, K, conj. rewrite !L5_det_product.
    replace (det (transpose (rot (t * beta)))) with (det (rot (t * beta))) by (unfold det, transpose; simpl; ring).
    rewrite L5_det_rotation. ring.
Qed.

Lemma F_at_0 (x y beta : R) (v : vec) : F x y beta v 0 = (x - 1) * v1 v ^ 2 + (y - 1) * v2 v ^ 2.
Proof.
  unfold F. rewrite Rmult_0_l. destruct v; unfold qform, G_mat, mvec, rot; simpl. rewrite cos_0, sin_0. field.
Qed.

(* dF/dt at t = 0 (identity L9.second-derivative-at-0, halved). *)
Lemma F_derivative_at_0 (x y beta : R) (v : vec) :
  is_derive (F x y beta v) 0
    ((x - 1) ^ 2 * v1 v ^ 2 + (y - 1) ^ 2 * v2 v ^ 2 + 4 * beta * ((y - 1) - (x - 1)) * v1 v * v2 v).
Proof.
  apply (is_derive_ext (fun t =>
    (x - 1) * (1 + t * (x - 1)) * (cos (t * beta) * v1 v - sin (t * beta) * v2 v) ^ 2
    + beta * ((1 + t * (y - 1)) ^ 2 - (1 + t * (x - 1)) ^ 2)
      * (cos (t * beta) * v1 v - sin (t * beta) * v2 v) * (sin (t * beta) * v1 v + cos (t * beta) * v2 v)
    + (y - 1) * (1 + t * (y - 1)) * (sin (t * beta) * v1 v + cos (t * beta) * v2 v) ^ 2)).
  { intros t. unfold F. destruct v; unfold qform, G_mat, mvec, rot; simpl. field. }
  auto_derive; [exact I |]. rewrite !Rmult_0_l, cos_0, sin_0. ring.
Qed.

(* A symmetric form with negative determinant takes a negative value. *)
Lemma indefinite_witness (p h r : R) : p * r - h * h < 0 -> exists w, qform (Mat p h h r) w < 0.
Proof.
  intros Hd. destruct (Rtotal_order r 0) as [Hr | [Hr | Hr]].
  - exists (Vec 0 1). unfold qform; simpl. lra.
  - subst r. assert (h <> 0) by (intros ->; lra).
    exists (Vec 1 (- (p + 1) / (2 * h))). unfold qform; simpl. match goal with |- ?e < 0 => replace e with (-1) by (field; assumption) end. lra.
  - exists (Vec r (- h)). unfold qform; simpl.
    replace (r * (p * r + h * - h) + - h * (h * r + r * - h)) with (r * (p * r - h * h)) by ring. nra.
Qed.

(* f(0) = 0 and f'(0) > 0 give f(d) > 0 for some d in (0, 1]. *)
Lemma positive_after_0 (f : R -> R) (L : R) :
  is_derive f 0 L -> f 0 = 0 -> 0 < L -> exists d, 0 < d <= 1 /\ 0 < f d.
Proof.
  intros Hd H0 HL. apply is_derive_Reals in Hd.
  destruct (Hd (L / 2)) as [delta Hdelta]; [lra |].
  pose proof (cond_pos delta) as Hdp.
  set (d := Rmin (delta / 2) 1).
  assert (Hdd : 0 < d /\ d <= delta / 2 /\ d <= 1) by (unfold d; repeat split; [apply Rmin_pos; lra | apply Rmin_l | apply Rmin_r]).
  exists d. split; [lra |].
  specialize (Hdelta d ltac:(lra) ltac:(rewrite Rabs_right; lra)).
  rewrite Rplus_0_l, H0, Rminus_0_r in Hdelta. apply Rabs_def2 in Hdelta.
  assert (0 < f d / d) by lra.
  replace (f d) with (f d / d * d) by (field; lra). apply Rmult_lt_0_compat; lra.
Qed.

Definition bil (W : mat) (v e : vec) : R :=
  v1 v * (m11 W * v1 e + m12 W * v2 e) + v2 v * (m21 W * v1 e + m22 W * v2 e)
  + v1 e * (m11 W * v1 v + m12 W * v2 v) + v2 e * (m21 W * v1 v + m22 W * v2 v).

Lemma qform_expand (W : mat) (v e : vec) (eps : R) :
  qform W (Vec (v1 v + eps * v1 e) (v2 v + eps * v2 e)) =
  qform W v + bil W v e * eps + qform W e * eps ^ 2.
Proof. destruct W, v, e; unfold qform, bil; simpl; ring. Qed.

(* The mixed case m1 m2 < 0: at a v0 with F v0 0 = 0 and dF/dt(0) > 0, F v0 d > 0 for some d in (0, 1];
   moving v0 along -G_0 v0 makes F(., 0) < 0 and keeps F(., d) > 0. *)
Lemma mixed_case (x y beta : R) (v0 : vec) (L : R) :
  is_derive (F x y beta v0) 0 L -> F x y beta v0 0 = 0 -> 0 < L ->
  0 < (x - 1) ^ 2 * v1 v0 ^ 2 + (y - 1) ^ 2 * v2 v0 ^ 2 ->
  exists v d, 0 < d <= 1 /\ F x y beta v 0 < 0 /\ 0 < F x y beta v d.
Proof.
  intros Hd H0 HL Hg.
  destruct (positive_after_0 _ _ Hd H0 HL) as [d [Hd01 Hpos]].
  set (e := Vec (- (x - 1) * v1 v0) (- (y - 1) * v2 v0)).
  rewrite F_is_K in Hpos. set (W := K x y beta d) in Hpos.
  destruct (small_eps (- 2 * ((x - 1) ^ 2 * v1 v0 ^ 2 + (y - 1) ^ 2 * v2 v0 ^ 2))
              ((x - 1) * v1 e ^ 2 + (y - 1) * v2 e ^ 2) (qform W v0)
              (bil W v0 e) (qform W e) ltac:(lra) Hpos) as [eps [Heps [H1 H2]]].
  exists (Vec (v1 v0 + eps * v1 e) (v2 v0 + eps * v2 e)), d. split; [exact Hd01 |]. split.
  - rewrite F_at_0. rewrite F_at_0 in H0. cbn [v1 v2].
    replace ((x - 1) * (v1 v0 + eps * v1 e) ^ 2 + (y - 1) * (v2 v0 + eps * v2 e) ^ 2)
      with (((x - 1) * v1 v0 ^ 2 + (y - 1) * v2 v0 ^ 2)
            + (- 2 * ((x - 1) ^ 2 * v1 v0 ^ 2 + (y - 1) ^ 2 * v2 v0 ^ 2)) * eps
            + ((x - 1) * v1 e ^ 2 + (y - 1) * v2 e ^ 2) * eps ^ 2) by (unfold e; simpl; ring).
    lra.
  - rewrite F_is_K. fold W. rewrite qform_expand. lra.
Qed.

(* L9, direction (=>): if A_s is good for norm, G(t) >= 0 on [0, 1]. *)
Theorem L9_necessary (x y alpha beta : R) :
  0 < x -> 0 < y -> good_for_norm (A_s x y alpha beta) -> forall t, 0 <= t <= 1 -> 0 <= G x y beta t.
Proof.
  intros Hx Hy Hgood t0 Ht0. apply Rnot_lt_le. intros HG.
  assert (Hsign : forall v t1 t2, 0 <= t1 <= 1 -> 0 <= t2 <= 1 ->
                  0 < F x y beta v t1 -> F x y beta v t2 < 0 -> False).
  { intros v t1 t2 H1 H2 P N. unfold good_for_norm in Hgood. rewrite L6_unit_vs_all in Hgood.
    specialize (Hgood v). rewrite L4 in Hgood.
    apply (L1_consequence _ (fun t => 2 * F x y beta v t) t1 t2 (fun t _ => L9_derivative x y alpha beta v t));
      [exact H1 | lra | exact H2 | lra | exact Hgood]. }
  destruct (K_entries x y beta t0) as [EK HdK].
  set (W := K x y beta t0) in EK, HdK.
  assert (Hdet : m11 W * m22 W - m12 W * m12 W < 0).
  { rewrite EK in HdK. unfold det in HdK; cbn [m11 m12 m21 m22] in HdK. lra. }
  assert (Hneg : exists w, F x y beta w t0 < 0).
  { destruct (indefinite_witness _ _ _ Hdet) as [w Hw]. exists w. rewrite F_is_K. fold W. rewrite EK. exact Hw. }
  assert (Hpos : exists w, 0 < F x y beta w t0).
  { destruct (indefinite_witness (- m11 W) (- m12 W) (- m22 W) ltac:(lra)) as [w Hw]. exists w.
    rewrite F_is_K. fold W. rewrite EK. destruct w; unfold qform in *; simpl in *. lra. }
  (* the form K_{t0} near a witness w: qform W (w + eps e) *)
  assert (Hnear : forall w e, F x y beta w t0 <> 0 -> exists eps, 0 < eps <= 1 /\
            (F x y beta (Vec (v1 w + eps * v1 e) (v2 w + eps * v2 e)) t0 < 0 <-> F x y beta w t0 < 0) /\
            (0 < F x y beta (Vec (v1 w + eps * v1 e) (v2 w + eps * v2 e)) t0 <-> 0 < F x y beta w t0)).
  { intros w e Hw. rewrite F_is_K in Hw. fold W in Hw.
    destruct (Rlt_or_le 0 (qform W w)) as [Hp | Hn].
    - destruct (small_eps (-1) 0 (qform W w) (bil W w e) (qform W e) ltac:(lra) Hp) as [eps [He [_ H2]]].
      exists eps. split; [exact He |]. rewrite !F_is_K. fold W. rewrite qform_expand. split; split; intros; lra.
    - destruct (small_eps (-1) 0 (- qform W w) (- bil W w e) (- qform W e) ltac:(lra) ltac:(lra))
        as [eps [He [_ H2]]].
      exists eps. split; [exact He |]. rewrite !F_is_K. fold W. rewrite qform_expand. split; split; intros; lra. }
  set (m1 := x - 1) in *. set (m2 := y - 1) in *.
  assert (HF0 : forall v, F x y beta v 0 = m1 * v1 v ^ 2 + m2 * v2 v ^ 2) by (intros; apply F_at_0).
  assert (Hnz : forall w, F x y beta w t0 <> 0 -> 0 < v1 w ^ 2 + v2 w ^ 2).
  { intros [a b] Hw. simpl. destruct (Req_dec a 0), (Req_dec b 0); subst; [| nra ..].
    exfalso. apply Hw. rewrite F_is_K. unfold qform; simpl. ring. }
  destruct (Rtotal_order (m1 * m2) 0) as [Hmix | [Hzero | Hsame]].
  - (* m1 m2 < 0: the second derivative at the root of F(., 0) *)
    assert (Hmain : forall v0, F x y beta v0 0 = 0 -> 0 < m1 ^ 2 * v1 v0 ^ 2 + m2 ^ 2 * v2 v0 ^ 2 ->
              0 < m1 ^ 2 * v1 v0 ^ 2 + m2 ^ 2 * v2 v0 ^ 2 + 4 * beta * (m2 - m1) * v1 v0 * v2 v0 -> False).
    { intros v0 H0 Hg HL.
      destruct (mixed_case x y beta v0 _ (F_derivative_at_0 x y beta v0) H0 HL Hg) as [v [d [Hd [N P]]]].
      exact (Hsign v d 0 ltac:(lra) ltac:(lra) P N). }
    set (sb := if Rle_dec 0 beta then 1 else -1).
    assert (Hsb : 0 <= beta * sb /\ sb ^ 2 = 1) by (unfold sb; destruct (Rle_dec 0 beta); split; lra).
    destruct (Rlt_or_le m1 0) as [Hm1 | Hm1].
    + assert (Hm2 : 0 < m2) by nra.
      pose proof (sqrt_sqrt m2 ltac:(lra)) as S2. pose proof (sqrt_sqrt (- m1) ltac:(lra)) as S1.
      pose proof (sqrt_lt_R0 m2 Hm2) as P2. pose proof (sqrt_lt_R0 (- m1) ltac:(lra)) as P1.
      apply (Hmain (Vec (sqrt m2) (sb * sqrt (- m1)))); cbn [v1 v2].
      * rewrite HF0. cbn [v1 v2]. replace ((sb * sqrt (- m1)) ^ 2) with (sb ^ 2 * (sqrt (- m1) * sqrt (- m1))) by ring.
        replace (sqrt m2 ^ 2) with (sqrt m2 * sqrt m2) by ring. rewrite S1, S2, (proj2 Hsb). ring.
      * replace (sqrt m2 ^ 2) with (sqrt m2 * sqrt m2) by ring. rewrite S2. nra.
      * replace ((sb * sqrt (- m1)) ^ 2) with (sb ^ 2 * (sqrt (- m1) * sqrt (- m1))) by ring.
        replace (sqrt m2 ^ 2) with (sqrt m2 * sqrt m2) by ring. rewrite S1, S2, (proj2 Hsb).
        assert (0 <= beta * sb * (m2 - m1) * sqrt m2 * sqrt (- m1)).
        { apply Rmult_le_pos; [apply Rmult_le_pos; [apply Rmult_le_pos; [exact (proj1 Hsb) | lra] | lra] | lra]. }
        assert (0 < m1 ^ 2 * m2 + m2 ^ 2 * (1 * - m1)) by nra. nra.
    + assert (Hm1' : 0 < m1) by (destruct Hm1 as [| E]; [assumption | rewrite <- E in Hmix; lra]).
      assert (Hm2 : m2 < 0) by nra.
      pose proof (sqrt_sqrt (- m2) ltac:(lra)) as S2. pose proof (sqrt_sqrt m1 ltac:(lra)) as S1.
      pose proof (sqrt_lt_R0 (- m2) ltac:(lra)) as P2. pose proof (sqrt_lt_R0 m1 Hm1') as P1.
      apply (Hmain (Vec (sqrt (- m2)) (- sb * sqrt m1))); cbn [v1 v2].
      * rewrite HF0. cbn [v1 v2]. replace ((- sb * sqrt m1) ^ 2) with (sb ^ 2 * (sqrt m1 * sqrt m1)) by ring.
        replace (sqrt (- m2) ^ 2) with (sqrt (- m2) * sqrt (- m2)) by ring. rewrite S1, S2, (proj2 Hsb). ring.
      * replace (sqrt (- m2) ^ 2) with (sqrt (- m2) * sqrt (- m2)) by ring. rewrite S2. nra.
      * replace ((- sb * sqrt m1) ^ 2) with (sb ^ 2 * (sqrt m1 * sqrt m1)) by ring.
        replace (sqrt (- m2) ^ 2) with (sqrt (- m2) * sqrt (- m2)) by ring. rewrite S1, S2, (proj2 Hsb).
        assert (0 <= beta * sb * (m1 - m2) * sqrt (- m2) * sqrt m1).
        { apply Rmult_le_pos; [apply Rmult_le_pos; [apply Rmult_le_pos; [exact (proj1 Hsb) | lra] | lra] | lra]. }
        assert (0 < m1 ^ 2 * - m2 + m2 ^ 2 * (1 * m1)) by nra. nra.
  - (* m1 m2 = 0: one of them is 0, not both (else G = 0) *)
    assert (Hnot00 : ~ (m1 = 0 /\ m2 = 0)).
    { intros [E1 E2]. unfold m1, m2 in *. assert (x = 1) by lra. assert (y = 1) by lra. subst.
      unfold G in HG. lra. }
    destruct (Rmult_integral _ _ Hzero) as [E1 | E2].
    + assert (m2 <> 0) by (intros E; apply Hnot00; split; assumption).
      destruct (Rlt_or_le 0 m2) as [Hm2 | Hm2].
      * destruct Hneg as [[a b] Hw]. destruct (Req_dec b 0) as [-> | Hb];
          [| assert (0 < b ^ 2) by (rewrite <- Rsqr_pow2; apply Rsqr_pos_lt; exact Hb)].
        -- destruct (Hnear (Vec a 0) (Vec 0 1) ltac:(lra)) as [eps [He Hiff]]. cbn [v1 v2] in Hiff.
           pose proof (pow_lt eps 2 (proj1 He)).
           apply (Hsign (Vec (a + eps * 0) (0 + eps * 1)) 0 t0); [lra | exact Ht0 | | apply (proj1 Hiff), Hw].
           rewrite HF0, E1. cbn [v1 v2]. nra.
        -- apply (Hsign (Vec a b) 0 t0); [lra | exact Ht0 | | exact Hw]. rewrite HF0, E1. cbn [v1 v2]. nra.
      * destruct Hpos as [[a b] Hw]. destruct (Req_dec b 0) as [-> | Hb];
          [| assert (0 < b ^ 2) by (rewrite <- Rsqr_pow2; apply Rsqr_pos_lt; exact Hb)].
        -- destruct (Hnear (Vec a 0) (Vec 0 1) ltac:(lra)) as [eps [He Hiff]]. cbn [v1 v2] in Hiff.
           pose proof (pow_lt eps 2 (proj1 He)).
           apply (Hsign (Vec (a + eps * 0) (0 + eps * 1)) t0 0); [exact Ht0 | lra | | ].
           ++ apply (proj2 Hiff), Hw.
           ++ rewrite HF0, E1. cbn [v1 v2]. assert (m2 < 0) by lra. nra.
        -- apply (Hsign (Vec a b) t0 0); [exact Ht0 | lra | exact Hw |]. rewrite HF0, E1. cbn [v1 v2].
           assert (m2 < 0) by lra. nra.
    + assert (m1 <> 0) by (intros E; apply Hnot00; split; assumption).
      destruct (Rlt_or_le 0 m1) as [Hm1 | Hm1].
      * destruct Hneg as [[a b] Hw]. destruct (Req_dec a 0) as [-> | Ha];
          [| assert (0 < a ^ 2) by (rewrite <- Rsqr_pow2; apply Rsqr_pos_lt; exact Ha)].
        -- destruct (Hnear (Vec 0 b) (Vec 1 0) ltac:(lra)) as [eps [He Hiff]]. cbn [v1 v2] in Hiff.
           pose proof (pow_lt eps 2 (proj1 He)).
           apply (Hsign (Vec (0 + eps * 1) (b + eps * 0)) 0 t0); [lra | exact Ht0 | | apply (proj1 Hiff), Hw].
           rewrite HF0, E2. cbn [v1 v2]. nra.
        -- apply (Hsign (Vec a b) 0 t0); [lra | exact Ht0 | | exact Hw]. rewrite HF0, E2. cbn [v1 v2]. nra.
      * destruct Hpos as [[a b] Hw]. destruct (Req_dec a 0) as [-> | Ha];
          [| assert (0 < a ^ 2) by (rewrite <- Rsqr_pow2; apply Rsqr_pos_lt; exact Ha)].
        -- destruct (Hnear (Vec 0 b) (Vec 1 0) ltac:(lra)) as [eps [He Hiff]]. cbn [v1 v2] in Hiff.
           pose proof (pow_lt eps 2 (proj1 He)).
           apply (Hsign (Vec (0 + eps * 1) (b + eps * 0)) t0 0); [exact Ht0 | lra | | ].
           ++ apply (proj2 Hiff), Hw.
           ++ rewrite HF0, E2. cbn [v1 v2]. assert (m1 < 0) by lra. nra.
        -- apply (Hsign (Vec a b) t0 0); [exact Ht0 | lra | exact Hw |]. rewrite HF0, E2. cbn [v1 v2].
           assert (m1 < 0) by lra. nra.
  - (* m1 m2 > 0: F(., 0) has one strict sign on v <> 0 *)
    destruct (Rlt_or_le 0 m1) as [Hm1 | Hm1].
    + assert (0 < m2) by nra. destruct Hneg as [w Hw].
      pose proof (Hnz w ltac:(lra)).
      apply (Hsign w 0 t0); [lra | exact Ht0 | | exact Hw]. rewrite HF0. nra.
    + assert (m1 < 0) by (destruct Hm1 as [| E]; [assumption | rewrite E in Hsame; lra]). assert (m2 < 0) by nra.
      destruct Hpos as [w Hw]. pose proof (Hnz w ltac:(lra)).
      apply (Hsign w t0 0); [exact Ht0 | lra | exact Hw |]. rewrite HF0. nra.
Qed.

(* L9 as LEMMAS.md states it. *)
Theorem L9 (x y alpha beta : R) :
  0 < x -> 0 < y -> (good_for_norm (A_s x y alpha beta) <-> forall t, 0 <= t <= 1 -> 0 <= G x y beta t).
Proof.
  intros Hx Hy. split; [apply L9_necessary; assumption | apply L9_sufficient; assumption].
Qed.
