// src/bake/manifest.cpp — the manifest written last, saying whether the run completed.
#include "manifest.hpp"

#include <span>
#include <string>

#include "ocean/io.hpp"

namespace ocean::bake::detail {

Status finish_manifest(const std::filesystem::path& dir, Json& manifest, const Status& stop,
                       long long frames_asked, std::string_view what) noexcept {
  try {
    manifest["complete"] = stop.ok();
    if (stop.ok()) {
      manifest.erase("stopped");
    } else {
      manifest["stopped"] = stop.code() == ErrorCode::cancelled ? "cancelled" : stop.message();
    }
    const std::string text = manifest.dump(2) + "\n";
    const std::filesystem::path path = dir / kManifestName;
    const Status written =
        io::write_bytes_atomically(path, {std::as_bytes(std::span(text.data(), text.size()))});
    if (stop.code() != ErrorCode::cancelled) return stop.ok() ? written : stop;
    std::string message(what);
    message.append(" cancelled after ")
        .append(manifest["frames_written"].dump())
        .append(" of ")
        .append(std::to_string(frames_asked))
        .append(" frames; ");
    if (written.ok()) {
      message.append(io::quoted(path)).append(" says \"complete\": false");
    } else {
      message.append("no manifest: ").append(written.message());
    }
    return {ErrorCode::cancelled, std::move(message)};
  } catch (const std::exception& e) {  // out of memory for the text
    return io_error(std::string(what) + " failed: " + e.what());
  }
}

}  // namespace ocean::bake::detail
