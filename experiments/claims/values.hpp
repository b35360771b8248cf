#pragma once
// Values in claims.json: matrices as arrays of rows, exact numbers as "p/q" strings.
// (Build matrices with these helpers: a brace-initialised nlohmann::json of pairs becomes an object.)
#include "theory/exact/rational.hpp"

#include <nlohmann/json.hpp>

namespace affinterp::claims {

/// An exact matrix as an array of rows of "p/q" strings.
template <class Derived>
nlohmann::json exact_matrix(const Eigen::MatrixBase<Derived>& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index j = 0; j < m.cols(); ++j) row.push_back(exact::to_string(m(i, j)));
    rows.push_back(row);
  }
  return rows;
}

/// A floating-point matrix as an array of rows of numbers (JSON keeps 17 significant digits).
template <class Derived>
nlohmann::json float_matrix(const Eigen::MatrixBase<Derived>& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index j = 0; j < m.cols(); ++j) row.push_back(static_cast<double>(m(i, j)));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace affinterp::claims
