// ocean/render.hpp — the Vulkan ocean renderer: the quadtree LOD mesh (ocean/lod.hpp) displaced
// by the simulation's cascades, shaded with sky reflection, Fresnel, sun specular, scattering,
// foam and horizon fog into a linear HDR image, then tone-mapped into an sRGB image.
//
// Inputs: either a CPU Frame (upload(): its half-float displacement and packed RGBA8 mips are
// copied into the renderer's own images at the start of the next draw, as Aebi, VR Ocean, §4.3,
// applies them), or the GPU images of a VulkanBackend on the same Context
// (use_simulation_images(): no copy). Outputs: the HDR and the sRGB image, on the device or read
// back.
//
// Contract: make() and configure() allocate; draw()/record() allocate nothing. Every failure is
// a Status with a one-line message ("no Vulkan device: ...", out of device memory, ...).
// Threading: one thread drives a renderer; it shares the Context's queue with the backend.
// Equations (R.n): docs/rendering.md.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "ocean/far_field.hpp"
#include "ocean/interop.hpp"
#include "ocean/lod.hpp"
#include "ocean/objects.hpp"
#include "ocean/plan.hpp"
#include "ocean/sim.hpp"
#include "ocean/tessellation.hpp"
#include "ocean/underwater.hpp"
#include "ocean/vk.hpp"
#include "ocean/vk/images.hpp"

