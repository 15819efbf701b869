// Fuzzes the OBJ loader (tinyobjloader, validation, welding): any bytes give a mesh or an Error.
#include "core/error.h"
#include "fuzz/fuzz_support.h"
#include "io/obj_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = prt::fuzz::WriteInput(data, size, ".obj");
  try {
    const prt::LoadedMesh mesh = prt::LoadObj(path);
    // A loaded mesh is complete: every triangle indexes its vertices.
    for (const auto& t : mesh.mesh.triangles)
      for (int c = 0; c < 3; ++c)
        if (static_cast<std::size_t>(t[c]) >= mesh.mesh.positions.size()) __builtin_trap();
  } catch (const prt::Error&) {
  }
  return 0;
}
