// What the soak program reads about its own process (Linux): resident memory and its peak from
// /proc/self/status, the open file descriptors in /proc/self/fd, and the bytes the C heap has
// handed out (glibc mallinfo2).
//
// Contract: read_process() opens /proc files and allocates a little; call it between frames, not
// inside a timed one. A field that cannot be read is −1 (not Linux, no /proc, not glibc).
#pragma once

#include <cstdint>

namespace ocean::soak {

struct ProcessSample {
  double rss_mib = -1.0;          ///< VmRSS: resident now
  double hwm_mib = -1.0;          ///< VmHWM: the most ever resident
  int open_fds = -1;              ///< entries of /proc/self/fd, the one used to list them excluded
  double heap_in_use_mib = -1.0;  ///< malloc'd and not freed (mallinfo2 uordblks + hblkhd)
};

ProcessSample read_process();

/// "model name" of the first CPU in /proc/cpuinfo, or "unknown".
const char* cpu_model();

}  // namespace ocean::soak
