#include "checks/inputs/fuzz/mesh_reader_fuzz.hpp"

#include "experiments/inputs/mesh_file.hpp"
#include "theory/global/mesh_validation.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace affinterp::fuzz {

namespace {

[[noreturn]] void defect(const std::string& what) {
  std::fprintf(stderr, "mesh reader defect: %s\n", what.c_str());
  std::abort();
}

/// Parses with `parse`; on success checks the mesh and the OBJ round trip. True when it parsed.
template <class Parse>
bool exercise(Parse parse, std::string_view text) {
  global::Mesh mesh;
  try {
    mesh = parse(text, "fuzz");
  } catch (const io::MeshFileError& e) {
    const std::string message = e.what();
    if (message.empty() || message.find('\n') != std::string::npos) defect("error not on one line: " + message);
    return false;
  }
  try {
    global::check_well_formed(mesh);
    global::orient_counter_clockwise(mesh);
  } catch (const global::InvalidMesh&) {
    return true;
  }
  const global::Mesh back = io::parse_obj(io::obj_text(mesh), "round trip");
  if (back.vertices != mesh.vertices || back.triangles != mesh.triangles) defect("OBJ round trip changed the mesh");
  return true;
}

}  // namespace

int mesh_reader_one_input(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    return exercise(io::parse_obj, text) + exercise(io::parse_off, text);
  } catch (const std::exception& e) {
    defect(std::string("unexpected exception: ") + e.what());
  }
}

}  // namespace affinterp::fuzz
