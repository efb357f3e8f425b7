// shallows.hpp — the shallows scenes of `ocean view --shallows` and `ocean render --shallows`:
// lily pads (a damping mask that calms the sea's short bands, docs/waves.md W.13), a lagoon (a
// bathymetry that shoals to an island rising above the sea, W.12, with its surf, W.25–W.27, and
// its beach drawn as land, docs/rendering.md R.63–R.64) and a beach (a planar beach whose sea's
// peak wave refracts and shoals towards the shore, W.32–W.38).
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "ocean/sim.hpp"
#include "ocean/waves.hpp"

namespace ocean::cli {

/// The shallows scenes.
enum class Shallows : int { none = 0, lily_pads = 1, lagoon = 2, beach = 3 };
inline constexpr std::array<const char*, 4> kShallowsLabels = {"none", "lily pads", "lagoon",
                                                               "beach"};
/// "none", "lily-pads", "lagoon" or "beach"; nullopt otherwise.
std::optional<Shallows> parse_shallows(std::string_view name);

/// The lagoon's island: the land rises 1 m per 5 m from the shoreline at kLagoonShore_m to a
/// plateau kLagoonIslandHeight_m above the sea.
inline constexpr double kLagoonShore_m = 50.0;
inline constexpr double kLagoonIslandHeight_m = 4.0;
/// The lagoon's rim: 20 m deep at kLagoonReef_m from the centre, where a reef wall falls to
/// kLagoonDeep_m at 200 m (the edge of the map's inscribed circle), deep enough that the light
/// of its bottom is gone (two-way transmittance e^{−2·a·d} ≤ 0.4 % at 450 nm, R.24) and the
/// water looks as the open sea's beyond the map.
inline constexpr double kLagoonReef_m = 150.0;
inline constexpr double kLagoonDeep_m = 300.0;

/// The beach: straight contours whose normal, the direction the bottom rises, points
/// kBeachNormal_deg from +x towards +z (the default wind sea, travelling along +x, meets them at
/// that angle); the shore kBeachShore_m from the centre along the normal, the bottom rising to it
/// at 1:20 from 10 m of depth 200 m out, and at 1:4 below that (a shelf down to the map's
/// kBeachDeep_m); the land rising at 1:20 to 3 m above the sea.
inline constexpr double kBeachNormal_deg = 35.0;
inline constexpr double kBeachShore_m = 100.0;
inline constexpr double kBeachDeep_m = 80.0;
inline constexpr double kBeachSize_m = 600.0;

/// The damping of a scene centred at `centre` for the cascades of `config`, or nullopt for
/// Shallows::none:
/// - lily pads: a 200 m mask, 0 (the low band only) inside a disc of radius 40 m, 1 beyond 60 m,
///   smoothstep between;
/// - lagoon: a 400 m depth map, d = (r − 50)/5 m at a distance r from the centre, from an island
///   4 m high (d = −4 inside r = 30 m, the shore at r = 50 m) to 20 m of depth at r = 150 m,
///   then a reef wall falling linearly to 300 m at r = 200 m and 300 m beyond; its waves break
///   by W.25–W.27 with `breaking_index` (0: no breaking) over the bands' variances of `config`;
/// - beach: a kBeachSize_m depth map of the planar beach above, breaking alike.
/// Errors: band_variances(config)'s, and Damping::make's (a breaking index outside [0.3, 1.5]).
Result<std::optional<waves::Damping>> shallows_damping(
    Shallows scene, std::array<double, 2> centre_m, const SimulationConfig& config,
    double breaking_index = waves::kMcCowanBreakingIndex);

/// The shore wave of a scene with a bathymetry (docs/waves.md W.38): the peak wave of the wave
/// system of `config` holding the most variance (its period Tp and mean direction; H0 = √(8·m0)
/// of cascade 0's variance) refracted
/// and shoaled over the scene's depth map (waves::ShoreWave, W.32–W.37), drawn as an animated
/// waveform of `frames` height maps over one period (looped), each the wave's height at the
/// cells' centres times β = √(1 − w0²), w0 cascade 0's depth weight (W.12): the deterministic
/// wave takes over the share of the low band's variance the depth law removes. Its height is
/// capped at `breaking_index`·d (W.36; 0 caps it at McCowan's 0.78·d all the same, as linear
/// shoaling without a cap grows without bound at the shoreline). nullopt for a
/// scene without a bathymetry (none, lily pads). Errors: the spectrum's, ShoreWave::make's.
Result<std::optional<waves::Waveform>> shallows_shore_wave(Shallows scene,
                                                           std::array<double, 2> centre_m,
                                                           const SimulationConfig& config,
                                                           double breaking_index, int resolution,
                                                           int frames);

}  // namespace ocean::cli
