#include "experiments/inputs/mesh3_file.hpp"

#include "experiments/inputs/mesh_file.hpp"
#include "experiments/inputs/polygon_soup_file.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <vector>

namespace affinterp::io {

namespace {

using global3::Mesh3;

/// MEDIT's whitespace-separated tokens with their line numbers; '#' starts a comment to the end of the line.
class MeditTokens {
 public:
  MeditTokens(std::string_view text, std::string name) : text_(text), name_(std::move(name)) {}

  bool next(std::string_view& token) {
    for (; at_ < text_.size(); ++at_) {
      const char c = text_[at_];
      if (c == '\n') ++line_;
      if (c == '#')
        at_ = std::min(text_.size(), text_.find('\n', at_)) - 1;
      else if (!std::isspace(static_cast<unsigned char>(c)))
        break;
    }
    if (at_ >= text_.size()) return false;
    const std::size_t start = at_;
    while (at_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[at_])) && text_[at_] != '#') ++at_;
    token = text_.substr(start, at_ - start);
    return true;
  }

  template <class Number>
  Number number(const char* what) {
    std::string_view token;
    if (!next(token)) fail(std::string("ends where ") + what + " was expected");
    Number x{};
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), x);
    if (error != std::errc() || end != token.data() + token.size())
      fail(std::string("'") + std::string(token) + "' is not " + what);
    return x;
  }

  [[noreturn]] void fail(const std::string& problem) const {
    throw MeshFileError(name_ + ":" + std::to_string(line_) + ": " + problem);
  }

 private:
  std::string_view text_;
  std::string name_;
  std::size_t at_ = 0, line_ = 1;
};

/// Entries per record of the MEDIT sections the reader skips (indices and references).
const std::map<std::string, int, std::less<>> skipped_medit_sections = {
    {"Edges", 3},    {"Quadrilaterals", 5},   {"Hexahedra", 9},     {"Corners", 1},
    {"Ridges", 1},   {"RequiredVertices", 1}, {"RequiredEdges", 1}, {"Normals", 3},
    {"Tangents", 3}, {"NormalAtVertices", 2}};

/// A section of `corners` indices (1-based) and a reference per record, as columns of 0-based indices.
Eigen::MatrixXi read_medit_elements(MeditTokens& tokens, int corners, Eigen::Index vertex_count) {
  const auto count = tokens.number<long long>("a count");
  if (count < 0 || count > std::numeric_limits<int>::max()) tokens.fail("bad element count");
  Eigen::MatrixXi elements(corners, static_cast<Eigen::Index>(count));
  for (Eigen::Index i = 0; i < elements.cols(); ++i) {
    for (int c = 0; c < corners; ++c) {
      const auto index = tokens.number<long long>("a vertex index");
      if (index < 1 || index > vertex_count)
        tokens.fail("element " + std::to_string(i) + " names vertex " + std::to_string(index) + " of " +
                    std::to_string(vertex_count) + " (1-based)");
      elements(c, i) = static_cast<int>(index - 1);
    }
    tokens.number<long long>("a reference");
  }
  return elements;
}

Eigen::Matrix3Xd read_medit_vertices(MeditTokens& tokens) {
  const auto count = tokens.number<long long>("a count");
  if (count < 1 || count > std::numeric_limits<int>::max()) tokens.fail("bad vertex count");
  Eigen::Matrix3Xd vertices(3, static_cast<Eigen::Index>(count));
  for (Eigen::Index k = 0; k < vertices.cols(); ++k) {
    for (int c = 0; c < 3; ++c) {
      vertices(c, k) = tokens.number<double>("a coordinate");
      if (!std::isfinite(vertices(c, k))) tokens.fail("vertex " + std::to_string(k) + " is not finite");
    }
    tokens.number<double>("a reference");
  }
  return vertices;
}

void skip_medit_section(MeditTokens& tokens, int entries) {
  const auto count = tokens.number<long long>("a count");
  for (long long r = 0; r < count * entries; ++r) tokens.number<double>("a number");
}

Mesh3 read_surface3(const std::filesystem::path& file) {
  TriangleSoup soup = read_triangle_soup(file);
  Mesh3 mesh;
  mesh.vertices = std::move(soup.vertices);
  mesh.elements = std::move(soup.triangles);
  return mesh;
}

/// The extension of `file`, lower case.
std::string lowercase_extension(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return extension;
}

/// The next whitespace-separated token of `text` from `at`, skipping `#` comments to the end of their line.
std::string_view next_token(std::string_view text, std::size_t& at) {
  while (at < text.size()) {
    if (text[at] == '#')
      while (at < text.size() && text[at] != '\n') ++at;
    else if (std::isspace(static_cast<unsigned char>(text[at])))
      ++at;
    else
      break;
  }
  const std::size_t first = at;
  while (at < text.size() && !std::isspace(static_cast<unsigned char>(text[at])) && text[at] != '#') ++at;
  return text.substr(first, at - first);
}

/// Whether `token` is a number equal to 0.
bool is_zero(std::string_view token) {
  double value = 1;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  return error == std::errc() && end == token.data() + token.size() && value == 0;
}

}  // namespace

