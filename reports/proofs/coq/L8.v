(* L8: Dines' theorem in the form used (level N), and how W >= 0 is written (LEMMAS.md, L8). *)
Require Import Reals Lra Psatz.
Require Import Affinterp.Defs Affinterp.Small Affinterp.L7 Affinterp.L13.
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

(* ---- The statement's direction (=>), through the 2x2 case of the S-lemma. ---- *)

(* A quadratic f(u) = a + 2 b u + c u^2 that is >= 0 on (-1, 1) is f = g + mu (1 - u^2) with mu >= 0 and
   g >= 0 on all of R (its leading coefficient c + mu >= 0). *)
Lemma interval_S_lemma (a b c : R) :
  (forall u, -1 < u < 1 -> 0 <= a + 2 * b * u + c * u ^ 2) ->
  exists mu, 0 <= mu /\ 0 <= c + mu /\ forall u, 0 <= (a - mu) + 2 * b * u + (c + mu) * u ^ 2.
Proof.
  intros Hf. pose proof (Hf 0 ltac:(lra)) as Ha. replace (a + 2 * b * 0 + c * 0 ^ 2) with a in Ha by ring.
  (* the ends: f(1), f(-1) >= 0, each by a small step inside *)
  assert (E1 : 0 <= a + 2 * b + c).
  { destruct (Rle_or_lt 0 (a + 2 * b + c)) as [| F]; [assumption | exfalso].
    destruct (small_eps (-1) 0 (- (a + 2 * b + c)) (2 * b + 2 * c) (- c) ltac:(lra) ltac:(lra)) as [e [He [_ H2]]].
    pose proof (Hf (1 - e) ltac:(lra)) as H. nra. }
  assert (E2 : 0 <= a - 2 * b + c).
  { destruct (Rle_or_lt 0 (a - 2 * b + c)) as [| F]; [assumption | exfalso].
    destruct (small_eps (-1) 0 (- (a - 2 * b + c)) (- 2 * b + 2 * c) (- c) ltac:(lra) ltac:(lra)) as [e [He [_ H2]]].
    pose proof (Hf (-1 + e) ltac:(lra)) as H. nra. }
  destruct (Rle_or_lt c a) as [Hca | Hca].
  - (* mu = (a - c)/2: g(u) = ((a + c)/2)(1 + u^2) + 2 b u, and |b| <= (a + c)/2 *)
    exists ((a - c) / 2). split; [lra | split; [lra |]]. intros u.
    assert (0 <= ((a + c) / 2 + b) * (1 + u) ^ 2 / 2) by (apply Rmult_le_pos; [apply Rmult_le_pos; [lra | apply pow2_ge_0] | lra]).
    assert (0 <= ((a + c) / 2 - b) * (1 - u) ^ 2 / 2) by (apply Rmult_le_pos; [apply Rmult_le_pos; [lra | apply pow2_ge_0] | lra]).
    replace ((a - (a - c) / 2) + 2 * b * u + (c + (a - c) / 2) * u ^ 2)
      with (((a + c) / 2 + b) * (1 + u) ^ 2 / 2 + ((a + c) / 2 - b) * (1 - u) ^ 2 / 2) by field.
    lra.
  - (* mu = 0: c > a >= 0, the vertex -b/c lies in [-1, 1], so a c >= b^2 *)
    exists 0. split; [lra | split; [lra |]]. intros u.
    assert (Hb : - c <= b <= c) by (split; lra).
    assert (Hv : b * b <= a * c).
    { destruct (Req_dec b c) as [-> | Hbc]; [nra |]. destruct (Req_dec b (- c)) as [-> | Hbc']; [nra |].
      pose proof (Hf (- b / c) ltac:(split; [apply (Rmult_lt_reg_r c); [lra | unfold Rdiv; rewrite Rmult_assoc, Rinv_l by lra; lra]
                                          | apply (Rmult_lt_reg_r c); [lra | unfold Rdiv; rewrite Rmult_assoc, Rinv_l by lra; lra]])) as H.
      replace (a + 2 * b * (- b / c) + c * (- b / c) ^ 2) with ((a * c - b * b) / c) in H by (field; lra).
      destruct (Rle_or_lt (b * b) (a * c)) as [| Hl]; [assumption | exfalso].
      assert (0 < (b * b - a * c) * / c) by (apply Rmult_lt_0_compat; [lra | apply Rinv_0_lt_compat; lra]).
      unfold Rdiv in H. lra. }
    replace ((a - 0) + 2 * b * u + (c + 0) * u ^ 2) with (((c * u + b) ^ 2 + (a * c - b * b)) / c) by (field; lra).
    unfold Rdiv. apply Rmult_le_pos; [pose proof (pow2_ge_0 (c * u + b)); lra | left; apply Rinv_0_lt_compat; lra].
Qed.

(* Q = diag(q1, q2) with q1 > 0. *)
Lemma dines_diag (p11 p12 p22 q1 q2 : R) :
  (~ exists v, qform (Mat p11 p12 p12 p22) v < 0 < qform (Mat q1 0 0 q2) v) -> 0 < q1 ->
  exists nu, 0 <= nu /\ psd (madd (Mat p11 p12 p12 p22) (mscale (- nu) (Mat q1 0 0 q2))).
Proof.
  intros H Hq1.
  assert (Hpos : forall a b, 0 < q1 * a ^ 2 + q2 * b ^ 2 -> 0 <= p11 * a ^ 2 + 2 * p12 * a * b + p22 * b ^ 2).
  { intros a b Hq. destruct (Rle_or_lt 0 (p11 * a ^ 2 + 2 * p12 * a * b + p22 * b ^ 2)) as [| Hn]; [assumption |].
    exfalso. apply H. exists (Vec a b). unfold qform; simpl. split; nra. }
  assert (Eqf : forall nu a b, qform (madd (Mat p11 p12 p12 p22) (mscale (- nu) (Mat q1 0 0 q2))) (Vec a b)
                = p11 * a ^ 2 + 2 * p12 * a * b + p22 * b ^ 2 - nu * (q1 * a ^ 2 + q2 * b ^ 2))
    by (intros; unfold qform, madd, mscale; simpl; ring).
  destruct (Rle_or_lt 0 q2) as [Hq2 | Hq2].
  - (* Q(v) > 0 off the line a = 0, so P >= 0 there, and at a = 0 by a small step: nu = 0 *)
    exists 0. split; [lra |]. intros [a b]. rewrite Eqf.
    destruct (Req_dec a 0) as [-> | Ha].
    + assert (Hp22 : 0 <= p22).
      { destruct (Rle_or_lt 0 p22) as [| Hn]; [assumption | exfalso].
        destruct (small_eps (-1) 0 (- p22) (- 2 * p12) (- p11) ltac:(lra) ltac:(lra)) as [e [He [_ H2]]].
        pose proof (Hpos e 1 ltac:(assert (0 < e ^ 2) by (apply pow_lt; lra); nra)). nra. }
      assert (0 <= p22 * b ^ 2) by (apply Rmult_le_pos; [lra | apply pow2_ge_0]). nra.
    + assert (0 < a ^ 2) by (rewrite <- Rsqr_pow2; apply Rsqr_pos_lt, Ha).
      assert (0 <= q2 * b ^ 2) by (apply Rmult_le_pos; [lra | apply pow2_ge_0]).
      pose proof (Hpos a b ltac:(nra)). nra.
  - (* Q indefinite: with k^2 = q1 / (-q2), f(u) = P(1, k u) >= 0 on (-1, 1), where Q(1, k u) = q1 (1 - u^2) *)
    set (k := sqrt (q1 / - q2)).
    assert (Hk2 : k * k = q1 / - q2) by (apply sqrt_sqrt; unfold Rdiv; apply Rmult_le_pos; [lra | left; apply Rinv_0_lt_compat; lra]).
    assert (Hk : 0 < k) by (apply sqrt_lt_R0; unfold Rdiv; apply Rmult_lt_0_compat; [lra | apply Rinv_0_lt_compat; lra]).
    assert (Hkq : k * k * q2 = - q1) by (rewrite Hk2; field; lra).
    destruct (interval_S_lemma p11 (p12 * k) (p22 * (k * k))) as [mu [Hmu [Hc Hg]]].
    { intros u Hu. replace (p11 + 2 * (p12 * k) * u + p22 * (k * k) * u ^ 2)
        with (p11 * 1 ^ 2 + 2 * p12 * 1 * (k * u) + p22 * (k * u) ^ 2) by ring.
      apply Hpos. replace (q1 * 1 ^ 2 + q2 * (k * u) ^ 2) with (q1 - (- (k * k * q2)) * u ^ 2) by ring.
      replace (- (k * k * q2)) with q1 by lra.
      assert (0 < 1 - u ^ 2) by nra.
      replace (q1 - q1 * u ^ 2) with (q1 * (1 - u ^ 2)) by ring. apply Rmult_lt_0_compat; lra. }
    exists (mu / q1). split; [unfold Rdiv; apply Rmult_le_pos; [lra | left; apply Rinv_0_lt_compat; lra] |].
    intros [a b]. rewrite Eqf.
    destruct (Req_dec a 0) as [-> | Ha].
    + replace (p11 * 0 ^ 2 + 2 * p12 * 0 * b + p22 * b ^ 2 - mu / q1 * (q1 * 0 ^ 2 + q2 * b ^ 2))
        with ((p22 * (k * k) + mu) * b ^ 2 / (k * k)).
      * unfold Rdiv. apply Rmult_le_pos; [apply Rmult_le_pos; [lra | apply pow2_ge_0] | left; apply Rinv_0_lt_compat; nra].
      * assert (Hq1e : q1 = - (k * k * q2)) by lra. rewrite Hq1e. field. repeat split; lra.
    + pose proof (Hg (b / (k * a))) as Hu.
      assert (0 < a ^ 2) by (rewrite <- Rsqr_pow2; apply Rsqr_pos_lt, Ha).
      replace (p11 * a ^ 2 + 2 * p12 * a * b + p22 * b ^ 2 - mu / q1 * (q1 * a ^ 2 + q2 * b ^ 2))
        with (a ^ 2 * ((p11 - mu) + 2 * (p12 * k) * (b / (k * a)) + (p22 * (k * k) + mu) * (b / (k * a)) ^ 2)).
      * apply Rmult_le_pos; lra.
      * assert (Hq1e : q1 = - (k * k * q2)) by lra. rewrite Hq1e. field. repeat split; lra.
Qed.

Lemma qform_swap (a b c x y : R) : qform (Mat a b b c) (Vec x y) = qform (Mat c b b a) (Vec y x).
Proof. unfold qform; simpl; ring. Qed.

(* The statement used, direction (=>): with no v such that P(v) < 0 < Q(v), Q <= 0 or P - nu Q >= 0 for some
   nu >= 0. Q is diagonalised by a rotation O (L13), which carries P to O^T P O and keeps both orders (L7);
   dines_diag does the diagonal case. *)
Theorem L8_necessary (P Q : mat) :
  symmetric P -> symmetric Q -> (~ exists v, qform P v < 0 < qform Q v) ->
  nsd Q \/ exists nu, 0 <= nu /\ psd (madd P (mscale (- nu) Q)).
Proof.
  intros HP HQ H.
  destruct (Classical_Prop.classic (nsd Q)) as [| HnQ]; [left; assumption | right].
  destruct Q as [d e e' f]. unfold symmetric in HQ; simpl in HQ. subst e'.
  destruct (L13_eigenvalues_real d e f) as [q1 [q2 [Hs Hp]]].
  destruct (L13_spectral d e f q1 q2 Hs Hp) as [O [HO HQd]].
  assert (HconjQ : conj O (Mat d e e f) = Mat q1 0 0 q2).
  { rewrite HQd. destruct HO as [HO _]. unfold conj.
    transitivity (mmul (mmul (transpose O) O) (mmul (diag q1 q2) (mmul (transpose O) O))).
    - destruct O; unfold mmul, transpose, diag; simpl; f_equal; ring.
    - rewrite HO. unfold diag, mmul, Id2; simpl; f_equal; ring. }
  set (P' := conj O P).
  assert (HP' : P' = Mat (m11 P') (m12 P') (m12 P') (m22 P')).
  { unfold P', conj. destruct P as [a b b' c]. unfold symmetric in HP; simpl in HP. subst b'.
    destruct O; unfold mmul, transpose; simpl; f_equal; ring. }
  assert (H' : ~ exists w, qform P' w < 0 < qform (Mat q1 0 0 q2) w).
  { intros [w Hw]. apply H. exists (mvec O w). unfold P' in Hw. rewrite <- HconjQ, !qform_conj in Hw. exact Hw. }
  rewrite HP' in H'.
  assert (Hback : forall nu, psd (madd P' (mscale (- nu) (Mat q1 0 0 q2))) ->
                             psd (madd P (mscale (- nu) (Mat d e e f)))).
  { intros nu Hpsd. apply (psd_conj O); [exact HO |]. rewrite conj_lin, HconjQ. exact Hpsd. }
  (* Q is not <= 0, so q1 > 0 or q2 > 0 *)
  assert (Hq : 0 < q1 \/ 0 < q2).
  { destruct (Rlt_or_le 0 q1) as [| H1]; [left; assumption |]. destruct (Rlt_or_le 0 q2) as [| H2]; [right; assumption |].
    exfalso. apply HnQ. intros v. rewrite <- (mvec_transpose_cancel O v HO), <- qform_conj, HconjQ.
    destruct (mvec (transpose O) v) as [a b]. unfold qform; simpl.
    assert (0 <= - q1 * a * a) by (rewrite Rmult_assoc; apply Rmult_le_pos; nra).
    assert (0 <= - q2 * b * b) by (rewrite Rmult_assoc; apply Rmult_le_pos; nra). lra. }
  destruct Hq as [Hq1 | Hq2].
  - destruct (dines_diag _ _ _ q1 q2 H' Hq1) as [nu [Hnu Hpsd]]. exists nu. split; [exact Hnu |].
    apply Hback. rewrite HP'. exact Hpsd.
  - assert (H'' : ~ exists w, qform (Mat (m22 P') (m12 P') (m12 P') (m11 P')) w < 0 < qform (Mat q2 0 0 q1) w).
    { intros [[a b] Hw]. apply H'. exists (Vec b a). rewrite !(qform_swap _ _ _ b a). exact Hw. }
    destruct (dines_diag _ _ _ q2 q1 H'' Hq2) as [nu [Hnu Hpsd]]. exists nu. split; [exact Hnu |].
    apply Hback. rewrite HP'. intros [a b]. specialize (Hpsd (Vec b a)).
    unfold madd, mscale in *; simpl in *. rewrite qform_swap. simpl. exact Hpsd.
Qed.

(* L8's statement as LEMMAS.md states it, both directions. *)
Theorem L8 (P Q : mat) :
  symmetric P -> symmetric Q ->
  ((~ exists v, qform P v < 0 < qform Q v) <-> nsd Q \/ exists nu, 0 <= nu /\ psd (madd P (mscale (- nu) Q))).
Proof.
  intros HP HQ. split; [apply L8_necessary; assumption | apply L8_sufficient].
Qed.
