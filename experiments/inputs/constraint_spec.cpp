#include "experiments/inputs/constraint_spec.hpp"

#include "experiments/inputs/mesh_file.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace affinterp::io {

namespace {

[[noreturn]] void refuse(const std::string& kind, const std::string& spec, const std::string& problem) {
  std::string message = kind;
  message += " '";
  message += spec;
  message += "': ";
  throw std::invalid_argument(message + problem);
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t end; (end = text.find(separator, start)) != std::string::npos; start = end + 1)
    parts.push_back(text.substr(start, end - start));
  parts.push_back(text.substr(start));
  return parts;
}

std::optional<double> to_number(const std::string& text) {
  double x = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (error != std::errc() || end != text.data() + text.size() || text.empty() || !std::isfinite(x))
    return std::nullopt;
  return x;
}

struct Parser {
  std::string kind, spec;

  Eigen::Index vertex(const std::string& text) const {
    long long k = -1;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), k);
    if (error != std::errc() || end != text.data() + text.size() || text.empty() || k < 0)
      refuse(kind, spec, "'" + text + "' is not a vertex index (0, 1, 2, ...)");
    return static_cast<Eigen::Index>(k);
  }

  /// Splits "body@C" into body and C (1 when absent).
  std::pair<std::string, double> weighted(const std::string& text) const {
    const auto at = text.rfind('@');
    if (at == std::string::npos) return {text, 1.0};
    const auto c = to_number(text.substr(at + 1));
    if (!c || *c <= 0) refuse(kind, spec, "the weight after '@' must be a positive number");
    return {text.substr(0, at), *c};
  }

  /// The points "x1,y1;x2,y2;..." (Dim = 2) or "x1,y1,z1;..." (Dim = 3), at least two.
  template <int Dim>
  Eigen::Matrix<double, Dim, Eigen::Dynamic> points(const std::string& text) const {
    const auto items = split(text, ';');
    Eigen::Matrix<double, Dim, Eigen::Dynamic> result(Dim, static_cast<Eigen::Index>(items.size()));
    for (std::size_t j = 0; j < items.size(); ++j) {
      const auto coordinates = split(items[j], ',');
      bool valid = coordinates.size() == Dim;
      for (int d = 0; valid && d < Dim; ++d) {
        const auto x = to_number(coordinates[static_cast<std::size_t>(d)]);
        if (x) result(d, static_cast<Eigen::Index>(j)) = *x;
        valid = x.has_value();
      }
      if (!valid) refuse(kind, spec, "'" + items[j] + "' is not a point '" + (Dim == 2 ? "x,y" : "x,y,z") + "'");
    }
    if (result.cols() < 2) refuse(kind, spec, "a path needs at least two points (t = 0 and t = 1)");
    return result;
  }
};

}  // namespace

global::PinnedVertex parse_pin(const std::string& spec) {
  const Parser p{"--pin", spec};
  const auto [body, c] = p.weighted(spec);
  return {p.vertex(body), c};
}

global::VertexLocus parse_locus(const std::string& spec) {
  const Parser p{"--locus", spec};
  const auto colon = spec.find(':');
  if (colon == std::string::npos) refuse(p.kind, spec, "expected 'V[@C]:x1,y1;x2,y2;...'");
  const auto [head, c] = p.weighted(spec.substr(0, colon));
  return {p.vertex(head), p.points<2>(spec.substr(colon + 1)), c};
}

global3::VertexLocus3 parse_locus3(const std::string& spec) {
  const Parser p{"--locus", spec};
  const auto colon = spec.find(':');
  if (colon == std::string::npos) refuse(p.kind, spec, "expected 'V[@C]:x1,y1,z1;x2,y2,z2;...'");
  const auto [head, c] = p.weighted(spec.substr(0, colon));
  return {p.vertex(head), p.points<3>(spec.substr(colon + 1)), c};
}

