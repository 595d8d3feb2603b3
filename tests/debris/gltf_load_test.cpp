// glTF files loaded under fragsim's rules: a buffer's uri resolves only inside the mesh file's
// folder and only to a regular file (a FIFO blocked the reader for ever, and ../../../../etc/passwd
// was opened and its size printed), uris are percent-decoded as the specification says, data:
// uris are capped, and a required extension fragsim cannot honour (Draco, meshopt) is refused.

#include "debris/gltf_load.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "io/input_error.hpp"

namespace fragsim {
namespace {

namespace fs = std::filesystem;

class GltfLoad : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fragsim_gltf_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_ / "mesh");
    const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    write("mesh/tri.bin", std::string(reinterpret_cast<const char*>(xyz), sizeof xyz));
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& bytes) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }
  // A one-triangle file whose buffer is `uri`, with `extra` members at the top level.
  static std::string gltf(const std::string& uri, const std::string& extra = "") {
    return R"({"asset":{"version":"2.0"},)" + extra + R"("buffers":[{"byteLength":36,"uri":")" +
           uri +
           R"("}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],)"
           R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}]})";
  }
  // The message loading `json` as mesh/piece.gltf throws; empty if it loads.
  std::string error_of(const std::string& json) {
    try {
      load_gltf(json, (dir_ / "mesh" / "piece.gltf").string(), false);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  std::string mesh_path() const { return (dir_ / "mesh" / "piece.gltf").string(); }
  fs::path dir_;
};

TEST_F(GltfLoad, ABufferBesideTheFileIsRead) {
  EXPECT_EQ(error_of(gltf("tri.bin")), "");
  const tinygltf::Model m = load_gltf(gltf("tri.bin"), mesh_path(), false);
  ASSERT_EQ(m.buffers.size(), 1u);
  EXPECT_EQ(m.buffers[0].data.size(), 36u);
}

TEST_F(GltfLoad, AFifoIsRefusedWithoutOpeningIt) {
  ASSERT_EQ(::mkfifo((dir_ / "mesh" / "pipe.bin").c_str(), 0600), 0);
  // Opening the FIFO for reading would block this test for ever: it returns at once.
  EXPECT_EQ(error_of(gltf("pipe.bin")),
            mesh_path() +
                ": not a readable glTF file: uri 'pipe.bin' names a FIFO, not a "
                "regular file");
}

TEST_F(GltfLoad, AUriOutsideTheFilesFolderIsRefusedWithoutOpeningIt) {
  const std::string outside = mesh_path() + ": not a readable glTF file: uri '";
  const std::string rule = "' lies outside the mesh file's folder " +
                           fs::canonical(dir_ / "mesh").string() +
                           " (uris are resolved only inside it)";
  EXPECT_EQ(error_of(gltf("../../../../etc/passwd")), outside + "../../../../etc/passwd" + rule);
  // Percent-encoded dots are dots.
  EXPECT_EQ(error_of(gltf("%2e%2e/%2E%2E/etc/passwd")), outside + "../../etc/passwd" + rule);
  // A file beside the folder, reached by '..' or by a symbolic link inside it.
  write("outside.bin", std::string(36, '\0'));
  EXPECT_EQ(error_of(gltf("../outside.bin")), outside + "../outside.bin" + rule);
  fs::create_symlink(dir_ / "outside.bin", dir_ / "mesh" / "link.bin");
  EXPECT_EQ(error_of(gltf("link.bin")), outside + "link.bin" + rule);
  // A link that stays inside, and a '..' that comes back in, are fine.
  fs::create_symlink(dir_ / "mesh" / "tri.bin", dir_ / "mesh" / "inside.bin");
  EXPECT_EQ(error_of(gltf("inside.bin")), "");
  EXPECT_EQ(error_of(gltf("../mesh/tri.bin")), "");
  // No shell expansion of a uri (tinygltf's own reader runs wordexp).
  EXPECT_EQ(error_of(gltf("~/tri.bin")),
            mesh_path() + ": not a readable glTF file: File not found : ~/tri.bin");
}

TEST_F(GltfLoad, UrisArePercentDecodedAsTheSpecificationSays) {
  // '+' is a plus sign (tinygltf's decoder makes it a space); %20 is a space.
  // The file with the space is 40 bytes, so reading it for the 36-byte buffer shows.
  write("mesh/a+b.bin", std::string(36, '\0'));
  write("mesh/a b.bin", std::string(40, '\0'));
  EXPECT_EQ(error_of(gltf("a+b.bin")), "");
  EXPECT_EQ(error_of(gltf("a%2Bb.bin")), "");
  EXPECT_NE(error_of(gltf("a%20b.bin")).find("but got 40"), std::string::npos);
  EXPECT_EQ(error_of(gltf("a%zz.bin")),
            mesh_path() + ": uri 'a%zz.bin' has a '%' not followed by two hex digits");
  EXPECT_EQ(error_of(gltf("tri.bin%")),
            mesh_path() + ": uri 'tri.bin%' has a '%' not followed by two hex digits");
  EXPECT_EQ(error_of(gltf("tri%00.bin")),
            mesh_path() + ": uri 'tri%00.bin' has %00, a NUL byte, which no file name holds");
}

TEST_F(GltfLoad, DataUrisAboveTheLimitAreRefusedBeforeDecoding) {
  // 64 MiB and 3 bytes of zeros, base64: "AAAA" per 3 bytes.
  const std::size_t groups = kMaxDataUriBytes / 3 + 2;
  const std::string uri = "data:application/octet-stream;base64," + std::string(4 * groups, 'A');
  const std::string m = error_of(gltf(uri));
  EXPECT_EQ(m.rfind(mesh_path() + ": buffers: uri 'data:application/octet-stream;base64,AAAA", 0),
            0u)
      << m.substr(0, 200);
  EXPECT_NE(m.find("above the 64 MiB limit of embedded data"), std::string::npos)
      << m.substr(0, 300);
  EXPECT_LT(m.size(), 400u);  // the uri is shown cut short
}

TEST_F(GltfLoad, RequiredExtensionsFragsimCannotHonourAreRefused) {
  const auto requiring = [](const std::string& e) {
    return gltf("tri.bin",
                R"("extensionsUsed":[")" + e + R"("],"extensionsRequired":[")" + e + R"("],)");
  };
  EXPECT_EQ(error_of(requiring("KHR_draco_mesh_compression")),
            mesh_path() +
                ": requires the extension KHR_draco_mesh_compression: Draco-compressed meshes are "
                "not supported; export without compression (Blender's glTF exporter: untick "
                "Data > Compression)");
  EXPECT_EQ(error_of(requiring("EXT_meshopt_compression")),
            mesh_path() +
                ": requires the extension EXT_meshopt_compression: meshopt-compressed meshes are "
                "not supported; export without compression (gltfpack: leave out -c and -cc)");
  EXPECT_NE(error_of(requiring("EXT_mesh_gpu_instancing"))
                .find(": requires the extension EXT_mesh_gpu_instancing, which fragsim does not "
                      "support"),
            std::string::npos);
  // Required but only about looks: read. Used but not required: read (the file has a fallback).
  EXPECT_EQ(error_of(requiring("KHR_materials_emissive_strength")), "");
  EXPECT_EQ(error_of(requiring("KHR_texture_transform")), "");
  EXPECT_EQ(error_of(gltf("tri.bin", R"("extensionsUsed":["EXT_meshopt_compression"],)")), "");
}

TEST_F(GltfLoad, AGlbsRequiredExtensionIsFoundInItsJsonChunk) {
  std::string json = gltf("tri.bin", R"("extensionsRequired":["KHR_draco_mesh_compression"],)");
  while (json.size() % 4 != 0) json += ' ';
  const auto le32 = [](std::uint32_t v) {
    std::string b(4, '\0');
    for (int i = 0; i < 4; ++i) b[static_cast<std::size_t>(i)] = static_cast<char>(v >> (8 * i));
    return b;
  };
  const std::string glb = "glTF" + le32(2) + le32(static_cast<std::uint32_t>(20 + json.size())) +
                          le32(static_cast<std::uint32_t>(json.size())) + "JSON" + json;
  try {
    load_gltf(glb, (dir_ / "mesh" / "piece.glb").string(), true);
    ADD_FAILURE() << "loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Draco-compressed meshes are not supported"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fragsim
