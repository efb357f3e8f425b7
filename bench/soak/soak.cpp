// soak — a long run of the render scene (ocean/scene.hpp) that watches for growth: the simulation
// stepped at 60 frames per simulated second and every frame drawn and read back, 10 000 frames by
// default (2.8 simulated minutes; --frames 216000 is an hour), with the camera turning once per
// simulated minute so that the LOD selection keeps changing.
//
// What it reports, at the start, at the end of the warm-up and at the end of each window after it:
//   RSS, HWM   VmRSS and VmHWM of /proc/self/status (resident now, most ever resident);
//   heap       bytes malloc has handed out and not taken back (glibc mallinfo2);
//   fds        open file descriptors (/proc/self/fd);
//   vk objs    the Vulkan driver's live host allocations of object scope ("vk alloc": of every
//              scope, "vk KiB": their bytes, "new/f": allocations made per frame). The program
//              makes its own instance and device with counting VkAllocationCallbacks and gives
//              them to the library with vk::adopt_context, as an engine would; the library is
//              unchanged and passes no allocator for the objects it creates, and a driver that
//              then takes their host memory from the device's allocator (Mesa's drivers do,
//              lavapipe included) shows every live buffer, memory, image, view, pipeline, pool and
//              fence there. At start-up a buffer is created and destroyed to measure that this
//              driver does (the "probe" line); where it does not, the counts are printed but not
//              judged. Counting costs three relaxed atomic adds per driver allocation (about 100 a
//              frame on lavapipe, for command recording) and nothing else on the frame's path; it
//              sees the driver's host memory, not device memory.
//   frame ms   median and 99th percentile of the frames of the window (step + draw + read back,
//              wall clock, so other load on the machine shows here).
// Teardown: after the measured scene is destroyed, the driver must hold no more object allocations
// than before it was made (a leak on a destroy path). A first scene is made, drawn and destroyed
// beforehand, so that what the driver makes once per device (its own caches) is in that baseline.
//
// Verdict: growth from the end of the warm-up to the last frame beyond kMaxRssGrowthMiB of RSS,
// kMaxHeapGrowthMiB of heap, any descriptor or any Vulkan object, or any object left after
// teardown; the last line says "no growth: ..." or "growth in ...: ..." and the exit status is 0
// or 1 (2: bad usage or a failure, one line "soak: error: ..."). Frame time is reported, not
// judged: it depends on what else the machine runs.
//
// Usage: soak [--frames N] [--warmup N] [--backend cpu|vulkan] [--size N] [--width W]
//             [--height H] [--windows K]   (soak --help). Progress goes to stderr.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "counted_device.hpp"
#include "ocean/scene.hpp"
#include "options.hpp"
#include "process_probe.hpp"

