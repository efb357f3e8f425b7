// The process's own memory and descriptors (process_probe.hpp).
#include "process_probe.hpp"

#include <dirent.h>

#include <cstdio>
#include <cstring>
#include <string>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace ocean::soak {

namespace {

constexpr double kKiBPerMiB = 1024.0;

// The value of a "Name:  1234 kB" line of /proc/self/status, in MiB; −1 when absent.
double status_mib(const std::string& status, const char* name) {
  const std::size_t at = status.find(name);
  if (at == std::string::npos) return -1.0;
  long long kib = -1;
  if (std::sscanf(status.c_str() + at + std::strlen(name), " %lld", &kib) != 1) return -1.0;
  return static_cast<double>(kib) / kKiBPerMiB;
}

std::string read_small_file(const char* path) {
  std::string text;
  std::FILE* f = std::fopen(path, "r");
  if (f == nullptr) return text;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, f)) > 0;) text.append(buffer, n);
  std::fclose(f);
  return text;
}

int count_fds() {
  DIR* dir = opendir("/proc/self/fd");
  if (dir == nullptr) return -1;
  int n = 0;
  while (const dirent* e = readdir(dir))
    if (e->d_name[0] != '.') ++n;
  closedir(dir);
  return n - 1;  // the descriptor of `dir` itself
}

}  // namespace

ProcessSample read_process() {
  ProcessSample s;
  const std::string status = read_small_file("/proc/self/status");
  s.rss_mib = status_mib(status, "VmRSS:");
  s.hwm_mib = status_mib(status, "VmHWM:");
  s.open_fds = count_fds();
#if defined(__GLIBC__) && (__GLIBC__ > 2 || __GLIBC_MINOR__ >= 33)
  const struct mallinfo2 m = mallinfo2();
  s.heap_in_use_mib = static_cast<double>(m.uordblks + m.hblkhd) / (kKiBPerMiB * kKiBPerMiB);
#endif
  return s;
}

const char* cpu_model() {
  static const std::string model = [] {
    const std::string info = read_small_file("/proc/cpuinfo");
    const std::size_t at = info.find("model name");
    if (at == std::string::npos) return std::string("unknown");
    const std::size_t colon = info.find(':', at), end = info.find('\n', at);
    if (colon == std::string::npos || colon > end) return std::string("unknown");
    return info.substr(colon + 2, end - colon - 2);
  }();
  return model.c_str();
}

}  // namespace ocean::soak
