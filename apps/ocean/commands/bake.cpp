// `ocean bake`: simulates frames (or one whole loop) and writes displacement, normal, Jacobian,
// foam and the packed normal/foam/smoothness mip chain as .npy, PNG and/or OpenEXR, every file
// atomically, with a manifest.json describing what was written.
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <set>

#include "cli_common.hpp"
#include "commands.hpp"
#include "contact_sheet.hpp"
#include "io/atomic_file.hpp"
#include "io/exr.hpp"
#include "io/npy.hpp"
#include "io/png_image.hpp"
#include "ocean/backends.hpp"
#include "progress.hpp"
#include "simulation_flags.hpp"

namespace ocean::cli {

namespace {

constexpr NumberOption<double> kFps{
    .flag = "--fps", .accept = Accept::in_range, .lo = 1e-3, .hi = 1e4};
constexpr NumberOption<double> kTime{.flag = "--time", .accept = Accept::finite};
constexpr NumberOption<long long> kFrames{.flag = "--frames",
                                          .accept = Accept::integer_in_range,
                                          .lo = 1.0,
                                          .hi = 1e6,
                                          .echo = Echo::text};

struct BakeOptions {
  SimulationFlags sim;
  std::string out;
  std::vector<std::string> formats;
  std::string frames, fps = "30", time = "0", backend = "cpu";
  bool loop = false;
  std::string contact_sheet;
};

struct FrameWriter {
  std::filesystem::path dir;
  std::set<std::string> formats;
  double height_range_m;  // PNG height maps map [−range, +range] to [0, 65535]
  nlohmann::ordered_json files = nlohmann::ordered_json::array();

