// ocean/waves.hpp — what is added to the spectral sea in a local, world-space area: procedural
// Kelvin wakes of moving objects and pre-authored height maps, composited into one non-periodic
// layer of height and horizontal displacement (Mitchell 2005, §3.4). The CPU reference; backends
// and the renderer mirror it.
//
// Conventions (docs/conventions.md, docs/waves.md): SI units, Y up, the sea is the x–z plane.
// Headings and rotations are degrees from +x towards +z (0 = +x, 90 = +z). The layer's cell
// (col, row) is the point that starts at world (x0 + (col + ½)·size/N, z0 + (row + ½)·size/N) and
// is displaced by (Dx, h, Dz), like a cascade texel; the layer adds to the sea's displacement
// there. Displacement follows the sea's sign, D = λ·Σ i·k̂·h̃·e^{ik·x} (crests sharpen).
// Equation numbers (W.n) refer to docs/waves.md.
//
// Threading: a LocalLayer is immutable once made; every const method may be called from any
// number of threads at once.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ocean/core.hpp"
#include "ocean/names.hpp"

namespace ocean::waves {

/// Sane limits of the layer's grid side N.
inline constexpr int kMinLocalResolution = 16;
inline constexpr int kMaxLocalResolution = 4096;
/// Default peak height of a wake as a fraction of its hull length (0.02·L: 0.2 m for a 10 m
/// boat, 2 m for a 100 m ship — of the order of observed ship-wave heights near the hull).
inline constexpr double kDefaultPeakHeightPerLength = 0.02;
/// The width of a wake's pressure across the track over its length along it (W.4), β: a hull is
/// slender, and a pressure as wide as it is long moves the cusp lines outwards by its own width,
/// which widens the wake near the object. 0.35 keeps the envelope's edge within 0.3° of a point
/// disturbance's from 2 hull lengths behind at Fr = 0.1–0.4 while the wake still narrows at high
/// Froude numbers as Rabaud & Moisy (2013) observe (W.11, W.18).
inline constexpr double kWakePressureAspect = 0.35;

/// The square world area the layer covers and its grid.
struct LocalArea {
  std::array<double, 2> origin_m{-128.0, -128.0};  ///< (x0, z0): the corner of smallest x and z
  double size_m = 256.0;                           ///< side, m, finite and > 0
  int resolution = 512;  ///< N cells per side, in [kMinLocalResolution, kMaxLocalResolution]
  /// Width of the soft edge as a fraction of size_m, in [0, 0.5]: the layer's weight rises from
  /// 0 at the border to 1 at this distance inside (smoothstep), so it fades into the sea.
  double edge_fraction = 0.1;
};
/// invalid_argument naming the field, the value and the valid range.
Status validate(const LocalArea& area);
/// World (x, z) of the centre of cell (col, row).
std::array<double, 2> cell_centre(const LocalArea& area, int col, int row);
/// The soft-edge weight at world (x, z): 0 outside the area and on its border, 1 inside the
/// edge band, smoothstep between (W.9).
double edge_weight(const LocalArea& area, double x, double z);

/// A timed point of an object's path.
struct Waypoint {
  double time_s = 0.0;
  double x_m = 0.0;
  double z_m = 0.0;
};

/// The foam a hull makes (docs/waves.md W.20–W.21): along its waterline, the rim of its footprint
/// (an ellipse of the wake's length L and of width beam_m, centred on the object and along its
/// heading), and a trail behind it whose half width grows as b(s) = B/2·(1 + s/L)^n (a turbulent
/// wake's spreading, Tennekes & Lumley 1972, §4.2), whose foam is spread over that width and ages
/// as e^{−τ/T} with its age τ = s/U. The simulator carries it on with the sea's own foam
/// accumulation and decay (M.7.4, M.7.9).
struct HullFoam {
  /// B, the footprint's width at the waterline, m, finite, in [0, 1000]; 0: no foam.
  double beam_m = 0.0;
  /// C₀, the foam's coverage on the waterline and at the trail's start, in [0, 1].
  double coverage = 1.0;
  /// The waterline foam's e-folding width outside the footprint, m, in [0, 100]; 0: B/4.
  double rim_width_m = 0.0;
  /// T, the trail's foam lifetime, s, in (0, 3600]: the bubbles a hull and its propeller mix in
  /// last minutes, far longer than a whitecap's foam (W.21).
  double lifetime_s = 40.0;
  /// n, the trail's spreading exponent, in [0, 1]: ½ a plane wake, ⅓ an axisymmetric one
  /// (Tennekes & Lumley 1972, §4.2).
  double spread_exponent = 1.0 / 3.0;
};
/// invalid_argument naming the field.
Status validate(const HullFoam& foam);
/// The half width b(s) of the trail s metres behind the object (W.21), m.
double trail_half_width_m(const HullFoam& foam, double hull_length_m, double s_m);
/// The foam coverage in [0, 1] of a hull of length L at speed U (m/s), at s metres behind its
/// centre and ζ to its left (W.20–W.21): the larger of the waterline's and the trail's.
double hull_foam_coverage(const HullFoam& foam, double hull_length_m, double speed_mps, double s_m,
                          double zeta_m);

/// A thin ship's hull for Michell's integral (W.23): its half-breadth f ≥ 0 below the
/// waterline, constant on each cell of a grid over x in [−L/2, L/2] (bow at +x) and depth in
/// [0, T], 0 beyond the ends (a transom is a step).
struct ThinHull {
  double length_m = 0.0;  ///< L, [0.01, 1000]
  double draft_m = 0.0;   ///< T, [1e-4, 1000]
  int columns = 0;        ///< cells along x, [2, 4096]
  int rows = 0;           ///< cells in depth, [1, 4096]
  /// f per cell, m, index row·columns + column; row 0 at the waterline, column 0 at the stern.
  std::vector<double> half_breadth_m;
};
/// invalid_argument naming the field.
Status validate(const ThinHull& hull);
/// Michell's wave resistance of the hull at speed U over the density of the water, R/ρ in m⁴/s²
/// (W.23). The hull is validated by the caller.
double michell_resistance_per_density(const ThinHull& hull, double speed_mps,
                                      double gravity_mps2 = 9.81);

/// The steady ship-wave pattern of an object moving over deep, calm water (W.1–W.7): the linear
/// wake of a pressure disturbance of length hull_length_m (a slender cone-tipped pressure
/// p ∝ e^{−ρ/a}, ρ² = s² + (ζ/β)², β = kWakePressureAspect, W.4), centred on the object's
/// position: Kelvin's 19.47° cusps, the amplitude largest along them and falling to half just
/// outside (W.18), and transverse waves of wavelength 2πU²/g at low Froude numbers
/// Fr = U/√(gL); narrower at Fr ≳ 0.5 (Rabaud & Moisy 2013, W.11).
struct KelvinWake {
  double x_m = 0.0;             ///< position at time 0 (no path), m
  double z_m = 0.0;             ///< position at time 0 (no path), m
  double heading_deg = 0.0;     ///< direction of travel, finite (no path)
  double speed_mps = 5.0;       ///< U, finite, in (0, 100] (no path)
  double hull_length_m = 10.0;  ///< L, finite, in [0.01, 1000]
  /// The largest |height| of the steady pattern, m (≥ 0, finite); unset: the height whose
  /// pattern carries Michell's wave resistance of `thin_hull` (W.24), or without one 0.02·L.
  std::optional<double> peak_height_m;
  /// The hull that makes the wake (W.23–W.24); its length should be hull_length_m. Null: none.
  std::shared_ptr<const ThinHull> thin_hull;
  /// Optional fade of the amplitude behind the object, e^{−s/fade_length_m}, m; 0 = none (the
  /// pattern then decays only as the linear solution does, W.8).
  double fade_length_m = 0.0;
  /// Empty: the object moves in a straight line, at (x_m, z_m) at time 0, along heading_deg at
  /// speed_mps. Two or more waypoints (times strictly increasing): the position is interpolated
  /// linearly between them and extrapolated along the first/last segment; heading and speed are
  /// those of the current segment (the pattern is the steady wake of that motion, swung rigidly
  /// on a turn). One waypoint: the object stays there, with heading_deg and speed_mps (a moored
  /// object in a current).
  std::vector<Waypoint> path;
  /// The foam along the hull's waterline and in its trail (W.20–W.21); beam_m = 0: none.
  HullFoam foam;
};
/// invalid_argument for NaN, negative or out-of-range values, naming the field.
Status validate(const KelvinWake& wake);

/// Where the object is, which way it heads and how fast, at time t.
struct WakePose {
  double x_m = 0.0, z_m = 0.0;
  double heading_rad = 0.0;
  double speed_mps = 0.0;
};
WakePose pose_at(const KelvinWake& wake, double time_s);

/// What a WakeTrack records and the wake it makes (W.17).
struct WakeTrackParams {
  double hull_length_m = 10.0;  ///< L of the wake, [0.01, 1000]
  /// The wake's largest |height|, m (≥ 0); unset: as KelvinWake (from thin_hull, or 0.02·L).
  std::optional<double> peak_height_m;
  std::shared_ptr<const ThinHull> thin_hull;  ///< as KelvinWake
  double fade_length_m = 0.0;  ///< as KelvinWake, m ≥ 0
  HullFoam foam;               ///< as KelvinWake
  double interval_s = 0.5;     ///< time between recorded waypoints, (0, 60]
  int waypoints = 8;           ///< how many of the newest are kept, [2, 4096]
  /// Below this speed over the kept track (m/s, [0, 100)) the object makes no wake.
  double min_speed_mps = 0.5;
  /// The wake's speed moves in steps of this relative size, (0, 0.1]: a new pattern (a table,
  /// W.7) is needed only when the speed leaves its step, not whenever it wobbles.
  double speed_step = 0.01;
  /// The wake's speed changes at most once per this many seconds, ≥ 0 (a boat speeding up
  /// computes a few tables, not one per step).
  double retune_s = 2.0;
};
/// invalid_argument naming the field.
Status validate(const WakeTrackParams& params);

/// The horizontal track of a moving object (a floating body, a vehicle) recorded at a fixed
/// interval, and the Kelvin wake that follows it (W.17): the newest waypoints are the wake's
/// path, its speed the mean speed along them, quantised, so that a layer remade with the new
/// path (LocalLayer::make with tables_from) shares its table while the speed holds. Heave, pitch
/// and roll play no part: only (x, z) is recorded.
class WakeTrack {
 public:
  /// Allocates the waypoints once. invalid_argument naming the field.
  static Result<WakeTrack> make(const WakeTrackParams& params);
  /// The object is at (x, z) at time t: recorded when interval_s has passed since the last
  /// waypoint (the first call always records); a time before the last waypoint starts the track
  /// afresh. Never allocates.
  void record(double time_s, double x_m, double z_m);
  /// Forgets the track.
  void clear();
  /// The mean speed along the kept waypoints, m/s; 0 with fewer than two.
  [[nodiscard]] double track_speed_mps() const;
  /// The wake's speed: track_speed_mps quantised to speed_step, held for retune_s; 0 while the
  /// track is slower than min_speed_mps (or faster than 100 m/s, KelvinWake's limit).
  [[nodiscard]] double wake_speed_mps() const { return wake_speed_mps_; }
  /// The waypoints kept, oldest first.
  [[nodiscard]] std::size_t size() const { return count_; }
  [[nodiscard]] const Waypoint& waypoint(std::size_t i) const;
  /// Writes the wake into `out` and returns true, or returns false (no wake: wake_speed_mps is
  /// 0). The path is the kept waypoints, the newest at its recorded time and each earlier one
  /// timed back from it along the track at the wake's speed, so every segment shares one table
  /// and the object moves on from the newest waypoint along the last segment's heading
  /// (pose_at). Reuses out.path's storage: no allocation once it has held `waypoints` points.
  bool wake(KelvinWake& out) const;

