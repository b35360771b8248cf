#pragma once
// The project's registry of claims: every statement of the two papers the suite decides, with a
// stable ID, where it is printed, and a paraphrase in our own words.
//   Kaji, Hirose, Sakata, Mizoguchi, Anjyo: Mathematical Analysis on Affine Maps for 2D Shape
//     Interpolation, Proc. SCA 2012 ("kaji.*").
//   Matsushita: A Study on 2D Shape Interpolation Using Affine Maps, doctoral thesis, Kyushu
//     University, 2015 ("thesis.*").
#include <span>
#include <string_view>

namespace affinterp::claims {

struct ClaimInfo {
  std::string_view id;         ///< stable: tools downstream look claims up by it
  std::string_view group;      ///< report section
  std::string_view where;      ///< place in the paper
  std::string_view statement;  ///< paraphrase of what is claimed
};

std::span<const ClaimInfo> catalogue();
const ClaimInfo* find_claim(std::string_view id);

}  // namespace affinterp::claims
