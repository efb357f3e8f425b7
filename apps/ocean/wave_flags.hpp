// The flags of the local layer (ocean/waves.hpp) shared by `ocean bake`, `ocean query` and `ocean
// render`:
// --calm, --kelvin-wake, --waveform, --local-area, --local-resolution, turned into a layer, and
// --damping-mask, --bathymetry, turned into the damping of the sea's bands (query only).
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ocean/sim.hpp"
#include "ocean/waves.hpp"

namespace ocean::cli {

struct WaveFlags {
  bool calm = false;
  std::vector<std::string> wakes;      ///< X,Z,HEADING_DEG,SPEED_MPS,LENGTH_M
  std::vector<std::string> waveforms;  ///< FILE,X,Z,SIZE_M,AMPLITUDE_M[,ROTATION_DEG]
  std::string local_area;              ///< X0,Z0,SIZE_M
  std::string local_resolution = "512";
  std::string damping_mask;  ///< FILE,X0,Z0,SIZE_M
  std::string bathymetry;    ///< FILE,X0,Z0,SIZE_M
  /// A scene of shallows.hpp about the origin, instead of both maps.
  std::string shallows = "none";
  /// γ of depth-induced breaking over the bathymetry (W.25), H_max = γ·d; "0" turns it off.
  std::string breaking_index = "0.78";
};
void add_wave_flags(CLI::App& command, WaveFlags& flags);

/// The layer the flags describe (built by world::World::make), or nullopt when they give no
/// wake, waveform or area. A malformed value or an unreadable file is an error naming the flag
/// and echoing the value (ocean::excerpt); wakes or waveforms without --local-area an error that
/// names a square holding them at `time_s` (docs/waves.md W.19) and the --local-resolution it
/// needs.
Result<std::optional<waves::LayerParams>> layer_params(const WaveFlags& flags, double choppiness,
                                                       double time_s = 0.0);

/// The damping of the sea's bands the flags describe (--damping-mask, --bathymetry, or
/// --shallows: a scene of shallows.hpp centred on the origin), for the cascades of `config`, or
/// null when none is given. --shallows with either map, or an unknown scene, is an error. An
/// unreadable file, a bad placement, a mask value outside [0, 1], a NaN depth or land above 10 km,
/// a PNG bathymetry, a breaking index outside [0.3, 1.5] (other than 0, no breaking) or either flag
/// with --calm is an error naming the flag. The bands break over the bathymetry by W.25–W.27 with
/// the sea's band variances.
Result<std::shared_ptr<const waves::Damping>> make_damping(const WaveFlags& flags,
                                                           const SimulationConfig& config);

/// With --shallows lagoon or beach (and neither --calm nor a bad flag, which make_damping
/// reports): the scene's shore wave (shallows_shore_wave, docs/waves.md W.38) added to the
/// layer's waveforms, kShoreWaveFrames frames over one period at --local-resolution; without a
/// layer, one made over the scene's depth map. Errors: a bad --local-resolution, the spectrum's.
Status add_shore_wave(const WaveFlags& flags, const SimulationConfig& config,
                      std::optional<waves::LayerParams>& layer);
/// Frames of the shore wave's looped waveform per period: 32 keep the amplitude of the blend
/// between two frames of the travelling wave above cos(π/32) = 0.995 of its own (W.16).
inline constexpr int kShoreWaveFrames = 32;

/// The damping sampled on a square grid over its maps (the union of the mask's and the
/// bathymetry's rectangles) for a renderer: per cell `bands` weights (Damping::band_weights; 1
/// beyond the damping's bands) and the depth (+inf where no bathymetry covers the cell).
struct DampingSamples {
  std::array<double, 2> origin_m{0.0, 0.0};
  double size_m = 0.0;
  int resolution = 0;
  std::vector<float> band_weights;  ///< bands per cell, row-major, rows along +z
  std::vector<float> depth_m;
  std::vector<float> breaking_fraction;  ///< Q_b per cell (Damping::surf, W.26)
};
DampingSamples sample_damping(const waves::Damping& damping, int resolution, std::size_t bands);

/// Prints the layer's warnings at time t on stderr, "ocean: warning: ..." each.
void print_warnings(const waves::LocalLayer& layer, double time_s);

}  // namespace ocean::cli