 private:
  WakeTrack() = default;
  WakeTrackParams params_;
  std::vector<Waypoint> ring_;  // capacity params_.waypoints
  std::size_t first_ = 0, count_ = 0;
  double wake_speed_mps_ = 0.0;
  double retuned_s_ = 0.0;  // when wake_speed_mps_ last changed
};

/// A 2-D height map: rows × cols samples, row-major, row r along +z and column c along +x before
/// rotation.
struct HeightMap {
  int rows = 0;
  int cols = 0;
  std::vector<float> values;
};
/// Largest side of a height map file.
inline constexpr int kMaxHeightMapSide = 16384;
/// Reads a height map: NumPy .npy (2-D, '<f4' or '<f8', C order; values used as they are),
/// PNG (8- or 16-bit grayscale, mapped linearly from [0, max] to [−1, 1]) or OpenEXR (its only
/// channel, or its "Y" channel; half or float values used as they are, file row 0 as map row 0).
/// io_error "cannot read '<path>': <reason>" for a missing, unreadable or corrupt file (an EXR
/// file's errors are those of io::read_exr); invalid_argument "cannot read '<path>': <problem>"
/// for a malformed or unsupported file (colour PNG, 3-D array, an EXR with several channels and
/// no "Y", another extension), an oversized one, or non-finite values. The path is echoed through
/// ocean::excerpt. Never throws; safe on arbitrary bytes.
Result<HeightMap> load_height_map(const std::filesystem::path& path);

/// The placeholder of the frame number in a sequence's file pattern: "{frame}" (the number in
/// decimal, as many digits as it has) or "{frame:W}" (zero-padded to W digits, W in 1..9).
inline constexpr std::string_view kFramePlaceholder = "{frame";
/// Most frames in a height map sequence, and most samples all its frames hold together (256 MiB
/// of float).
inline constexpr int kMaxSequenceFrames = 10000;
inline constexpr std::size_t kMaxSequenceSamples = std::size_t{1} << 26;
/// True when `pattern` names a numbered sequence (holds kFramePlaceholder).
bool is_sequence_pattern(std::string_view pattern);
/// Reads a numbered sequence of height maps (W.16): the files of `pattern`'s folder whose names
/// are the pattern with the placeholder replaced by a frame number, in the order of their numbers,
/// which must run without a gap from the smallest (0, 1 or any other). Each file is read with
/// load_height_map. invalid_argument, one line naming the pattern: a malformed placeholder, no
/// matching file, a gap ("frame 12 missing between 11 and 13"), two files of one number ("7" and
/// "007"), frames of different sizes ("frame 3 is 64x32, frame 0 64x64"), more than
/// kMaxSequenceFrames frames or kMaxSequenceSamples samples; a frame's own errors name its file.
Result<std::vector<std::shared_ptr<const HeightMap>>> load_height_map_sequence(
    const std::filesystem::path& pattern);

/// What an animated waveform does after its last frame (W.16).
enum class Playback {
  loop,  ///< starts again: the last frame blends into the first, period = frames / fps
  hold,  ///< stays on the last frame (and on the first before time 0)
};
/// The names of the playbacks in flags and messages.
inline constexpr std::array<EnumName<Playback>, 2> kPlaybackNames{{
    {Playback::loop, "loop"},
    {Playback::hold, "hold"},
}};

/// A pre-authored waveform placed in the world: one still height map, or an animated sequence.
struct Waveform {
  std::shared_ptr<const HeightMap> map;  ///< a still map (used when `frames` is empty)
  /// An animated waveform (W.16): maps of one size, frame i shown at time i / fps_hz, linearly
  /// interpolated between frames; empty for a still map.
  std::vector<std::shared_ptr<const HeightMap>> frames;
  double fps_hz = 24.0;                ///< frames per second of `frames`, finite, in (0, 1000]
  Playback playback = Playback::loop;  ///< after the last frame
  double x_m = 0.0;                    ///< centre, m
  double z_m = 0.0;                    ///< centre, m
  double size_m = 10.0;       ///< extent along the map's columns, m (> 0); rows scale alike
  double amplitude_m = 1.0;   ///< height = amplitude·value, m (finite)
  double rotation_deg = 0.0;  ///< from +x towards +z
};
/// invalid_argument for a missing map (no map and no frames), frames of different sizes or
/// missing, a bad fps, size, amplitude or rotation.
Status validate(const Waveform& waveform);
/// Which frames an animated waveform shows at time t and how much of the second (W.16): frame
/// `first` weighted 1 − `blend` and frame `second` weighted `blend`, blend in [0, 1). A still map:
/// {0, 0, 0}.
struct FramePair {
  std::size_t first = 0;
  std::size_t second = 0;
  double blend = 0.0;
};
FramePair frame_pair(const Waveform& waveform, double time_s);
/// Height of the waveform at world (x, z) at time t: amplitude times the bilinear sample of its
/// map (clamped at the map's edge cells), 0 outside its rectangle (W.10); for a sequence the two
/// frames of frame_pair(t) sampled alike and blended (W.16). Never allocates.
double waveform_height(const Waveform& waveform, double x, double z, double time_s = 0.0);

/// A 2-D map placed in the world by its corner: sample (row r, col c) lies at world
/// x = x0 + (c + ½)·cell, z = z0 + (r + ½)·cell, cell = size_m / cols, so the map covers
/// [x0, x0 + size_m] × [z0, z0 + size_m·rows/cols] (rows along +z, as the local layer's files).
struct PlacedMap {
  std::shared_ptr<const HeightMap> map;
  std::array<double, 2> origin_m{0.0, 0.0};  ///< (x0, z0), finite
  double size_m = 0.0;                       ///< extent along the columns, m, finite and > 0
};
/// Bilinear value of the map at world (x, z), clamped to the edge samples inside its rectangle;
/// `outside` beyond the rectangle. Never allocates.
double sample(const PlacedMap& placed, double x, double z, double outside);

/// Most cascades (bands) a Damping weighs.
inline constexpr std::size_t kMaxBands = 16;
/// The highest land a bathymetry may hold (as a depth of −10 km), m.
inline constexpr double kMaxLandHeight_m = 1e4;
/// The breaking index of a solitary wave, H/d (McCowan 1894, "On the highest wave of permanent
/// type"): the default γ of depth-induced breaking (W.25).
inline constexpr double kMcCowanBreakingIndex = 0.78;

/// Where the sea's high-frequency bands are damped: a mask and a bathymetry, both optional.
struct DampingParams {
  /// Values in [0, 1]: 0 = the low band (cascade 0) only, 1 = every band; 1 outside the map.
  std::optional<PlacedMap> mask;
  /// Water depth, m, finite and ≥ −kMaxLandHeight_m; deep water (no attenuation) outside the map.
  /// A negative depth is land, −d its height above the mean sea level (W.28): no waves there.
  std::optional<PlacedMap> bathymetry;
  /// Representative wavenumber of each band, rad/m, lowest band first (sim.hpp's
  /// band_wavenumbers); 1 to kMaxBands values, finite and > 0.
  std::vector<double> band_wavenumbers_radpm;
  double gravity_mps2 = 9.81;  ///< g > 0
  /// The deep-water height variance of each band, m², lowest band first (sim.hpp's
  /// band_variances): what depth-induced breaking weighs the local sea by (W.25). Empty: no
  /// breaking (the bands are damped by W.12–W.13 alone); else one value per band, finite, ≥ 0.
  std::vector<double> band_variances_m2;
  /// γ of W.25: the highest wave over water of depth d is γ·d. McCowan's (1894) solitary wave,
  /// 0.78, by default; Battjes & Janssen (1978) fitted 0.8 for random waves on a beach. Finite,
  /// in [0.3, 1.5] (Thornton & Guza 1983's rms index 0.42 lies within it, applied to H_rms).
  double breaking_index = kMcCowanBreakingIndex;
};
/// invalid_argument naming the field and value: a bad placement, a mask value outside [0, 1], a
/// non-finite depth or land higher than kMaxLandHeight_m ("bathymetry value 12 = nan ..."), bad
/// wavenumbers, band variances of another count than the wavenumbers or negative, a breaking index
/// outside [0.3, 1.5].
Status validate(const DampingParams& params);

/// The fraction of breaking waves Q_b of Battjes & Janssen (1978) (W.26): the waves' heights
/// taken as Rayleigh-distributed with rms b·H_max, truncated at H_max, Q_b is the root in (0, 1)
/// of (1 − Q_b)/ln Q_b = −b². 0 for b ≤ 0, 1 for b ≥ 1 (the saturated surf zone); increasing
/// between, ≈ e^{−1/b²} for small b. b = H_rms/H_max; NaN gives 0.
double breaking_fraction(double rms_over_max);

/// The sea's height statistics at a point of a bathymetry with depth-induced breaking (W.25–W.27).
struct Surf {
  double depth_m = 0.0;  ///< d (+inf off the bathymetry or without one)
  /// H_rms = √(8·Σ w_c²·m0_c) of the bands as the depth law and the mask damp them (W.12–W.13),
  /// before breaking limits it, m (Longuet-Higgins 1952: √8 σ for Rayleigh heights).
  double rms_height_m = 0.0;
  double max_height_m = 0.0;  ///< H_max = γ·d (W.25), m; +inf in deep water
  /// What W.27 leaves of H_rms: min(H_rms, H_max), m.
  double limited_rms_height_m = 0.0;
  double breaking_fraction = 0.0;  ///< Q_b(H_rms/H_max) (W.26): the foam coverage of the surf
};

/// The amplitude weight of a band of (deep-water) wavenumber k over water of depth d (W.12):
/// √Φ(ω, d), ω = √(g·k), Φ the Kitaigorodskii depth factor of TMA (Bouws et al. 1985) relative
/// to its deep-water value 1. In [0, 1]; 1 for d = ∞, 0 for d = 0.
double depth_band_weight(double wavenumber_radpm, double depth_m, double gravity_mps2);

/// The per-band weights of a damping mask and a bathymetry at any world point (W.12–W.13): what
/// the height queries multiply each cascade's displacement by, and what a renderer multiplies
/// each cascade's sample by per pixel. Immutable; const methods are thread-safe.
class Damping {
 public:
  static Result<Damping> make(DampingParams params);
  [[nodiscard]] const DampingParams& params() const { return params_; }
  [[nodiscard]] std::size_t band_count() const { return params_.band_wavenumbers_radpm.size(); }
  /// Weight of each band at world (x, z), out[c] for cascade c (out.size() ≥ band_count(); the
  /// rest is left alone): depth_band_weight(k_c, depth(x, z)) times, for every band but the low
  /// one, the mask value m(x, z) (W.13); with band variances, every band then times
  /// H_max/H_rms where the local H_rms exceeds H_max = γ·d (W.27). Never allocates.
  void band_weights(double x, double z, std::span<double> out) const;
  /// The local wave heights and the fraction of breaking waves at world (x, z) (W.25–W.27). No
  /// band variances: H_rms 0, nothing breaks. Never allocates.
  [[nodiscard]] Surf surf(double x, double z) const;

