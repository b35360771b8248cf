#include "experiments/claims/claim.hpp"

#include <cctype>

namespace affinterp::claims {

std::string_view to_string(Chapter chapter) {
  switch (chapter) {
    case Chapter::local:
      return "local";
    case Chapter::global:
      return "global";
    case Chapter::origin:
      return "origin";
    case Chapter::sym3:
      return "sym3";
    case Chapter::atlas:
      return "atlas";
    case Chapter::atlas3:
      return "atlas3";
    case Chapter::global3:
      return "global3";
  }
  return "?";
}

std::string_view report_section(Chapter chapter) {
  switch (chapter) {
    case Chapter::local:
      return "Local interpolation (Kaji §3 and Appendix; thesis §2.2)";
    case Chapter::global:
    case Chapter::origin:
      return "Global interpolation (Kaji §4 and Appendix; thesis §2.3)";
    case Chapter::sym3:
      return "Exponential of 3×3 symmetric matrices (thesis ch. 3)";
    case Chapter::atlas:
      return "The goodness atlas (beyond the papers: where each homotopy is good, proved for all reals)";
    case Chapter::atlas3:
      return "The 3D goodness atlas (beyond the papers: the sequel Kaji et al. announce, for 3×3 maps)";
    case Chapter::global3:
      return "3D interpolation and blending (beyond the papers: the sequel Kaji et al. announce, for 3D meshes)";
  }
  return "?";
}

std::string file_stem(std::string_view claim_id) {
  std::string stem(claim_id);
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return stem;
}

}  // namespace affinterp::claims
