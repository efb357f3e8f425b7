// ocean/preset.hpp — the preset file format: SimulationConfig ⇄ JSON, the built-in presets by
// name, and presets assembled in layers (defaults ← preset ← key=value overrides).
//
// Format: one JSON object with the keys of SimulationConfig, units in the names ("fetch_m",
// "direction_deg"); unset numbers are null, "gamma" may be "auto", "depth_m" null is deep water,
// "sea.swell" null is no swell. Every key is optional (absent keys keep SimulationConfig's
// defaults); unknown keys and wrong types are errors that name the key's path in the document
// ("sea.wind_sea.fetch_m: expected a number, got a string"). presets/*.json are examples.
// Besides the simulation a preset may carry settings of the picture (PictureSettings), which
// `ocean render` and `ocean view` use unless their flags say otherwise:
//   "far_field_range": [D_min, D_max]   where the far field takes over, m (docs/rendering.md R.13)
//   "underwater": {"scattering_per_m": b}   the water's turbidity, 1/m (R.51, R.54, R.66)
//
// Bounds: a preset holds at most kMaxPresetBytes bytes and nests objects and arrays at most
// kMaxPresetDepth deep; both are checked before a document is built, so neither a huge file
// (`--preset /dev/zero`) nor a deeply nested one exhausts memory or the stack.
//
// Errors are Status/Result values (invalid_argument for content, io_error for files); nothing
// throws. Every function allocates; all are thread-safe (a Document is used from one thread).
// A user's text echoed in a message is shortened and escaped by ocean::excerpt.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ocean/sim.hpp"

namespace ocean::preset {

/// The largest preset text or file, in bytes (1 MiB; the built-in presets are about 1 KiB).
inline constexpr std::size_t kMaxPresetBytes = std::size_t{1} << 20;
/// The deepest nesting of objects and arrays in a preset ({} is 1, {"a": []} is 2). The format
/// itself needs 5; the bound keeps the recursive walks over a document (merge, copy) shallow.
inline constexpr int kMaxPresetDepth = 64;
/// The longest key path of Document::set, in bytes ("sea.wind_sea.spreading.s" is 24).
inline constexpr std::size_t kMaxKeyBytes = 256;
/// The longest value of Document::set, in bytes.
inline constexpr std::size_t kMaxValueBytes = std::size_t{64} << 10;
/// How long a preset that is a FIFO may stay without a writer before reading it fails, in
/// milliseconds (a named pipe nothing writes to would otherwise block forever).
inline constexpr int kFifoWaitMs = 5000;

/// Settings of the picture a preset may carry besides the simulation; absent keys stay unset.
struct PictureSettings {
  /// "far_field_range": [D_min, D_max], m: finite, 0 ≤ D_min < D_max (render::FarFieldRange).
  std::optional<std::array<double, 2>> far_field_range_m;
  /// "underwater": {"scattering_per_m": b}, 1/m in [0, kMaxScatteringPerM]: the water's
  /// scattering coefficient (render::Underwater::scattering_per_m; 0.072 of clear open ocean by
  /// default, about 0.3–1 in coastal water). It sets the fog, the light shafts and the
  /// visibility 4.8/(a + b) (docs/rendering.md R.51, R.54, R.66).
  std::optional<double> scattering_per_m;
};
/// The largest scattering coefficient a preset may set, 1/m (render::Underwater's range).
inline constexpr double kMaxScatteringPerM = 10.0;

/// The most spaces a level to_json indents by; a larger indent is written as this one.
inline constexpr int kMaxPresetIndent = 64;

/// The preset document of `config`: every key, in a fixed order. `indent` < 0 writes one line,
/// otherwise that many spaces per level, at most kMaxPresetIndent (nlohmann::json reads past its
/// indentation buffer beyond 512). Numbers round-trip exactly through from_json.
std::string to_json(const SimulationConfig& config, int indent = -1);

/// Reads a preset document and validates the configuration (validate() and SeaState::make).
/// Errors (invalid_argument): "the document is not valid JSON", "the document is larger than
/// 1048576 bytes (1 MiB), the most a preset may hold", "the document nests deeper than 64
/// levels".
Result<SimulationConfig> from_json(std::string_view text);

/// The built-in presets (presets/*.json compiled in), in order: "calm", "moderate", "storm".
std::vector<std::string_view> builtin_names();
/// The JSON text of a built-in preset; empty when `name` is none of builtin_names().
std::string_view builtin_json(std::string_view name);
/// The configuration of a built-in preset; unknown names are invalid_argument.
Result<SimulationConfig> builtin(std::string_view name);

/// A preset assembled in layers, in the order the calls are made: SimulationConfig's defaults,
/// then presets merged over them (key by key: an object merges into an object, any other value
/// replaces; null is a value, "unset", as in from_json, not a removal that would restore a
/// default), then single-key overrides. config() reads and validates the result.
class Document {
 public:
  Document();  ///< SimulationConfig{} as a document
  ~Document();
  Document(Document&&) noexcept;
  Document& operator=(Document&&) noexcept;
  /// A copy to try changes on (the C API keeps a change only when the result is valid).
  Document(const Document& other);
  Document& operator=(const Document& other);

