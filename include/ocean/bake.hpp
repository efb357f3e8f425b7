// ocean/bake.hpp — baking a simulation to disk: every frame's displacement, normal, Jacobian, foam
// and packed normal/foam/smoothness mip chain as .npy, PNG and/or OpenEXR files, each written
// atomically, with a manifest.json describing what was written. What `ocean bake` runs; an engine,
// a binding or a render farm calls it without the command-line tool.
//
// A bake into a folder is a transaction: one bake at a time per folder (a lock), every output
// checked before the first frame, the old manifest removed before the first new file, and the
// manifest written last saying whether the bake completed. A folder whose manifest.json says
// "complete": true holds a whole bake; one with "complete": false, or with no manifest, does not.
//
// Files of frame f (five digits) and cascade k, in the output directory:
//   npy: displacement_c<k>_f<f>.npy [N][N][3] (Dx, h, Dz) m, normal_… [N][N][3], jacobian_… [N][N],
//        foam_… [N][N], nfs_c<k>_f<f>_mip<l>.npy [N>>l][N>>l][4] (packed map / 255)
//   png: nfs_c<k>_f<f>_mip<l>.png RGBA8, height_c<k>_f<f>.png 16-bit gray mapping
//        [−height_png_range_m, +height_png_range_m] to [0, 65535]
//   exr: displacement_c<k>_f<f>.exr R,G,B float32; maps_c<k>_f<f>.exr normal.X/Y/Z, jacobian, foam
//        half; nfs_c<k>_f<f>_mip<l>.exr R,G,B,A half
//   with a local layer (any format): local_height_f<f>.npy [N][N] float32 heights of the layer,
//        row i at z = z0 + (i + ½)·size/N, column j at x = x0 + (j + ½)·size/N; unless calm, the
//        layer composited with the sea (Frame::local, M.7.9) on the same grid:
//        local_displacement_f<f>.npy [N][N][3] (Dx, h, Dz) m, local_normal_f<f>.npy [N][N][3],
//        local_jacobian_f<f>.npy [N][N], local_foam_f<f>.npy [N][N] (accumulated)
// Rows are row-major [row][col]; texel (col,row) starts at world (col,row)·L/N.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ocean/core.hpp"
#include "ocean/plan.hpp"
#include "ocean/sim.hpp"
#include "ocean/waves.hpp"

