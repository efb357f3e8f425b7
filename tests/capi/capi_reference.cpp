// The C API's reference: one scenario computed through the C++ API (ocean/preset.hpp,
// ocean/backends.hpp, ocean/spectrum.hpp) and written, with the scenario itself, to a text file
// that the C program (capi_test.c) and the Python ctypes test (capi_ctypes_test.py) read and
// repeat through libocean_c.so alone. Numbers are printed with 17 significant digits, so they
// read back as the same doubles: both tests compare for exact equality.
//
// Usage: capi_reference OUT.txt
// Lines: "preset <name>", "set <key=value>", "time <t>", "height <x> <z> <h>",
//        "spectrum <model> <hs_m> <tp_s> <omega> <S>",
//        "surface <x> <z> <h> <nx> <ny> <nz> <u> <w> <v>" (Simulator::surface_at of the same
//        scenario with the velocity output, on a serial runner: one thread, as the C test's job
//        system).
#include <array>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "ocean/backends.hpp"
#include "ocean/preset.hpp"
#include "ocean/spectrum.hpp"

namespace {

int fail(const ocean::Status& s) {
  std::fprintf(stderr, "capi_reference: %s\n", s.message().c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: capi_reference OUT.txt\n");
    return 2;
  }
  const std::string preset = "moderate";
  const std::vector<std::string> sets = {"resolution=32", "seed=7", "choppiness=0.8"};
  const double time_s = 1.25;
  ocean::preset::Document doc;
  if (ocean::Status s = doc.merge_preset(preset); !s.ok()) return fail(s);
  for (const std::string& assignment : sets) {
    if (ocean::Status s = doc.set(assignment); !s.ok()) return fail(s);
  }
  ocean::Result<ocean::SimulationConfig> config = doc.config();
  if (!config.ok()) return fail(config.status());
  ocean::Result<std::unique_ptr<ocean::Simulator>> sim =
      ocean::make_simulator(config.value(), "cpu");
  if (!sim.ok()) return fail(sim.status());
  sim.value()->step(time_s);
  // Points spread over several cells of every cascade, off the texel grid, one at the origin.
  std::vector<std::array<double, 2>> xz;
  for (int i = 0; i < 24; ++i) xz.push_back({-61.7 + 13.3 * i, 17.1 - 9.7 * i});
  xz.push_back({0.0, 0.0});
  std::vector<ocean::HeightSample> heights(xz.size());
  sim.value()->heights_at(xz, heights);
  ocean::SimulationConfig with_velocity = config.value();
  with_velocity.outputs.velocity = true;
  ocean::Result<std::unique_ptr<ocean::Simulator>> serial =
      ocean::make_simulator(with_velocity, "cpu", ocean::make_serial_runner());
  if (!serial.ok()) return fail(serial.status());
  serial.value()->step(time_s);
  std::vector<ocean::SurfaceSample> surface(xz.size());
  serial.value()->surface_at(xz, surface);

  std::FILE* out = std::fopen(argv[1], "w");
  if (out == nullptr) {
    std::perror(argv[1]);
    return 1;
  }
  std::fprintf(out, "preset %s\n", preset.c_str());
  for (const std::string& assignment : sets) std::fprintf(out, "set %s\n", assignment.c_str());
  std::fprintf(out, "time %.17g\n", time_s);
  for (std::size_t i = 0; i < xz.size(); ++i) {
    std::fprintf(out, "height %.17g %.17g %.17g\n", xz[i][0], xz[i][1], heights[i].height_m);
  }
  for (std::size_t i = 0; i < xz.size(); ++i) {
    const ocean::SurfaceSample& p = surface[i];
    std::fprintf(out, "surface %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", xz[i][0],
                 xz[i][1], p.height_m, p.normal[0], p.normal[1], p.normal[2], p.velocity[0],
                 p.velocity[1], p.velocity[2]);
  }
  // A JONSWAP sea of Hs = 2.5 m, Tp = 8 s: S(ω) on both sides of the peak and in the tail.
  ocean::FrequencySpectrumParams p;
  p.model = ocean::SpectrumModel::jonswap;
  p.significant_wave_height_m = 2.5;
  p.peak_period_s = 8.0;
  ocean::Result<ocean::FrequencySpectrum> spectrum = ocean::FrequencySpectrum::make(p);
  if (!spectrum.ok()) return fail(spectrum.status());
  for (double omega : {0.0, 0.3, 0.6, 0.785, 1.0, 2.0, 5.0}) {
    std::fprintf(out, "spectrum jonswap 2.5 8 %.17g %.17g\n", omega, spectrum.value()(omega));
  }
  return std::fclose(out) == 0 ? 0 : 1;
}