namespace ocean::render {

/// What the shading and the sky depend on. Radiometric quantities are in one relative unit
/// (the sun's irradiance at the top of the atmosphere is `sun_irradiance`); exposure maps it to
/// the display.
struct ShadingParams {
  double sun_azimuth_deg = 35.0;    ///< direction towards the sun, clockwise from +x towards +z
  double sun_elevation_deg = 20.0;  ///< above the horizon, (−90, 90]
  double sun_irradiance = 20.0;     ///< > 0
  double sky_brightness = 1.0;      ///< scale of the sky's radiance, ≥ 0
  double aerosol = 1.0;             ///< Mie density relative to a clear day (haze), ≥ 0
  double aerosol_g = 0.76;          ///< Henyey–Greenstein asymmetry of the haze, [0, 0.99)
  /// Single-scattering albedo of the water body (deep Atlantic blue-green by default), [0, 1].
  std::array<double, 3> water_colour = {0.004, 0.016, 0.028};
  double crest_scatter = 0.9;    ///< gain of the light through thin wave crests, ≥ 0
  double foam_brightness = 1.0;  ///< foam albedo scale, ≥ 0
  /// Microfacet α of the waves shorter than the finest cascade, (0, 1], for a sea that names no
  /// wind (given by Hs and Tp); a wind sea's is √ of its short-wave slope variance
  /// (SurfaceDescription::unresolved_slope_variance, docs/rendering.md R.5).
  double roughness = 0.08;
  double fog_density_per_m = 6e-5;  ///< ρ of the horizon fog (R.8), ≥ 0
  double exposure = 0.45;           ///< multiplies the HDR image before tone mapping, > 0
  /// The air between the eye and the water dims and hazes it (R.8b): the sky's atmosphere
  /// (R.1–R.4) along the segment, so the sea seen from altitude lies under the air it is seen
  /// through.
  bool aerial_perspective = true;
  /// The waves shorter than the finest cascade (SurfaceDescription::short_waves) drawn as detail
  /// normals where the pixels resolve them, their slope variance taken out of the roughness there
  /// (R.62): ripples on the nearest water. Off: all of it stays roughness.
  bool ripples = true;
  /// The sea's whitecaps drawn as white patches where a field of the unresolved sea falls below
  /// the breaking threshold, the cover's mean kept (R.11b). Off: each cascade's breaking
  /// probability drawn as a grey fraction.
  bool whitecap_patches = true;
};
/// invalid_argument naming the field for non-finite values or values outside the ranges above.
Status validate(const ShadingParams& params);
/// Looks for the sky: "clear" (the defaults), "hazy", "overcast" (thick haze, no visible sun
/// disc, grey water: storms), "sunset" (sun 4° up). invalid_argument for other names.
Result<ShadingParams> sky_preset(std::string_view name);
/// Supersampling's resolve (docs/rendering.md R.60): a picture drawn `factor` times wider and
/// taller, averaged over factor × factor blocks in linear light — each sRGB value decoded
/// (IEC 61966-2-1), the block's mean encoded again, rounded; alpha averaged as stored. `rgba` is
/// width·height RGBA8, top row first; the result (width/factor)·(height/factor) pixels.
/// invalid_argument when factor < 1, does not divide both sides, or the size does not match.
Result<std::vector<std::uint8_t>> resolve_supersampled(std::span<const std::uint8_t> rgba,
                                                       int width, int height, int factor);
/// The same for linear HDR RGBA floats: the plain block mean.
Result<std::vector<float>> resolve_supersampled(std::span<const float> rgba, int width, int height,
                                                int factor);
/// The largest supersampling factor `ocean render --supersample` takes.
inline constexpr int kMaxSupersample = 4;

/// The names sky_preset knows, in the order messages and help texts list them.
inline constexpr std::array<std::string_view, 4> kSkyNames = {"clear", "hazy", "overcast",
                                                              "sunset"};

enum class DebugView : std::uint8_t {
  shaded,       ///< the water as it looks
  lod_colours,  ///< shading tinted by quadtree level
  wireframe,    ///< the LOD mesh's edges only (needs fillModeNonSolid)
  /// The water's shading normal N as linear colour 0.5·N + 0.5 (no fog; the HDR image holds it
  /// as computed, read_hdr) and its foam coverage in the HDR image's alpha.
  normals,
};
/// The names of the debug views in flags and messages.
inline constexpr std::array<EnumName<DebugView>, 4> kDebugViewNames{{
    {DebugView::shaded, "shaded"},
    {DebugView::lod_colours, "lod"},
    {DebugView::wireframe, "wireframe"},
    {DebugView::normals, "normals"},
}};
/// The view's name in kDebugViewNames ("shaded" for a value outside the enum).
std::string_view to_string(DebugView view);
/// The view of a name in kDebugViewNames; invalid_argument listing the names otherwise.
Result<DebugView> parse_debug_view(std::string_view name);

/// Earth's mean radius, m (IUGG; Moritz, "Geodetic Reference System 1980").
inline constexpr double kEarthRadius_m = 6.371e6;

/// The sea on a sphere (docs/rendering.md R.30–R.38) instead of the flat sea: a planet of radius
/// View::planet_radius_m covered by the cube-sphere LOD of ocean/sphere.hpp. The view's camera
/// (position and target) is then in metres along the local axes (east, up, north) of the
/// surface point at (latitude, longitude), with the origin on the sphere there: a camera at
/// (0, h, 0) is h metres above that point. The sky, the sun's direction and the fog are in those
/// axes. Not drawn on the sphere: the far field, the hex tiles, the local layer, the damping, the
/// seabed, the objects and the wireframe view.
struct SphereView {
  bool enabled = false;
  double latitude_deg = 0.0;     ///< [−90, 90]
  double longitude_deg = 0.0;    ///< finite, from +x towards +z
  double finest_patch_m = 16.0;  ///< side below which no patch splits, > 0
};

/// One picture's camera, mesh and look. Positions are world metres in double precision; the
/// renderer draws relative to the quadtree's centre (R.16), so a camera 10⁷ m from the world's
/// origin sees the same sea as one near it.
struct View {
  lod::Camera camera;
  lod::Quality quality = lod::quality_preset(lod::QualityPreset::high);
  double ocean_size_m = 4096.0;  ///< side S of the quadtree square, [256, 8192]
  /// Outer half-extent of the horizon skirt, m; ≤ 0: 10·S, or on a curved world beyond the
  /// horizon (1.25·√(2R(h + Hs)) rounded up to a power of two) when that is farther.
  double skirt_half_extent_m = -1.0;
  /// Radius R of the planet whose curvature bends the sea down by d²/(2R) at a horizontal
  /// distance d from the camera (docs/rendering.md R.15), so the horizon sits at its dip
  /// √(2h/R) below level; > 0; +infinity: a flat world.
  double planet_radius_m = kEarthRadius_m;
  ShadingParams shading;
  /// Where the far field (R.13) and the hex-tiled lookups (R.14) take over from the simulation.
  FarFieldRange far_field;
  DebugView debug = DebugView::shaded;
  /// Meshes placed in the world (indices into Renderer::set_meshes), drawn after the water and
  /// depth-tested with it (R.20). Each model matrix must be finite.
  std::vector<ObjectInstance> objects;
  /// Whether the water mirrors the objects (planar reflection, R.53). The stereo pass draws none
  /// (its reflection target is one view's); a mono picture to compare with it turns this off.
  bool object_reflections = true;
  /// A seabed seen through the water (R.22–R.23); off by default.
  Seabed seabed;
  /// The sea on a sphere of radius planet_radius_m (R.30–R.38); off by default.
  SphereView sphere;
  /// The water seen from a camera below the surface (R.50–R.52); absorption is seabed's.
  Underwater underwater;
  /// The mesh: the quadtree (default) or the tessellated base grid of [VR-GIS FFT+Perlin]
  /// (R.40–R.42), which needs a device with tessellation shaders (`unsupported` from record()
  /// otherwise).
  TessellationParams tessellation;
  /// Temporal anti-aliasing of record()/draw() (docs/rendering.md R.61): each frame's projection
  /// moved by a sub-pixel offset of the Halton (2, 3) sequence, and the frame blended into the
  /// last result, fetched where the motion vectors say each pixel was and clipped to the colours
  /// of the pixel's neighbourhood; the shading filters over a quarter of the pixel's footprint
  /// (the 16 jitter positions sample it as a 4 × 4 grid does). Needs
  /// Renderer::set_motion_vectors(true) and a flat sea of the quadtree (`unsupported` from
  /// record() with the sphere or the tessellated mesh, which draw no motion vectors); allocates
  /// two RGBA16F images of the picture's size (8 bytes a pixel each, outside
  /// kTargetBytesPerPixel) on first use. record_stereo() refuses it (`unsupported`).
  struct TemporalAntiAliasing {
    bool enabled = false;
    /// The new frame's weight in the blend, (0, 1]; the first frames after a start or a resize
    /// weigh 1/n (their plain mean) until that is smaller.
    double current_weight = 0.2;
  } temporal_aa;
};
Status validate(const View& view);
/// invalid_argument naming the field for a latitude outside [−90, 90], a non-finite longitude,
/// a planet radius that is not finite and positive, a finest patch ≤ 0, objects, a seabed or the
/// wireframe view in the view, or a camera inside the planet.
Status validate_sphere(const View& view);

/// What the last draw did.
struct RenderStats {
  std::uint32_t patches = 0;     ///< instances drawn (skirt excluded)
  std::uint32_t draw_calls = 0;  ///< instanced draws of patches + the skirt + sky + tone map
  std::uint64_t triangles = 0;   ///< patch and skirt triangles submitted
  std::array<std::uint32_t, lod::kMaxLevels + 1> patches_per_level{};
  double cpu_select_ms = 0.0;  ///< LOD selection
  double gpu_ms = 0.0;         ///< GPU time of the whole draw (0 without timestamps)
};

/// Memory the renderer's targets take per pixel of the image: the device-local HDR (RGBA16F,
/// 8 bytes), depth (D32, 4) and sRGB (RGBA8, 4) images, and a host-visible read-back buffer as
/// large as the HDR image.
inline constexpr std::uint64_t kTargetBytesPerPixel = 16;
inline constexpr std::uint64_t kReadbackBytesPerPixel = 8;

/// An HDR environment map (docs/rendering.md R.17): the radiance arriving from every direction
/// as an equirectangular (latitude–longitude) image that replaces the analytic sky in the
/// background, the reflections and the fog. Column u (of width) looks towards the azimuth
/// 2π·(u + ½)/width from +x towards +z, as the sky table; row r (of height) at the elevation
/// π/2 − π·(r + ½)/height: row 0 is the zenith.
struct Environment {
  int width = 0;           ///< 2·height
  int height = 0;          ///< [2, 8192]
  std::vector<float> rgb;  ///< width·height·3 linear radiances, finite and ≥ 0, row 0 on top
};
/// Reads an equirectangular OpenEXR file (channels R, G, B, half or float) into an Environment,
/// halved (box filter) until it is at most 2048 wide. io_error "cannot read '<path>': ..." when
/// the file cannot be read or is not OpenEXR (a PNG or JPEG is not HDR); invalid_argument when
/// it lacks R, G or B, is not twice as wide as high, or holds negative or non-finite values.
Result<Environment> load_environment(const std::filesystem::path& path);

struct RendererParams {
  int width = 1280;  ///< [1, 16384] and what the device and memory hold (Renderer::resize)
  int height = 720;  ///< [1, 16384] and what the device and memory hold (Renderer::resize)
};

/// A world-space grid of (Dx, h, Dz) over the square [x0, x0 + size] × [z0, z0 + size]: the shape
/// of ocean/waves.hpp's LocalFrame, cell (col, row) at the cell's centre.
struct LocalLayerGrid {
  std::array<double, 2> origin_m{0.0, 0.0};
  double size_m = 0.0;
  int resolution = 0;                   ///< N cells per side
  std::span<const float> displacement;  ///< 3·N² floats, or empty for no layer
};

/// Bands a DampingGrid carries per cell (cascades beyond it are not damped).
inline constexpr std::size_t kDampingBands = 8;
/// The damping of the bands on a square world grid (ocean/waves.hpp's Damping sampled at the
/// cells' centres): per cell kDampingBands amplitude weights in [0, 1] (cascade c's at index c)
/// and the water depth, m (+inf or anything ≥ 1000 m: deep water). Outside the square nothing is
/// damped.
struct DampingGrid {
  std::array<double, 2> origin_m{0.0, 0.0};
  double size_m = 0.0;
  int resolution = 0;                   ///< N cells per side
  std::span<const float> band_weights;  ///< kDampingBands·N² values, or empty for none
  std::span<const float> depth_m;       ///< N² values; negative: land, −d its height (R.64)
  /// N² fractions of breaking waves Q_b in [0, 1] (waves::Damping::surf, W.26), drawn as the
  /// surf's foam coverage (R.63); empty: none.
  std::span<const float> breaking_fraction;
};

class Renderer {
 public:
  /// Builds pipelines, targets and the patch meshes. The context must have been created with
  /// ContextParams::graphics (unsupported otherwise).
  static Result<std::unique_ptr<Renderer>> make(std::shared_ptr<vk::Context> context,
                                                const RendererParams& params);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// New target size (allocates). Refused (invalid_argument, naming the size and the limit)
  /// before anything is allocated or the old targets are released, when a side is outside
  /// [1, 16384] or above the device's maxImageDimension2D, when the device-local targets
  /// (kTargetBytesPerPixel, and the read-back buffer where that heap is host-visible too)
  /// exceed the device's largest device-local heap, or when the host memory they take exceeds
  /// memory_budget() (ocean/memory_budget.hpp): the read-back buffer, and on a CPU device
  /// (lavapipe) the targets too.
  Status resize(int width, int height);
  /// Sizes the cascade images for the surface of a simulation plan (SimulationPlan::surface,
  /// ocean/plan.hpp; the CPU upload path) and keeps the cascade sizes, tiling wavelengths, bounds
  /// and noise fit the shaders need. Call again after the simulation is reconfigured.
  Status configure(const SurfaceDescription& surface);
  /// CPU path: copies `frame` (configured as above) into a staging buffer; the next draw copies
  /// it into the images first. Its far-field noise map (Frame::far_noise, when the simulation
  /// computes one) is copied too and drawn inside its window (docs/rendering.md R.13b); the far
  /// field shows frame.time_s. invalid_argument for a map of the wrong size (the old one stays
  /// staged).
  Status upload(const Frame& frame);
  /// GPU path: samples these images (a VulkanBackend's on the same context) from now on, until
  /// upload() or configure() is called. The images must stay alive while they are in use.
  void use_simulation_images(const vk::SimulationImages& images);
  /// GPU path with the far field's noise map: as above, and the map in images.far_noise read where
  /// it lies, in the window `frame`'s FarNoiseFrame describes, the far field at frame.time_s (the
  /// frame of the backend the images belong to; its arrays are not read). Allocates the map's
  /// image when its side changes. invalid_argument when the frame's map and the buffer differ in
  /// size.
  Status use_simulation_images(const vk::SimulationImages& images, const Frame& frame);
  /// The far field's noise map of `frame` alone (what upload() copies besides the cascades), the
  /// far field at frame.time_s: for a path that hands the cascades over otherwise (take_shared).
  /// invalid_argument for a map of the wrong size.
  Status set_far_noise(const Frame& frame);
  /// Shared path (a simulation on another API on the same GPU: CUDA; ocean/interop.hpp): makes a
  /// device-local buffer in interop::inputs_layout of the configuration, exportable, and two
  /// exportable semaphores (timeline where they export, else binary; see shared_semaphores()
  /// for a device that exports none), and returns their descriptors for the simulation to
  /// import. Needs configure() first and a context made with ContextParams::external_interop
  /// (else `unsupported` naming the missing extension); replaced by the next share_inputs() and
  /// released by configure().
  Result<interop::SharedInputs> share_inputs();
  /// Shared path, frame n (1, 2, …, one per frame the simulation wrote): submits, on the queue, a
  /// wait for `written` (≥ n, or the binary signal), the copy of the shared buffer into the
  /// sampled images and the signal of `read` (= n); the next draw samples frame n. No host wait
  /// for the simulation; waits only for the previous take's copy to have finished (its fence).
  Status take_shared(std::uint64_t frame);
  /// The shared path's semaphores {written, read}; null before share_inputs(). Where the device
  /// cannot export semaphores (no VK_KHR_external_semaphore_fd: SharedInputs::written_fd and
  /// read_fd are −1) they are timeline semaphores of this device, for a producer on the host
  /// (vkSignalSemaphore, vkWaitSemaphores) or on this device; a CUDA producer needs them exported.
  [[nodiscard]] std::array<VkSemaphore, 2> shared_semaphores() const;
  /// The local layer alone (ocean/waves.hpp: wakes and waveforms; docs/rendering.md R.19) to add
  /// to the cascades from the next draw on, until this or set_local_surface is called again:
  /// `grid` is a LocalFrame's area and displacement (float3 (Dx, h, Dz) per cell, row-major, rows
  /// along +z). Its displacement adds to the sea's; its own slope and instantaneous foam (the
  /// ramp on its own Jacobian) add to the sea's shading: for callers without a simulator (a calm
  /// sea, a layer drawn over images from elsewhere). An empty displacement removes the layer.
  /// Copies the data (staging); reallocates only when the side changes. invalid_argument for a
  /// bad area, a side outside [1, 4096] or an array of the wrong size.
  Status set_local_layer(const LocalLayerGrid& grid);
  /// The composited local surface (Frame::local, ocean/sim.hpp; docs/math.md M.7.9–M.7.10) to
  /// draw from the next draw on, until this or set_local_layer is called again (R.19): the
  /// layer's displacement adds to the cascades', and what the layer changes in the composited
  /// surface's slope and accumulated foam (`normal` against `sea_normal`, `foam` against
  /// `sea_foam`) adds to the cascades' shading, so wakes fold and foam with the sea's crests and
  /// the sea is drawn unchanged wherever the layer changes nothing. What Scene::step hands over
  /// when its simulator has a local layer. resolution 0 removes the layer. Same copying and
  /// errors as set_local_layer (every array sized for its resolution: 3·N² or N² floats).
  Status set_local_surface(const LocalSurfaceFrame& local);
  /// The damping of the cascades by a mask and a bathymetry (docs/waves.md W.12–W.13;
  /// docs/rendering.md R.24) from the next draw on: each cascade's displacement, slope and foam
  /// scaled by its weight, and shallow water tinted by the seabed seen through it (pure water's
  /// absorption). An empty grid removes it. Same errors and copying as set_local_layer().
  Status set_damping(const DampingGrid& grid);
  /// A calm sea: the cascades are neither drawn nor shaded, only the local layer (true), or the
  /// sea again (false, the default).
  void set_calm(bool calm);

