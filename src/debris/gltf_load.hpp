#pragma once
// A glTF file (.gltf or .glb) loaded by tinygltf under fragsim's rules for what a mesh file may
// reach and require. A buffer's or image's uri is percent-decoded as the glTF specification says
// (RFC 3986, where '+' is a plus sign, not a space as tinygltf's own decoder takes it) and resolved
// only inside the mesh file's folder. After `..` and symbolic links the file must lie under the
// folder and be a regular file, checked before it is opened, so a uri naming /etc/passwd or a FIFO
// is refused without being opened. A data: uri may hold at most kMaxDataUriBytes. A file whose
// extensionsRequired lists an extension that changes geometry is refused, as the specification
// requires of a loader that does not support it.

#include <tiny_gltf.h>
#include <cstddef>
#include <cstdint>
#include <string>

namespace fragsim {

// An embedded (base64) buffer or image decodes to at most this. 64 MiB is 5.6 million float
// positions, far more than a convex piece needs, and keeps the decoded copy small beside the text
// it came from. Larger data belongs in a .bin file beside the .gltf, or in a .glb.
inline constexpr std::size_t kMaxDataUriBytes = std::size_t{64} << 20;

// An external buffer file is read up to this size.
inline constexpr std::uintmax_t kMaxBufferFileBytes = std::uintmax_t{1} << 30;

// The model in `bytes` (a .glb when binary). `path` names the file in messages, and its folder is
// where uris are resolved. Throws InputError, one line naming the file and, where it is one uri's
// or extension's fault, that uri or extension.
tinygltf::Model load_gltf(const std::string& bytes, const std::string& path, bool binary);

}  // namespace fragsim