namespace {

using ocean::soak::DriverMemory;
using ocean::soak::ProcessSample;

constexpr double kFrameRate_hz = 60.0;
// RSS may move by a few pages as glibc's arenas and the driver's caches settle after the warm-up
// without anything leaking; 4 MiB over 10 000 frames is still 400 bytes a frame, far below any
// per-frame leak of a buffer, a picture or a Vulkan object.
constexpr double kMaxRssGrowthMiB = 4.0;
// The heap counts bytes, not pages: no room for fragmentation noise, 1 MiB (100 bytes a frame).
constexpr double kMaxHeapGrowthMiB = 1.0;
constexpr int kExitGrowth = 1;
constexpr int kExitFailure = 2;

int fail(const std::string& message) {
  std::fprintf(stderr, "soak: error: %s\n", message.c_str());
  return kExitFailure;
}

// Two cascades of a 12 m/s wind sea (the scene tests' small sea) on an N × N grid.
ocean::SimulationConfig sea(int resolution) {
  ocean::SimulationConfig c;
  c.resolution = resolution;
  c.cascade_patch_sizes_m = {200.0, 47.0};
  c.sea.wind_sea.spectrum.wind_speed_mps = 12.0;
  c.sea.wind_sea.spectrum.fetch_m = 100e3;
  return c;
}

// 5 m above the sea, looking level, turned once per simulated minute.
ocean::render::View view_at(double time_s, int width, int height) {
  const double turn = 2.0 * std::numbers::pi * time_s / 60.0;
  ocean::render::View v;
  v.camera = {.position_m = {0.0, 5.0, 0.0},
              .target_m = {100.0 * std::cos(turn), 5.0, 100.0 * std::sin(turn)},
              .fov_y_rad = 50.0 * std::numbers::pi / 180.0,
              .aspect = static_cast<double>(width) / height,
              .near_m = 0.2,
              .far_m = 2e5};
  v.quality = ocean::lod::quality_preset(ocean::lod::QualityPreset::low);
  v.ocean_size_m = 2048.0;
  return v;
}

struct Row {
  const char* label = "";
  int frame = 0;  // frames done
  ProcessSample process;
  DriverMemory driver;
  double median_ms = -1.0, p99_ms = -1.0;  // of the window that ends here; −1: none
  double allocations_per_frame = -1.0;     // driver allocations made per frame of the window
};

// Median and 99th percentile (nearest rank) of times[from, to); `scratch` holds a copy.
void window_stats(const std::vector<float>& times, int from, int to, std::vector<float>& scratch,
                  Row& row) {
  if (to <= from) return;
  scratch.assign(times.begin() + from, times.begin() + to);
  const auto rank = [&](double q) {
    const auto k = static_cast<std::ptrdiff_t>(std::ceil(q * static_cast<double>(scratch.size())));
    std::nth_element(scratch.begin(), scratch.begin() + std::max<std::ptrdiff_t>(k - 1, 0),
                     scratch.end());
    return static_cast<double>(
        scratch[static_cast<std::size_t>(std::max<std::ptrdiff_t>(k - 1, 0))]);
  };
  row.median_ms = rank(0.5);
  row.p99_ms = rank(0.99);
}

void print_row(const Row& r) {
  std::printf("%-9s %7d %8.1f %8.1f %8.1f %8.2f %4d %8lld %8lld %9.1f", r.label, r.frame,
              r.frame / kFrameRate_hz, r.process.rss_mib, r.process.hwm_mib,
              r.process.heap_in_use_mib, r.process.open_fds,
              static_cast<long long>(r.driver.objects), static_cast<long long>(r.driver.all),
              static_cast<double>(r.driver.bytes) / 1024.0);
  if (r.median_ms >= 0.0)
    std::printf(" %7.1f %7.2f %7.2f\n", r.allocations_per_frame, r.median_ms, r.p99_ms);
  else
    std::printf(" %7s %7s %7s\n", "-", "-", "-");
}

// A line on stderr now and then: in place on a terminal, every tenth of the run otherwise.
class Progress {
 public:
  explicit Progress(int total) : total_(total), terminal_(::isatty(STDERR_FILENO) == 1) {}
  void update(int done, float last_ms) {
    const auto now = std::chrono::steady_clock::now();
    const bool due = terminal_ ? now - last_ > std::chrono::milliseconds(500)
                               : done % std::max(total_ / 10, 1) == 0;
    if (!due && done != total_) return;
    last_ = now;
    std::fprintf(stderr, "%ssoak: frame %d/%d, %.2f ms, RSS %.1f MiB%s", terminal_ ? "\r" : "",
                 done, total_, static_cast<double>(last_ms), ocean::soak::read_process().rss_mib,
                 terminal_ && done != total_ ? "" : "\n");
    std::fflush(stderr);
  }

