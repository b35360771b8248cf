#include "experiments/inputs/sym3/off_file.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace affinterp::sym3 {

namespace {

/// The next token of an OFF stream, skipping '#' comments.
bool next_token(std::istream& in, std::string& token) {
  while (in >> token) {
    if (token[0] != '#') return true;
    std::getline(in, token);
  }
  return false;
}

template <class T>
T next_number(std::istream& in, const std::filesystem::path& file, const char* what) {
  std::string token;
  if (!next_token(in, token)) throw std::runtime_error(file.string() + ": truncated (expected " + what + ")");
  std::istringstream parse(token);
  T value;
  if (!(parse >> value) || !parse.eof()) throw std::runtime_error(file.string() + ": bad " + what + " '" + token + "'");
  return value;
}

}  // namespace

Mesh3 read_off(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot open");
  std::string header;
  if (!next_token(in, header) || header != "OFF") throw std::runtime_error(file.string() + ": not an OFF file");
  const auto n_vertices = next_number<long>(in, file, "vertex count");
  const auto n_faces = next_number<long>(in, file, "face count");
  next_number<long>(in, file, "edge count");
  if (n_vertices <= 0 || n_faces <= 0) throw std::runtime_error(file.string() + ": empty mesh");

  Mesh3 mesh;
  mesh.vertices.resize(3, n_vertices);
  for (long k = 0; k < n_vertices; ++k)
    for (int d = 0; d < 3; ++d) mesh.vertices(d, k) = next_number<double>(in, file, "coordinate");
  std::vector<Eigen::Vector3i> triangles;
  triangles.reserve(n_faces);
  for (long f = 0; f < n_faces; ++f) {
    const auto corners = next_number<int>(in, file, "face size");
    if (corners < 3) throw std::runtime_error(file.string() + ": face with fewer than 3 corners");
    std::vector<int> face(corners);
    for (int& v : face) {
      v = next_number<int>(in, file, "vertex index");
      if (v < 0 || v >= n_vertices) throw std::runtime_error(file.string() + ": vertex index out of range");
    }
    for (int c = 1; c + 1 < corners; ++c) triangles.emplace_back(face[0], face[c], face[c + 1]);
  }
  mesh.triangles.resize(3, static_cast<Eigen::Index>(triangles.size()));
  for (std::size_t i = 0; i < triangles.size(); ++i) mesh.triangles.col(i) = triangles[i];
  return mesh;
}

}  // namespace affinterp::sym3
