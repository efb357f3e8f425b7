// src/capi/simulator.cpp — ocean_simulator: a Simulator made by backend name
// (ocean/backends.hpp), stepped, its published frame's fields described as views, and batched
// height queries.
#include <array>
#include <cmath>
#include <cstdint>

#include "capi_internal.hpp"
#include "job_system.hpp"
#include "ocean/backends.hpp"

namespace ocean::capi {
namespace {

// World coordinates a height query accepts, m: far beyond any sea, and small enough that every
// texel index of the finest possible patch (0.01 m at N = 2048) stays an exact integer.
constexpr double kMaxCoordinate_m = 1e9;

// Points queried per call of Simulator::heights_at / surface_at: the query needs no allocation.
constexpr std::size_t kHeightBatch = 256;

// The output bits ocean_simulator_options::outputs may carry.
constexpr std::uint32_t kOutputBits =
    OCEAN_OUTPUT_NORMAL | OCEAN_OUTPUT_JACOBIAN | OCEAN_OUTPUT_FOAM | OCEAN_OUTPUT_VELOCITY;

Status require_simulator(const ocean_simulator* s, std::string_view function) {
  return require_not_null(s, function, "simulator");
}

// The element size of a view, bytes.
std::size_t element_bytes(ocean_element_type type) {
  return type == OCEAN_ELEMENT_FLOAT32 ? 4 : type == OCEAN_ELEMENT_FLOAT16 ? 2 : 1;
}

// The view of an N × N array of `channels` elements (level 0, or one packed mip level).
template <typename T>
Status describe(const LargeVector<T>& data, std::size_t offset, int width, int channels,
                ocean_element_type type, std::string_view name, ocean_field_view& view) {
  if (data.empty()) {
    return unsupported("the " + std::string(name) +
                       " field is not computed by this configuration (see outputs)");
  }
  view.data = data.data() + offset;
  view.width = width;
  view.height = width;
  view.channels = channels;
  view.element = type;
  view.row_stride_bytes =
      static_cast<std::size_t>(width) * static_cast<std::size_t>(channels) * element_bytes(type);
  return {};
}

}  // namespace

Status field_view(const CascadeFrame& c, ocean_field field, int32_t level, ocean_field_view& v) {
  const int n = c.resolution;
  if (field != OCEAN_FIELD_PACKED && level != 0) {
    return invalid_argument("level = " + std::to_string(level) +
                            " is out of range: must be 0 for a field other than packed");
  }
  switch (field) {
    case OCEAN_FIELD_DISPLACEMENT:
      return describe(c.displacement, 0, n, 3, OCEAN_ELEMENT_FLOAT32, "displacement", v);
    case OCEAN_FIELD_DISPLACEMENT_HALF:
      return describe(c.displacement_half, 0, n, 4, OCEAN_ELEMENT_FLOAT16, "displacement", v);
    case OCEAN_FIELD_NORMAL: return describe(c.normal, 0, n, 3, OCEAN_ELEMENT_FLOAT32, "normal", v);
    case OCEAN_FIELD_JACOBIAN:
      return describe(c.jacobian, 0, n, 1, OCEAN_ELEMENT_FLOAT32, "jacobian", v);
    case OCEAN_FIELD_FOAM: return describe(c.foam, 0, n, 1, OCEAN_ELEMENT_FLOAT32, "foam", v);
    case OCEAN_FIELD_PACKED: {
      const int levels = static_cast<int>(std::log2(n)) + 1;
      if (level < 0 || level >= levels) {
        return invalid_argument("level = " + std::to_string(level) +
                                " is out of range: must be 0 to " + std::to_string(levels - 1));
      }
      return describe(c.packed_mips, mip_offset(n, level), n >> level, 4, OCEAN_ELEMENT_UINT8,
                      "packed", v);
    }
    case OCEAN_FIELD_VELOCITY:
      return describe(c.velocity, 0, n, 3, OCEAN_ELEMENT_FLOAT32, "velocity", v);
    case OCEAN_FIELD_MAX_ENUM: break;
  }
  return invalid_argument("field = " + std::to_string(static_cast<int>(field)) +
                          " is out of range: must be 0 to 6 (ocean_field)");
}

Status device_status(const Simulator& simulator) {
  const DeviceCapabilities* device = capabilities(simulator.backend());
  return device != nullptr ? device->status() : Status{};
}

namespace {

// ocean_simulator_step and _kick: the checks, then `frame` (Simulator::step or kick) at time_s.
ocean_status start_frame(ocean_simulator* simulator, double time_s, std::string_view function,
                         void (Simulator::*frame)(double)) {
  return guarded([&]() -> Status {
    if (Status s = require_simulator(simulator, function); !s.ok()) return s;
    if (Status s = require_finite("time_s", time_s); !s.ok()) return s;
    (simulator->simulator.get()->*frame)(time_s);
    // A kicked frame may still run (its failure shows at the wait).
    return frame == &Simulator::kick ? Status{} : device_status(*simulator->simulator);
  });
}

// The checks every point query makes, in the order ocean_simulator_heights makes them: the
// simulator, then (unless count is 0) the arrays, then every point, before anything is written.
Status check_points(const ocean_simulator* simulator, std::string_view f, const double* x,
                    const double* z, std::size_t count, const double* out, std::string_view name) {
  if (Status s = require_simulator(simulator, f); !s.ok()) return s;
  if (count == 0) return {};
  if (Status s = require_not_null(x, f, "x"); !s.ok()) return s;
  if (Status s = require_not_null(z, f, "z"); !s.ok()) return s;
  if (Status s = require_not_null(out, f, name); !s.ok()) return s;
  for (std::size_t i = 0; i < count; ++i) {
    if (std::abs(x[i]) <= kMaxCoordinate_m && std::abs(z[i]) <= kMaxCoordinate_m) continue;
    const bool bad_x = !(std::abs(x[i]) <= kMaxCoordinate_m);
    return require_in_range(indexed(bad_x ? "x" : "z", i), bad_x ? x[i] : z[i], -kMaxCoordinate_m,
                            kMaxCoordinate_m);
  }
  return {};
}

// Simulator::surface_at over the points in batches on the stack; `write(i, sample)` stores
// point i's result.
template <typename Write>
void surface_batches(const Simulator& simulator, const double* x, const double* z,
                     std::size_t count, Write&& write) {
  std::array<std::array<double, 2>, kHeightBatch> xz;
  std::array<SurfaceSample, kHeightBatch> samples;
  for (std::size_t start = 0; start < count; start += kHeightBatch) {
    const std::size_t n = std::min(kHeightBatch, count - start);
    for (std::size_t i = 0; i < n; ++i) xz[i] = {x[start + i], z[start + i]};
    simulator.surface_at(std::span(xz.data(), n), std::span(samples.data(), n));
    for (std::size_t i = 0; i < n; ++i) write(start + i, samples[i]);
  }
}

}  // namespace

Status simulator_with_options(const ocean_config& config, const ocean_simulator_options& o,
                              std::string_view f, const BackendFactory& make,
                              ocean_simulator*& out) {
  const std::string prefix = std::string(f) + ": options->";
  if (o.struct_size < sizeof(ocean_simulator_options)) {
    return invalid_argument(prefix + "struct_size = " + std::to_string(o.struct_size) +
                            " is too small: set it with ocean_simulator_options_init");
  }
  if (!make && o.backend == nullptr) return invalid_argument(prefix + "backend is NULL");
  if ((o.outputs & ~kOutputBits) != 0) {
    return invalid_argument(prefix + "outputs = " + std::to_string(o.outputs) +
                            " has unknown bits: must be a combination of ocean_output_flags (" +
                            std::to_string(kOutputBits) + " all)");
  }
  if (o.threads < 0 || o.threads > kMaxRunnerThreads) {
    return invalid_argument(prefix + "threads = " + std::to_string(o.threads) +
                            " is out of range: must be 0 (every hardware thread) to " +
                            std::to_string(kMaxRunnerThreads));
  }
  std::shared_ptr<TaskRunner> runner;
  if (o.job_system != nullptr) {
    if (o.threads != 0) {
      return invalid_argument(prefix + "threads = " + std::to_string(o.threads) +
                              " with a job system: must be 0 (the job system's threads are used)");
    }
    if (Status s = validate_job_system(*o.job_system, f); !s.ok()) return s;
    runner = make_job_system_runner(*o.job_system);
  } else {
    runner = std::shared_ptr<TaskRunner>(make_tbb_runner(o.threads));
  }
  const int threads = runner->concurrency();
  SimulationConfig c = config.config;
  c.outputs = {.normal = (o.outputs & OCEAN_OUTPUT_NORMAL) != 0,
               .jacobian = (o.outputs & OCEAN_OUTPUT_JACOBIAN) != 0,
               .foam = (o.outputs & OCEAN_OUTPUT_FOAM) != 0,
               .velocity = (o.outputs & OCEAN_OUTPUT_VELOCITY) != 0};
  Result<std::unique_ptr<Backend>> backend = make ? make() : make_backend(o.backend);
  if (!backend.ok()) return backend.status();
  Result<std::unique_ptr<Simulator>> sim =
      Simulator::make(c, std::move(backend).value(), std::move(runner));
  if (!sim.ok()) return sim.status();
  out = new ocean_simulator{std::move(sim).value()};
  log_created(*out->simulator, threads);
  return {};
}

}  // namespace ocean::capi

