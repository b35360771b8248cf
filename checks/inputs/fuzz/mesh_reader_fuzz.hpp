#pragma once
// One fuzz input for the mesh reader: the bytes are parsed as OBJ and as OFF; a parsed mesh is checked
// (global::check_well_formed, orientation) and written back as OBJ, which must read back identically.
// The only acceptable failures are the reader's and the checks' one-line errors: anything else (another
// exception, a crash, a sanitizer report, a hang) is a defect. Shared by the libFuzzer target
// (mesh_reader_libfuzzer.cpp) and the deterministic mutation test (mesh_reader_fuzz_test.cpp).
#include <cstddef>
#include <cstdint>

namespace affinterp::fuzz {

/// Returns the number of formats (0–2) the input parsed as; aborts on a defect.
int mesh_reader_one_input(const std::uint8_t* data, std::size_t size);

}  // namespace affinterp::fuzz
