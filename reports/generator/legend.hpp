#pragma once
// The legends of the summary page: what each verdict means, and how strong each kind of evidence is.
#include <nlohmann/json.hpp>

#include <sstream>

namespace affinterp::report {

void write_verdict_legend(std::ostringstream& md);
/// The strengths' meanings, then how many of `claims` (claims.json's array) have each.
void write_strength_legend(std::ostringstream& md, const nlohmann::json& claims);

}  // namespace affinterp::report