  /// Uploads the meshes View::objects refers to by index (allocates; replaces the previous set,
  /// waiting for the device first). invalid_argument naming the mesh (validate(Mesh)).
  Status set_meshes(std::span<const Mesh> meshes);

  /// Records the frame into `cmd` (outside any render pass): pending uploads, the HDR pass (sky,
  /// patches, skirt), the tone-map pass. Afterwards the sRGB image is in TRANSFER_SRC_OPTIMAL.
  Status record(VkCommandBuffer cmd, const View& view);
  /// Builds what `view` needs before recording: the patch mesh when the quality's V changed
  /// (uploaded through the renderer's own command buffer). record() does it too when needed;
  /// calling it first keeps the upload out of a frame. draw() calls it.
  Status prepare(const View& view);
  /// record() on the renderer's own command buffer, submitted and waited for.
  Status draw(const View& view);
  /// Stereo in one pass (VK_KHR_multiview; docs/rendering.md R.25): the two eyes of
  /// stereo_eyes(view.camera, ipd_m) drawn by the same draws, from one LOD selection (from the
  /// head, culled by the hull of both eyes' frusta) and one simulation state, into the left and
  /// right halves of the targets: each eye is width()/2 × height() and view.camera.aspect is an
  /// eye's. Afterwards as record(): the sRGB image holds the side-by-side picture. Allocates the
  /// layered targets and the multiview pipelines on first use (and the targets after a resize).
  /// unsupported when the context lacks multiview (Context::multiview); invalid_argument for an
  /// IPD that is negative or not finite, or an odd width.
  Status record_stereo(VkCommandBuffer cmd, const View& view, double ipd_m);
  /// Stereo in one pass from two arbitrary eyes (R.25, R.27): `eyes` left then right, each its
  /// own pose, roll and field of view (lod::Camera::up, lod::Camera::fov: a headset's located
  /// views). view.camera is the head: the LOD's distances are measured from its position, and
  /// the selection is culled by the planes bounding both eyes' frusta (lod::bounding_frustum).
  /// Otherwise as above; invalid_argument naming the eye for an invalid eye camera.
  Status record_stereo(VkCommandBuffer cmd, const View& view,
                       const std::array<lod::Camera, 2>& eyes);
  /// record_stereo() on the renderer's own command buffer, submitted and waited for.
  Status draw_stereo(const View& view, double ipd_m);
  Status draw_stereo(const View& view, const std::array<lod::Camera, 2>& eyes);
  /// Motion vectors (docs/rendering.md R.26) from the next draw() on (true), or none (false, the
  /// default): per pixel, how far the surface point seen there moved on the screen since the
  /// previous draw — the camera's motion and the waves' (the same undisplaced point, the
  /// previous frame's cascades and camera) — into an RG16F target read by read_motion(). The
  /// first draw after enabling (or after a configure() to another size) has no previous
  /// frame and shows none. Allocates its pipelines here, the target and a copy of the cascades'
  /// displacement at the next draw. Objects and the local layer carry no motion of their own
  /// (the water's or the sky's is written under an object). unsupported at draw time with
  /// use_simulation_images() (only uploaded cascades are kept); not with record_stereo().
  Status set_motion_vectors(bool on);
  /// The last draw's motion, pixels (dx, dy) per pixel, rows down, top row first
  /// (width·height·2 floats): the point at pixel (x, y) was at (x − dx, y − dy) a frame ago.
  /// invalid_argument when motion vectors are off or nothing was drawn with them.
  Status read_motion(std::vector<float>& xy);
  /// After the submission holding a record()ed frame has completed: that frame's GPU time, ms
  /// (0 on devices without timestamps). draw() fills stats().gpu_ms itself.
  Result<double> read_gpu_ms();
  /// Uses `environment` (load_environment) for the sky, its reflections and the fog from now on,
  /// scaled by ShadingParams::sky_brightness; nullptr returns to the analytic sky. Allocates and
  /// uploads (waits for the GPU). The sun's light and specular stay analytic (R.17).
  Status set_environment(const Environment* environment);
  /// The last draw's sRGB pixels, RGBA8, top row first (width·height·4 bytes).
  Status read_srgb(std::vector<std::uint8_t>& rgba);
  /// The last draw's linear HDR pixels, RGBA float, top row first (width·height·4 floats).
  Status read_hdr(std::vector<float>& rgba);