global::EdgeDirection parse_edge_direction(const std::string& spec) {
  const Parser p{"--edge-direction", spec};
  const auto [body, c] = p.weighted(spec);
  const auto parts = split(body, ':');
  if (parts.size() != 2 && parts.size() != 3) refuse(p.kind, spec, "expected 'I:J[:homotopy|linear][@C]'");
  global::EdgeDirection edge{p.vertex(parts[0]), p.vertex(parts[1]), global::EdgeDirection::Path::local_homotopy, c};
  if (edge.i == edge.j) refuse(p.kind, spec, "the edge's two vertices must differ");
  if (parts.size() == 3) {
    if (parts[2] == "linear")
      edge.path = global::EdgeDirection::Path::linear;
    else if (parts[2] != "homotopy")
      refuse(p.kind, spec, "the path must be 'homotopy' or 'linear'");
  }
  return edge;
}

std::optional<global::BarycentreLocus> parse_barycentre(const std::string& spec) {
  const Parser p{"--barycentre-locus", spec};
  if (spec == "none") return std::nullopt;
  const auto [body, c] = p.weighted(spec);
  global::BarycentreLocus locus{Eigen::Matrix2Xd(2, 0), c};
  if (body != "linear") locus.points = p.points<2>(body);
  return locus;
}

std::optional<global3::BarycentreLocus3> parse_barycentre3(const std::string& spec) {
  const Parser p{"--barycentre-locus", spec};
  if (spec == "none") return std::nullopt;
  const auto [body, c] = p.weighted(spec);
  global3::BarycentreLocus3 locus{c, Eigen::Matrix3Xd(3, 0)};
  if (body != "linear") locus.points = p.points<3>(body);
  return locus;
}

namespace {

void check_vertex(Eigen::Index k, const std::string& what, Eigen::Index vertex_count) {
  if (k >= vertex_count)
    throw std::invalid_argument(what + " names vertex " + std::to_string(k) + " but the mesh has " +
                                std::to_string(vertex_count) + " vertices (indices start at 0)");
}

}  // namespace

global3::Constraints3 parse_constraints3(const std::vector<std::string>& pins, const std::vector<std::string>& loci,
                                         const std::string& barycentre, Eigen::Index vertex_count) {
  global3::Constraints3 constraints;
  for (const std::string& spec : pins) {
    constraints.pinned.push_back(parse_pin(spec));
    check_vertex(constraints.pinned.back().vertex, "--pin", vertex_count);
  }
  for (const std::string& spec : loci) {
    constraints.loci.push_back(parse_locus3(spec));
    check_vertex(constraints.loci.back().vertex, "--locus", vertex_count);
  }
  constraints.barycentre = parse_barycentre3(barycentre);
  return constraints;
}

void check_constraint_vertices(const global::Constraints& constraints, Eigen::Index vertex_count) {
  const auto check = [&](Eigen::Index k, const std::string& what) { check_vertex(k, what, vertex_count); };
  for (const auto& pin : constraints.pinned) check(pin.vertex, "--pin");
  for (const auto& locus : constraints.loci) check(locus.vertex, "--locus");
  for (const auto& edge : constraints.edges) {
    check(edge.i, "--edge-direction");
    check(edge.j, "--edge-direction");
  }
}

Eigen::VectorXd read_weights(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw MeshFileError(file.string() + ": cannot be opened");
  std::vector<double> weights;
  long long line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    line = line.substr(0, line.find('#'));
    const auto first = line.find_first_not_of(" \t\r"), last = line.find_last_not_of(" \t\r");
    if (first == std::string::npos) continue;
    const auto w = to_number(line.substr(first, last - first + 1));
    if (!w) throw MeshFileError(file.string() + ":" + std::to_string(line_number) + ": not a finite number");
    weights.push_back(*w);
  }
  return Eigen::Map<Eigen::VectorXd>(weights.data(), static_cast<Eigen::Index>(weights.size()));
}

}  // namespace affinterp::io
