// ffmpeg started with an argument vector, fed through a pipe (see video_writer.hpp).
#include "video_writer.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <string>
#include <system_error>

#include "ocean/io.hpp"

extern char** environ;  // NOLINT: POSIX declares it nowhere else

namespace ocean::cli {

namespace {

// Leaves room for ".<name>.tmp-<pid>.mp4" within the usual 255-byte NAME_MAX, as the library's
// temporaries do.
constexpr std::size_t kMaxNameBytesInTemporary = 200;

std::string shown(const std::filesystem::path& path) { return "'" + excerpt(path.string()) + "'"; }

// The last line ffmpeg wrote (its own messages are one line each), shortened for ours.
std::string last_line(std::FILE* messages) {
  if (messages == nullptr || std::fseek(messages, 0, SEEK_END) != 0) return {};
  const long size = std::ftell(messages);
  const long from = std::max(0L, size - 4096L);
  if (size <= 0 || std::fseek(messages, from, SEEK_SET) != 0) return {};
  std::string text(static_cast<std::size_t>(size - from), '\0');
  text.resize(std::fread(text.data(), 1, text.size(), messages));
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  const std::size_t start = text.find_last_of("\r\n");
  return excerpt(start == std::string::npos ? text : text.substr(start + 1), 160);
}

std::string ending(int status) {
  if (WIFEXITED(status)) return "exit " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return "signal " + std::to_string(WTERMSIG(status));
  return "wait status " + std::to_string(status);
}

// posix_spawn's attributes and file actions, destroyed on every path out of open().
struct SpawnSetup {
  posix_spawnattr_t attr{};
  posix_spawn_file_actions_t actions{};
  SpawnSetup() {
    posix_spawnattr_init(&attr);
    posix_spawn_file_actions_init(&actions);
  }
  ~SpawnSetup() {
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
  }
  SpawnSetup(const SpawnSetup&) = delete;
  SpawnSetup& operator=(const SpawnSetup&) = delete;
};

}  // namespace

Status VideoWriter::open(const std::filesystem::path& out, int width, int height, double fps) {
  // A device, FIFO, socket or directory under the name is refused before ffmpeg starts.
  if (Status s = io::check_parent_writable(out); !s.ok()) return s;
  out_ = out;
  const std::string leaf = out.filename().string();
  temp_ = out.parent_path() / ("." + leaf.substr(0, kMaxNameBytesInTemporary) + ".tmp-" +
                               std::to_string(::getpid()) + ".mp4");
  std::signal(SIGPIPE, SIG_IGN);
  messages_ = std::tmpfile();
  if (messages_ == nullptr || ::fcntl(fileno(messages_), F_SETFD, FD_CLOEXEC) != 0)
    return io_error("cannot write " + shown(out) +
                    ": no file for ffmpeg's messages: " + io::errno_message(errno));
  int input[2];
  if (::pipe2(input, O_CLOEXEC) != 0)
    return io_error("cannot write " + shown(out) +
                    ": no pipe to ffmpeg: " + io::errno_message(errno));
  input_ = input[1];
  char size[32], rate[32];
  std::snprintf(size, sizeof size, "%dx%d", width, height);
  std::snprintf(rate, sizeof rate, "%.6f", fps);
  std::vector<std::string> args = {"ffmpeg", "-hide_banner", "-loglevel", "error", "-y"};
  // In: raw RGBA frames of this size and rate on standard input.
  args.insert(args.end(),
              {"-f", "rawvideo", "-pix_fmt", "rgba", "-s", size, "-r", rate, "-i", "pipe:0"});
  // Out: H.264 in yuv420p (which needs even sizes: pad by one pixel) in an MP4 container.
  // "file:" keeps ffmpeg from reading a name with a colon as a protocol, or one that starts
  // with a dash as an option.
  args.insert(args.end(), {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt",
                           "yuv420p", "-crf", "18", "-f", "mp4", "file:" + temp_.string()});
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  SpawnSetup spawn;
  // The pipe's read end becomes ffmpeg's standard input; its output and errors go to the
  // messages file (the dup2 copies lose close-on-exec). SIGPIPE is ignored here, not in ffmpeg.
  posix_spawn_file_actions_adddup2(&spawn.actions, input[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&spawn.actions, fileno(messages_), STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&spawn.actions, fileno(messages_), STDERR_FILENO);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGPIPE);
  posix_spawnattr_setsigdefault(&spawn.attr, &defaults);
  posix_spawnattr_setflags(&spawn.attr, POSIX_SPAWN_SETSIGDEF);
  const int failed =
      posix_spawnp(&pid_, "ffmpeg", &spawn.actions, &spawn.attr, argv.data(), environ);
  ::close(input[0]);
  if (failed != 0) {
    pid_ = -1;
    if (failed == ENOENT)
      return unsupported("cannot write " + shown(out) +
                         ": MP4 needs the ffmpeg program on PATH (Debian: apt-get install "
                         "ffmpeg); or write a PNG sequence");
    return io_error("cannot write " + shown(out) +
                    ": cannot start ffmpeg: " + io::errno_message(failed));
  }
  return {};
}

Status VideoWriter::write(const std::vector<std::uint8_t>& rgba) {
  const std::uint8_t* data = rgba.data();
  std::size_t left = rgba.size();
  while (left > 0) {
    const ssize_t n = ::write(input_, data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return fail(errno == EPIPE ? "ffmpeg stopped reading"
                                 : "writing to ffmpeg: " + io::errno_message(errno));
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  return {};
}

Status VideoWriter::close() {
  const std::string ended = finish();
  if (!ended.empty()) return fail("ffmpeg failed");
  // Again before the rename, as the library's atomic writes do: a device or FIFO may have been
  // put under the name while ffmpeg encoded, and a rename would replace it.
  if (Status s = io::check_parent_writable(out_); !s.ok()) {
    std::error_code ignored;
    std::filesystem::remove(temp_, ignored);
    return s;
  }
  std::error_code ec;
  std::filesystem::rename(temp_, out_, ec);
  if (ec) return fail("ffmpeg left no video (" + ec.message() + ")");
  return {};
}

std::string VideoWriter::finish() {
  if (input_ >= 0) ::close(input_);  // end of input: ffmpeg finishes the file and exits
  input_ = -1;
  if (pid_ < 0) return ended_;
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0) {
    if (errno == EINTR) continue;
    pid_ = -1;
    ended_ = "not reaped: " + io::errno_message(errno);
    return ended_;
  }
  pid_ = -1;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return ended_;
  ended_ = ending(status);
  if (const std::string line = last_line(messages_); !line.empty()) ended_ += ": " + line;
  return ended_;
}

Status VideoWriter::fail(const std::string& what) {
  const std::string ended = finish();
  std::error_code ec;
  std::filesystem::remove(temp_, ec);
  return io_error("cannot write " + shown(out_) + ": " + what +
                  (ended.empty() ? "" : " (" + ended + ")"));
}

VideoWriter::~VideoWriter() {
  if (pid_ >= 0 || input_ >= 0) {
    finish();
    std::error_code ec;
    std::filesystem::remove(temp_, ec);
  }
  if (messages_ != nullptr) std::fclose(messages_);
}

}  // namespace ocean::cli
