// ocean/sim.hpp — the simulation front end: configuration, cascades, per-frame outputs, the
// Backend interface every implementation (CPU reference, Vulkan, ...) provides, and the
// Simulator that double-buffers frames and answers height queries.
//
// Conventions (docs/conventions.md): a cascade is a periodic square patch of side L sampled on
// an N×N grid; texel (col, row) is the surface point that starts at world (x, z) =
// (col·L/N, row·L/N) and is displaced to (x + Dx, h, z + Dz). Displacements are metres,
// Y up. Equation numbers (M.n) refer to docs/math.md.
//
// Threading: a Simulator is driven from one thread. kick() runs a frame on the task runner while
// the caller keeps reading the previous frame; frame() and the queries read the last completed
// frame and are safe to call concurrently with a kicked step.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ocean/core.hpp"
#include "ocean/memory.hpp"
#include "ocean/spectrum.hpp"
#include "ocean/task_runner.hpp"

namespace ocean {

namespace waves {
class LocalLayer;  // ocean/waves.hpp
class Damping;     // ocean/waves.hpp
}  // namespace waves
class SimulationPlan;  // ocean/plan.hpp

/// How surface normals and the Jacobian are obtained from the synthesised fields.
enum class NormalMethod {
  /// Central differences of the displacement, toroidal wrap (Aebi, VR Ocean, eqs. 45–46).
  central_difference,
  /// Inverse FFTs of the slope and displacement-gradient spectra (Tessendorf 2001, eq. 37;
  /// Vincevičius 2024, eq. 2.8; Paleologue 2024, "Computing the Normals").
  analytic,
  /// 3×3 Sobel filter of the displacement (Mitchell 2005, §3.2).
  sobel,
};
/// The names of the normal methods in presets, flags and messages.
inline constexpr std::array<EnumName<NormalMethod>, 3> kNormalMethodNames{{
    {NormalMethod::central_difference, "central-difference"},
    {NormalMethod::analytic, "analytic"},
    {NormalMethod::sobel, "sobel"},
}};
/// The method's name in kNormalMethodNames.
std::string_view to_string(NormalMethod method);
/// The method of a name in kNormalMethodNames; invalid_argument listing the names otherwise.
Result<NormalMethod> parse_normal_method(std::string_view name);

/// What the blue channel of the packed RGBA8 map carries.
enum class BlueChannel {
  foam,      ///< accumulated foam coverage in [0, 1] (what shading needs)
  jacobian,  ///< saturate(J/2 + 1/2), Aebi, VR Ocean, eq. 50
};
/// The names of the blue-channel contents in presets and messages.
inline constexpr std::array<EnumName<BlueChannel>, 2> kBlueChannelNames{{
    {BlueChannel::foam, "foam"},
    {BlueChannel::jacobian, "jacobian"},
}};

/// Where foam comes from (M.7.4).
enum class FoamSource {
  /// A linear ramp on each cascade's own Jacobian, from `jacobian_start` to `jacobian_full`
  /// (Vincevičius 2024, §2.4): one band of the spectrum rarely folds on its own, so the coverage
  /// depends on the cascades and their constants, not on the sea.
  ramp,
  /// Breaking by Longuet-Higgins (1969)'s criterion: the surface breaks where its downward
  /// acceleration exceeds α·g. For linear deep-water waves J − 1 = λ·a_z/g, so that is
  /// J < 1 − λ·α on the whole surface (every cascade and the waves shorter than the finest). Each
  /// cascade's map holds the probability of it given its own J, the rest of the sea's Jacobian
  /// taken as Gaussian with the variance the spectrum gives it (SimulationPlan, CascadePlan::
  /// foam_source): the whitecap fraction of the sea, whichever cascade one looks at.
  breaking,
};
/// The names of the foam sources in presets and messages.
inline constexpr std::array<EnumName<FoamSource>, 2> kFoamSourceNames{{
    {FoamSource::ramp, "ramp"},
    {FoamSource::breaking, "breaking"},
}};

struct FoamParams {
  FoamSource source = FoamSource::breaking;
  /// α of FoamSource::breaking: the downward acceleration, as a fraction of g, beyond which a
  /// crest breaks. ½ is the crest of Stokes's limiting wave (Longuet-Higgins 1969, "On wave
  /// breaking and the equilibrium spectrum of wind-generated waves"). In (0, 2].
  double breaking_acceleration = 0.5;
  /// FoamSource::ramp: foam appears where a cascade's Jacobian falls below `jacobian_start` and
  /// is full at `jacobian_full` (linear ramp between, M.7.4). J < 0 is a fold (Aebi, VR Ocean,
  /// eq. 48).
  double jacobian_start = 0.8;
  double jacobian_full = 0.5;
  /// Decay of accumulated foam per second (Vincevičius 2024, §2.4.2); 0 keeps foam forever,
  /// large values disable accumulation.
  double decay_per_s = 0.6;
};

/// The per-texel float arrays a frame carries besides those every frame has (the float3 and half4
/// displacement and the packed RGBA8 chain with its mips: the texture set a renderer needs, all it
/// uploads, as in Aebi, VR Ocean, §3.7–3.9). Arrays not requested stay empty and are neither
/// computed into nor written, which saves 20 bytes per texel of stores and memory; foam still
/// accumulates (in the backend's state) when the packed map's blue channel carries it.
struct FrameOutputs {
  bool normal = true;    ///< CascadeFrame::normal (float3)
  bool jacobian = true;  ///< CascadeFrame::jacobian
  bool foam = true;      ///< CascadeFrame::foam
  /// CascadeFrame::velocity: the surface particles' velocity by one more set of inverse FFTs per
  /// frame (M.7.11). Off by default: it costs a frame two more transforms per cascade. The CPU
  /// backend computes it; the others refuse it at configure (unsupported).
  bool velocity = false;
  /// The default arrays (all but the velocity, which costs transforms of its own).
  static constexpr FrameOutputs all() { return {}; }
  /// Only the texture set a renderer needs: the displacement (float3 + half4) and the RGBA8 chain.
  static constexpr FrameOutputs textures() { return {false, false, false}; }
  friend bool operator==(const FrameOutputs&, const FrameOutputs&) = default;
};

/// What one cascade (band) contributes to the surface (Mitchell 2005, §3.3: a low band that
/// displaces the geometry and a broad band that only shades it). Applied to each published
/// frame by apply_band_roles, so every consumer of a frame (height queries, renderer, bake)
/// honours it.
enum class BandRole {
  both,      ///< moves the surface and shades it (the default)
  displace,  ///< moves the surface only: its normal map is flat (0, 1, 0), J = 1, no foam
  shade,     ///< shades only (normals, Jacobian, foam): its displacement is 0
};
/// The names of the band roles in presets, flags and messages.
inline constexpr std::array<EnumName<BandRole>, 3> kBandRoleNames{{
    {BandRole::both, "both"},
    {BandRole::displace, "displace"},
    {BandRole::shade, "shade"},
}};
/// The role's name in kBandRoleNames.
std::string_view to_string(BandRole role);
/// The roles of a comma-separated list of names ("displace,both,shade"), one per cascade;
/// invalid_argument naming the unknown entry and listing the names.
Result<std::vector<BandRole>> parse_band_roles(std::string_view list);

/// The default sea: a fetch-limited JONSWAP wind sea, U10 = 10 m/s over 100 km, Donelan–Banner
/// spreading, waves travelling towards +x.
inline SeaStateParams default_sea_state() {
  SeaStateParams p;
  p.wind_sea.spectrum = {.model = SpectrumModel::jonswap,
                         .wind_speed_mps = kDefaultWindSpeedMps,
                         .fetch_m = kDefaultFetchM};
  p.wind_sea.spreading = {.model = SpreadingModel::donelan_banner};
  return p;
}

/// The noise maps of [VR-GIS FFT+Perlin] (docs/references.md; docs/rendering.md R.13a): the far
/// field's noise (R.13, fitted to cascade 0 by fit_far_field_noise, ocean/far_noise.hpp) as
/// per-frame data, height and surface gradient on a square window of the world, each octave
/// advected at the mean phase velocity of the waves it stands for. Computed by the backend beside
/// the cascades: on the CPU as a task of the frame graph next to the cascades' chains, on Vulkan as
/// a dispatch in the frame's submission with no barrier between it and the FFT, on CUDA on a stream
/// of its own in the frame's graph. Off by default (resolution 0): no map, no work.
struct FarNoiseConfig {
  int resolution = 0;  ///< N texels per side: 0 (off) or in [16, 4096]
  /// World (x, z) of texel (0, 0), m; texel (col, row) is the point origin + (col, row)·size/N.
  std::array<double, 2> origin_m{-4096.0, -4096.0};
  double size_m = 8192.0;  ///< side of the window, m, in [1, 1e6]
};

struct SimulationConfig {
  SeaStateParams sea = default_sea_state();  ///< wave systems and dispersion
  int resolution = 256;                      ///< N per cascade, a power of two in [16, 2048]
  /// Patch side of each cascade, m, largest first. Non-integer ratios keep the patterns of the
  /// cascades from lining up (visible tiling). Each cascade synthesises one band of |k| (M.7.1).
  std::vector<double> cascade_patch_sizes_m = {1000.0, 233.0, 57.0};
  double choppiness = 1.0;  ///< λ ≥ 0 (Aebi, VR Ocean, eq. 25); 0 = heights only
  /// T: the surface repeats after T seconds; 0 = never. Every ω is quantised down to a multiple
  /// of 2π/T (M.2.4), so T must be at least shortest_loop_period_s(): shorter, the longest waves
  /// quantise to ω' = 0 and stand still. At most 1e6 s.
  double loop_period_s = 200.0;
  std::uint64_t seed = 1;
  AmplitudeConvention convention = AmplitudeConvention::variance_preserving;
  NormalMethod normals = NormalMethod::central_difference;
  /// Base microfacet roughness r ∈ [0, 1] encoded in the normal length (Aebi, VR Ocean, eq. 49).
  double roughness = 0.1;
  FoamParams foam;
  BlueChannel blue_channel = BlueChannel::foam;
  FrameOutputs outputs;  ///< which optional arrays each frame carries
  /// The role of each cascade, band_roles[c] for cascade c: empty = every cascade BandRole::both;
  /// otherwise exactly one per cascade.
  std::vector<BandRole> band_roles;
  FarNoiseConfig far_noise;  ///< the far field's noise map (off by default)
};

/// Validates a configuration (and, when it loops, its sea state); the message names the field,
/// the value and the valid range.
Status validate(const SimulationConfig& config);

/// The shortest loop period T, s, at which every resolved wave still moves: T at which the lowest
/// wavenumber of every cascade's band keeps ⌊ω(k)·T/2π⌋ ≥ 1 (M.2.4) — in practice cascade 0's
/// longest wave, 2π/L0. Exact: quantize_omega gives that wave ω' > 0 at this T, 0 just below.
/// Errors are those of SeaState::make.
Result<double> shortest_loop_period_s(const SimulationConfig& config);

/// The wavenumber band [k_min, k_max) of each cascade: cascade c starts where cascade c−1 stops,
/// at half of cascade c−1's Nyquist wavenumber π·N/L (M.7.1). Rad/m.
std::vector<std::array<double, 2>> cascade_bands(const SimulationConfig& config);

/// The representative wavenumber of each cascade's band, rad/m, for the damping of the bands
/// (ocean/waves.hpp, W.14): the geometric mean of the band's finite edges, cascade 0's lower edge
/// taken at its fundamental 2π/L₀ and the last cascade's upper edge at its Nyquist π·N/L.
std::vector<double> band_wavenumbers(const SimulationConfig& config);
/// The expected height variance of each cascade's band, m², lowest first: Σ expected_wave_power
/// over the cascade's grid (what a realisation's texels hold on average), for depth-induced
/// breaking (ocean/waves.hpp DampingParams::band_variances_m2, W.25). Errors are those of
/// SeaState::make and make_initial_spectrum.
Result<std::vector<double>> band_variances(const SimulationConfig& config);

/// How cascade `index` generates its spectrum: its grid, its band, and its own seed
/// (seed + 0x9e3779b9·index, so cascades are independent realisations).
InitialSpectrumParams cascade_spectrum_params(const SimulationConfig& config, std::size_t index);

/// Number of texels in mip levels 0..log2 N of an N×N map: (4N² − 1)/3.
std::size_t mip_chain_texels(int resolution);
/// Offset of mip level m in the contiguous chain (Aebi, VR Ocean, eq. 55).
std::size_t mip_offset(int resolution, int level);

/// The outputs of one cascade for one frame. Arrays are row-major, index row·N + col, in
/// LargeVector storage (cache-line aligned; huge pages when large).
struct CascadeFrame {
  int resolution = 0;
  double patch_size_m = 0.0;
  LargeVector<float> displacement;               ///< float3 (Dx, h, Dz) per texel, m (eq. 44)
  LargeVector<std::uint16_t> displacement_half;  ///< half4 (Dx, h, Dz, 0), texture-ready
  // The next three are empty unless SimulationConfig::outputs requests them.
  LargeVector<float> normal;    ///< float3 unit normal of the displaced surface
  LargeVector<float> jacobian;  ///< J of the horizontal map (eq. 48)
  LargeVector<float> foam;      ///< accumulated foam coverage [0, 1]
  /// float3 ∂(Dx, h, Dz)/∂t per texel, m/s: the velocity of the surface particle that starts at
  /// the texel (M.7.11); empty unless SimulationConfig::outputs.velocity.
  LargeVector<float> velocity;
  /// RGBA8 (normal x, normal z, blue channel, smoothness), all mips, packed as eq. 51.
  LargeVector<std::uint32_t> packed_mips;
};

/// The sea and the local layer summed on the layer's grid (docs/math.md M.7.9): what the surface
/// is where wakes and waveforms are, with the normal, Jacobian and foam of the sum, so a wake
/// folds and foams where it meets a crest of the sea as the sea itself does. Cell (col, row) is
/// the point that starts at (x0 + (col + ½)·size/N, z0 + (row + ½)·size/N), as the layer's.
struct LocalSurfaceFrame {
  std::array<double, 2> origin_m{};  ///< (x0, z0) of the layer's area
  double size_m = 0.0;               ///< side of the area, m
  int resolution = 0;                ///< N cells per side; 0: no local layer, arrays empty
  /// float3 (Dx, h, Dz) per cell, index row·N + col, m: Simulator::displacement_at at the cell
  /// centre (the cascades as the frame carries them, damped, plus the layer).
  std::vector<float> displacement;
  std::vector<float> normal;    ///< float3 unit normal of the summed surface (M.7.5)
  std::vector<float> jacobian;  ///< J of the summed horizontal map (eq. 48)
  std::vector<float> foam;      ///< accumulated foam coverage [0, 1] from J (M.7.4)
  /// float3 (Dx, h, Dz) of the layer alone per cell, m (LocalLayer::displacement_at at the cell
  /// centre): what a consumer that draws the sea at its own resolution adds to it (R.19).
  std::vector<float> layer_displacement;
  /// The normal and the accumulated foam of the sea alone on the same grid, by the same
  /// differences and the same accumulation as `normal` and `foam` (M.7.10): where the layer is 0
  /// in a cell and its neighbours (and has been since the foam restarted) they equal `normal` and
  /// `foam` exactly, so `normal − sea_normal` and `foam − sea_foam` are what the layer changes.
  std::vector<float> sea_normal;
  std::vector<float> sea_foam;
};

/// The far field's noise map of one frame (FarNoiseConfig, docs/rendering.md R.13a).
struct FarNoiseFrame {
  std::array<double, 2> origin_m{};  ///< world (x, z) of texel (0, 0), m
  double size_m = 0.0;               ///< side of the window, m
  int resolution = 0;                ///< N texels per side; 0: no map, array empty
  /// float3 (h, ∂h/∂x, ∂h/∂z) per texel, index row·N + col: the height, m, and the surface
  /// gradient of the noise at texel (col, row)'s world point at the frame's time (the normal is
  /// (−∂h/∂x, 1, −∂h/∂z) normalised).
  LargeVector<float> height_slope;
};

struct Frame {
  double time_s = 0.0;
  std::uint64_t index = 0;  ///< frames computed since configuration
  std::vector<CascadeFrame> cascades;
  /// The local surface, computed by the Simulator after the backend's step when a local layer
  /// is set (Simulator::set_local_layer); empty otherwise.
  LocalSurfaceFrame local;
  /// The far field's noise map, computed by the backend when SimulationConfig::far_noise is on;
  /// empty otherwise.
  FarNoiseFrame far_noise;
};

/// Sizes every array of `frame` for `config` (one CascadeFrame per cascade, mips included; the
/// arrays config.outputs does not request empty; the far-field noise map when config.far_noise
/// is on) and resets the values: displacement, normal
/// and foam 0, Jacobian 1. What Backend::allocate does.
void allocate_frame(const SimulationConfig& config, Frame& frame);

/// Applies config.band_roles to a frame a backend computed for `config` (docs/math.md M.7.8): a
/// shade-only cascade's displacement (float3 and half4) and velocity become 0, a displace-only
/// cascade's normal becomes (0, 1, 0), its Jacobian 1, its foam 0 and its packed map (every mip)
/// the flat texel of the configured roughness. What Simulator does to every frame it publishes; the
/// other arrays are left as the backend wrote them. Never allocates; no-op without roles.
void apply_band_roles(const SimulationConfig& config, Frame& frame);

/// A simulation implementation. configure() allocates and plans; step() never allocates,
/// never throws and writes every field of `out` (whose arrays configure() sized).
class Backend {
 public:
  virtual ~Backend() = default;
  [[nodiscard]] virtual std::string_view name() const = 0;
  /// Allocates and generates the spectra of a resolved plan (ocean/plan.hpp). May be called
  /// again with a new plan. A backend keeps no reference to `plan`.
  virtual Status configure(const SimulationPlan& plan, TaskRunner& runner) = 0;
  /// Resolves `config` (SimulationPlan::make: validation, sea state) and configures from it.
  Status configure(const SimulationConfig& config, TaskRunner& runner);
  /// Sizes the arrays of a frame for the configured simulation.
  virtual void allocate(Frame& frame) const = 0;
  /// Computes the frame at `time_s`, every cascade as BandRole::both (the Simulator applies the
  /// roles and sets Frame::index). Foam accumulates over the time since the previous step.
  virtual void step(double time_s, Frame& out) = 0;
  /// Moves the far field's noise map (SimulationConfig::far_noise) to a window whose texel (0, 0)
  /// lies at world `origin_m` from the next step() on (the size and resolution stay); the frame's
  /// FarNoiseFrame::origin_m says which window it holds. Allocates nothing. Backends without the
  /// map (it is off, or they refuse it at configure) ignore it.
  virtual void set_far_noise_origin(const std::array<double, 2>& origin_m) { (void)origin_m; }
  /// A hint from a frame loop that step(…, out) follows soon (about 1 ms): brings the state and
  /// `out`'s arrays that the step reads and writes into the caches of the threads that will
  /// compute them, so that a frame after an idle gap does not start from cold caches
  /// (docs/performance.md, paced frames). Changes nothing the step computes; allocates nothing;
  /// costs about the step's memory traffic in time. The default (GPU backends) does nothing.
  virtual void warm_caches(const Frame& out) { (void)out; }
};

/// The result of a height query at a world position (x, z).
struct HeightSample {
  double height_m = 0.0;                 ///< surface height above the mean level
  std::array<double, 3> displacement{};  ///< (Dx, h, Dz) at the source point, m
  std::array<double, 2> source_xz{};     ///< undisplaced point that lands on (x, z)
  int iterations = 0;                    ///< inverse iterations used
};

/// The surface above a world position (x, z): Simulator::surface_at.
struct SurfaceSample {
  double height_m = 0.0;  ///< as HeightSample::height_m for the same point (bit-identical)
  /// Unit normal (nx, ny, nz) of the rendered surface, ny > 0 where the horizontal map does not
  /// fold: (−∂η/∂x, 1, −∂η/∂z) normalised, η(x, z) the height (M.7.11).
  std::array<double, 3> normal{0.0, 1.0, 0.0};
  /// (u, w, v): velocity of the water particle at the surface there, m/s (x, y up, z), the time
  /// derivative of the displacement of the particle that the horizontal map carries onto (x, z)
  /// (linear theory, M.7.11). NaN when the published frame carries no velocity
  /// (SimulationConfig::outputs.velocity off).
  std::array<double, 3> velocity{0.0, 0.0, 0.0};
};

class Simulator {
 public:
  /// Configures the backend; runner = nullptr uses oneTBB with all hardware threads.
  static Result<std::unique_ptr<Simulator>> make(const SimulationConfig& config,
                                                 std::unique_ptr<Backend> backend,
                                                 std::shared_ptr<TaskRunner> runner = nullptr);
  ~Simulator();
  Simulator(const Simulator&) = delete;
  Simulator& operator=(const Simulator&) = delete;

