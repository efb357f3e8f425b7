// ocean/io.hpp — writing files atomically: the crash-safe file replacement every output of the
// library goes through, and the NumPy .npy, OpenEXR and PNG writers built on it.
//
// Every writer replaces its file atomically (a reader sees the old file or the complete new one,
// never a partial one), reports failures as Status values naming the path, and never throws.
// libpng and OpenEXR are private dependencies: this header includes neither.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>

#include "ocean/core.hpp"

namespace ocean::io {

// ---- atomic file replacement ---------------------------------------------------------------

/// Produces the new contents of a file by writing them to `temporary`, which already exists
/// (empty) when the callback runs. Returns ok, or a Status whose message is the reason for the
/// failure (e.g. "No space left on device"); the message ends up in the final error unchanged.
using WriteCallback = std::function<ocean::Status(const std::filesystem::path& temporary)>;

/// Replaces (or creates) `path` with the file produced by `write`, so that at every moment `path`
/// either holds its old contents or the complete new ones — never a partial file.
///
/// Contract:
///  - Creates a new, uniquely named temporary ".<name>.tmp-<pid>-<counter>" in the directory of
///    `path` (permissions 0666 minus the umask), calls `write(temporary)`, fsyncs the temporary,
///    renames it over `path` and fsyncs the directory (best effort: a failing directory fsync
///    does not fail the call, the data are already complete).
///  - The directory of `path` must exist; it is not created (see ensure_directory).
///  - Only a regular file is replaced: `path` must be absent, a regular file, or a symbolic
///    link that dangles or leads to a regular file (the link itself is then replaced, not its
///    target). A directory, device, FIFO or socket at `path` (or at the end of its link) is
///    io_error "cannot write '<path>': it is a character device, not a regular file" (or "it
///    links to ..."), found before the callback runs and checked again just before the rename.
///  - On any failure the temporary is removed, `path` is untouched and the result is io_error
///    "cannot write '<path>': <reason>", the reason coming from errno (strerror text, e.g.
///    "No such file or directory") or from the message of the Status returned by `write`.
///    Exceptions thrown by `write` are caught and reported the same way.
///  - A `path` that is empty or does not end in a file name ("dir/", ".", "..") or an empty
///    callback is invalid_argument, and nothing is created.
///  - Never throws. Safe to call from several threads at once (distinct temporaries).
ocean::Status write_atomically(const std::filesystem::path& path, const WriteCallback& write);

/// Atomically replaces `path` with the concatenation of `parts` (write_atomically with a callback
/// that writes the bytes, retrying short writes and EINTR). Same contract as write_atomically.
/// Empty parts are allowed; no part is copied.
ocean::Status write_bytes_atomically(const std::filesystem::path& path,
                                     std::initializer_list<std::span<const std::byte>> parts);

/// Makes sure `dir` exists as a directory, creating it and any missing parents.
///
/// Contract: ok if `dir` is (or now is) a directory, including when it already existed or was
/// created concurrently by someone else; an empty `dir` means the current directory and is ok.
/// Otherwise io_error "cannot create directory '<dir>': <reason>", e.g. "'<component>' exists
/// and is not a directory" or "Permission denied". Never throws.
ocean::Status ensure_directory(const std::filesystem::path& dir);

/// `path` in single quotes as messages echo it: at most 240 bytes, control bytes and invalid
/// UTF-8 escaped (ocean::excerpt), so a one-line message stays one line whatever the name holds.
std::string quoted(const std::filesystem::path& path);

/// Checks, before long work, that a file could be created at `path`: its directory (the
/// current one when `path` has none) exists and is writable, and nothing but a regular file is
/// in the way (as write_atomically). io_error "cannot write '<path>': No such file or
/// directory", "...: Permission denied" or "...: it is a FIFO, not a regular file" otherwise.
/// Never throws.
ocean::Status check_parent_writable(const std::filesystem::path& path);

/// The strerror text for an errno value, e.g. "No such file or directory". Never throws (returns
/// an empty string if even building the message fails).
std::string errno_message(int err) noexcept;

// ---- Reading a whole file under a size limit ---------------------------------------------

/// What read_bounded may take: every reader of a user's file (a preset, a bake manifest, an
/// environment map, a height map) names its limit here, so that a huge file, /dev/zero or a pipe
/// that never ends is refused after at most `max_bytes + 1` bytes were read.
struct ReadLimits {
  std::uint64_t max_bytes = 0;  ///< the most the file may hold, bytes
  std::string_view what;        ///< what the file is, for messages: "preset", "manifest"...;
                                ///< empty for the plain "cannot read '<path>': ..." form
  bool regular_only = false;    ///< refuse a FIFO, device, socket or directory before reading
  bool no_follow = false;       ///< refuse a symbolic link at `path` itself (O_NOFOLLOW)
  int fifo_wait_ms = 5000;      ///< a FIFO with no writer after this long is an io_error
};

/// The text of the file at `path`, read whole under `limits`.
///
/// Contract: at most `limits.max_bytes + 1` bytes are ever read or held, whatever `path` is (a
/// regular file, a pipe, /dev/zero). The file is opened without blocking (a FIFO's open would
/// wait for a writer forever) and a FIFO is given `fifo_wait_ms` to produce data. Errors:
/// io_error "cannot read <what> '<path>': <reason>" (the reason "it is a FIFO, not a regular
/// file" with `regular_only`, "it is a symbolic link" with `no_follow`, or strerror's text);
/// invalid_argument "<what> '<path>' is larger than <N> bytes (<human>), the most a <what> may
/// hold". With an empty `what` the messages are those of the format readers: "cannot read
/// '<path>': <reason>" and "cannot read '<path>': it is larger than <N> bytes (<human>), the
/// limit". The path is echoed through ocean::excerpt. Never throws.
ocean::Result<std::string> read_bounded(const std::filesystem::path& path,
                                        const ReadLimits& limits);

/// `bytes` as messages state a limit: "1048576 bytes (1 MiB)".
std::string byte_limit_text(std::uint64_t bytes);

// ---- NumPy .npy (format 1.0, little-endian float32, C order) -------------------------------

/// Largest number of dimensions write_npy accepts (NumPy 1.x's NPY_MAXDIMS).
inline constexpr std::size_t kNpyMaxDims = 32;

/// Writes `data` as a NumPy .npy file (format version 1.0, dtype '<f4', fortran_order False).
///
/// Contract:
///  - `data` points to product(shape) floats in C order (last index fastest); it may be null only
///    when that product is 0. An empty `shape` writes a 0-d array of one value.
///  - The header is laid out byte for byte as numpy.save writes it (including its spare space for
///    growing the first axis), padded with spaces and ended by '\n' so that the data start at a
///    multiple of 64 bytes. Values are stored bit-exactly (NaN payloads included), little-endian.
///  - Written atomically (see write_atomically): on failure `path` keeps its old contents.
///  - invalid_argument for more than kNpyMaxDims dimensions, a size that overflows, or null data;
///    io_error "cannot write '<path>': <reason>" for file system failures. Never throws.
ocean::Status write_npy(const std::filesystem::path& path, const float* data,
                        std::span<const std::size_t> shape);

// ---- OpenEXR scanline images (ZIP compressed, half or float channels) -----------------------

/// Largest width or height write_exr accepts.
inline constexpr int kExrMaxDimension = 16384;
/// Largest number of channels write_exr accepts.
inline constexpr int kExrMaxChannels = 1024;
/// Largest file read_exr reads, bytes (2 GiB): it reads the whole file once for its header check,
/// so the file is bounded before a byte is read. Twice the reader's 1 GiB budget of samples as
/// floats: room for that budget stored uncompressed, with a tiled file's mip levels (a third
/// more) and the offset tables and headers.
inline constexpr std::uint64_t kExrMaxFileBytes = std::uint64_t{2} << 30;

/// How samples are stored in the file (values are always passed as float).
enum class ExrPixelType { half, float32 };

/// One channel to write: `data` points to width*height floats, row-major, row 0 the top row.
struct ExrChannel {
  std::string name;
  const float* data = nullptr;
};

/// Writes a single-part scanline OpenEXR file with ZIP compression; every channel has the same
/// pixel `type`. Data window and display window are (0,0)-(width-1,height-1), line order
/// increasing y, so row 0 of each channel is the top row of the image.
///
/// Contract:
///  - invalid_argument (nothing written) unless 1 <= width, height <= kExrMaxDimension, there are
///    1..kExrMaxChannels channels, each with non-null data and a unique, non-empty name of at most
///    255 bytes without NUL characters.
///  - float32 stores values bit-exactly. half rounds to nearest; magnitudes beyond 65504 become
///    infinities, NaN stays NaN.
///  - Written atomically (see write_atomically): on failure `path` keeps its old contents and
///    the result is io_error "cannot write '<path>': <reason>". Write errors that OpenEXR would
///    swallow while finishing the file are detected too. Never throws.
ocean::Status write_exr(const std::filesystem::path& path, int width, int height,
                        std::span<const ExrChannel> channels, ExrPixelType type);

/// An OpenEXR image read by read_exr: one plane of width*height floats (row-major, row 0 on top)
/// per channel. Channels come in the file's order, which OpenEXR sorts by name.
struct ExrImage {
  int width = 0;
  int height = 0;
  std::vector<std::string> channel_names;
  std::vector<ExrPixelType> pixel_types;
  std::vector<std::vector<float>> planes;
};

/// Reads every channel of an OpenEXR file (scanline or tiled, any compression) as floats.
///
/// Contract: of a multi-part file only the first part is read. io_error "cannot read '<path>':
/// <reason>" if the file cannot be opened; is not a regular file ("it is a FIFO, not a regular
/// file; an OpenEXR file is read whole, at most 2147483648 bytes (2 GiB)") or holds more than
/// kExrMaxFileBytes ("it holds N bytes, more than the 2147483648 bytes (2 GiB) an OpenEXR file
/// may hold"), both refused before a byte is read, so /dev/zero and a FIFO fail at once; is not an
/// OpenEXR file, is corrupt or truncated, is a deep image, has subsampled or UINT channels, a data
/// window larger than kExrMaxDimension in either direction, more than kExrMaxChannels channels,
/// or needs more than 1 GiB of samples as floats. The header is checked first (see exr_header.hpp:
/// every attribute inside the file and read by OpenEXR as its declared size), then the data window
/// and the sample budget, before OpenEXR reads the file and sizes its buffers from them. The pixels
/// are read in blocks of rows, so memory grows with the rows the file holds rather than with the
/// size it declares. The file is read whole once for the header check. Never throws (OpenEXR
/// exceptions become io_error).
ocean::Result<ExrImage> read_exr(const std::filesystem::path& path);

// ---- PNG images from raw samples (8-bit 1–4 channels, 16-bit gray) -------------------------

/// Largest width or height the PNG writers accept (libpng's default user limit).
inline constexpr int kPngMaxDimension = 1000000;
/// The most bytes a PNG reader lets one chunk other than the image data declare (and libpng
/// allocate for one, decompressed text and ICC profiles included): 8 MiB. A file whose chunk
/// declares more, or more than the file holds, is refused before libpng allocates anything.
inline constexpr std::uint64_t kPngMaxChunkBytes = std::uint64_t{8} << 20;

/// Writes an 8-bit PNG: `channels` 1 = gray, 2 = gray+alpha, 3 = RGB, 4 = RGBA.
///
/// Contract:
///  - `pixels` holds width*height*channels bytes, rows top to bottom, channels interleaved
///    (alpha not premultiplied). Samples are stored exactly; no gamma or colour-space chunk is
///    written, no filtering of values.
///  - invalid_argument (nothing written) unless 1 <= width, height <= kPngMaxDimension, channels
///    is 1..4, `pixels` is non-null and the byte size does not overflow.
///  - Written atomically (see write_atomically); io_error "cannot write '<path>': <reason>" on
///    failure, leaving `path` as it was. Never throws.
ocean::Status write_png8(const std::filesystem::path& path, int width, int height, int channels,
                         const std::uint8_t* pixels);

/// Writes a 16-bit grayscale PNG from native-endian samples (stored big-endian in the file, as
/// PNG requires); otherwise the same contract as write_png8 with channels = 1.
ocean::Status write_png16_gray(const std::filesystem::path& path, int width, int height,
                               const std::uint16_t* pixels);

}  // namespace ocean::io