  Status write(const CascadeFrame& c, const std::string& stem) {
    const int n = c.resolution;
    const auto un = static_cast<std::size_t>(n);
    const auto texels = un * un;
    const auto record = [&](const std::string& name) {
      files.push_back(name);
      return dir / name;
    };
    if (formats.contains("npy")) {
      const std::size_t vec3[] = {un, un, 3}, scalar[] = {un, un};
      if (Status s =
              io::write_npy(record("displacement_" + stem + ".npy"), c.displacement.data(), vec3);
          !s.ok())
        return s;
      if (Status s = io::write_npy(record("normal_" + stem + ".npy"), c.normal.data(), vec3);
          !s.ok())
        return s;
      if (Status s = io::write_npy(record("jacobian_" + stem + ".npy"), c.jacobian.data(), scalar);
          !s.ok())
        return s;
      if (Status s = io::write_npy(record("foam_" + stem + ".npy"), c.foam.data(), scalar); !s.ok())
        return s;
    }
    if (formats.contains("exr")) {
      std::vector<float> planes(6 * texels);
      for (std::size_t i = 0; i < texels; ++i) {
        for (std::size_t k = 0; k < 3; ++k) {
          planes[k * texels + i] = c.displacement[3 * i + k];
          planes[(3 + k) * texels + i] = c.normal[3 * i + k];
        }
      }
      const io::ExrChannel displacement[] = {
          {"R", planes.data()}, {"G", planes.data() + texels}, {"B", planes.data() + 2 * texels}};
      if (Status s = io::write_exr(record("displacement_" + stem + ".exr"), n, n, displacement,
                                   io::ExrPixelType::float32);
          !s.ok()) {
        return s;
      }
      const io::ExrChannel maps[] = {{"normal.X", planes.data() + 3 * texels},
                                     {"normal.Y", planes.data() + 4 * texels},
                                     {"normal.Z", planes.data() + 5 * texels},
                                     {"jacobian", c.jacobian.data()},
                                     {"foam", c.foam.data()}};
      if (Status s =
              io::write_exr(record("maps_" + stem + ".exr"), n, n, maps, io::ExrPixelType::half);
          !s.ok()) {
        return s;
      }
    }
    // The packed normal/foam/smoothness chain, one image per mip level.
    const int levels = std::countr_zero(static_cast<unsigned>(n));
    for (int level = 0; level <= levels; ++level) {
      const int size = n >> level;
      const auto count = static_cast<std::size_t>(size) * static_cast<std::size_t>(size);
      const std::uint32_t* packed = c.packed_mips.data() + mip_offset(n, level);
      const std::string name = "nfs_" + stem + "_mip" + std::to_string(level);
      std::vector<std::uint8_t> rgba(4 * count);
      for (std::size_t i = 0; i < count; ++i) {
        for (std::size_t k = 0; k < 4; ++k)
          rgba[4 * i + k] = static_cast<std::uint8_t>(packed[i] >> (8 * k));
      }
      if (formats.contains("png")) {
        if (Status s = io::write_png8(record(name + ".png"), size, size, 4, rgba.data()); !s.ok())
          return s;
      }
      if (formats.contains("exr") || formats.contains("npy")) {
        std::vector<float> values(4 * count);
        for (std::size_t i = 0; i < 4 * count; ++i) values[i] = rgba[i] / 255.0f;
        if (formats.contains("npy")) {
          const std::size_t shape[] = {static_cast<std::size_t>(size),
                                       static_cast<std::size_t>(size), 4};
          if (Status s = io::write_npy(record(name + ".npy"), values.data(), shape); !s.ok())
            return s;
        }
        if (formats.contains("exr")) {
          std::vector<float> planar(4 * count);
          for (std::size_t i = 0; i < count; ++i) {
            for (std::size_t k = 0; k < 4; ++k) planar[k * count + i] = values[4 * i + k];
          }
          const io::ExrChannel ch[] = {{"R", planar.data()},
                                       {"G", planar.data() + count},
                                       {"B", planar.data() + 2 * count},
                                       {"A", planar.data() + 3 * count}};
          if (Status s =
                  io::write_exr(record(name + ".exr"), size, size, ch, io::ExrPixelType::half);
              !s.ok())
            return s;
        }
      }
    }
    if (formats.contains("png")) {
      std::vector<std::uint16_t> height(texels);
      for (std::size_t i = 0; i < texels; ++i) {
        const double t = 0.5 + 0.5 * c.displacement[3 * i + 1] / height_range_m;
        height[i] = static_cast<std::uint16_t>(std::lround(std::clamp(t, 0.0, 1.0) * 65535.0));
      }
      if (Status s = io::write_png16_gray(record("height_" + stem + ".png"), n, n, height.data());
          !s.ok())
        return s;
    }
    return {};
  }
};

int run_bake(const BakeOptions& o) {
  if (o.out.empty()) return report(invalid_argument("bake needs --out DIR"));
  std::set<std::string> formats(o.formats.begin(), o.formats.end());
  if (formats.empty()) formats = {"npy"};
  for (const std::string& f : formats) {
    if (f != "npy" && f != "png" && f != "exr") {
      return report(invalid_argument("--format = '" + f + "' is unknown: must be exr, png or npy"));
    }
  }
  Result<SimulationConfig> config = resolve_config(o.sim);
  if (!config.ok()) return report(config.status());
  const SimulationConfig& c = config.value();
  Result<double> fps = parse(kFps, o.fps);
  if (!fps.ok()) return report(fps.status());
  Result<double> start = parse(kTime, o.time);
  if (!start.ok()) return report(start.status());
  long long frames = 1;
  if (o.loop) {
    if (!o.frames.empty()) return report(invalid_argument("give --frames N or --loop, not both"));
    if (!(c.loop_period_s > 0))
      return report(invalid_argument("--loop needs a loop period > 0 (--loop-period)"));
    frames = std::llround(c.loop_period_s * fps.value());
    if (frames < 1 || frames > 1000000)
      return report(invalid_argument("--loop at --fps " + o.fps + " gives " +
                                     std::to_string(frames) + " frames: must be 1 to 1000000"));
  } else if (!o.frames.empty()) {
    Result<long long> v = parse(kFrames, o.frames);
    if (!v.ok()) return report(v.status());
    frames = v.value();
  }
  // Fail on an unusable output directory before any simulation work.
  if (Status s = io::ensure_directory(o.out); !s.ok()) return report(s);
  Result<std::unique_ptr<Simulator>> sim = make_simulator(c, o.backend);
  if (!sim.ok()) return report(sim.status());
  const double hs = 4.0 * std::sqrt(SeaState::make(c.sea).value().variance_m2());
  FrameWriter writer{.dir = o.out, .formats = formats, .height_range_m = std::max(hs, 1e-3)};
  nlohmann::ordered_json manifest{
      {"generator", "ocean bake"},
      {"backend", o.backend},
      {"config", to_json(c)},
      {"fps", fps.value()},
      {"formats", formats},
      {"height_png_range_m", writer.height_range_m},
      {"layout",
       "row-major [row][col][channel]; texel (col,row) starts at world (col, row)*L/N; "
       "displacement = (Dx, h, Dz) m; nfs = RGBA8 (normal x, normal z, foam, smoothness)"},
      {"cascades", nlohmann::ordered_json::array()},
      {"frames", nlohmann::ordered_json::array()}};
  for (double size : c.cascade_patch_sizes_m)
    manifest["cascades"].push_back({{"patch_size_m", size}, {"resolution", c.resolution}});
  Progress progress("bake", frames);
  for (long long f = 0; f < frames; ++f) {
    const double t = start.value() + static_cast<double>(f) / fps.value();
    sim.value()->step(t);
    writer.files = nlohmann::ordered_json::array();
    char index[24];
    std::snprintf(index, sizeof index, "%05lld", f);
    const Frame& frame = sim.value()->frame();
    for (std::size_t k = 0; k < frame.cascades.size(); ++k) {
      if (Status s = writer.write(frame.cascades[k], "c" + std::to_string(k) + "_f" + index);
          !s.ok()) {
        return report(s);
      }
    }
    manifest["frames"].push_back({{"index", f}, {"time_s", t}, {"files", writer.files}});
    if (f == 0 && !o.contact_sheet.empty()) {
      char title[200];
      std::snprintf(title, sizeof title,
                    "ocean bake: %s, Hs %.2f m, t = %.2f s, %d^2 × %zu cascades",
                    std::string(to_string(c.sea.wind_sea.spectrum.model)).c_str(), hs, t,
                    c.resolution, c.cascade_patch_sizes_m.size());
      const Result<SheetSize> sheet =
          write_contact_sheet(frame_maps_sheet(frame, title), o.contact_sheet);
      if (!sheet.ok()) return report(sheet.status());
    }
    progress.update(f + 1);
  }
  progress.finish();
  const std::string text = manifest.dump(2) + "\n";
  if (Status s = io::write_bytes_atomically(std::filesystem::path(o.out) / "manifest.json",
                                            {std::as_bytes(std::span(text.data(), text.size()))});
      !s.ok()) {
    return report(s);
  }
  std::cerr << "ocean: wrote " << frames << " frame(s) to " << o.out << "\n";
  return kExitOk;
}

}  // namespace

Command add_bake_command(CLI::App& app) {
  auto o = std::make_shared<BakeOptions>();
  CLI::App* command = app.add_subcommand(
      "bake", "Simulate frames and write displacement/normal/foam maps with mips (npy, png, exr)");
  add_simulation_flags(*command, o->sim);
  command->add_option("--out", o->out, "output directory (created if missing)");
  command->add_option("--format", o->formats, "exr | png | npy (repeatable; default npy)");
  add_option(*command, kFrames, o->frames, "number of frames (default 1)");
  command->add_flag("--loop", o->loop, "one whole loop period of frames at --fps");
  add_option(*command, kFps, o->fps, "frames per second")->capture_default_str();
  add_option(*command, kTime, o->time, "time of the first frame, s")->capture_default_str();
  command->add_option("--backend", o->backend, "simulation backend (see ocean info)")
      ->capture_default_str();
  command->add_option("--contact-sheet", o->contact_sheet,
                      "also draw the first frame's maps to this PNG");
  return {command, [o] { return run_bake(*o); }};
}

}  // namespace ocean::cli