 private:
  // W.12–W.13's weights of every band into out[0, band_count()); returns the depth (+inf off
  // the bathymetry).
  double depth_weights(double x, double z, std::span<double> out) const;
  DampingParams params_;
};

/// The steepest foreshore the run-up law is applied at (W.41): Stockdon et al. (2006) fitted it
/// on sandy beaches far gentler than this; a steeper slope (a cliff, a grid's step) is taken as it.
inline constexpr double kMaxForeshoreSlope = 0.2;

/// The deep-water wavelength of waves of period T, L0 = g·T²/(2π), m (W.40).
double deep_water_wavelength_m(double period_s, double gravity_mps2);

/// Run-up statistics on a beach (W.41, Stockdon, Holman, Howd & Sallenger 2006), elevations above
/// the mean sea level, m.
struct Runup {
  double setup_m = 0.0;    ///< ⟨η⟩ = 0.35·β_f·√(H0·L0) (their eq. 10)
  double swash_m = 0.0;    ///< S = √(H0·L0·(0.563·β_f² + 0.004)), the significant swash height
  double runup2_m = 0.0;   ///< R2% = 1.1·(⟨η⟩ + S/2) (their eq. 19), exceeded by 2 % of the maxima
  double rundown_m = 0.0;  ///< ⟨η⟩ − S/2: the lowest the drawn swash retreats to (W.42)
};
/// Stockdon et al.'s (2006) set-up, swash and R2% for deep-water significant height H0 (m), the
/// deep-water wavelength of the peak period L0 (m, W.40) and the foreshore slope β_f (tan of its
/// angle; |β_f| is used, clamped to kMaxForeshoreSlope; NaN is taken as the clamp). All zero
/// unless H0 > 0 and L0 > 0. Never allocates.
Runup stockdon_runup(double h0_m, double l0_m, double foreshore_slope);
/// The elevation of the swash's water line at `phase` of its cycle (cycles; its fraction is used),
/// m (W.42): Shen & Meyer's (1963) parabola in time from the run-down at phase 0 up to R2% at ½
/// and back, rundown + (R2% − rundown)·4φ(1 − φ).
double swash_elevation_m(const Runup& runup, double phase);
/// The phase offset of the swash at the shoreline point (x, z), cycles (W.43): slow waves along
/// the shore a fraction of L0 long, so the water line is not one rigid line. 0 unless L0 > 0.
double swash_alongshore_phase(double x_m, double z_m, double l0_m);

/// A floating object's waterline foam without a wake (W.20): the rim of its footprint, an
/// ellipse of length_m along its heading and foam.beam_m across it, centred at (x, z).
struct Footprint {
  double x_m = 0.0, z_m = 0.0;  ///< centre, finite
  double heading_deg = 0.0;     ///< finite
  double length_m = 1.0;        ///< (0, 1000]
  HullFoam foam;                ///< its beam, coverage and rim width (no trail: it is at rest)
};
/// invalid_argument naming the field.
Status validate(const Footprint& footprint);

/// Everything composited into a layer.
struct LayerParams {
  LocalArea area;
  std::vector<KelvinWake> wakes;
  std::vector<Waveform> waveforms;
  std::vector<Footprint> footprints;  ///< waterline foam of objects at rest (W.20)
  double choppiness = 1.0;     ///< λ ≥ 0 for the wakes' horizontal displacement (finite)
  double gravity_mps2 = 9.81;  ///< g > 0
};

/// One evaluation of the layer on its grid.
struct LocalFrame {
  double time_s = 0.0;
  LocalArea area;
  std::vector<float> displacement;  ///< float3 (Dx, h, Dz) per cell, index row·N + col, m
  std::vector<float> foam;  ///< the hulls' foam coverage in [0, 1] per cell (W.20–W.21)
};

class LocalLayer {
 public:
  /// Validates the parameters and computes each distinct (U, L) wake pattern once, on a table in
  /// the object's frame reaching twice the side behind the object, or the area's far corner from
  /// an object farther away whose wake meets it (W.5–W.7; about 2 frames' evaluate, 0.02–0.7 s for
  /// N = 512–2048). invalid_argument names the offending wake or waveform
  /// ("wakes[1].speed_mps = -3 ..."). With `tables_from`, a pattern that layer holds for the same
  /// (U, L), g and cell, reaching as far, is shared instead of computed (W.17): a layer remade
  /// with a moving object's new path costs the copy of its parameters, not a table.
  /// `tables_from` may be destroyed after.
  static Result<std::unique_ptr<LocalLayer>> make(LayerParams params,
                                                  const LocalLayer* tables_from = nullptr);
  ~LocalLayer();
  LocalLayer(const LocalLayer&) = delete;
  LocalLayer& operator=(const LocalLayer&) = delete;

