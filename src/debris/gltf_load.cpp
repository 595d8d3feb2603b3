#include "debris/gltf_load.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string_view>
#include <vector>

#include "debris/mesh_message.hpp"
#include "io/input_error.hpp"

namespace fragsim {
namespace {

namespace fs = std::filesystem;

// A uri as a message shows it (a data: uri can be megabytes).
std::string shown_uri(std::string_view uri) {
  return shown(uri, 80);
}

// Extensions that a file may require and fragsim still reads right, because they change how a
// surface looks or what else the file holds, never a mesh's positions. Any other required extension
// (compression, quantization, instancing, ones not yet written) is refused.
bool extension_keeps_geometry(const std::string& name) {
  static const std::array<const char*, 6> kKept = {"KHR_texture_transform", "KHR_texture_basisu",
                                                   "EXT_texture_webp",      "EXT_texture_avif",
                                                   "KHR_lights_punctual",   "KHR_xmp_json_ld"};
  if (name.rfind("KHR_materials_", 0) == 0) return true;
  return std::find(kKept.begin(), kKept.end(), name) != kKept.end();
}

std::string unsupported_extension(const std::string& name) {
  if (name == "KHR_draco_mesh_compression") {
    return "requires the extension KHR_draco_mesh_compression: Draco-compressed meshes are not "
           "supported; export without compression (Blender's glTF exporter: untick "
           "Data > Compression)";
  }
  if (name == "EXT_meshopt_compression") {
    return "requires the extension EXT_meshopt_compression: meshopt-compressed meshes are not "
           "supported; export without compression (gltfpack: leave out -c and -cc)";
  }
  return "requires the extension " + shown_uri(name) +
         ", which fragsim does not support (it may change the meshes' positions); export "
         "without it";
}

// The uri decoded as RFC 3986 says, or why it cannot be (a '%' not followed by two hex digits, or
// one that decodes to a NUL byte, which no file name holds).
bool percent_decode(const std::string& uri, std::string& out, std::string& why) {
  const auto hex = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  out.clear();
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] != '%') {
      out += uri[i];
      continue;
    }
    if (i + 2 >= uri.size()) {
      why = "has a '%' not followed by two hex digits";
      return false;
    }
    const int hi = hex(uri[i + 1]);
    const int lo = hex(uri[i + 2]);
    if (hi < 0 || lo < 0) {
      why = "has a '%' not followed by two hex digits";
      return false;
    }
    if (hi == 0 && lo == 0) {
      why = "has %00, a NUL byte, which no file name holds";
      return false;
    }
    out += static_cast<char>(hi * 16 + lo);
    i += 2;
  }
  return true;
}

// tinygltf's decoding of the same uri (its dlib::urldecode), where '+' becomes a space.
std::string tinygltf_decoded(const std::string& uri, const std::string& spec) {
  std::string out;
  for (std::size_t i = 0, j = 0; i < uri.size(); ++i, ++j) {
    if (uri[i] == '%') {
      out += spec[j];
      i += 2;
    } else {
      out += uri[i] == '+' ? ' ' : uri[i];
    }
  }
  return out;
}

bool is_data_uri(const std::string& uri) {
  return uri.rfind("data:", 0) == 0;
}

// What the callbacks need: the folder uris resolve in, the names tinygltf will ask for mapped to
// the files the uris name, and the first rule broken (tinygltf turns a refused file into "not
// found", so the rule is the message).
struct Access {
  fs::path folder;     // canonical
  std::string prefix;  // the folder as tinygltf joins it to a uri, with its '/'
  std::map<std::string, std::string> file_of;  // tinygltf's decoded uri -> the spec's
  std::string broken;
};