  /// Merges a built-in preset or a preset file. A bare name (no directory, no extension) that
  /// is not an existing file selects a built-in preset. Any file may be named (a pipe, a
  /// device): reading stops after kMaxPresetBytes, and a FIFO that no writer opens within
  /// kFifoWaitMs is an io_error ("...: no process wrote to the FIFO within 5 s"). Errors, `label`
  /// being how the caller names this input (a flag, a field):
  ///   invalid_argument "<label> = <name> is neither a file nor a preset: must be calm,
  ///                     moderate, storm or a JSON file"
  ///   io_error         "cannot read preset '<path>': <reason>"
  ///   invalid_argument "preset '<path>' is larger than 1048576 bytes (1 MiB), the most a
  ///                     preset may hold"
  ///   invalid_argument "preset '<path>' nests deeper than 64 levels"
  ///   invalid_argument "preset '<path>' is not valid JSON"
  /// On error the document is unchanged.
  Status merge_preset(std::string_view name_or_path, std::string_view label = "preset");

  /// Sets one key: `assignment` is "dotted.key=value", the value JSON or else a bare string
  /// ("normals=analytic"); missing objects on the path are created. The key holds at most
  /// kMaxKeyBytes bytes, the value kMaxValueBytes, and the parts of the key plus the nesting
  /// of the value at most kMaxPresetDepth levels. Errors (invalid_argument):
  ///   "<label> '<assignment>': expected key=value", "<label> '<assignment>': empty key part",
  ///   "<label> <key>: '<part>' is not inside an object",
  ///   "<label> '<assignment>': the key is <n> bytes: must be at most 256",
  ///   "<label> '<assignment>': the value is <n> bytes: must be at most 65536",
  ///   "<label> '<assignment>': nests deeper than 64 levels".
  /// On error the document may hold the objects created on the path so far.
  Status set(std::string_view assignment, std::string_view label = "set");

  /// The configuration the document describes (as from_json).
  [[nodiscard]] Result<SimulationConfig> config() const;
  /// The picture settings the document carries. Errors (invalid_argument), one line:
  ///   "far_field_range: expected [DMIN, DMAX], two distances in metres, got <value>",
  ///   "far_field_range: [<a>, <b>] must be finite distances with 0 <= DMIN < DMAX",
  ///   "underwater.scattering_per_m = <b> is out of range: must be in [0, 10] 1/m" (also
  ///   "underwater: expected an object", "underwater.<key>: unknown key", "underwater.
  ///   scattering_per_m: expected a number").
  [[nodiscard]] Result<PictureSettings> picture() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ocean::preset
