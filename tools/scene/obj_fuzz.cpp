// libFuzzer target: an OBJ stone (tools/scene/obj_reader.hpp) through everything a case's
// `mesh_file` goes through (build_stone: the reader, check_mesh, check_solid, the mass properties
// and their plausibility, the principal axes) on arbitrary bytes. A mesh comes from a user's
// exporter or scanner, not from stoneskip: bad input must end in an InputError, never a crash, a
// hang or undefined behaviour.
#include <cstddef>
#include <cstdint>
#include <string>

#include "tools/io/input_error.hpp"
#include "tools/io/scratch_dir.hpp"
#include "tools/scene/stone_case.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // build_stone reads the file a case names: the bytes go to a file of this process's own.
  static const stoneskip::ScratchDir scratch("stoneskip_obj_fuzz");
  stoneskip::StoneSpec spec;
  spec.shape = stoneskip::StoneShape::mesh_file;
  spec.mesh_file = scratch.write("stone.obj", std::string(reinterpret_cast<const char*>(data), size)).string();
  spec.density_kg_m3 = 2500;
  try {
    (void)stoneskip::build_stone(spec, "fuzz.toml");
  } catch (const stoneskip::InputError&) {
  }
  return 0;
}
