(* L1: on [0, 1], monotone <=> the derivative keeps one sign (LEMMAS.md, L1).
   f is differentiable at every t in [0, 1] (two-sided: every f the suite applies L1 to is defined and
   differentiable on all of R); no continuity of f' is needed. *)
Require Import Reals Lra.
From Coquelicot Require Import Coquelicot.
Require Import Affinterp.Defs.
Open Scope R_scope.

(* A difference quotient of a non-decreasing function, taken inside [0, 1], is >= 0: so f'(t) < 0 is refuted
   by a small step to the right (t < 1) or to the left (t = 1). *)
Lemma derivative_nonneg_of_nondecreasing (f : R -> R) (t l : R) :
  0 <= t <= 1 -> derivable_pt_lim f t l -> nondecreasing01 f -> 0 <= l.
Proof.
  intros Ht Hd Hf.
  destruct (Rle_or_lt 0 l) as [Hl | Hl]; [exact Hl |].
  destruct (Hd (- l / 2)) as [delta Hdelta]; [lra |].
  assert (Hq : forall h, h <> 0 -> Rabs h < delta -> 0 <= (f (t + h) - f t) / h -> False).
  { intros h Hh0 Hhd Hq. specialize (Hdelta h Hh0 Hhd).
    apply Rabs_def2 in Hdelta. lra. }
  pose proof (cond_pos delta) as Hdpos. exfalso.
  destruct (Rlt_or_le t 1) as [Ht1 | Ht1].
  - set (h := Rmin (delta / 2) (1 - t)).
    assert (Hh : 0 < h /\ h <= delta / 2 /\ h <= 1 - t).
    { unfold h; repeat split; [apply Rmin_pos; lra | apply Rmin_l | apply Rmin_r]. }
    apply (Hq h); [lra | rewrite Rabs_right; lra |].
    apply Rdiv_le_0_compat; [| lra].
    assert (f t <= f (t + h)) by (apply Hf; lra). lra.
  - set (h := Rmin (delta / 2) 1).
    assert (Hh : 0 < h /\ h <= delta / 2 /\ h <= 1).
    { unfold h; repeat split; [apply Rmin_pos; lra | apply Rmin_l | apply Rmin_r]. }
    apply (Hq (- h)); [lra | rewrite Rabs_left; lra |].
    assert (f (t + - h) <= f t) by (apply Hf; lra).
    replace ((f (t + - h) - f t) / - h) with ((f t - f (t + - h)) / h) by (field; lra).
    apply Rdiv_le_0_compat; lra.
Qed.

Theorem L1_nondecreasing (f f' : R -> R) :
  (forall t, 0 <= t <= 1 -> is_derive f t (f' t)) ->
  (nondecreasing01 f <-> forall t, 0 <= t <= 1 -> 0 <= f' t).
Proof.
  intros Hd. split.
  - intros Hf t Ht. apply (derivative_nonneg_of_nondecreasing f t); auto.
    apply is_derive_Reals, Hd, Ht.
  - intros Hpos s t Hs Hst Ht.
    destruct (Req_dec s t) as [-> | Hne]; [lra |].
    destruct (MVT_cor2 f f' s t) as [c [Hc Hcst]]; [lra | |].
    + intros c Hc. apply is_derive_Reals, Hd. lra.
    + assert (0 <= f' c) by (apply Hpos; lra).
      assert (0 <= f' c * (t - s)) by (apply Rmult_le_pos; lra). lra.
Qed.

Theorem L1_nonincreasing (f f' : R -> R) :
  (forall t, 0 <= t <= 1 -> is_derive f t (f' t)) ->
  (nonincreasing01 f <-> forall t, 0 <= t <= 1 -> f' t <= 0).
Proof.
  intros Hd.
  assert (Hd' : forall t, 0 <= t <= 1 -> is_derive (fun t => - f t) t (- f' t)).
  { intros t Ht. apply (is_derive_opp f), Hd, Ht. }
  pose proof (L1_nondecreasing (fun t => - f t) (fun t => - f' t) Hd') as H.
  unfold nondecreasing01, nonincreasing01 in *. split.
  - intros Hf t Ht. assert (0 <= - f' t); [apply H; [intros s u Hs Hsu Hu; specialize (Hf s u Hs Hsu Hu); lra | exact Ht] | lra].
  - intros Hneg s u Hs Hsu Hu.
    assert (- f s <= - f u); [apply H; [intros t Ht; specialize (Hneg t Ht); lra | lra ..] | lra].
Qed.

(* L1 as LEMMAS.md states it: f is monotone on [0, 1] iff f' >= 0 on [0, 1] or f' <= 0 on [0, 1]. *)
Theorem L1 (f f' : R -> R) :
  (forall t, 0 <= t <= 1 -> is_derive f t (f' t)) ->
  (monotone01 f <->
   (forall t, 0 <= t <= 1 -> 0 <= f' t) \/ (forall t, 0 <= t <= 1 -> f' t <= 0)).
Proof.
  intros Hd. unfold monotone01.
  rewrite (L1_nondecreasing f f' Hd), (L1_nonincreasing f f' Hd). tauto.
Qed.

(* The consequence used below: f' strictly positive somewhere and strictly negative somewhere on [0, 1]
   means f is not monotone. *)
Theorem L1_consequence (f f' : R -> R) (t1 t2 : R) :
  (forall t, 0 <= t <= 1 -> is_derive f t (f' t)) ->
  0 <= t1 <= 1 -> 0 < f' t1 -> 0 <= t2 <= 1 -> f' t2 < 0 -> ~ monotone01 f.
Proof.
  intros Hd H1 Hp H2 Hn. rewrite (L1 f f' Hd).
  intros [H | H]; [specialize (H t2 H2) | specialize (H t1 H1)]; lra.
Qed.