  /// The same from a plan already resolved (the plan is copied; its far-noise fit is shared).
  static Result<std::unique_ptr<Simulator>> make(const SimulationPlan& plan,
                                                 std::unique_ptr<Backend> backend,
                                                 std::shared_ptr<TaskRunner> runner = nullptr);
  /// Regenerates spectra and buffers for a new configuration (on demand, Aebi, VR Ocean, §4.2.1).
  Status reconfigure(const SimulationConfig& config);
  Status reconfigure(const SimulationPlan& plan);
  /// Computes the frame at time_s synchronously and publishes it.
  void step(double time_s);
  /// Starts computing the frame at time_s in the background (into the back buffer).
  void kick(double time_s);
  /// Waits for the kicked frame and publishes it (swaps front and back). No-op if none.
  void wait();
  /// A hint from a frame loop that the next step or kick follows within about 1–3 ms: wakes
  /// the runner's workers (TaskRunner::wake) and warms the caches for the back buffer
  /// (Backend::warm_caches). Call it before waiting for the frame's start (ocean xr: before
  /// xrWaitFrame), not right before step(). Waits for a kicked frame first; allocates nothing.
  void prepare_step();

  /// The last published frame.
  [[nodiscard]] const Frame& frame() const;
  /// Hands one of the two frame buffers (`buffer`: frame() or the one the next step writes, the
  /// back buffer) to the caller and puts a copy of it in its place. The returned Frame owns the
  /// buffer's arrays at the same addresses, so pointers into them stay valid after later steps;
  /// the simulation continues exactly as before (the copy holds the same data). Waits for a
  /// kicked frame first. Allocates one frame. `buffer` must be one of the two buffers.
  [[nodiscard]] Frame detach(const Frame& buffer);
  /// The buffer the next step or kick writes (the one frame() is not).
  [[nodiscard]] const Frame& back_buffer() const;
  [[nodiscard]] const SimulationConfig& config() const { return config_; }
  /// The plan the backend was configured from (its config() is the configuration before any
  /// set_far_noise_origin).
  [[nodiscard]] const SimulationPlan& plan() const { return *plan_; }
  [[nodiscard]] const Backend& backend() const { return *backend_; }

