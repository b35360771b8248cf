#pragma once
// A claim of the two papers, declared in its own file together with the check that decides it:
//   Kaji, Hirose, Sakata, Mizoguchi, Anjyo: Mathematical Analysis on Affine Maps for 2D Shape
//     Interpolation, Proc. SCA 2012 ("kaji.*").
//   Matsushita: A Study on 2D Shape Interpolation Using Affine Maps, doctoral thesis, Kyushu
//     University, 2015 ("thesis.*").
// Beyond the papers: the goodness atlases ("atlas.*", "atlas3.*") and the 3D sequel Kaji et al. announce ("sequel.*").
// The file is experiments/claims/<chapter>/<file_stem(id)>.cpp (kaji.polar.det → local/kaji_polar_det.cpp).
// It opens with the declaration, a ClaimDeclaration at namespace scope, which adds the claim to
// registered_claims() (registry.hpp) before main runs; under it, the reading, method and sizes, then the check.
#include "experiments/claims/context.hpp"
#include "experiments/claims/outcome.hpp"

#include <functional>
#include <string>
#include <string_view>

namespace affinterp::claims {

/// The folders experiments/claims/<chapter>/, in the report's order.
enum class Chapter { local, global, origin, sym3, atlas, atlas3, global3 };

/// The chapter's folder name.
std::string_view to_string(Chapter chapter);
/// The report section a chapter's claims appear under (the origin study is part of the global chapter).
std::string_view report_section(Chapter chapter);

using Check = std::function<Outcome(const ClaimContext&)>;

struct Claim {
  std::string_view id;         ///< stable: tools downstream look claims up by it; never renamed
  Chapter chapter;             ///< folder and report section
  std::string_view where;      ///< place in the paper
  std::string_view statement;  ///< paraphrase of what is claimed, in our own words
  /// How strong the verdict its method reaches is (grid, sample, exact counterexample, measured); a check that
  /// proves its claim for all reals says so in its Outcome, which takes precedence.
  Strength strength = Strength::unstated;
  Check check;  ///< decides the claim; empty while its check is not written (verdict `pending`)
};

/// The name of a claim's file: its ID with every character other than a letter or digit written '_'.
std::string file_stem(std::string_view claim_id);

/// Registers `claim` in registered_claims() when constructed. Define exactly one, at namespace scope, in the
/// claim's file; a malformed or repeated ID stops the program before main, naming the ID.
class ClaimDeclaration {
 public:
  explicit ClaimDeclaration(Claim claim);
};

}  // namespace affinterp::claims
