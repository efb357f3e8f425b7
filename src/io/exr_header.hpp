// exr_header.hpp (private to src/io) — the check the OpenEXR reader makes on a file's header before
// it lets OpenEXR read the file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace ocean::io {

/// What the header walk found: the first problem, or the size of the first part's image.
struct ExrHeaderInfo {
  std::string problem;           ///< empty when the header is well formed
  std::int64_t width = 0;        ///< of the first part's data window ("dataWindow"); 0 if absent
  std::int64_t height = 0;       ///< as width
  std::size_t channels = 0;      ///< entries of the first part's channel list ("channels")
  std::int64_t tile_width = 0;   ///< of the first part's "tiles" (tiledesc); 0 when not tiled
  std::int64_t tile_height = 0;  ///< as tile_width
};

/// Walks the header(s) of the OpenEXR file `bytes` as OpenEXR 3.1 reads them. OpenEXR allocates an
/// attribute's declared size before it reads the value, so a file of a few hundred bytes can make
/// it allocate 2 GiB; and it reads some types (a channel list, fixed-size values) by their content
/// whatever the declared size says, so a size that disagrees puts its reading out of step with the
/// sizes checked here.
///
/// Contract: accepted are headers whose every attribute lies inside the file and is read by
/// OpenEXR as exactly its declared size: known fixed-size types with exactly their size, a
/// channel list whose entries and end fill its size, float vectors of whole floats, and every
/// other type (strings, string vectors, previews, ID manifests, whose contents OpenEXR checks
/// against the size, and types it does not know, kept opaque). Refused: "not an OpenEXR file
/// (wrong magic)", "truncated header" (a name or type without its end within 255 bytes or the
/// file), "header attribute '<name>' declares <n> bytes, more than the file holds", "header
/// attribute '<name>' of type '<type>' declares <n> bytes, not <m>" (m = -1: a channel list
/// without its end). Names and types are echoed through ocean::excerpt. Never throws on any
/// bytes (allocation failure aside); reads nothing outside `bytes`.
ExrHeaderInfo check_exr_header(std::string_view bytes);

}  // namespace ocean::io
