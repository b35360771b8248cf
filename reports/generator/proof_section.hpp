#pragma once
// A claim's proof for all reals on its page: each formulation's sentences with every checker's answer and the files
// to rerun them with, and what was tried for the record and answered nothing.
#include <nlohmann/json.hpp>

#include <sstream>
#include <string>

namespace affinterp::report {

/// Writes `proof` (claims.json's "proof"); its files' paths, relative to the report's folder, are prefixed with
/// `up` (the way from the page's folder back to the report's).
void write_proof(std::ostringstream& md, const nlohmann::json& proof, const std::string& up);

}  // namespace affinterp::report