extern "C" {

using namespace ocean::capi;

OCEAN_API ocean_status ocean_simulator_create(const ocean_config* config, const char* backend,
                                              ocean_simulator** out) {
  return guarded([&]() -> ocean::Status {
    constexpr std::string_view f = "ocean_simulator_create";
    if (ocean::Status s = require_not_null(config, f, "config"); !s.ok()) return s;
    if (ocean::Status s = require_not_null(backend, f, "backend"); !s.ok()) return s;
    if (ocean::Status s = require_not_null(out, f, "out"); !s.ok()) return s;
    // The library's own scheduler on every hardware thread, as make_simulator would make it.
    std::shared_ptr<ocean::TaskRunner> runner(ocean::make_tbb_runner());
    const int threads = runner->concurrency();
    ocean::Result<std::unique_ptr<ocean::Simulator>> sim =
        ocean::make_simulator(config->config, backend, std::move(runner));
    if (!sim.ok()) return sim.status();
    *out = new ocean_simulator{std::move(sim).value()};
    log_created(*(*out)->simulator, threads);
    return {};
  });
}

OCEAN_API void ocean_simulator_destroy(ocean_simulator* simulator) { delete simulator; }

OCEAN_API ocean_status ocean_simulator_step(ocean_simulator* simulator, double time_s) {
  return start_frame(simulator, time_s, "ocean_simulator_step", &ocean::Simulator::step);
}

OCEAN_API ocean_status ocean_simulator_kick(ocean_simulator* simulator, double time_s) {
  return start_frame(simulator, time_s, "ocean_simulator_kick", &ocean::Simulator::kick);
}

OCEAN_API ocean_status ocean_simulator_wait(ocean_simulator* simulator) {
  return guarded([&]() -> ocean::Status {
    if (ocean::Status s = require_simulator(simulator, "ocean_simulator_wait"); !s.ok()) return s;
    simulator->simulator->wait();
    return device_status(*simulator->simulator);
  });
}

OCEAN_API ocean_status ocean_simulator_frame_time(const ocean_simulator* simulator, double* time_s,
                                                  uint64_t* index) {
  return guarded([&]() -> ocean::Status {
    if (ocean::Status s = require_simulator(simulator, "ocean_simulator_frame_time"); !s.ok())
      return s;
    const ocean::Frame& frame = simulator->simulator->frame();
    if (time_s != nullptr) *time_s = frame.time_s;
    if (index != nullptr) *index = frame.index;
    return {};
  });
}

OCEAN_API ocean_status ocean_simulator_cascade_count(const ocean_simulator* simulator,
                                                     size_t* count) {
  return guarded([&]() -> ocean::Status {
    constexpr std::string_view f = "ocean_simulator_cascade_count";
    if (ocean::Status s = require_simulator(simulator, f); !s.ok()) return s;
    if (ocean::Status s = require_not_null(count, f, "count"); !s.ok()) return s;
    *count = simulator->simulator->frame().cascades.size();
    return {};
  });
}

OCEAN_API ocean_status ocean_simulator_field(const ocean_simulator* simulator, size_t cascade,
                                             ocean_field field, int32_t level,
                                             ocean_field_view* view) {
  return guarded([&]() -> ocean::Status {
    constexpr std::string_view f = "ocean_simulator_field";
    if (ocean::Status s = require_simulator(simulator, f); !s.ok()) return s;
    if (ocean::Status s = require_not_null(view, f, "view"); !s.ok()) return s;
    if (view->struct_size < sizeof(ocean_field_view)) {
      return ocean::invalid_argument(std::string(f) +
                                     ": view->struct_size = " + std::to_string(view->struct_size) +
                                     " is too small: set it to sizeof(ocean_field_view)");
    }
    const ocean::Frame& frame = simulator->simulator->frame();
    if (cascade >= frame.cascades.size()) {
      return ocean::invalid_argument("cascade = " + std::to_string(cascade) +
                                     " is out of range: must be 0 to " +
                                     std::to_string(frame.cascades.size() - 1));
    }
    const ocean::CascadeFrame& c = frame.cascades[cascade];
    ocean_field_view result{};
    result.struct_size = view->struct_size;
    result.patch_size_m = c.patch_size_m;
    if (ocean::Status s = field_view(c, field, level, result); !s.ok()) return s;
    *view = result;
    return {};
  });
}

OCEAN_API ocean_status ocean_simulator_heights(const ocean_simulator* simulator, const double* x,
                                               const double* z, size_t count, double* heights) {
  return guarded([&]() -> ocean::Status {
    if (ocean::Status s =
            check_points(simulator, "ocean_simulator_heights", x, z, count, heights, "heights");
        !s.ok() || count == 0)
      return s;
    std::array<std::array<double, 2>, kHeightBatch> xz;
    std::array<ocean::HeightSample, kHeightBatch> samples;
    for (std::size_t start = 0; start < count; start += kHeightBatch) {
      const std::size_t n = std::min(kHeightBatch, count - start);
      for (std::size_t i = 0; i < n; ++i) xz[i] = {x[start + i], z[start + i]};
      simulator->simulator->heights_at(std::span(xz.data(), n), std::span(samples.data(), n));
      for (std::size_t i = 0; i < n; ++i) heights[start + i] = samples[i].height_m;
    }
    return {};
  });
}

OCEAN_API ocean_status ocean_simulator_normals(const ocean_simulator* simulator, const double* x,
                                               const double* z, size_t count, double* normals) {
  return guarded([&]() -> ocean::Status {
    if (ocean::Status s =
            check_points(simulator, "ocean_simulator_normals", x, z, count, normals, "normals");
        !s.ok() || count == 0)
      return s;
    surface_batches(*simulator->simulator, x, z, count,
                    [&](std::size_t i, const ocean::SurfaceSample& sample) {
                      for (std::size_t k = 0; k < 3; ++k) normals[3 * i + k] = sample.normal[k];
                    });
    return {};
  });
}

OCEAN_API ocean_status ocean_simulator_velocities(const ocean_simulator* simulator, const double* x,
                                                  const double* z, size_t count,
                                                  double* velocities) {
  return guarded([&]() -> ocean::Status {
    constexpr std::string_view f = "ocean_simulator_velocities";
    if (ocean::Status s = require_simulator(simulator, f); !s.ok()) return s;
    if (!simulator->simulator->has_velocity()) {
      return ocean::unsupported(std::string(f) +
                                ": the simulator does not compute the velocity: create it with "
                                "OCEAN_OUTPUT_VELOCITY in ocean_simulator_options::outputs");
    }
    if (ocean::Status s = check_points(simulator, f, x, z, count, velocities, "velocities");
        !s.ok() || count == 0)
      return s;
    surface_batches(*simulator->simulator, x, z, count,
                    [&](std::size_t i, const ocean::SurfaceSample& sample) {
                      for (std::size_t k = 0; k < 3; ++k)
                        velocities[3 * i + k] = sample.velocity[k];
                    });
    return {};
  });
}

OCEAN_API void ocean_simulator_options_init(ocean_simulator_options* options) {
  if (options == nullptr) return;
  *options = ocean_simulator_options{};
  options->struct_size = sizeof(ocean_simulator_options);
  options->backend = "cpu";
  options->threads = 0;
  options->job_system = nullptr;
  options->outputs = OCEAN_OUTPUT_DEFAULT;
}

OCEAN_API ocean_status ocean_simulator_create_with_options(const ocean_config* config,
                                                           const ocean_simulator_options* options,
                                                           ocean_simulator** out) {
  return guarded([&]() -> ocean::Status {
    constexpr std::string_view f = "ocean_simulator_create_with_options";
    if (ocean::Status s = require_not_null(config, f, "config"); !s.ok()) return s;
    if (ocean::Status s = require_not_null(out, f, "out"); !s.ok()) return s;
    ocean_simulator_options defaults;
    ocean_simulator_options_init(&defaults);
    // Only the struct_size first: a caller's struct may be shorter than this library's.
    const ocean_simulator_options* o = options != nullptr ? options : &defaults;
    return simulator_with_options(*config, *o, f, {}, *out);
  });
}

}  // extern "C"
