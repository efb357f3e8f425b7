// An MP4 written by the ffmpeg program: raw RGBA frames go to its standard input through a pipe,
// H.264 comes out into a temporary file beside the output, renamed over it once ffmpeg has
// succeeded. ffmpeg is started with an argument vector (posix_spawnp), never through a shell, so
// no byte of the output name is ever read as a command.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "ocean/core.hpp"

namespace ocean::cli {

class VideoWriter {
 public:
  VideoWriter() = default;
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;
  /// Stops an unfinished ffmpeg (its input closed, the child reaped) and removes its temporary.
  ~VideoWriter();

  /// Starts ffmpeg for `out`, frames of `width` x `height` at `fps`. Errors (one line, the name
  /// shown as ocean::excerpt writes it): io_error when `out` cannot be written
  /// (io::check_parent_writable: a missing folder, or a device, FIFO, socket or directory under
  /// the name, before ffmpeg starts), unsupported when no ffmpeg is on PATH, io_error when it
  /// cannot be started. SIGPIPE is ignored from here on in this process, so that an ffmpeg that
  /// stops reading gives a write error rather than killing the tool; ffmpeg itself starts with
  /// the default SIGPIPE action.
  Status open(const std::filesystem::path& out, int width, int height, double fps);
  /// Sends one frame: width * height * 4 bytes of sRGB RGBA. When ffmpeg has stopped reading,
  /// it is reaped and the error says how it ended and the last line it wrote.
  Status write(const std::vector<std::uint8_t>& rgba);
  /// Ends the input, waits for ffmpeg and renames the temporary over the output, after checking
  /// the output's name again (only a regular file, or nothing, is replaced); on any failure the
  /// temporary is removed and nothing is left under the output's name.
  Status close();

 private:
  // Closes the pipe, reaps ffmpeg (once) and returns how it ended ("exit 3: <its last line>");
  // empty when it exited with status 0.
  std::string finish();
  // Finishes, removes the temporary and returns "cannot write '<out>': <what> (<ending>)".
  Status fail(const std::string& what);

  std::filesystem::path out_, temp_;
  pid_t pid_ = -1;
  int input_ = -1;                 // the write end of ffmpeg's standard input
  std::FILE* messages_ = nullptr;  // ffmpeg's standard error and output (an unnamed file)
  std::string ended_;              // finish()'s verdict, once ffmpeg is reaped
};

}  // namespace ocean::cli