  [[nodiscard]] VkImage srgb_image() const;
  /// Hs = 4·√m0 of the configured sea state, m (what the culling boxes and crest light use).
  [[nodiscard]] double significant_wave_height_m() const;
  [[nodiscard]] int width() const;
  [[nodiscard]] int height() const;
  [[nodiscard]] const RenderStats& stats() const { return stats_; }
  [[nodiscard]] const vk::Context& context() const { return *context_; }

  struct State;  // Vulkan objects (src/render/state.hpp)

 private:
  Renderer() = default;
  std::shared_ptr<vk::Context> context_;
  std::unique_ptr<State> state_;
  RenderStats stats_;
};

/// The default interpupillary distance, m: the adult mean (Dodgson, "Variation and extrema of
/// human interpupillary distance", 2004: 63 mm; headsets default to 63–64 mm).
inline constexpr double kDefaultIpd_m = 0.064;
/// The left and right eyes of a head whose camera is `head` (docs/rendering.md R.25): moved by
/// ∓ipd/2 along the head's right axis (forward × the head's up), looking along the head's direction
/// (parallel axes) with its field of view, aspect, near and far planes. invalid_argument for an
/// IPD that is negative or not finite.
Result<std::array<lod::Camera, 2>> stereo_eyes(const lod::Camera& head, double ipd_m);

/// The sun's unit direction for azimuth/elevation (world, Y up).
std::array<double, 3> sun_direction(double azimuth_deg, double elevation_deg);

}  // namespace ocean::render

