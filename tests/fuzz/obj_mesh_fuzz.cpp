// libFuzzer target: the bytes are an .obj mesh file for parse_pieces; the checks are
// mesh_fuzz_checks.hpp's.

#include <cstddef>
#include <cstdint>
#include <string>

#include "mesh_fuzz_checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fragsim::fuzz::check_pieces(std::string(reinterpret_cast<const char*>(data), size), "fuzz.obj");
  return 0;
}