 private:
  int total_;
  bool terminal_;
  std::chrono::steady_clock::time_point last_{};
};

ocean::Result<std::unique_ptr<ocean::render::Scene>> make_scene(
    const ocean::soak::CountedDevice& device, const ocean::soak::Options& o) {
  return ocean::render::Scene::make(
      device.context(),
      {.config = sea(o.size), .backend = o.backend, .width = o.width, .height = o.height});
}

// One frame: simulate, draw, read the picture back.
ocean::Status frame(ocean::render::Scene& scene, double time_s, const ocean::soak::Options& o,
                    std::vector<std::uint8_t>& pixels) {
  if (ocean::Status s = scene.step(time_s); !s.ok()) return s;
  if (ocean::Status s = scene.renderer().draw(view_at(time_s, o.width, o.height)); !s.ok())
    return s;
  return scene.renderer().read_srgb(pixels);
}

ocean::Status settle(const ocean::soak::CountedDevice& device, const ocean::soak::Options& o) {
  ocean::Result<std::unique_ptr<ocean::render::Scene>> scene = make_scene(device, o);
  if (!scene.ok()) return scene.status();
  std::vector<std::uint8_t> pixels;
  constexpr int kFrames = 3;
  for (int f = 0; f < kFrames; ++f)
    if (ocean::Status s = frame(*scene.value(), f / kFrameRate_hz, o, pixels); !s.ok()) return s;
  return {};
}

std::string signed_number(double value, const char* format) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return (value >= 0.0 ? "+" : "") + std::string(text);
}

}  // namespace