  /// Adds a local layer (ocean/waves.hpp: wakes, waveforms) to the surface the queries see, so
  /// that displacement_at and heights_at return sea + layer, the layer taken at the published
  /// frame's time, and to every frame computed from now on: Frame::local, the layer composited
  /// with the sea before normals, Jacobian and foam (M.7.9). Its foam restarts here unless the
  /// layer replaces one on the same grid (origin, size and resolution equal): then the composited
  /// surface carries on, foam included. Allocates the local surface of both frames (unless the
  /// grid is the same); waits for a kicked step. nullptr removes it. Call it while no query runs.
  void set_local_layer(std::shared_ptr<const waves::LocalLayer> layer);
  [[nodiscard]] const waves::LocalLayer* local_layer() const { return local_layer_.get(); }
  /// Damps the sea's bands where a mask or a bathymetry says (ocean/waves.hpp, W.12–W.13): the
  /// queries multiply cascade c's displacement at (x, z) by band_weights(x, z)[c]; the local
  /// layer is not damped. Its bands should be band_wavenumbers(config()); a Damping with fewer
  /// bands than cascades leaves the rest undamped. nullptr removes it. Call it while no query
  /// runs (and again after reconfigure with a different set of cascades).
  void set_damping(std::shared_ptr<const waves::Damping> damping);
  [[nodiscard]] const waves::Damping* damping() const { return damping_.get(); }
  /// Moves the far field's noise map to the window whose texel (0, 0) lies at world `origin_m`
  /// (finite, |x|, |z| ≤ 1e9 m) for the frames computed from now on: a renderer keeps the map
  /// around its camera this way (ocean/far_field.hpp, far_noise_window; docs/rendering.md
  /// R.13b). Waits for a kicked step; allocates nothing; a no-op while the map is off.
  void set_far_noise_origin(const std::array<double, 2>& origin_m);

