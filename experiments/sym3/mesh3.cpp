#include "experiments/sym3/mesh3.hpp"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
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
  if (!(parse >> value) || !parse.eof())
    throw std::runtime_error(file.string() + ": bad " + what + " '" + token + "'");
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

Mesh3 midpoint_subdivision(const Mesh3& mesh) {
  std::vector<Eigen::Vector3d> vertices;
  for (Eigen::Index k = 0; k < mesh.vertex_count(); ++k) vertices.push_back(mesh.vertices.col(k));
  std::unordered_map<std::uint64_t, int> midpoint_of_edge;
  auto midpoint = [&](int a, int b) {
    const auto key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
    auto [it, inserted] = midpoint_of_edge.try_emplace(key, static_cast<int>(vertices.size()));
    if (inserted) vertices.push_back((mesh.vertices.col(a) + mesh.vertices.col(b)) / 2);
    return it->second;
  };
  Mesh3 fine;
  fine.triangles.resize(3, 4 * mesh.triangle_count());
  for (Eigen::Index i = 0; i < mesh.triangle_count(); ++i) {
    const int a = mesh.triangles(0, i), b = mesh.triangles(1, i), c = mesh.triangles(2, i);
    const int ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    fine.triangles.col(4 * i) << a, ab, ca;
    fine.triangles.col(4 * i + 1) << ab, b, bc;
    fine.triangles.col(4 * i + 2) << ca, bc, c;
    fine.triangles.col(4 * i + 3) << ab, bc, ca;
  }
  fine.vertices.resize(3, static_cast<Eigen::Index>(vertices.size()));
  for (std::size_t k = 0; k < vertices.size(); ++k) fine.vertices.col(k) = vertices[k];
  return fine;
}

}  // namespace affinterp::sym3
