// ocean/bake.hpp — baking a simulation to disk: every frame's displacement, normal, Jacobian, foam
// and packed normal/foam/smoothness mip chain as .npy, PNG and/or OpenEXR files, each written
// atomically, with a manifest.json describing what was written. What `ocean bake` runs; an engine,
// a binding or a render farm calls it without the command-line tool.
//
// Files of frame f (five digits) and cascade k, in the output directory:
//   npy: displacement_c<k>_f<f>.npy [N][N][3] (Dx, h, Dz) m, normal_… [N][N][3], jacobian_… [N][N],
//        foam_… [N][N], nfs_c<k>_f<f>_mip<l>.npy [N>>l][N>>l][4] (packed map / 255)
//   png: nfs_c<k>_f<f>_mip<l>.png RGBA8, height_c<k>_f<f>.png 16-bit gray mapping
//        [−height_png_range_m, +height_png_range_m] to [0, 65535]
//   exr: displacement_c<k>_f<f>.exr R,G,B float32; maps_c<k>_f<f>.exr normal.X/Y/Z, jacobian, foam
//        half; nfs_c<k>_f<f>_mip<l>.exr R,G,B,A half
// Rows are row-major [row][col]; texel (col,row) starts at world (col,row)·L/N.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "ocean/core.hpp"
#include "ocean/sim.hpp"

namespace ocean::bake {

/// The most frames one bake writes.
inline constexpr long long kMaxFrames = 1000000;

/// Which file formats a bake writes; any combination, at least one.
struct Formats {
  bool npy = true;   ///< float32 arrays (NumPy .npy): every map and every mip level
  bool png = false;  ///< RGBA8 packed-map mips and a 16-bit height map
  bool exr = false;  ///< OpenEXR: displacement float32, the other maps and the mips half
};

/// What to bake and where. Frame f is simulated at start_time_s + f / fps.
struct BakeParams {
  std::filesystem::path output_dir;      ///< created (with parents) if missing; must not be empty
  Formats formats;                       ///< the file formats written for every frame
  long long frame_count = 1;             ///< frames to write, 1..kMaxFrames (see loop_frame_count)
  double fps = 30.0;                     ///< frames per second, finite and > 0
  double start_time_s = 0.0;             ///< simulation time of frame 0, finite
  std::string generator = "ocean bake";  ///< the manifest's "generator" entry
};

/// One frame written, reported to the caller's callback.
struct FrameDone {
  long long index = 0;           ///< the frame just written, 0..frame_count−1
  long long frame_count = 0;     ///< frames of the whole bake
  double time_s = 0.0;           ///< its simulation time
  const Frame* frame = nullptr;  ///< the simulated fields; valid only during the callback
};

/// Called after each frame's files are written, on the calling thread. A non-ok Status stops the
/// bake: bake() returns it unchanged, and no manifest is written.
using FrameCallback = std::function<Status(const FrameDone&)>;

/// The frames of one whole loop period of `config` at `fps`: round(loop_period_s · fps). Zero or
/// less when the configuration has no loop period (loop_period_s <= 0); the caller checks the
/// result against 1..kMaxFrames. Pure; never fails.
long long loop_frame_count(const SimulationConfig& config, double fps);

/// The half-range of the PNG height maps, m: four standard deviations of the sea surface height
/// of `config`'s spectrum (the significant wave height Hs), at least 1 mm. Written to the
/// manifest as "height_png_range_m".
double height_png_range_m(const SimulationConfig& config);

/// Bakes `params.frame_count` frames of a simulation of `config` on the backend named `backend`
/// (see make_backend), writing the files listed at the top of this header and, last,
/// <output_dir>/manifest.json (generator, backend, config as the preset document, fps, formats,
/// height_png_range_m, layout, cascades, and per frame its index, time and files).
///
/// Contract:
///  - Creates output_dir first, before any simulation work (io_error "cannot create directory
///    '<dir>': <reason>"), then makes the simulator (its errors unchanged, e.g. "unsupported:
///    built without ...").
///  - Every file is replaced atomically (see ocean/io.hpp); the first failing write stops the bake
///    with its io_error "cannot write '<path>': <reason>". Files of frames already written stay.
///  - invalid_argument for an empty output_dir, no format, frame_count outside 1..kMaxFrames, or
///    a non-finite or non-positive fps or a non-finite start time (nothing written).
///  - Calls `on_frame` (if set) after every frame. Blocking; allocates per frame; never throws.
Status bake(const SimulationConfig& config, std::string_view backend, const BakeParams& params,
            const FrameCallback& on_frame = {});

/// Bakes with an existing simulator (its configuration and backend name go to the manifest); the
/// simulator is stepped to every frame's time. Same contract otherwise, except that no simulator
/// is made.
Status bake(Simulator& simulator, const BakeParams& params, const FrameCallback& on_frame = {});

}  // namespace ocean::bake