Mesh3 parse_medit(std::string_view text, const std::string& name) {
  MeditTokens tokens(text, name);
  Mesh3 mesh;
  Eigen::MatrixXi triangles, tetrahedra;
  for (std::string_view keyword; tokens.next(keyword) && keyword != "End";) {
    if (keyword == "MeshVersionFormatted")
      tokens.number<int>("a version");
    else if (keyword == "Dimension") {
      if (tokens.number<int>("a dimension") != 3) tokens.fail("Dimension must be 3");
    } else if (keyword == "Vertices")
      mesh.vertices = read_medit_vertices(tokens);
    else if (keyword == "Tetrahedra")
      tetrahedra = read_medit_elements(tokens, 4, mesh.vertex_count());
    else if (keyword == "Triangles")
      triangles = read_medit_elements(tokens, 3, mesh.vertex_count());
    else if (const auto skipped = skipped_medit_sections.find(keyword); skipped != skipped_medit_sections.end())
      skip_medit_section(tokens, skipped->second);
    else
      tokens.fail("unknown keyword '" + std::string(keyword) + "' (read: Vertices, Tetrahedra, Triangles)");
  }
  if (mesh.vertex_count() == 0) throw MeshFileError(name + ": no Vertices section");
  // a tetrahedral mesh's Triangles are its boundary facets, not elements of their own
  mesh.elements = tetrahedra.cols() > 0 ? tetrahedra : triangles;
  if (mesh.element_count() == 0) throw MeshFileError(name + ": no Tetrahedra or Triangles");
  return mesh;
}

bool surely_flat(std::string_view text, bool off) {
  std::size_t at = 0;
  if (!off) {
    for (std::size_t line = 0; line < text.size(); line = at + 1) {
      at = std::min(text.find('\n', line), text.size());
      const std::string_view record = text.substr(line, at - line);
      std::size_t in = 0;
      if (next_token(record, in) != "v") continue;
      next_token(record, in), next_token(record, in);
      const std::string_view z = next_token(record, in);
      if (!z.empty() && !is_zero(z)) return false;
    }
    return true;
  }
  if (next_token(text, at) != "OFF") return false;
  long long vertices = 0;
  const std::string_view count = next_token(text, at);
  const auto [end, error] = std::from_chars(count.data(), count.data() + count.size(), vertices);
  if (error != std::errc() || end != count.data() + count.size() || vertices < 0) return false;
  next_token(text, at), next_token(text, at);  // the faces' and the edges' counts
  for (long long k = 0; k < vertices; ++k) {
    next_token(text, at), next_token(text, at);
    if (!is_zero(next_token(text, at))) return false;
  }
  return true;
}

Mesh3 read_mesh3(const std::filesystem::path& file) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) throw MeshFileError(file.string() + ": no such file");
  const std::string extension = lowercase_extension(file);
  if (extension == ".mesh") return parse_medit(file_text(file), file.string());
  if (extension == ".obj" || extension == ".off" || extension == ".ply" || extension == ".stl")
    return read_surface3(file);
  throw MeshFileError(file.string() + ": unknown 3D mesh format '" + extension +
                      "' (.obj, .off, .ply, .stl surfaces; .mesh tetrahedra)");
}

std::optional<Mesh3> read_if_3d(const std::filesystem::path& file) {
  const std::string extension = lowercase_extension(file);
  if (extension == ".mesh") return read_mesh3(file);
  try {
    if ((extension == ".obj" || extension == ".off") && surely_flat(file_text(file), extension == ".off"))
      return std::nullopt;  // the 2D reader's, without a full read here first
    Mesh3 mesh = read_mesh3(file);
    if ((mesh.vertices.row(2).array() != 0).any()) return mesh;
  } catch (const MeshFileError&) {
  }
  return std::nullopt;
}

const char* mesh3_extension(const Mesh3& mesh) { return mesh.corners() == 4 ? ".mesh" : ".obj"; }

std::string mesh3_text(const Mesh3& mesh) {
  std::ostringstream text;
  text.precision(17);
  const bool medit = mesh.corners() == 4;
  if (medit) text << "MeshVersionFormatted 2\nDimension 3\nVertices\n" << mesh.vertex_count() << "\n";
  for (Eigen::Index k = 0; k < mesh.vertex_count(); ++k)
    text << (medit ? "" : "v ") << mesh.vertices(0, k) << ' ' << mesh.vertices(1, k) << ' ' << mesh.vertices(2, k)
         << (medit ? " 0\n" : "\n");
  if (medit) text << "Tetrahedra\n" << mesh.element_count() << "\n";
  for (Eigen::Index i = 0; i < mesh.element_count(); ++i) {
    text << (medit ? "" : "f");
    for (int c = 0; c < mesh.corners(); ++c) text << (medit && c == 0 ? "" : " ") << mesh.elements(c, i) + 1;
    text << (medit ? " 0\n" : "\n");
  }
  if (medit) text << "End\n";
  return text.str();
}

void write_mesh3(const Mesh3& mesh, const std::filesystem::path& file) {
  std::ofstream out(file, std::ios::binary);
  out << mesh3_text(mesh);
  if (!out.flush()) throw MeshFileError(file.string() + ": cannot be written");
}

}  // namespace affinterp::io