int main(int argc, char** argv) {
  ocean::Result<ocean::soak::Options> parsed = ocean::soak::parse_options(argc, argv);
  if (!parsed.ok()) return fail(parsed.status().message());
  const ocean::soak::Options o = parsed.value();
  if (o.help) {
    std::fputs(ocean::soak::usage(), stdout);
    return 0;
  }

  if (ocean::Status s = ocean::validate(sea(o.size)); !s.ok()) return fail(s.message());
  ocean::Result<std::unique_ptr<ocean::soak::CountedDevice>> made =
      ocean::soak::CountedDevice::make();
  if (!made.ok()) return fail(made.status().message());
  ocean::soak::CountedDevice& device = *made.value();
  ocean::Result<ocean::soak::ProbeResult> probe = device.probe();
  if (!probe.ok()) return fail(probe.status().message());
  const bool counted = probe.value().objects_while_alive >= 2;
  std::printf(
      "soak: %d frames at %.0f Hz (%.1f simulated s), backend %s, grid %d, 2 cascades, "
      "render %dx%d, warm-up %d frames\n",
      o.frames, kFrameRate_hz, o.frames / kFrameRate_hz, o.backend.c_str(), o.size, o.width,
      o.height, o.warmup);
  std::printf("cpu: %s; vulkan device: %s (%s)\n", ocean::soak::cpu_model(),
              device.context()->info.name.c_str(), device.context()->info.driver.c_str());
  std::printf(
      "probe: a buffer and its memory = %+lld object allocations, %+lld after destroying "
      "them: Vulkan objects %s\n",
      static_cast<long long>(probe.value().objects_while_alive),
      static_cast<long long>(probe.value().objects_after),
      counted ? "counted" : "NOT visible to the allocation callbacks (not judged)");

  // A first scene, made, drawn and destroyed, so that what the driver creates once for a device
  // (lavapipe keeps a few object allocations after its first pipelines and draws) is in the
  // baseline of the teardown check below, and not mistaken for a leak of the measured scene.
  const DriverMemory before_settling = device.live();
  if (ocean::Status s = settle(device, o); !s.ok()) return fail(s.message());
  const DriverMemory before_scene = device.live();
  std::printf(
      "settle: a first scene left %+lld object allocations in the driver (made once per "
      "device)\n",
      static_cast<long long>(before_scene.objects - before_settling.objects));
  ocean::Result<std::unique_ptr<ocean::render::Scene>> scene_made = make_scene(device, o);
  if (!scene_made.ok()) return fail(scene_made.status().message());
  std::unique_ptr<ocean::render::Scene> scene = std::move(scene_made).value();

  // Everything the loop touches is sized here: it allocates nothing itself.
  std::vector<float> times(static_cast<std::size_t>(o.frames));
  std::vector<float> scratch;
  scratch.reserve(times.size());
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(o.width) * o.height * 4);
  std::vector<int> ends{o.warmup};
  for (int k = 1; k <= o.windows; ++k)
    ends.push_back(o.warmup +
                   static_cast<int>(static_cast<long long>(o.frames - o.warmup) * k / o.windows));
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  std::vector<Row> rows{
      {.label = "start", .process = ocean::soak::read_process(), .driver = device.live()}};

  std::printf("%-9s %7s %8s %8s %8s %8s %4s %8s %8s %9s %7s %7s %7s\n", "", "frame", "sim s",
              "RSS MiB", "HWM MiB", "heap MiB", "fds", "vk objs", "vk alloc", "vk KiB", "new/f",
              "med ms", "p99 ms");
  print_row(rows.front());
  Progress progress(o.frames);
  int window_start = 0;
  for (int f = 0, next = 0; f < o.frames; ++f) {
    const double time_s = f / kFrameRate_hz;
    const auto t0 = std::chrono::steady_clock::now();
    if (ocean::Status s = frame(*scene, time_s, o, pixels); !s.ok())
      return fail("frame " + std::to_string(f) + ": " + s.message());
    times[static_cast<std::size_t>(f)] =
        std::chrono::duration<float, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (f + 1 == ends[static_cast<std::size_t>(next)]) {
      Row r{.label = next == 0 ? "warm-up" : "window",
            .frame = f + 1,
            .process = ocean::soak::read_process(),
            .driver = device.live()};
      window_stats(times, window_start, f + 1, scratch, r);
      r.allocations_per_frame =
          static_cast<double>(r.driver.made - rows.back().driver.made) / (f + 1 - window_start);
      window_start = f + 1;
      rows.push_back(r);
      if (next + 1 < static_cast<int>(ends.size())) ++next;
    }
    progress.update(f + 1, times[static_cast<std::size_t>(f)]);
  }
  for (std::size_t i = 1; i < rows.size(); ++i) print_row(rows[i]);

  scene.reset();
  const DriverMemory after_scene = device.live();

  const Row& warm = rows[1];
  const Row& last = rows.back();
  const double rss = last.process.rss_mib - warm.process.rss_mib;
  const double heap = last.process.heap_in_use_mib - warm.process.heap_in_use_mib;
  const int fds = last.process.open_fds - warm.process.open_fds;
  const long long objects = last.driver.objects - warm.driver.objects;
  const long long leaked = after_scene.objects - before_scene.objects;
  std::vector<std::string> grew;
  if (rss > kMaxRssGrowthMiB) grew.push_back("RSS");
  if (heap > kMaxHeapGrowthMiB) grew.push_back("heap");
  if (fds > 0) grew.push_back("file descriptors");
  if (counted && objects > 0) grew.push_back("Vulkan objects");
  if (counted && leaked > 0) grew.push_back("Vulkan objects left after the scene was destroyed");
  std::string list;
  for (const std::string& g : grew) list += (list.empty() ? "" : ", ") + g;
  std::printf(
      "limits after the warm-up: RSS +%.0f MiB, heap +%.0f MiB, fds +0, Vulkan objects +0%s; "
      "frame median %.2f -> %.2f ms (not judged)\n",
      kMaxRssGrowthMiB, kMaxHeapGrowthMiB, counted ? "" : " (not judged: not visible)",
      warm.median_ms, last.median_ms);
  std::printf(
      "%s: RSS %s MiB, heap %s MiB, fds %+d, Vulkan objects %+lld (allocations %+lld, "
      "%s KiB), %+lld after teardown\n",
      grew.empty() ? "no growth" : ("growth in " + list).c_str(),
      signed_number(rss, "%.1f").c_str(), signed_number(heap, "%.2f").c_str(), fds, objects,
      static_cast<long long>(last.driver.all - warm.driver.all),
      signed_number(static_cast<double>(last.driver.bytes - warm.driver.bytes) / 1024.0, "%.1f")
          .c_str(),
      leaked);
  return grew.empty() ? 0 : kExitGrowth;
}
