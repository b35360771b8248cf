#include "plots/viewer/viewer3.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string_view>

namespace affinterp::plots {

extern const std::string_view viewer3_page;  // plots/viewer/viewer3.html, embedded by plots/viewer/embed.cmake

namespace {

namespace fs = std::filesystem;

std::string text_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + " is missing (install Debian's libjs-three for the 3D viewer)");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The faces drawn and the element of each: a surface's triangles, or the faces of tetrahedra that no other
/// tetrahedron shares, each turned outward (for det [b−a c−a d−a] > 0: bcd, adc, abd, acb).
std::pair<std::vector<int>, std::vector<int>> drawn_faces(const global3::Mesh3& mesh) {
  std::vector<int> faces, elements;
  if (mesh.corners() == 3) {
    faces.assign(mesh.elements.data(), mesh.elements.data() + mesh.elements.size());
    for (Eigen::Index i = 0; i < mesh.element_count(); ++i) elements.push_back(static_cast<int>(i));
    return {faces, elements};
  }
  constexpr std::array<std::array<int, 3>, 4> outward{{{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}};
  std::map<std::array<int, 3>, int> uses;
  const auto key = [&](Eigen::Index i, const std::array<int, 3>& face) {
    std::array<int, 3> k{mesh.elements(face[0], i), mesh.elements(face[1], i), mesh.elements(face[2], i)};
    std::sort(k.begin(), k.end());
    return k;
  };
  for (Eigen::Index i = 0; i < mesh.element_count(); ++i)
    for (const auto& face : outward) ++uses[key(i, face)];
  for (Eigen::Index i = 0; i < mesh.element_count(); ++i)
    for (const auto& face : outward)
      if (uses[key(i, face)] == 1) {
        for (const int c : face) faces.push_back(mesh.elements(c, i));
        elements.push_back(static_cast<int>(i));
      }
  return {faces, elements};
}

std::vector<float> coordinates(const Eigen::Matrix3Xd& v) { return {v.data(), v.data() + v.size()}; }

void replace(std::string& page, std::string_view marker, const std::string& text) {
  const auto at = page.find(marker);
  if (at == std::string::npos) throw std::logic_error("viewer3.html lacks " + std::string(marker));
  page.replace(at, marker.size(), text);
}

}  // namespace

fs::path three_js_folder() {
  const char* folder = std::getenv("AFFINTERP_THREE_DIR");
  return folder && *folder ? fs::path(folder) : fs::path("/usr/share/javascript/three");
}

void write_viewer3(const fs::path& html, const std::string& title, const global3::Mesh3& rest,
                   const std::vector<Viewer3Frame>& frames, std::span<const unsigned char> near_folds) {
  const std::string three = text_of(three_js_folder() / "build" / "three.min.js");
  const std::string orbit = text_of(three_js_folder() / "examples" / "js" / "controls" / "OrbitControls.js");
  const auto [faces, face_elements] = drawn_faces(rest);
  nlohmann::json data = {{"title", title},
                         {"faces", faces},
                         {"faceElements", face_elements},
                         {"elementCount", rest.element_count()},
                         {"rest", coordinates(rest.vertices)},
                         {"frames", nlohmann::json::array()},
                         {"labels", nlohmann::json::array()},
                         {"nearFolds", nlohmann::json::array()},
                         {"inverted", nlohmann::json::array()}};
  for (const Viewer3Frame& frame : frames) {
    data["frames"].push_back(coordinates(frame.vertices)), data["labels"].push_back(frame.label);
    if (frame.inverted) data["inverted"].push_back(*frame.inverted);
  }
  if (data["inverted"].size() < frames.size()) data["inverted"] = nullptr;
  for (std::size_t i = 0; i < near_folds.size(); ++i)
    if (near_folds[i]) data["nearFolds"].push_back(i);
  std::string json = data.dump();
  // inside a <script> element "</" would end it
  for (std::size_t at = 0; (at = json.find("</", at)) != std::string::npos; at += 3) json.replace(at, 2, "<\\/");
  std::string page(viewer3_page);
  // the data's marker first (it is the first occurrence: the head holds the libraries' markers only), then the
  // libraries', which come before the data
  replace(page, "@AFFINTERP_DATA@", json);
  replace(page, "@AFFINTERP_ORBIT@", orbit);
  replace(page, "@AFFINTERP_THREE@", three);
  std::ofstream out(html, std::ios::binary);
  out << page;
  if (!out.flush()) throw std::runtime_error(html.string() + ": cannot be written");
}

}  // namespace affinterp::plots