namespace ocean::render {

/// The analytic sky of the renderer (docs/rendering.md R.1–R.4): single scattering by air
/// (Rayleigh) and haze (Mie, Henyey–Greenstein) in a plane-parallel exponential atmosphere, sun
/// light attenuated along the Kasten–Young air mass, plus an isotropic multiple-scattering
/// share. Linear radiance in the unit of ShadingParams::sun_irradiance, per RGB channel.
struct Sky {
  explicit Sky(const ShadingParams& params);
  /// Radiance arriving from the unit direction `dir` (world, Y up); directions below the
  /// horizon give the horizon's radiance.
  [[nodiscard]] std::array<double, 3> radiance(std::array<double, 3> dir) const;
  /// Sun irradiance reaching sea level on a plane facing the sun.
  [[nodiscard]] std::array<double, 3> sun_irradiance_ground() const;
  /// Irradiance from the whole sky dome on a horizontal plane (∫ L cosθ dω, numerically).
  [[nodiscard]] std::array<double, 3> sky_irradiance_horizontal() const;

  /// The sky-view table the shaders sample: kLutWidth × kLutHeight RGBA float texels, row-major,
  /// u = azimuth/2π (azimuth from +x towards +z), v = √(elevation/(π/2)) of the texel centre.
  static constexpr int kLutWidth = 128;
  static constexpr int kLutHeight = 64;
  void fill_lut(std::span<float> rgba) const;