// The file `joined` (folder + '/' + uri, as tinygltf builds it) stands for, or empty when it is
// not one fragsim lets tinygltf read (then `broken` may say why).
std::string checked_file(Access& a, const std::string& joined) {
  // tinygltf also looks in the current folder ("./" + uri); uris resolve in the file's only.
  if (joined.compare(0, a.prefix.size(), a.prefix) != 0) return "";
  std::string uri = joined.substr(a.prefix.size());
  const auto known = a.file_of.find(uri);
  if (known != a.file_of.end()) uri = known->second;
  const auto refuse = [&](const std::string& why) {
    if (a.broken.empty()) a.broken = "uri '" + shown_uri(uri) + "' " + why;
    return std::string();
  };
  if (uri.find('\0') != std::string::npos) return refuse("holds a NUL byte");
  std::error_code ec;
  const fs::path real = fs::weakly_canonical(a.folder / fs::path(uri).relative_path(), ec);
  if (ec) return refuse("cannot be resolved (" + ec.message() + ")");
  const auto rel = std::mismatch(a.folder.begin(), a.folder.end(), real.begin(), real.end());
  if (rel.first == a.folder.end() && rel.second == real.end()) {
    return refuse("names the mesh file's folder, not a file");
  }
  if (rel.first != a.folder.end()) {
    return refuse("lies outside the mesh file's folder " + a.folder.string() +
                  " (uris are resolved only inside it)");
  }
  const fs::file_status st = fs::status(real, ec);
  if (ec || !fs::exists(st)) return "";  // tinygltf then says "File not found"
  if (fs::is_fifo(st)) return refuse("names a FIFO, not a regular file");
  if (fs::is_directory(st)) return refuse("names a folder, not a regular file");
  if (!fs::is_regular_file(st)) return refuse("is not a regular file");
  return real.string();
}

bool file_exists(const std::string& path, void* user) {
  return !checked_file(*static_cast<Access*>(user), path).empty();
}

// No expansion, because tinygltf's own runs wordexp, which would read "~" or "$HOME" in a uri.
std::string expand_nothing(const std::string& path, void*) {
  return path;
}

bool read_file(std::vector<unsigned char>* out, std::string* err, const std::string& path,
               void* user) {
  Access& a = *static_cast<Access*>(user);
  const std::string file = checked_file(a, path);
  const auto fail = [&](const std::string& why) {
    if (err != nullptr) *err += why;
    return false;
  };
  if (file.empty()) return fail("refused");
  // Checked as a regular file above; opened without blocking and checked again on the open
  // descriptor, so a file swapped for a FIFO in between cannot block the read.
  const int fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return fail("cannot open it");
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    if (a.broken.empty()) a.broken = "a uri's file is not a regular file";
    return fail("not a regular file");
  }
  if (static_cast<std::uintmax_t>(st.st_size) > kMaxBufferFileBytes) {
    ::close(fd);
    return fail("larger than 1 GiB");
  }
  out->resize(static_cast<std::size_t>(st.st_size));
  std::size_t done = 0;
  while (done < out->size()) {
    const ssize_t n = ::read(fd, out->data() + done, out->size() - done);
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  ::close(fd);
  if (done != out->size()) return fail("cannot read it");
  return true;
}

// Images do not shape a piece, so none is decoded.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                const unsigned char*, int, void*) {
  return true;
}

// The JSON of a .gltf, or of a .glb's first chunk; empty if there is none to read (tinygltf
// then refuses the file in its own words).
std::string json_text(const std::string& bytes, bool binary) {
  if (!binary) return bytes;
  const auto le32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i) {
      v = (v << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)]);
    }
    return v;
  };
  if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0 || bytes.compare(16, 4, "JSON") != 0) {
    return "";
  }
  const std::uint32_t n = le32(12);
  if (n > bytes.size() - 20) return "";
  return bytes.substr(20, n);
}

