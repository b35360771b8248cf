#include "experiments/inputs/mesh_file.hpp"

#include "experiments/inputs/polygon_soup_file.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace affinterp::io {

namespace {

namespace fs = std::filesystem;

/// Counts and indices must fit the int vertex indices of global::Mesh.
constexpr long long max_count = INT_MAX;

/// Text split into lines and whitespace-separated tokens, with the position for error messages.
class LineReader {
 public:
  LineReader(std::string_view text, const std::string& name) : text_(text), name_(name) {
    if (const auto nul = text.find('\0'); nul != std::string_view::npos)
      fail_at(1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(nul), '\n'),
              "NUL byte: not a text mesh file");
  }

  /// Advances to the next line that has a token (comments after '#' removed); false at the end.
  bool next() {
    while (position_ < text_.size()) {
      const std::size_t end = std::min(text_.find('\n', position_), text_.size());
      std::string_view line = text_.substr(position_, end - position_);
      position_ = end + 1;
      ++line_number_;
      if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
      tokens_.clear();
      std::size_t i = 0;
      while (i < line.size()) {
        while (i < line.size() && is_space(line[i])) ++i;
        const std::size_t start = i;
        while (i < line.size() && !is_space(line[i])) ++i;
        if (i > start) tokens_.push_back(line.substr(start, i - start));
      }
      if (!tokens_.empty()) return true;
    }
    return false;
  }

  const std::vector<std::string_view>& tokens() const { return tokens_; }
  long long line_number() const { return line_number_; }

  [[noreturn]] void fail(const std::string& problem) const { fail_at(line_number_, problem); }
  [[noreturn]] void fail_at(long long line, const std::string& problem) const {
    throw MeshFileError(name_ + ":" + std::to_string(line) + ": " + problem);
  }
  [[noreturn]] void fail_at_end(const std::string& problem) const { throw MeshFileError(name_ + ": " + problem); }

  double number(std::string_view token) const {
    std::string_view digits = token;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    double x = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), x);
    if (error != std::errc() || end != digits.data() + digits.size() || digits.empty())
      fail(quoted(token) + " is not a number");
    return x;
  }

  long long integer(std::string_view token) const {
    std::string_view digits = token;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    long long n = 0;
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
    if (error == std::errc::result_out_of_range) fail(quoted(token) + " is out of range");
    if (error != std::errc() || end != digits.data() + digits.size() || digits.empty())
      fail(quoted(token) + " is not an integer");
    return n;
  }

  /// The token in quotes as it may be shown on one line (built by appending: GCC 12 misreports "'" + s).
  static std::string quoted(std::string_view token) {
    std::string shown = "'";
    shown += printable(token);
    shown += "'";
    return shown;
  }

  /// The token as it may be shown on one line: at most 40 characters, control bytes as '?'.
  static std::string printable(std::string_view token) {
    std::string shown(token.substr(0, 40));
    for (char& c : shown)
      if (std::iscntrl(static_cast<unsigned char>(c))) c = '?';
    return token.size() > 40 ? shown + "..." : shown;
  }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

  std::string_view text_;
  const std::string& name_;
  std::size_t position_ = 0;
  long long line_number_ = 0;
  std::vector<std::string_view> tokens_;
};

/// Reads the planar point (x, y) from `tokens[first..]`: x y, or x y z with z = 0.
void read_point(const LineReader& in, std::size_t first, std::vector<double>& coordinates) {
  const auto& tokens = in.tokens();
  const double x = in.number(tokens[first]), y = in.number(tokens[first + 1]);
  if (tokens.size() == first + 3) {
    const double z = in.number(tokens[first + 2]);
    if (z != 0)
      in.fail("z = " + LineReader::printable(tokens[first + 2]) + " is not 0: only planar meshes (z = 0) are read");
  }
  coordinates.push_back(x);
  coordinates.push_back(y);
}

global::Mesh assemble(std::vector<double>& coordinates, std::vector<int>& corners) {
  global::Mesh mesh;
  mesh.vertices =
      Eigen::Map<Eigen::Matrix2Xd>(coordinates.data(), 2, static_cast<Eigen::Index>(coordinates.size() / 2));
  mesh.triangles = Eigen::Map<Eigen::Matrix3Xi>(corners.data(), 3, static_cast<Eigen::Index>(corners.size() / 3));
  return mesh;
}

}  // namespace