  /// The atmosphere the sky and the aerial perspective share (R.1): Rayleigh extinction at sea
  /// level per channel and its scale height, the haze's (times `aerosol`) and its scale height.
  struct Air {
    std::array<double, 3> rayleigh_per_m;
    double rayleigh_height_m;
    double mie_per_m;
    double mie_height_m;
  };
  [[nodiscard]] Air air() const;
  /// The air between an eye at height `eye_y_m` and a point at height `point_y_m`, `distance_m`
  /// apart, seen along the unit `view_dir` from the eye (R.8b): what the point's radiance is
  /// multiplied by (transmittance) and what the air adds (in-scattered sun light).
  struct AerialPerspective {
    std::array<double, 3> transmittance;
    std::array<double, 3> inscattered;
  };
  [[nodiscard]] AerialPerspective aerial_perspective(double eye_y_m, double point_y_m,
                                                     double distance_m,
                                                     std::array<double, 3> view_dir) const;

  ShadingParams params;
  std::array<double, 3> sun;  ///< unit direction towards the sun
};

/// Relative optical air mass of Kasten & Young (1989) for a zenith cosine μ ∈ [0, 1] (R.3):
/// 1 at the zenith, ≈ 38 at the horizon.
double air_mass(double mu);

}  // namespace ocean::render