  /// Displacement (Dx, h, Dz) summed over cascades at the undisplaced point (x, z), bilinear
  /// between texels exactly as a GPU samples the maps with wrap addressing (M.7.6), plus the
  /// local layer's (Dx, h, Dz) there when one is set; each cascade weighed by the damping's band
  /// weight at (x, z) when one is set.
  [[nodiscard]] std::array<double, 3> displacement_at(double x, double z) const;
  /// Height of the rendered surface above world (x, z): finds the undisplaced point p with
  /// p + D_xz(p) = (x, z) by fixed-point iteration and Newton refinement (M.7.7), then
  /// returns h(p); D includes the local layer when one is set. Batched: out.size() must equal
  /// xz.size().
  void heights_at(std::span<const std::array<double, 2>> xz, std::span<HeightSample> out) const;
  /// The surface above world (x, z): the height of heights_at (the same inverse, bit-identical),
  /// the unit normal from the gradient of the bilinear displacement at the source point, and the
  /// particle velocity there from the frame's velocity arrays (NaN without them; see
  /// has_velocity), each cascade weighed by the damping like the displacement; the local layer's
  /// velocity is the central difference of its displacement over ±1 ms. Batched: out.size()
  /// must equal xz.size(). Allocates nothing.
  void surface_at(std::span<const std::array<double, 2>> xz, std::span<SurfaceSample> out) const;
  /// Whether the published frame carries the velocity (SimulationConfig::outputs.velocity).
  [[nodiscard]] bool has_velocity() const;

 private:
  Simulator() = default;
  /// Computes the back frame: the backend's step, the band roles, the local surface.
  void compute(double time_s);
  /// Frame::local of `back` from its cascades and the layer (local_surface.cpp).
  void compute_local_surface(Frame& back);
  struct Async;
  SimulationConfig config_;
  std::shared_ptr<const SimulationPlan> plan_;
  std::unique_ptr<Backend> backend_;
  std::shared_ptr<TaskRunner> runner_;
  Frame frames_[2];
  int front_ = 0;
  std::unique_ptr<Async> async_;
  std::shared_ptr<const waves::LocalLayer> local_layer_;
  std::shared_ptr<const waves::Damping> damping_;
  bool local_foam_reset_ = true;  ///< the next local surface starts its foam afresh
};

/// The height queries of Simulator::heights_at on a local layer alone, at time t: the surface of
/// a calm sea carrying only the layer's wakes and waveforms.
void heights_at(const waves::LocalLayer& layer, double time_s,
                std::span<const std::array<double, 2>> xz, std::span<HeightSample> out);

}  // namespace ocean