// The rules that need the file's own text before tinygltf reads it: required extensions (a file
// that requires meshopt would otherwise fail later as a missing buffer, without the reason), data:
// uris' sizes (refused before they are decoded) and each uri's decoding.
void check_json(const std::string& json, const std::string& path, Access& a) {
  const nlohmann::json doc = nlohmann::json::parse(json, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return;
  const auto required = doc.find("extensionsRequired");
  if (required != doc.end() && required->is_array()) {
    for (const auto& e : *required) {
      if (e.is_string() && !extension_keeps_geometry(e.get<std::string>())) {
        throw InputError(path + ": " + unsupported_extension(e.get<std::string>()));
      }
    }
  }
  for (const char* kind : {"buffers", "images"}) {
    const auto list = doc.find(kind);
    if (list == doc.end() || !list->is_array()) continue;
    for (const auto& item : *list) {
      if (!item.is_object() || !item.contains("uri") || !item["uri"].is_string()) continue;
      const std::string uri = item["uri"].get<std::string>();
      if (is_data_uri(uri)) {
        const auto comma = uri.find(',');
        const std::size_t decoded =
            comma == std::string::npos ? 0 : (uri.size() - comma - 1) / 4 * 3;
        if (decoded > kMaxDataUriBytes) {
          throw InputError(path + ": " + std::string(kind) + ": uri '" + shown_uri(uri) +
                           "' holds about " + std::to_string(decoded >> 20) +
                           " MiB, above the 64 MiB limit of embedded data (write it to a .bin "
                           "file beside the .gltf, or a .glb)");
        }
        continue;
      }
      std::string spec;
      std::string why;
      if (!percent_decode(uri, spec, why)) {
        throw InputError(path + ": uri '" + shown_uri(uri) + "' " + why);
      }
      const std::string theirs = tinygltf_decoded(uri, spec);
      const auto [it, added] = a.file_of.emplace(theirs, spec);
      if (!added && it->second != spec) {
        throw InputError(path + ": uris '" + shown_uri(uri) + "' and another decode to '" +
                         shown_uri(it->second) + "' and '" + shown_uri(spec) +
                         "', which this reader cannot tell apart; rename one file");
      }
    }
  }
}

}  // namespace

tinygltf::Model load_gltf(const std::string& bytes, const std::string& path, bool binary) {
  std::string dir = fs::path(path).parent_path().string();
  if (dir.empty()) dir = ".";
  Access access;
  std::error_code ec;
  access.folder = fs::weakly_canonical(dir, ec);
  if (ec) access.folder = fs::absolute(dir).lexically_normal();
  access.prefix = dir.back() == '/' ? dir : dir + "/";
  check_json(json_text(bytes, binary), path, access);

  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks({&file_exists, &expand_nothing, &read_file, nullptr, &access});
  loader.SetImageLoader(&skip_image, nullptr);
  tinygltf::Model model;
  std::string err;
  std::string warn;
  bool ok = false;
  // tinygltf reports most bad input in err, but not all. A .glb buffer of byteLength 0 beside a BIN
  // chunk makes it index an empty vector with at() (found by gltf_mesh_fuzz in CI), and a library's
  // exception must reach the user as the same one line as its other refusals.
  try {
    ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn,
                                              reinterpret_cast<const unsigned char*>(bytes.data()),
                                              static_cast<unsigned int>(bytes.size()), dir)
                : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(),
                                             static_cast<unsigned int>(bytes.size()), dir);
  } catch (const std::exception& e) {
    throw InputError(path + ": not a readable glTF file: the glTF reader failed (" +
                     one_line(e.what()) + ")");
  }
  if (!access.broken.empty()) {
    throw InputError(path + ": not a readable glTF file: " + access.broken);
  }
  if (!ok) throw InputError(path + ": not a readable glTF file: " + one_line(err));
  // The same rule after reading, for a file whose JSON the check above could not see.
  for (const std::string& e : model.extensionsRequired) {
    if (!extension_keeps_geometry(e)) throw InputError(path + ": " + unsupported_extension(e));
  }
  return model;
}

}  // namespace fragsim
