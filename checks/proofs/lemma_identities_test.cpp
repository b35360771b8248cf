// The algebraic steps of the lemmas L1–L13 written out in reports/proofs/LEMMAS.md, rechecked exactly: each
// identity is built here from the lemma's own objects with its steps left to the checkers (step_nodes.hpp: the
// derivative as diff, the substitution as subs, products, transposes and determinants of the lemma's matrices),
// decided by the identity prover's two checkers (GiNaC's normal() after GiNaC performs the steps, and the exact
// grid performing them itself), and its files must equal the committed ones in reports/proofs/lemmas/
// (<name>.ginsh, rerun with `ginsh`, which performs the steps too; .ginsh.out; .grid.out). No external decider
// runs.
// After a deliberate change, regenerate the committed files from the folder the failure message names.
#include "experiments/proofs/identity.hpp"
#include "experiments/proofs/step_nodes.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace affinterp::proofs::lemma_identities_test {
namespace {

using GiNaC::ex;
using GiNaC::matrix;

/// The names of every symbol of the identities.
const char* const names[] = {"t",  "a",  "b",   "c",   "d",   "b11",  "b12", "b21", "b22", "v1", "v2",
                             "co", "si", "x",   "y",   "h",   "beta", "phi", "sg",  "pi",  "B",  "l1",
                             "l2", "E",  "u11", "u12", "u21", "u22",  "l",   "cc",  "ss"};

/// One symbol per name, shared by every identity and by the parser of the committed scripts.
const GiNaC::symbol& sym(const std::string& name) {
  static const std::map<std::string, GiNaC::symbol> table = [] {
    std::map<std::string, GiNaC::symbol> t;
    for (const char* n : names) t.emplace(n, GiNaC::symbol(n));
    return t;
  }();
  return table.at(name);
}

/// e with `value` for the symbol `name`: a substitution the checkers perform.
ex at(const ex& e, const std::string& name, const ex& value) { return substitution(e, sym(name), value); }
ex d_dt(const ex& e) { return derivative(e, sym("t")); }

matrix mat(const ex& m00, const ex& m01, const ex& m10, const ex& m11) { return matrix{{m00, m01}, {m10, m11}}; }
/// The entries as one column: what prove_identity compares entry by entry.
matrix column(const std::vector<ex>& list) {
  matrix m(static_cast<unsigned>(list.size()), 1);
  for (unsigned i = 0; i < list.size(); ++i) m(i, 0) = list[i];
  return m;
}
matrix column(const ex& e0, const ex& e1) { return column(std::vector<ex>{e0, e1}); }
/// The entries of a and b, row by row, as one column.
matrix stacked(const matrix& a, const matrix& b) {
  std::vector<ex> list;
  for (const matrix* m : {&a, &b})
    for (unsigned i = 0; i < m->nops(); ++i) list.push_back(m->op(i));
  return column(list);
}
matrix identity2() { return mat(1, 0, 0, 1); }
/// A matrix-valued step (a product, a transpose) as the matrix of its entries, each an entry node: entrywise sums
/// and multiples of it stay plain arithmetic while the step itself is left to the checkers.
matrix entries_of(const ex& M) {
  const auto [rows, cols] = shape(M);
  matrix m(rows, cols);
  for (unsigned k = 0; k < rows * cols; ++k) m(k / cols, k % cols) = entry(M, k);
  return m;
}
matrix T(const matrix& m) { return entries_of(transposed(m)); }
/// The product of the factors, left to right, performed by the checkers.
matrix mm(std::vector<ex> factors) { return entries_of(product(factors)); }
ex norm_squared(const matrix& w) { return GiNaC::pow(w(0, 0), 2) + GiNaC::pow(w(1, 0), 2); }
/// vᵀ W v for a 2-column v.
ex form(const matrix& W, const matrix& v) { return entry(product({transposed(v), W, v}), 0); }
matrix sym_part(const matrix& M) { return M.add(T(M)).mul_scalar(GiNaC::numeric(1, 2)); }

/// R = [[co, −si], [si, co]] (a rotation when co² + si² = 1, the papers' R_θ with co = cos θ, si = sin θ).
matrix rotation() { return mat(sym("co"), -sym("si"), sym("si"), sym("co")); }
ex rotation_gram() { return GiNaC::pow(sym("co"), 2) + GiNaC::pow(sym("si"), 2); }
matrix general_B() { return mat(sym("b11"), sym("b12"), sym("b21"), sym("b22")); }
matrix blend(const matrix& B) { return identity2().mul_scalar(1 - sym("t")).add(B.mul_scalar(sym("t"))); }

std::vector<Identity> lemma_identities() {
  const ex t = sym("t"), x = sym("x"), y = sym("y"), beta = sym("beta"), sg = sym("sg"), pi = sym("pi"), B = sym("B");
  const matrix Bm = general_B(), v = column(sym("v1"), sym("v2")), R = rotation();
  const ex trB = Bm.trace(), detB = Bm.determinant();
  std::vector<Identity> list;

  // L2: det((1−t)I + tB) is 1 + c1 t + c2 t², its derivative affine with values tr B − 2, 2 det B − tr B.
  const ex f = determinant_of(blend(Bm));
  list.push_back({"L2.det-of-blend", "det((1-t)I + tB) = 1 + (tr B - 2)t + (1 - tr B + det B)t^2", f,
                  1 + (trB - 2) * t + (1 - trB + detB) * t * t});
  list.push_back({"L2.derivative-at-ends", "d/dt det((1-t)I + tB) at t = 0 and t = 1 is tr B - 2 and 2 det B - tr B",
                  column(at(d_dt(f), "t", 0), at(d_dt(f), "t", 1)), column(trB - 2, 2 * detB - trB)});

  // L3: ‖((1−t)I + tB)v‖² = ‖v‖² + 2t P(v) + t²‖Mv‖², M = B − I, P = sym M, Q = P + MᵀM.
  const matrix M = Bm.sub(identity2()), P = sym_part(M), Q = P.add(mm({transposed(M), M}));
  const ex q = norm_squared(mm({blend(Bm), v}));
  list.push_back({"L3.norm-squared-of-blend", "||((1-t)I + tB)v||^2 = ||v||^2 + 2t v^T P v + t^2 ||Mv||^2", q,
                  norm_squared(v) + 2 * t * form(P, v) + t * t * norm_squared(mm({M, v}))});
  list.push_back({"L3.half-derivative", "1/2 d/dt ||((1-t)I + tB)v||^2 = v^T P v + t ||Mv||^2, and v^T Q v at t = 1",
                  column(d_dt(q) / 2, at(d_dt(q) / 2, "t", 1)),
                  column(form(P, v) + t * norm_squared(mm({M, v})), form(Q, v))});

  // L5: rotations leave det and the norm alone.
  const matrix W = mat(sym("u11"), sym("u12"), sym("u21"), sym("u22"));
  list.push_back({"L5.det-rotation", "det R = co^2 + si^2", determinant_of(R), rotation_gram()});
  list.push_back({"L5.rotation-gram", "R^T R = R R^T = (co^2 + si^2) I",
                  stacked(mm({transposed(R), R}), mm({R, transposed(R)})),
                  stacked(identity2().mul_scalar(rotation_gram()), identity2().mul_scalar(rotation_gram()))});
  list.push_back({"L5.det-product", "det(W B) = det W det B for 2x2 W, B", determinant_of(product(W, Bm)),
                  determinant_of(W) * determinant_of(Bm)});
  list.push_back({"L5.norm-left-rotation", "||R w||^2 = (co^2 + si^2)||w||^2", norm_squared(mm({R, v})),
                  rotation_gram() * norm_squared(v)});

  // L6: the squared norm of a blend is homogeneous of degree 2 in v (the directions of the second formulations,
  // which do without Dines' theorem).
  list.push_back({"L6.norm-homogeneous", "||((1-t)I + tB)(l v)||^2 = l^2 ||((1-t)I + tB)v||^2",
                  norm_squared(mm({blend(Bm), v.mul_scalar(sym("l"))})),
                  GiNaC::pow(sym("l"), 2) * norm_squared(mm({blend(Bm), v}))});

  // L7: conjugation by a rotation O = R.
  const matrix A = mat(sym("a"), sym("b"), sym("c"), sym("d")), J = mat(0, -1, 1, 0);
  const matrix OtAO = mm({transposed(R), A, R});
  list.push_back({"L7.conjugated-blend", "(1-t)(co^2+si^2) I + t O^T A O = O^T((1-t)I + tA)O, O = R",
                  identity2().mul_scalar((1 - t) * rotation_gram()).add(OtAO.mul_scalar(t)),
                  mm({transposed(R), blend(A), R})});
  list.push_back({"L7.sym-and-gram", "sym(O^T A O) = O^T sym(A) O; (O^T A O)^T(O^T A O) = (co^2+si^2) O^T A^T A O",
                  stacked(sym_part(OtAO), mm({transposed(OtAO), OtAO})),
                  stacked(mm({transposed(R), sym_part(A), R}),
                          mm({transposed(R), transposed(A), A, R}).mul_scalar(rotation_gram()))});
  list.push_back({"L7.skew-part", "A = sym(A) + k J, k = (c - b)/2, J = [[0, -1], [1, 0]]", A,
                  sym_part(A).add(J.mul_scalar((sym("c") - sym("b")) / 2))});
  list.push_back(
      {"L7.skew-commutes", "O^T J O = (co^2 + si^2) J", mm({transposed(R), J, R}), J.mul_scalar(rotation_gram())});

  // L8 (b): a symmetric 2×2 W = [[x, h], [h, y]]: x vᵀWv = (x v1 + h v2)² + det W v2².
  const matrix Ws = mat(x, sym("h"), sym("h"), y);
  list.push_back({"L8.psd-completed-square", "x v^T W v = (x v1 + h v2)^2 + (xy - h^2) v2^2, W = [[x, h], [h, y]]",
                  x * form(Ws, v),
                  GiNaC::pow(x * sym("v1") + sym("h") * sym("v2"), 2) + determinant_of(Ws) * GiNaC::pow(sym("v2"), 2)});

  // L9: the SVD homotopy, D = diag(x, y), u = (cos ψ, sin ψ), ψ = φ + tβ.
  const ex m1 = x - 1, m2 = y - 1, a = 1 + t * m1, b = 1 + t * m2, psi = sym("phi") + t * beta;
  const matrix u = column(GiNaC::cos(psi), GiNaC::sin(psi)), Dt = blend(mat(x, 0, 0, y));
  const ex fs = norm_squared(mm({Dt, u}));
  const matrix G_t = mat(m1 * a, beta * (b * b - a * a) / 2, beta * (b * b - a * a) / 2, m2 * b);
  const ex G = 4 * m1 * m2 * a * b - beta * beta * t * t * GiNaC::pow(x - y, 2) * GiNaC::pow(2 + t * (x + y - 2), 2);
  list.push_back({"L9.norm-squared",
                  "||((1-t)I + tD)u||^2 = a^2 cos^2 psi + b^2 sin^2 psi, a = 1 + t(x-1), "
                  "b = 1 + t(y-1)",
                  fs, a * a * GiNaC::pow(GiNaC::cos(psi), 2) + b * b * GiNaC::pow(GiNaC::sin(psi), 2)});
  list.push_back(
      {"L9.derivative", "d/dt ||((1-t)I + tD)u(phi + t beta)||^2 = 2 u^T G_t u", d_dt(fs), 2 * form(G_t, u)});
  list.push_back({"L9.G-is-4-det", "4 det G_t = G(t) = 4(x-1)(y-1)ab - beta^2 t^2 (x-y)^2 (2 + t(x+y-2))^2",
                  4 * determinant_of(G_t), G});
  const ex c0 = GiNaC::cos(sym("phi")), s0 = GiNaC::sin(sym("phi"));
  list.push_back({"L9.second-derivative-at-0",
                  "d^2/dt^2 at t = 0: 2 m1^2 cos^2 phi + 2 m2^2 sin^2 phi + 8 beta (m2 - m1) sin phi cos phi",
                  at(derivative(fs, sym("t"), 2), "t", 0),
                  2 * m1 * m1 * c0 * c0 + 2 * m2 * m2 * s0 * s0 + 8 * beta * (m2 - m1) * s0 * c0});
  // cos²φ0 = cc, sin²φ0 = ss where d/dt at t = 0 vanishes, substituted.
  const ex cc = sym("cc"), ss = sym("ss");
  const GiNaC::exmap root{{cc, m2 / (m2 - m1)}, {ss, -m1 / (m2 - m1)}};
  list.push_back({"L9.mixed-signs-root",
                  "cos^2 = m2/(m2-m1), sin^2 = -m1/(m2-m1): sum 1, m1 cos^2 + m2 sin^2 = 0, "
                  "2 m1^2 cos^2 + 2 m2^2 sin^2 = -2 m1 m2",
                  column({substitution(cc + ss, root), substitution(m1 * cc + m2 * ss, root),
                          substitution(2 * m1 * m1 * cc + 2 * m2 * m2 * ss, root)}),
                  column({1, 0, -2 * m1 * m2})});

  // L12: G in σ = x + y − 2, π = (x−1)(y−1), B = β², and the chain at the largest admissible B*.
  const auto Gs = [&](const ex& tt, const ex& BB, const ex& pp) {
    return 4 * pp * (1 + tt * sg + tt * tt * pp) - BB * tt * tt * (sg * sg - 4 * pp) * GiNaC::pow(2 + tt * sg, 2);
  };
  const GiNaC::exmap to_xy{{sg, x + y - 2}, {pi, (x - 1) * (y - 1)}, {B, beta * beta}};
  list.push_back({"L12.svd-coordinates", "G(t) = 4 pi (1 + t sg + t^2 pi) - B t^2 (sg^2 - 4 pi)(2 + t sg)^2", G,
                  substitution(Gs(t, B, pi), to_xy)});
  list.push_back({"L12.condition-is-G1", "G(1) = 4xy(x-1)(y-1) - beta^2 (x-y)^2 (x+y)^2", at(G, "t", 1),
                  4 * x * y * (x - 1) * (y - 1) - beta * beta * GiNaC::pow(x - y, 2) * GiNaC::pow(x + y, 2)});
  list.push_back(
      {"L12.image", "1 + sg + pi = xy, sg^2 - 4 pi = (x-y)^2, 2 + sg = x + y",
       column({substitution(1 + sg + pi, to_xy), substitution(sg * sg - 4 * pi, to_xy), substitution(2 + sg, to_xy)}),
       column({x * y, GiNaC::pow(x - y, 2), x + y})});
  const ex C = GiNaC::pow(sg, 3) * (t * t * t + t * t + t) + sg * sg * pi * (t * t * t + t * t) +
               sg * sg * (t * t * t + 5 * t * t + 5 * t + 1) + 4 * sg * pi * t * t + 4 * sg * (t * t + 2 * t + 1) +
               4 * t + 4;
  list.push_back(
      {"L12.C", "(1-t)C = (1 + t sg + t^2 pi)(2 + sg)^2 - t^2 (2 + t sg)^2 (1 + sg + pi)", (1 - t) * C,
       (1 + t * sg + t * t * pi) * GiNaC::pow(2 + sg, 2) - t * t * GiNaC::pow(2 + t * sg, 2) * (1 + sg + pi)});
  const ex Bstar = 4 * pi * (1 + sg + pi) / ((sg * sg - 4 * pi) * GiNaC::pow(2 + sg, 2));
  list.push_back({"L12.G-at-Bstar",
                  "G(t) at B* = 4 pi (1+sg+pi)/((sg^2-4pi)(2+sg)^2) is 4 pi (1-t) C/(2+sg)^2, and "
                  "G(1) = 0 there",
                  column(at(Gs(t, B, pi), "B", Bstar), at(at(Gs(t, B, pi), "B", Bstar), "t", 1)),
                  column(4 * pi * (1 - t) * C / GiNaC::pow(2 + sg, 2), 0)});
  list.push_back({"L12.C-affine-in-pi", "C = C(pi = 0) + pi sg t^2 (sg(1 + t) + 4)", C,
                  at(C, "pi", 0) + pi * sg * t * t * (sg * (1 + t) + 4)});
  list.push_back({"L12.C-at-x-equals-y", "C(pi = sg^2/4) = (1 + t)(2 + t sg)^2 (2 + sg)^2/4", at(C, "pi", sg * sg / 4),
                  (1 + t) * GiNaC::pow(2 + t * sg, 2) * GiNaC::pow(2 + sg, 2) / 4});
  list.push_back({"L12.degenerate",
                  "G(t) at pi = 0 is -B t^2 sg^2 (2 + t sg)^2; at pi = sg^2/4 it is "
                  "sg^2 (1 + t sg/2)^2",
                  column(at(Gs(t, B, pi), "pi", 0), at(Gs(t, B, pi), "pi", sg * sg / 4)),
                  column(-B * t * t * sg * sg * GiNaC::pow(2 + t * sg, 2), sg * sg * GiNaC::pow(1 + t * sg / 2, 2))});

  // L10: exp-log, S = R diag(l1, l2) Rᵀ; E = e^{2(log l1 − log l2)} > 1 in the witness.
  const matrix Lambda = mat(sym("l1"), 0, 0, sym("l2")), w = mm({transposed(R), v});
  list.push_back({"L10.spectral-norm", "||R diag(l1, l2) R^T v||^2 = (co^2+si^2)(l1^2 w1^2 + l2^2 w2^2), w = R^T v",
                  norm_squared(mm({R, Lambda, w})),
                  rotation_gram() * (sym("l1") * sym("l1") * GiNaC::pow(w(0, 0), 2) +
                                     sym("l2") * sym("l2") * GiNaC::pow(w(1, 0), 2))});
  const ex w2sq = -sym("l1") * (1 + sym("E")) / (2 * sym("l2"));
  list.push_back({"L10.witness",
                  "w1 = 1, w2^2 = -l1(1 + E)/(2 l2): l1 + l2 w2^2 = l1(1 - E)/2, "
                  "l1 E + l2 w2^2 = l1(E - 1)/2",
                  column(sym("l1") + sym("l2") * w2sq, sym("l1") * sym("E") + sym("l2") * w2sq),
                  column(sym("l1") * (1 - sym("E")) / 2, sym("l1") * (sym("E") - 1) / 2)});

  // L11: A = R_α D R_β = (R_α R_β)(R_βᵀ D R_β) when R_β R_βᵀ = I; tr and det of S = R_βᵀ D R_β.
  const matrix D = mat(x, 0, 0, y), S = mm({transposed(R), D, R});
  list.push_back({"L11.polar-factor", "(co^2+si^2) U D R = (U R)(R^T D R) for every U, R = R_beta",
                  mm({W, D, R}).mul_scalar(rotation_gram()), mm({W, R, S})});
  list.push_back({"L11.trace-det", "tr(R^T D R) = (co^2+si^2) tr D, det(R^T D R) = (co^2+si^2)^2 det D",
                  column(S.trace(), determinant_of(S)),
                  column(rotation_gram() * D.trace(), GiNaC::pow(rotation_gram(), 2) * D.determinant())});

  // L13: S = [[x, h], [h, y]]: (z − l1)(z − l2) = z² − tr S z + det S when l1 + l2 = tr S, l1 l2 = det S; the
  // discriminant tr² − 4 det = (x − y)² + 4h² ≥ 0.
  list.push_back({"L13.discriminant", "tr(S)^2 - 4 det S = (x - y)^2 + 4 h^2, S = [[x, h], [h, y]]",
                  GiNaC::pow(Ws.trace(), 2) - 4 * determinant_of(Ws), GiNaC::pow(x - y, 2) + 4 * sym("h") * sym("h")});
  return list;
}

std::string read(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// The entries of a side, row by row (a matrix, or a matrix-valued step as entry nodes) or the side itself.
std::vector<ex> entries(const ex& side) {
  if (!GiNaC::is_a<matrix>(side)) {
    if (shape(side).first != 0) return entries(entries_of(side));
    return {side};
  }
  std::vector<ex> list;
  for (std::size_t i = 0; i < side.nops(); ++i) list.push_back(side.op(i));
  return list;
}

/// The committed script's sides, `is(normal((lhs)-(rhs))==0);` per line, read with GiNaC's parser.
std::vector<std::pair<ex, ex>> sides_of(const std::string& script) {
  GiNaC::symtab table;
  for (const char* n : names) table[n] = sym(n);
  const auto parse = [&table](const std::string& text) { return read_script_expression(text, table); };
  std::vector<std::pair<ex, ex>> sides;
  const std::string open = "is(normal((", middle = ")-(", close = "))==0);";
  for (const std::string& line : lines_of(script)) {
    if (line.rfind(open, 0) != 0) continue;
    const std::string body = line.substr(open.size(), line.size() - open.size() - close.size());
    // lhs ends at the one ")-(" where the parentheses opened after "((" are balanced.
    int depth = 0;
    for (std::size_t i = 0; i < body.size(); ++i) {
      if (depth == 0 && body.compare(i, middle.size(), middle) == 0) {
        sides.emplace_back(parse(body.substr(0, i)), parse(body.substr(i + middle.size())));
        break;
      }
      depth +=
          (body[i] == '(' || body[i] == '[' || body[i] == '{') - (body[i] == ')' || body[i] == ']' || body[i] == '}');
    }
  }
  return sides;
}

/// .grid.out without the names of its variables: GiNaC prints sums (also inside cos(φ + tβ)) in an order that
/// varies from process to process, so the lines "d(<variable>) = <bound>" are compared as a multiset of bounds.
std::multiset<std::string> grid_lines(const std::string& text) {
  std::multiset<std::string> lines;
  for (const std::string& line : lines_of(text))
    lines.insert(line.rfind("d(", 0) == 0 ? line.substr(line.rfind(") = ") + 1) : line);
  return lines;
}

const std::filesystem::path committed = std::filesystem::path(AFFINTERP_SOURCE_DIR) / "reports/proofs/lemmas";

// Each committed script states the identity built here from the lemma's objects (entry by entry, the same steps,
// up to GiNaC's order of terms), and the script as committed is decided "zero" by both checkers with the committed
// answers.
TEST(LemmaIdentities, EachCommittedScriptStatesItsIdentityAndHolds) {
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "lemma-identities";
  std::filesystem::remove_all(dir);
  for (const Identity& identity : lemma_identities()) {
    SCOPED_TRACE(identity.name);
    const std::filesystem::path script = committed / (identity.name + ".ginsh");
    if (!std::filesystem::exists(script)) {
      prove_identity(identity, {dir, "proofs/lemmas"});
      ADD_FAILURE() << script << " missing; written to " << dir;
      continue;
    }
    const std::vector<std::pair<ex, ex>> stated = sides_of(read(script));
    const std::vector<ex> lhs = entries(identity.lhs), rhs = entries(identity.rhs);
    ASSERT_EQ(stated.size(), lhs.size());
    std::vector<ex> stated_lhs, stated_rhs;
    for (std::size_t i = 0; i < lhs.size(); ++i) {
      EXPECT_TRUE((perform_steps(stated[i].first) - perform_steps(lhs[i])).normal().is_zero())
          << "entry " << i << ": lhs differs";
      EXPECT_TRUE((perform_steps(stated[i].second) - perform_steps(rhs[i])).normal().is_zero())
          << "entry " << i << ": rhs differs";
      EXPECT_EQ(has_steps(stated[i].first), has_steps(lhs[i])) << "entry " << i << ": lhs's steps differ";
      EXPECT_EQ(has_steps(stated[i].second), has_steps(rhs[i])) << "entry " << i << ": rhs's steps differ";
      stated_lhs.push_back(stated[i].first), stated_rhs.push_back(stated[i].second);
    }
    const ProofSentence s = prove_identity({identity.name, identity.meaning, column(stated_lhs), column(stated_rhs)},
                                           {dir, "proofs/lemmas"});
    EXPECT_EQ(s.result, "zero") << identity.meaning;
    EXPECT_EQ(lines_of(read(script)).at(0), lines_of(read(dir / (identity.name + ".ginsh"))).at(0));
    EXPECT_EQ(read(committed / (identity.name + ".ginsh.out")), read(dir / (identity.name + ".ginsh.out")));
    EXPECT_EQ(grid_lines(read(committed / (identity.name + ".grid.out"))),
              grid_lines(read(dir / (identity.name + ".grid.out"))));
  }
}

TEST(LemmaIdentities, EveryCommittedScriptIsBuiltHere) {
  std::set<std::string> built;
  for (const Identity& identity : lemma_identities()) built.insert(identity.name + ".ginsh");
  for (const auto& entry : std::filesystem::directory_iterator(committed))
    if (entry.path().extension() == ".ginsh") {
      EXPECT_TRUE(built.count(entry.path().filename().string())) << entry << " is built by no identity here";
    }
}

}  // namespace
}  // namespace affinterp::proofs::lemma_identities_test
