#include "experiments/apps/cli/sym3_io.hpp"

#include "experiments/apps/cli/command.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace affinterp::cli {

namespace {

std::string format(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

/// The line's matrix, or a one-line description of what is wrong with it.
sym3::Mat3 parse(const std::string& line, std::size_t number) {
  const std::string where = "line " + std::to_string(number) + ": ";
  std::istringstream tokens(line);
  std::vector<double> values;
  for (std::string token; tokens >> token;) {
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if (end != token.c_str() + token.size()) throw CommandFailed(where + "'" + token + "' is not a number", 1);
    if (!std::isfinite(value)) {  // "inf", "nan", and overflow such as 1e999
      throw CommandFailed(where + "'" + token + "' is not finite", 1);
    }
    values.push_back(value);
  }
  if (values.size() != 9) {
    throw CommandFailed(where + "expected 9 numbers (a 3×3 matrix, row-major), found " + std::to_string(values.size()),
                        1);
  }
  sym3::Mat3 S;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) S(i, j) = values[3 * i + j];
  for (int i = 0; i < 3; ++i) {
    for (int j = i + 1; j < 3; ++j) {
      if (S(i, j) != S(j, i)) {
        throw CommandFailed(where + "not symmetric: entry (" + std::to_string(i + 1) + "," + std::to_string(j + 1) +
                                ") = " + format(S(i, j)) + " but (" + std::to_string(j + 1) + "," +
                                std::to_string(i + 1) + ") = " + format(S(j, i)),
                            1);
      }
    }
  }
  return S;
}

}  // namespace

void for_each_symmetric_matrix(std::istream& in, const std::function<void(const sym3::Mat3&, std::size_t)>& each) {
  std::size_t number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.find_first_not_of(" \t\r\f\v") == std::string::npos) continue;
    each(parse(line, number), number);
  }
}

void write_line(std::ostream& out, std::span<const double> values) {
  for (std::size_t i = 0; i < values.size(); ++i) out << (i ? " " : "") << format(values[i]);
  out << std::endl;
}

}  // namespace affinterp::cli