namespace ocean::bake {

/// The most frames one bake writes.
inline constexpr long long kMaxFrames = 1000000;

/// The largest manifest.json merge() reads, bytes (64 MiB). A manifest takes 2.8 kB a frame for
/// three cascades of 256² .npy files (measured), 10.3 kB with every format and four cascades of
/// 512², so a shard holds up to about 23,000 frames (6,500 with every format); a longer bake
/// splits into more shards. A larger file is refused after reading at most this many bytes and
/// one more, before it is parsed.
inline constexpr std::uint64_t kMaxManifestBytes = std::uint64_t{64} << 20;

/// The lock file a bake holds in its output folder while it runs (flock(2), the holder's pid as
/// text); removed when the bake ends. A lock file left by a killed process blocks nothing.
inline constexpr const char* kLockFileName = ".ocean-bake.lock";

/// Which file formats a bake writes; any combination, at least one.
struct Formats {
  bool npy = true;   ///< float32 arrays (NumPy .npy): every map and every mip level
  bool png = false;  ///< RGBA8 packed-map mips and a 16-bit height map
  bool exr = false;  ///< OpenEXR: displacement float32, the other maps and the mips half
};

/// One machine's share of a bake: shard `index` of `count` holds the contiguous block of frames
/// shard_frames(frame_count, shard). Blocks rather than every count-th frame because foam
/// accumulates over the frames before: a shard steps the simulator through every earlier frame
/// without writing it, so that its files are bit-identical to a one-machine bake's, and a block
/// keeps that warm-up short (shard i of n simulates up to (i+1)/n of the frames).
struct Shard {
  long long index = 0;  ///< 0..count−1
  long long count = 1;  ///< 1..frame_count
};

/// The frames [first, end) of a bake.
struct FrameRange {
  long long first = 0;
  long long end = 0;
};

/// The frames of `shard` in a bake of `frame_count` frames: [⌊index·F/count⌋,
/// ⌊(index+1)·F/count⌋), F = frame_count. The shards 0..count−1 cover 0..F−1, each frame once,
/// each shard at least one frame when count ≤ F. Pure; preconditions as BakeParams::shard.
FrameRange shard_frames(long long frame_count, const Shard& shard);

/// Reads "I/N" (decimal integers, 0 ≤ I < N ≤ kMaxFrames) as a Shard. invalid_argument
/// "<label> = '<text>' is not I/N: must be a shard index 0 to N-1, a slash and a count 1 to
/// 1000000" otherwise.
Result<Shard> parse_shard(std::string_view text, std::string_view label = "shard");

/// What to bake and where. Frame f is simulated at start_time_s + f / fps.
struct BakeParams {
  std::filesystem::path output_dir;      ///< created (with parents) if missing; must not be empty
  Formats formats;                       ///< the file formats written for every frame
  long long frame_count = 1;             ///< frames to write, 1..kMaxFrames (see loop_frame_count)
  double fps = 30.0;                     ///< frames per second, finite and > 0
  double start_time_s = 0.0;             ///< simulation time of frame 0, finite
  std::string generator = "ocean bake";  ///< the manifest's "generator" entry
  /// Other files the caller writes during the bake (e.g. from the callback): checked with the
  /// output folder before the first frame (their folder exists and is writable; each is absent,
  /// a regular file or a symbolic link), so that a bad path fails at once. Not written by bake().
  std::vector<std::filesystem::path> other_outputs;
  /// Cancellation: when set and true, the bake stops before its next file (see bake()). May be
  /// set from another thread or from a signal handler (a lock-free atomic store is
  /// async-signal-safe). Not owned; must outlive the call.
  const std::atomic<bool>* cancel = nullptr;
  /// When set, every frame also writes the layer's heights at the frame's time
  /// (local_height_f<f>.npy) and, unless calm, the composited local surface (local_displacement_,
  /// local_normal_, local_jacobian_, local_foam_f<f>.npy: the layer is set on the simulator,
  /// Simulator::set_local_layer, so its foam accumulates from the first frame stepped); the
  /// manifest gains "local_area": {"origin_m": [x0, z0], "size_m", "resolution",
  /// "edge_fraction"} and "local_layer": {"wakes", "waveforms" (each map by "rows", "cols" and
  /// the CRC-32 of its samples as little-endian float32), "choppiness", "gravity_mps2"}.
  std::shared_ptr<const waves::LocalLayer> local_layer;
  /// A calm sea: no wind sea, so no cascade files (the simulator is not stepped; the manifest
  /// says "calm": true). Needs local_layer.
  bool calm = false;
  /// When set, write only this shard's frames (see Shard); the manifest then says which shard it
  /// holds ("shard": {"index", "count", "first_frame", "last_frame"}) and lists its frames only.
  /// Its count must be 1..frame_count and its index 0..count−1 (invalid_argument otherwise).
  std::optional<Shard> shard;
};

/// One frame written, reported to the caller's callback.
struct FrameDone {
  long long index = 0;        ///< the frame just written, 0..frame_count−1
  long long frame_count = 0;  ///< frames of the whole bake
  double time_s = 0.0;        ///< its simulation time
  const Frame* frame =
      nullptr;  ///< the simulated fields (null when calm); valid only during the callback
  const waves::LocalFrame* local = nullptr;  ///< the local layer's frame, or null
  double height_png_range_m = 0.0;           ///< the bake's height_png_range_m
};

/// Called after each frame's files are written, on the calling thread. A non-ok Status stops the
/// bake: bake() returns it unchanged, after writing a manifest saying "complete": false.
using FrameCallback = std::function<Status(const FrameDone&)>;

/// The frames of one whole loop period of `config` at `fps`: round(loop_period_s · fps). Zero or
/// less when the configuration has no loop period (loop_period_s <= 0); the caller checks the
/// result against 1..kMaxFrames. Pure; never fails.
long long loop_frame_count(const SimulationConfig& config, double fps);

/// The half-range of the PNG height maps, m: four standard deviations of the sea surface height
/// of the plan's spectrum (the significant wave height Hs), at least 1 mm. Written to the
/// manifest as "height_png_range_m".
double height_png_range_m(const SimulationPlan& plan);

/// Bakes `params.frame_count` frames of a simulation of `config` on the backend named `backend`
/// (see make_backend), writing the files listed at the top of this header and, last,
/// <output_dir>/manifest.json: generator, "complete" (true when every frame was written),
/// frame_count (asked for), frames_written, "stopped" (why, when not complete), backend, config
/// as the preset document, fps, start_time_s, formats, height_png_range_m, layout, cascades,
/// calm, and per frame written its index, time_s, files and, in the order of "files", each
/// file's size ("bytes") and CRC-32 ("crc32": eight lower-case hexadecimal digits, the CRC-32 of
/// zlib, PNG and Python's zlib.crc32), read back from the folder once the frame is written.
///
/// Contract:
///  - invalid_argument for an empty output_dir, no format, frame_count outside 1..kMaxFrames, or
///    a non-finite or non-positive fps or a non-finite start time (nothing touched).
///  - The start, before any simulation work: creates output_dir and its missing parents (io_error
///    "cannot create directory '<dir>': <reason>"); takes the folder's lock (kLockFileName) —
///    io_error "'<dir>' is being baked by process <pid> (it holds '<lock>')" at once if another
///    bake holds it, or "cannot write '<lock>': <reason>" for an unwritable folder; checks
///    other_outputs. Then makes the simulator (its errors unchanged, e.g. "unsupported: built
///    without ..."). Then removes temporaries left in the folder by dead bakes and removes the old
///    manifest.json (io_error if it cannot: a directory in its place). A start that fails, or is
///    cancelled, leaves everything as it was: no folder it created, the old bake untouched.
///  - Every file is replaced atomically (see ocean/io.hpp). The first failing write stops the bake
///    with its io_error "cannot write '<path>': <reason>" (e.g. "No space left on device", "File
///    too large"), as does a failing callback with its Status. When `params.cancel` becomes true,
///    the bake stops before its next file with ErrorCode::cancelled, "bake cancelled after <n> of
///    <frame_count> frames; '<manifest>' says \"complete\": false".
///  - A stopped bake removes the files of its unfinished frame, writes the manifest with
///    "complete": false listing the frames written whole (if that write fails too, the folder has
///    no manifest), releases the lock, and leaves no temporary file. Files of earlier bakes that
///    this one did not replace stay; only the files the manifest lists belong to the bake.
///  - Calls `on_frame` (if set) after every frame. Blocking; allocates per frame; never throws.
Status bake(const SimulationConfig& config, std::string_view backend, const BakeParams& params,
            const FrameCallback& on_frame = {});

/// Where to join shards and how to stop.
struct MergeParams {
  std::filesystem::path output_dir;  ///< created (with parents) if missing; not a shard's folder
  /// Cancellation between files, as BakeParams::cancel. Not owned; must outlive the call.
  const std::atomic<bool>* cancel = nullptr;
};

/// Joins the folders of a sharded bake (each written by bake() with BakeParams::shard) into
/// `params.output_dir`, so that its files and manifest.json are byte for byte those of the same
/// bake on one machine.
///
/// Contract:
///  - First, before touching anything, reads every shard's manifest.json and checks it: read with
///    io::read_bounded (at most kMaxManifestBytes; a regular file, never through a symbolic
///    link, so a FIFO or /dev/zero is refused at once), a complete shard ("complete": true, its
///    frames exactly its block, each at start_time_s + f/fps and listing the files of its own
///    frame, the same files every frame), every listed file a plain name and, by lstat, a regular
///    file (never a symbolic link, FIFO, device, socket or directory) of the size listed. A
///    manifest of the older format (no start_time_s, no "bytes" and "crc32") is refused: bake
///    the shard again. Then that the shards are of one bake: every entry but the shard's own
///    ("shard", "frames", "frames_written") the same, compared entry by entry down to the
///    leaves (generator, backend, config, frame_count, fps, start_time_s, formats,
///    height_png_range_m, layout, cascades, calm, local_area, local_layer), one shard count, no
///    shard twice, none missing, the output not a shard's folder. Last, every file is read
///    (O_NOFOLLOW, fstat: the same regular file) and its size and CRC-32 checked against the
///    manifest's. Errors (invalid_argument unless a file cannot be read, io_error), one line
///    each: "merge needs at least one shard folder", "cannot read manifest '<dir>/manifest.json':
///    it is a symbolic link" (or "it is a FIFO, not a regular file"), "manifest '<path>' is
///    larger than 67108864 bytes (64 MiB), the most a manifest may hold",
///    "'<dir>/manifest.json' is not a shard's manifest: <why>", "shard 1 of 4 in '<dir>' is
///    incomplete ...", "cannot merge: shard '<b>' differs from shard '<a>' in config.seed (6
///    vs 5)" (the entry's path, b's value, a's), "shard 2 of 4 is given twice: '<a>' and
///    '<b>'", "shard 3 of 4 is missing (frames 75 to 99; bake it with --shard 3/4)", and
///    "cannot merge: shard 0 of 4 in '<dir>': " followed by "'<file>' is a symbolic link",
///    "'<file>' is a FIFO, not a regular file", "the folder lacks '<file>', which its manifest
///    lists", "'<file>' holds 10 bytes, its manifest says 12: the file changed after the bake;
///    bake the shard again" (or "has CRC-32 <x>, its manifest says <y>: ..."), "frame 7 lists
///    '<file>', which is not a file of frame 7", "its manifest records no start time, file
///    sizes or CRC-32s (an older ocean wrote it): bake the shard again". Cancellation is checked
///    before each file read (ErrorCode::cancelled, nothing written).
///  - Then the output folder is held as bake() holds it (created, locked, the old manifest
///    removed before the first file), the files are copied frame by frame (each atomically, read
///    as above and its size and CRC-32 checked again as it is copied: a file changed after the
///    check fails the copy), and the manifest is written last. A failed copy or a cancellation
///    stops the merge as it stops a bake: the unfinished frame's files removed, "complete":
///    false listing the frames copied.
///  - Blocking; reads every shard's files twice (the check, the copy); never throws. The shard
///    folders are only read; they must not be baked into while the merge runs.
Status merge(std::span<const std::filesystem::path> shard_dirs, const MergeParams& params);

/// Bakes with an existing simulator (its configuration and backend name go to the manifest); the
/// simulator is stepped to every frame's time. Same contract otherwise, except that no simulator
/// is made.
Status bake(Simulator& simulator, const BakeParams& params, const FrameCallback& on_frame = {});

}  // namespace ocean::bake