  [[nodiscard]] const LayerParams& params() const { return params_; }
  /// How many wake tables make() computed: one per distinct (U, L), speeds equal to a relative
  /// 1e-6 counting as one (a path at constant speed needs one table, whatever its segments).
  [[nodiscard]] std::size_t table_count() const;
  /// How many of them make() computed (the rest were shared from `tables_from`).
  [[nodiscard]] std::size_t tables_computed() const;
  /// (Dx, h, Dz) of the layer at the undisplaced world point (x, z) at time t, m: the sum of the
  /// wakes (their tables moved and turned to each object's pose, bilinear) and the waveforms,
  /// times the soft-edge weight. Never allocates.
  [[nodiscard]] std::array<double, 3> displacement_at(double x, double z, double time_s) const;
  /// The hulls' foam coverage in [0, 1] at world (x, z) at time t (W.20–W.21): the largest of the
  /// wakes' HullFoam at their poses and of the footprints', times the soft-edge weight. Never
  /// allocates.
  [[nodiscard]] double foam_at(double x, double z, double time_s) const;
  /// Evaluates every cell at time t (displacement_at at the cell centres), sizing `out`.
  void evaluate(double time_s, LocalFrame& out) const;
  /// Warnings, one line each, for what will not show at time t: an object outside the area, a
  /// wake whose waves are too short for the grid (left out), or whose cusp waves are (under 6
  /// cells: weakened by the grid's taper, W.5, so the wake looks narrower than Kelvin's angle).
  [[nodiscard]] std::vector<std::string> warnings(double time_s) const;

  struct Impl;

 private:
  LocalLayer() = default;
  LayerParams params_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ocean::waves
