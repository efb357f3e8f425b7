// src/capi/spectrum.cpp — ocean_spectrum_evaluate: a FrequencySpectrum (ocean/spectrum.hpp) made
// from the C parameters and evaluated over an array of ω.
#include "ocean/spectrum.hpp"

#include <cmath>
#include <limits>

#include "capi_internal.hpp"

namespace ocean::capi {
namespace {

Result<FrequencySpectrumParams> to_params(const ocean_spectrum_params& c) {
  constexpr std::string_view f = "ocean_spectrum_evaluate";
  if (c.struct_size < sizeof(ocean_spectrum_params)) {
    return invalid_argument(std::string(f) +
                            ": params->struct_size = " + std::to_string(c.struct_size) +
                            " is too small: set it with ocean_spectrum_params_init");
  }
  if (Status s = require_not_null(c.model, f, "params->model"); !s.ok()) return s;
  Result<SpectrumModel> model = parse_spectrum_model(c.model);
  if (!model.ok()) return model.status();
  FrequencySpectrumParams p;
  p.model = model.value();
  p.significant_wave_height_m = c.hs_m;
  p.peak_period_s = c.tp_s;
  p.wind_speed_mps = c.wind_speed_mps;
  p.fetch_m = c.fetch_m;
  p.gamma = c.gamma;
  p.depth_m = c.depth_m;
  p.gravity_mps2 = c.gravity_mps2;
  return p;
}

}  // namespace
}  // namespace ocean::capi

extern "C" {

using namespace ocean::capi;

OCEAN_API void ocean_spectrum_params_init(ocean_spectrum_params* params) {
  if (params == nullptr) return;
  constexpr double unset = std::numeric_limits<double>::quiet_NaN();
  *params = ocean_spectrum_params{.struct_size = sizeof(ocean_spectrum_params),
                                  .model = "jonswap",
                                  .hs_m = unset,
                                  .tp_s = unset,
                                  .wind_speed_mps = unset,
                                  .fetch_m = unset,
                                  .gamma = unset,
                                  .depth_m = ocean::kInfiniteDepth,
                                  .gravity_mps2 = ocean::kDefaultGravity};
}

OCEAN_API ocean_status ocean_spectrum_evaluate(const ocean_spectrum_params* params,
                                               const double* omega, size_t count,
                                               double* spectrum) {
  return guarded([&]() -> ocean::Status {
    constexpr std::string_view f = "ocean_spectrum_evaluate";
    if (ocean::Status s = require_not_null(params, f, "params"); !s.ok()) return s;
    ocean::Result<ocean::FrequencySpectrumParams> p = to_params(*params);
    if (!p.ok()) return p.status();
    ocean::Result<ocean::FrequencySpectrum> s = ocean::FrequencySpectrum::make(p.value());
    if (!s.ok()) return s.status();
    if (count == 0) return {};
    if (ocean::Status st = require_not_null(omega, f, "omega"); !st.ok()) return st;
    if (ocean::Status st = require_not_null(spectrum, f, "spectrum"); !st.ok()) return st;
    for (std::size_t i = 0; i < count; ++i) {
      if (std::isfinite(omega[i]) && omega[i] >= 0.0) continue;
      const std::string name = indexed("omega", i);
      if (ocean::Status st = ocean::require_finite(name, omega[i]); !st.ok()) return st;
      return ocean::require_non_negative(name, omega[i]);
    }
    for (std::size_t i = 0; i < count; ++i) spectrum[i] = s.value()(omega[i]);
    return {};
  });
}

}  // extern "C"
