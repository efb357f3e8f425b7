// src/bake/output_folder.cpp — a bake's folder as a transaction: created and locked before any
// work, every output checked, the temporaries of dead bakes swept and the old manifest removed
// durably before the first new file, and a failed start undone.
#include "output_folder.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <climits>
#include <csignal>
#include <string_view>
#include <system_error>

#include "frame_files.hpp"
#include "ocean/io.hpp"

namespace ocean::bake::detail {
namespace {

namespace fs = std::filesystem;

constexpr const char* kManifest = "manifest.json";

// Whether `name` is io::write_atomically's temporary ".<leaf>.tmp-<pid>-<counter>" of a file a
// bake writes, left by a process that no longer runs (killed, or its machine went down).
bool dead_bake_temporary(std::string_view name) {
  const std::size_t tmp = name.rfind(".tmp-");
  if (name.size() < 2 || name[0] != '.' || tmp == std::string_view::npos) return false;
  const std::string_view leaf = name.substr(1, tmp - 1);
  bool ours = leaf == kManifest;
  for (std::string_view stem : kFileStems) ours = ours || leaf.starts_with(stem);
  if (!ours) return false;
  const std::string_view tail = name.substr(tmp + 5);  // "<pid>-<counter>"
  const std::size_t dash = tail.find('-');
  if (dash == 0 || dash == std::string_view::npos || dash > 10 || dash + 1 == tail.size())
    return false;
  long long pid = 0;
  for (std::size_t i = 0; i < tail.size(); ++i) {
    if (i == dash) continue;
    if (std::isdigit(static_cast<unsigned char>(tail[i])) == 0) return false;
    if (i < dash) pid = 10 * pid + (tail[i] - '0');
  }
  return pid > 0 && pid <= INT_MAX && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

// fsync of a folder, so that a removal in it is on disk before what follows; best effort.
void sync_folder(const fs::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  (void)::fsync(fd);
  ::close(fd);
}

}  // namespace

Status check_output_file(const fs::path& path) {
  if (Status s = io::check_parent_writable(path); !s.ok()) return s;
  std::error_code ec;
  const fs::file_type type = fs::symlink_status(path, ec).type();
  if (type == fs::file_type::not_found || type == fs::file_type::regular ||
      type == fs::file_type::symlink) {
    return {};
  }
  return io_error(
      "cannot write " + io::quoted(path) + ": " +
      (type == fs::file_type::directory ? "it is a directory" : "it is not a regular file"));
}

OutputFolder::~OutputFolder() {
  if (!begun_) undo_open();
}

void OutputFolder::undo_open() noexcept {
  lock_.release();
  for (const fs::path& dir : created_) {
    if (::rmdir(dir.c_str()) != 0) break;  // not empty (someone else's files): keep it
  }
  created_.clear();
}

Status OutputFolder::open(const fs::path& dir, std::span<const fs::path> other_outputs) {
  dir_ = dir;
  // The folders about to be made, deepest first ("out/" names the folder "out").
  const fs::path target = dir.has_filename() ? dir : dir.parent_path();
  for (fs::path p = target; !p.empty(); p = p.parent_path()) {
    std::error_code ec;
    if (fs::symlink_status(p, ec).type() != fs::file_type::not_found) break;
    created_.push_back(p);
    if (p == p.parent_path()) break;
  }
  Status s = io::ensure_directory(dir);
  if (s.ok()) {
    Result<FolderLock> lock = FolderLock::take(dir);
    if (lock.ok()) {
      lock_ = std::move(lock).value();
    } else {
      s = lock.status();
    }
  }
  for (const fs::path& file : other_outputs) {
    if (s.ok()) s = check_output_file(file);
  }
  if (!s.ok()) undo_open();
  return s;
}

Status OutputFolder::begin() {
  std::error_code ec;
  for (fs::directory_iterator it(dir_, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (dead_bake_temporary(name)) (void)::unlink(it->path().c_str());
  }
  const fs::path manifest = dir_ / kManifest;
  if (::unlink(manifest.c_str()) != 0 && errno != ENOENT) {
    const int err = errno;
    return io_error("cannot remove the old manifest " + io::quoted(manifest) + ": " +
                    io::errno_message(err));
  }
  sync_folder(dir_);
  begun_ = true;
  return {};
}

void OutputFolder::remove(const std::vector<std::string>& names) const noexcept {
  try {
    for (const std::string& name : names) (void)::unlink((dir_ / name).c_str());
  } catch (...) {  // out of memory for a path: the files stay, the manifest does not list them
  }
}

}  // namespace ocean::bake::detail
