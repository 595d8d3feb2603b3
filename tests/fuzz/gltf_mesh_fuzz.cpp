// libFuzzer target: the bytes are a glTF mesh file for parse_pieces: binary (.glb) when
// they start with glTF's magic "glTF", else JSON (.gltf); the checks are mesh_fuzz_checks.hpp's.
// External buffers are looked up in a folder that does not exist, so only data: URIs and the
// .glb's own chunk can feed the reader.

#include <cstddef>
#include <cstdint>
#include <string>

#include "mesh_fuzz_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const bool binary = bytes.rfind("glTF", 0) == 0;
  fragsim::fuzz::check_pieces(
      bytes, binary ? "/nonexistent-fragsim-fuzz/fuzz.glb" : "/nonexistent-fragsim-fuzz/fuzz.gltf");
  return 0;
}
