#pragma once
// What a claim's entry of claims.json says in one line, for the summary's table and the head of its page: how
// strong its verdict is, its evidence, and whether a figure is an interactive viewer.
#include <nlohmann/json.hpp>

#include <string>

namespace affinterp::report {

/// How strong a claim's verdict is, in the words of the report's "Strength" list.
std::string strength_words(const nlohmann::json& claim);

/// The evidence's method, sample size, seed, tolerance and worst deviation.
std::string one_line_evidence(const nlohmann::json& evidence);

/// The checkers that answered every sentence of a formulation they ran on, "qepcad, z3" ("none").
std::string checkers(const nlohmann::json& proof);

/// An interactive viewer page among a claim's figures (plots/viewer.hpp): linked, not shown as an image.
bool is_viewer(const std::string& path);

}  // namespace affinterp::report
