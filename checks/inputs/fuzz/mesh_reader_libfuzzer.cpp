// libFuzzer entry point of the mesh reader (built by checks/inputs/fuzz/CMakeLists.txt with clang).
#include "checks/inputs/fuzz/mesh_reader_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  affinterp::fuzz::mesh_reader_one_input(data, size);
  return 0;
}