std::string file_text(const fs::path& file) {
  const std::string name = file.string();
  std::error_code error;
  if (!fs::is_regular_file(file, error)) throw MeshFileError(name + ": no such file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw MeshFileError(name + ": cannot be opened");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw MeshFileError(name + ": cannot be read");
  return text;
}

namespace {

/// What an OFF file is read as.
enum class OffSurface {
  planar,   ///< a global::Mesh: z = 0, triangles only
  spatial,  ///< a sym3::Mesh3 (thesis Fig. 3.3): z kept, a polygon split into the fan of its first corner
};

/// The OFF reader: appends 2 (planar) or 3 (spatial) coordinates per vertex to `coordinates` and 3
/// corners per triangle to `corners`.
void parse_off_into(std::string_view text, const std::string& name, OffSurface surface,
                    std::vector<double>& coordinates, std::vector<int>& corners) {
  const bool planar = surface == OffSurface::planar;
  LineReader in(text, name);
  if (!in.next()) in.fail_at_end("empty file: expected an 'OFF' header");
  if (in.tokens().front() != "OFF")
    in.fail("expected the 'OFF' header, found " + LineReader::quoted(in.tokens().front()));
  std::vector<std::string_view> counts(in.tokens().begin() + 1, in.tokens().end());
  if (counts.empty()) {
    if (!in.next()) in.fail_at_end("file ends before the counts line 'vertices faces [edges]'");
    counts = in.tokens();
  }
  if (counts.size() != 2 && counts.size() != 3) in.fail("expected the counts 'vertices faces [edges]'");
  const long long vertex_count = in.integer(counts[0]), face_count = in.integer(counts[1]);
  if (vertex_count < 0 || face_count < 0) in.fail("negative count");
  if (vertex_count > max_count || face_count > max_count) in.fail("count beyond 2^31 - 1");
  if (!planar && (vertex_count == 0 || face_count == 0)) in.fail("empty mesh: no vertices or no faces");

  const std::size_t dimension = planar ? 2 : 3;
  coordinates.reserve(dimension * static_cast<std::size_t>(std::min(vertex_count, 1LL << 20)));
  for (long long k = 0; k < vertex_count; ++k) {
    if (!in.next())
      in.fail_at_end("file ends after " + std::to_string(k) + " of " + std::to_string(vertex_count) + " vertices");
    if (in.tokens().size() != 3) in.fail("vertex " + std::to_string(k) + ": expected 'x y z'");
    if (planar) {
      read_point(in, 0, coordinates);
      continue;
    }
    for (const std::string_view token : in.tokens()) {
      const double x = in.number(token);
      if (!std::isfinite(x))
        in.fail("vertex " + std::to_string(k) + ": " + LineReader::quoted(token) + " is not finite");
      coordinates.push_back(x);
    }
  }
  corners.reserve(3 * static_cast<std::size_t>(std::min(face_count, 1LL << 20)));
  std::vector<int> face;
  for (long long i = 0; i < face_count; ++i) {
    if (!in.next())
      in.fail_at_end("file ends after " + std::to_string(i) + " of " + std::to_string(face_count) + " faces");
    const auto& tokens = in.tokens();
    const std::string face_name = "face " + std::to_string(i);
    const long long size = in.integer(tokens[0]);
    if (planar && size != 3)
      in.fail(face_name + " has " + LineReader::printable(tokens[0]) +
              " vertices: only triangles are read (polygons are not triangulated)");
    if (size < 3) in.fail(face_name + " has " + LineReader::printable(tokens[0]) + " vertices: at least 3 are needed");
    if (static_cast<long long>(tokens.size()) < 1 + size)
      in.fail(face_name + ": expected " +
              (size == 3 ? std::string("'3 a b c'") : std::to_string(size) + " vertex indices after the size"));
    face.clear();
    for (std::size_t c = 1; c < tokens.size(); ++c) {
      if (static_cast<long long>(c) > size) {
        in.number(tokens[c]);  // a colour: checked to be numeric, not used
        continue;
      }
      const long long k = in.integer(tokens[c]);
      if (k < 0 || k >= vertex_count)
        in.fail(face_name + ": vertex index " + std::to_string(k) + " is out of range (" +
                std::to_string(vertex_count) + " vertices)");
      face.push_back(static_cast<int>(k));
    }
    for (std::size_t c = 1; c + 1 < face.size(); ++c) corners.insert(corners.end(), {face[0], face[c], face[c + 1]});
  }
  if (in.next()) in.fail("unexpected content after the last face");
}

}  // namespace

global::Mesh parse_obj(std::string_view text, const std::string& name) {
  LineReader in(text, name);
  std::vector<double> coordinates;
  struct FaceReference {
    long long index;            // as written: 1-based, or negative relative to the vertices so far
    long long vertices_before;  // vertices defined before the face's line
    long long line;
  };
  std::vector<FaceReference> references;
  while (in.next()) {
    const auto& tokens = in.tokens();
    const std::string_view keyword = tokens.front();
    if (keyword == "v") {
      if (tokens.size() != 3 && tokens.size() != 4) in.fail("expected 'v x y [z]'");
      if (coordinates.size() / 2 >= static_cast<std::size_t>(max_count)) in.fail("more than 2^31 - 1 vertices");
      read_point(in, 1, coordinates);
    } else if (keyword == "f") {
      if (tokens.size() != 4)
        in.fail("face with " + std::to_string(tokens.size() - 1) +
                " vertices: only triangles are read (polygons are not triangulated)");
      if (references.size() / 3 >= static_cast<std::size_t>(max_count)) in.fail("more than 2^31 - 1 faces");
      for (std::size_t c = 1; c < 4; ++c) {
        const std::string_view vertex = tokens[c].substr(0, tokens[c].find('/'));
        const long long index = in.integer(vertex);
        if (index == 0) in.fail("vertex index 0: OBJ indices start at 1 (negative ones count back)");
        references.push_back({index, static_cast<long long>(coordinates.size() / 2), in.line_number()});
      }
    } else if (keyword == "vt" || keyword == "vn" || keyword == "vp" || keyword == "g" || keyword == "o" ||
               keyword == "s" || keyword == "usemtl" || keyword == "mtllib") {
      continue;  // texture, normals, grouping and materials do not change the shape
    } else {
      in.fail("unsupported statement " + LineReader::quoted(keyword));
    }
  }
  const long long vertex_count = static_cast<long long>(coordinates.size() / 2);
  std::vector<int> corners;
  corners.reserve(references.size());
  for (const FaceReference& r : references) {
    const long long k = r.index > 0 ? r.index - 1 : r.vertices_before + r.index;
    if (k < 0 || k >= vertex_count)
      in.fail_at(r.line, "vertex index " + std::to_string(r.index) + " is out of range (" +
                             std::to_string(r.index > 0 ? vertex_count : r.vertices_before) + " vertices)");
    corners.push_back(static_cast<int>(k));
  }
  return assemble(coordinates, corners);
}

global::Mesh parse_off(std::string_view text, const std::string& name) {
  std::vector<double> coordinates;
  std::vector<int> corners;
  parse_off_into(text, name, OffSurface::planar, coordinates, corners);
  return assemble(coordinates, corners);
}

sym3::Mesh3 parse_off_surface(std::string_view text, const std::string& name) {
  std::vector<double> coordinates;
  std::vector<int> corners;
  parse_off_into(text, name, OffSurface::spatial, coordinates, corners);
  sym3::Mesh3 mesh;
  mesh.vertices =
      Eigen::Map<Eigen::Matrix3Xd>(coordinates.data(), 3, static_cast<Eigen::Index>(coordinates.size() / 3));
  mesh.triangles = Eigen::Map<Eigen::Matrix3Xi>(corners.data(), 3, static_cast<Eigen::Index>(corners.size() / 3));
  return mesh;
}

global::Mesh read_mesh(const fs::path& file) {
  const std::string name = file.string();
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (is_polygon_soup_extension(extension)) return read_polygon_soup_mesh(file);
  if (extension != ".obj" && extension != ".off")
    throw MeshFileError(name + ": unknown extension '" + extension + "': expected .obj, .off, .ply, .stl or .ts");
  const std::string text = file_text(file);
  return extension == ".obj" ? parse_obj(text, name) : parse_off(text, name);
}

sym3::Mesh3 read_off_surface(const fs::path& file) { return parse_off_surface(file_text(file), file.string()); }

std::string obj_text(const global::Mesh& mesh) {
  // std::to_chars: the shortest text that reads back to the same double, without the streams' locale and
  // formatting state, which made writing a 1M-triangle frame several times slower
  std::string out = "# " + std::to_string(mesh.vertex_count()) + " vertices, " + std::to_string(mesh.triangle_count()) +
                    " triangles (affinterp)\n";
  out.reserve(out.size() + 56 * static_cast<std::size_t>(mesh.vertex_count()) +
              24 * static_cast<std::size_t>(mesh.triangle_count()));
  char buffer[32];
  auto append = [&](auto x) {
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, x);
    out.append(buffer, end);
  };
  for (Eigen::Index k = 0; k < mesh.vertex_count(); ++k) {
    out += "v ", append(mesh.vertices(0, k)), out += ' ', append(mesh.vertices(1, k)), out += " 0\n";
  }
  for (Eigen::Index i = 0; i < mesh.triangle_count(); ++i) {
    out += "f ", append(mesh.triangles(0, i) + 1), out += ' ', append(mesh.triangles(1, i) + 1);
    out += ' ', append(mesh.triangles(2, i) + 1), out += '\n';
  }
  return out;
}

void write_obj(const global::Mesh& mesh, const fs::path& file) {
  std::ofstream out(file, std::ios::binary);
  out << obj_text(mesh);
  if (!out.flush()) throw MeshFileError(file.string() + ": cannot be written");
}

}  // namespace affinterp::io
