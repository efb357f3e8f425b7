// ocean.spectrum, ocean.spectrum_info, ocean.dispersion, ocean.spreading, ocean.depth_factor:
// the math of ocean/spectrum.hpp vectorised over numpy arrays, with the parameters and the error
// messages of `ocean spectrum`, `ocean dispersion` and `ocean spreading`.
//
// Keyword values reach the library as the tool's flags do (ocean::resolve, the ranges of
// kSeaStateParameters, ocean/parameters.hpp's checks), so that a value means exactly what the
// same flag means and a bad one gives the tool's message.
#include "ocean/spectrum.hpp"

#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <string>
#include <variant>

#include "arrays.hpp"
#include "bindings.hpp"
#include "errors.hpp"
#include "ocean/parameters.hpp"

namespace py = pybind11;

namespace ocean::python {
namespace {

using OptionalNumber = std::optional<double>;
using NumberOrName = std::optional<std::variant<double, std::string>>;

/// The sea-state keywords of ocean.spectrum, as `ocean spectrum`'s flags.
struct SeaKeywords {
  std::string model;
  OptionalNumber hs, tp, wind_speed, fetch;
  NumberOrName gamma;
  OptionalNumber depth, gravity;
  std::string depth_factor, fetch_law, normalization;
  OptionalNumber phillips_amplitude, cutoff_length;

  [[nodiscard]] FrequencySpectrumParams params() const {
    SpectrumInputs in{.model = model,
                      .hs = hs,
                      .tp = tp,
                      .wind_speed = wind_speed,
                      .fetch = fetch,
                      .depth = depth,
                      .gravity = gravity,
                      .phillips_amplitude = phillips_amplitude,
                      .cutoff_length = cutoff_length,
                      .depth_factor = depth_factor,
                      .fetch_law = fetch_law,
                      .normalization = normalization};
    if (gamma && std::holds_alternative<double>(*gamma)) {
      in.gamma = std::get<double>(*gamma);
    } else if (gamma && std::get<std::string>(*gamma) != "auto") {
      // Text other than 'auto' is read as the flag's text is.
      in.gamma = take(params::parse_number("--gamma", std::get<std::string>(*gamma)));
    }
    return take(resolve(in));
  }
};

FrequencySpectrum make_spectrum(const SeaKeywords& kw) {
  return take(FrequencySpectrum::make(kw.params()));
}

// The values every ω must take, as `ocean spectrum --omega` checks them.
void check_omegas(const DoubleArray& omega) {
  constexpr params::NumberOption<double> kOmega{.flag = "--omega",
                                                .accept = params::Accept::non_negative};
  for (py::ssize_t i = 0; i < omega.size(); ++i) {
    const double w = omega.data()[i];
    check(params::check(kOmega, w, format_number(w)));
  }
}

DoubleArray spectrum(const SeaKeywords& kw, const DoubleArray& omega) {
  const FrequencySpectrum s = make_spectrum(kw);
  check_omegas(omega);
  return map_values(omega, [&](double w) { return s(w); });
}

py::dict spectrum_info(const SeaKeywords& kw) {
  const FrequencySpectrum s = make_spectrum(kw);
  py::dict d;
  d["model"] = std::string(to_string(s.params().model));
  d["peak_omega"] = s.peak_omega();
  d["peak_period_s"] = 2.0 * kPi / s.peak_omega();
  d["gamma"] = s.gamma();
  d["alpha"] = s.alpha();
  d["hs_m"] = s.hs_m();
  d["m0"] = s.moment(0);
  d["m1"] = s.moment(1);
  d["m2"] = s.moment(2);
  return d;
}

// `ocean dispersion`: exactly one of k and ω; the others computed on the relation's domain.
py::dict dispersion(std::optional<DoubleArray> k, std::optional<DoubleArray> omega,
                    OptionalNumber depth, OptionalNumber gravity, bool capillary) {
  if (k.has_value() == omega.has_value())
    raise(invalid_argument("dispersion needs exactly one of --k K1,... or --omega W1,..."));
  DispersionParams params;
  if (depth) params.depth_m = *depth;
  if (gravity) params.gravity_mps2 = *gravity;
  if (capillary) params.capillarity_m3ps2 = kSeaWaterCapillarity;
  const Dispersion d = take(Dispersion::make(params));
  const DoubleArray& in = k ? *k : *omega;
  for (py::ssize_t i = 0; i < in.size(); ++i) {
    const double v = in.data()[i];
    check(k ? Dispersion::check_wavenumber("--k", v) : d.check_omega("--omega", v));
  }
  const DoubleArray kk = k ? *k : map_values(in, [&](double w) { return d.wavenumber(w); });
  py::dict out;
  out["k"] = kk;
  out["omega"] = omega ? *omega : map_values(kk, [&](double x) { return d.omega(x); });
  out["group_velocity"] = map_values(kk, [&](double x) { return d.group_velocity(x); });
  out["phase_velocity"] = map_values(kk, [&](double x) { return d.phase_velocity(x); });
  out["wavelength_m"] = map_values(kk, [](double x) { return 2.0 * kPi / x; });
  return out;
}

// `ocean spreading`: D(θ) at ω = omega_ratio·ωp, ωp from wind and fetch when given.
DoubleArray spreading(const DoubleArray& theta, const std::string& model, OptionalNumber s,
                      OptionalNumber alpha, bool symmetric, double omega_ratio,
                      OptionalNumber wind_speed, OptionalNumber fetch) {
  Result<SpreadingModel> m = parse_spreading_model(model);
  if (!m.ok()) raise(Status(m.status().code(), "--model: " + m.status().message()));
  SpreadingParams params{.model = m.value()};
  params.counter_wave_suppression = !symmetric;
  // NaN is no number to the tool's parser (params::parse_number), which refuses it as not finite.
  if (s && std::isnan(*s)) check(require_finite("--s", *s));
  if (alpha && std::isnan(*alpha)) check(require_finite("--alpha", *alpha));
  if (s) params.s = *s;
  if (alpha) params.alpha = *alpha;
  constexpr params::NumberOption<double> kOmegaRatio{.flag = "--omega-ratio",
                                                     .accept = params::Accept::positive};
  constexpr params::ParameterDoc wind = sea_state_parameter("wind_speed_mps");
  constexpr params::ParameterDoc fetch_range = sea_state_parameter("fetch_m");
  constexpr params::NumberOption<double> kWindSpeed{
      .flag = wind.flag, .accept = params::Accept::in_range, .lo = wind.lo, .hi = wind.hi};
  constexpr params::NumberOption<double> kFetch{.flag = fetch_range.flag,
                                                .accept = params::Accept::in_range,
                                                .lo = fetch_range.lo,
                                                .hi = fetch_range.hi};
  constexpr params::NumberOption<double> kTheta{.flag = "--theta",
                                                .accept = params::Accept::finite};
  check(params::check(kOmegaRatio, omega_ratio, format_number(omega_ratio)));
  SpreadingContext context{.omega_p = 1.0};
  if (wind_speed.has_value() != fetch.has_value())
    raise(invalid_argument("--wind-speed and --fetch must be given together"));
  if (wind_speed) {
    check(params::check(kWindSpeed, *wind_speed, format_number(*wind_speed)));
    check(params::check(kFetch, *fetch, format_number(*fetch)));
    context.wind_speed_mps = *wind_speed;
    context.omega_p =
        jonswap_fetch_law(*wind_speed, *fetch, kDefaultGravity, FetchLaw::hasselmann_1973)[1];
  } else if (params.model == SpreadingModel::mitsuyasu ||
             params.model == SpreadingModel::hasselmann) {
    raise(invalid_argument(std::string(to_string(params.model)) +
                           " spreading needs --wind-speed MPS --fetch M"));
  }
  const Spreading d = take(Spreading::make(params, context));
  for (py::ssize_t i = 0; i < theta.size(); ++i) {
    const double t = theta.data()[i];
    check(params::check(kTheta, t, format_number(t)));
  }
  const double omega = omega_ratio * context.omega_p;
  return map_values(theta, [&](double t) { return d(omega, t); });
}

// Kitaigorodskii's depth factor Φ(ω, h) of TMA, exact or Thompson–Vincent.
DoubleArray depth_factor(const DoubleArray& omega, double depth, double gravity,
                         const std::string& method) {
  const std::optional<DepthFactor> factor = value_of(kDepthFactorNames, method);
  if (!factor) {
    raise(invalid_argument("--depth-factor = '" + excerpt(method) + "' is unknown: must be " +
                           name_list(kDepthFactorNames, ", ", " or ")));
  }
  take(Dispersion::make({.gravity_mps2 = gravity, .depth_m = depth}));
  check_omegas(omega);
  return map_values(omega, [&](double w) { return tma_depth_factor(w, depth, gravity, *factor); });
}

// The numpy-style Parameters entries of the sea-state keywords (spectrum, spectrum_info).
const std::string kSeaKeywordsDoc = R"doc(model : str, optional
    pierson-moskowitz, jonswap (default), tma or phillips.
hs, tp : float, optional
    Significant wave height Hs, m, and peak period Tp, s, given together.
wind_speed : float, optional
    U10, m/s (U19.5 for pierson-moskowitz); with fetch for jonswap and tma.
fetch : float, optional
    Fetch F, m.
gamma : float or 'auto', optional
    JONSWAP peak enhancement, >= 1; 'auto' or None: from the sea state.
depth : float, optional
    Water depth of tma, m; None: deep water.
gravity : float, optional
    g, m/s^2; None: 9.81.
depth_factor : str, optional
    tma's depth factor: 'exact' or 'thompson-vincent'.
fetch_law : str, optional
    How fetch sets the peak: 'hasselmann' (2 pi 3.5 (g/U)(gF/U^2)^-0.33) or 'cube-root'
    (22 (g^2/(U F))^(1/3)).
normalization : str, optional
    JONSWAP's Hs/Tp normalisation: 'dnv' (1 - 0.287 ln gamma) or 'exact'.
phillips_amplitude : float, optional
    The Phillips amplitude A, dimensionless; None: Hs of Pierson-Moskowitz.
cutoff_length : float, optional
    The Phillips small-wave cutoff length l, m (factor exp(-k^2 l^2)).
)doc";

// The sea-state keywords, in the order and with the defaults of `ocean spectrum`'s flags.
template <class F>
void def_with_sea(py::module_& m, const char* name, F&& f, const char* doc) {
  m.def(name, std::forward<F>(f), py::arg("model") = "jonswap", py::kw_only(),
        py::arg("hs") = py::none(), py::arg("tp") = py::none(), py::arg("wind_speed") = py::none(),
        py::arg("fetch") = py::none(), py::arg("gamma") = py::none(), py::arg("depth") = py::none(),
        py::arg("gravity") = py::none(), py::arg("depth_factor") = "exact",
        py::arg("fetch_law") = "hasselmann", py::arg("normalization") = "dnv",
        py::arg("phillips_amplitude") = py::none(), py::arg("cutoff_length") = py::none(), doc);
}

}  // namespace

void bind_spectrum(py::module_& m) {
  m.attr("DEFAULT_WIND_SPEED_MPS") = kDefaultWindSpeedMps;
  m.attr("DEFAULT_FETCH_M") = kDefaultFetchM;
  m.def(
      "spectrum",
      [](const std::string& model, const DoubleArray& omega, OptionalNumber hs, OptionalNumber tp,
         OptionalNumber wind_speed, OptionalNumber fetch, NumberOrName gamma, OptionalNumber depth,
         OptionalNumber gravity, const std::string& depth_factor, const std::string& fetch_law,
         const std::string& normalization, OptionalNumber phillips_amplitude,
         OptionalNumber cutoff_length) {
        return spectrum({model, hs, tp, wind_speed, fetch, gamma, depth, gravity, depth_factor,
                         fetch_law, normalization, phillips_amplitude, cutoff_length},
                        omega);
      },
      py::arg("model") = "jonswap", py::kw_only(), py::arg("omega"), py::arg("hs") = py::none(),
      py::arg("tp") = py::none(), py::arg("wind_speed") = py::none(), py::arg("fetch") = py::none(),
      py::arg("gamma") = py::none(), py::arg("depth") = py::none(), py::arg("gravity") = py::none(),
      py::arg("depth_factor") = "exact", py::arg("fetch_law") = "hasselmann",
      py::arg("normalization") = "dnv", py::arg("phillips_amplitude") = py::none(),
      py::arg("cutoff_length") = py::none(),
      (std::string(R"doc(One-sided frequency spectrum S(omega) at every omega of an array of any shape.

With no sea state given, the default wind sea (DEFAULT_WIND_SPEED_MPS over DEFAULT_FETCH_M).
The keywords are the flags of `ocean spectrum`; a bad value raises ValueError naming it.

Parameters
----------
omega : array_like of float
    Angular frequencies, rad/s, finite and >= 0.
)doc") + kSeaKeywordsDoc + R"doc(
Returns
-------
numpy.ndarray
    S(omega), m^2 s/rad, shaped like omega.)doc")
          .c_str());
  def_with_sea(
      m, "spectrum_info",
      [](const std::string& model, OptionalNumber hs, OptionalNumber tp, OptionalNumber wind_speed,
         OptionalNumber fetch, NumberOrName gamma, OptionalNumber depth, OptionalNumber gravity,
         const std::string& depth_factor, const std::string& fetch_law,
         const std::string& normalization, OptionalNumber phillips_amplitude,
         OptionalNumber cutoff_length) {
        return spectrum_info({model, hs, tp, wind_speed, fetch, gamma, depth, gravity, depth_factor,
                              fetch_law, normalization, phillips_amplitude, cutoff_length});
      },
      (std::string(R"doc(The spectrum's derived constants.

Parameters
----------
)doc") + kSeaKeywordsDoc + R"doc(
Returns
-------
dict
    model, peak_omega (rad/s), peak_period_s, gamma, alpha, hs_m (4 sqrt(m0)) and the moments
    m0, m1, m2.)doc")
          .c_str());
  m.def("dispersion", &dispersion, py::kw_only(), py::arg("k") = py::none(),
        py::arg("omega") = py::none(), py::arg("depth") = py::none(),
        py::arg("gravity") = py::none(), py::arg("capillary") = false,
        R"doc(Finite-depth dispersion omega^2 = (g k + T k^3) tanh(k h), solved either way.

Parameters
----------
k : array_like of float, optional
    Wavenumbers, rad/m (exactly one of k and omega).
omega : array_like of float, optional
    Angular frequencies, rad/s.
depth : float, optional
    Water depth h, m; None: deep water.
gravity : float, optional
    g, m/s^2; None: 9.81.
capillary : bool, optional
    Add sea water's surface tension T.

Returns
-------
dict of str to numpy.ndarray
    k, omega, group_velocity, phase_velocity (m/s) and wavelength_m, shaped like the input.)doc");
  m.def("spreading", &spreading, py::arg("theta"), py::kw_only(),
        py::arg("model") = "donelan-banner", py::arg("s") = py::none(),
        py::arg("alpha") = py::none(), py::arg("symmetric") = false, py::arg("omega_ratio") = 1.0,
        py::arg("wind_speed") = py::none(), py::arg("fetch") = py::none(),
        R"doc(Directional spreading D(theta), normalised over (-pi, pi].

Parameters
----------
theta : array_like of float
    Angles from the mean direction, rad.
model : str, optional
    power-cosine, cos2s, mitsuyasu, hasselmann or donelan-banner (default).
s : float, optional
    The exponent: power-cosine |cos|^s, cos2s cos^2s(theta/2).
alpha : float, optional
    power-cosine's wind alignment in [0, 1]: s = 1 + 5 alpha^2, counter-wave energy
    0.01 + 0.49 (1 - alpha)^2.
symmetric : bool, optional
    power-cosine without counter-wave suppression (Tessendorf's |k.w|^s).
omega_ratio : float, optional
    omega / omega_p.
wind_speed, fetch : float, optional
    U10, m/s, and fetch, m, of mitsuyasu and hasselmann.

Returns
-------
numpy.ndarray
    D(theta), 1/rad, shaped like theta.)doc");
  m.def("depth_factor", &depth_factor, py::arg("omega"), py::kw_only(), py::arg("depth"),
        py::arg("gravity") = kDefaultGravity, py::arg("method") = "exact",
        R"doc(Kitaigorodskii's depth factor Phi(omega, h) of the TMA spectrum.

Parameters
----------
omega : array_like of float
    Angular frequencies, rad/s, finite and >= 0.
depth : float
    Water depth h, m.
gravity : float, optional
    g, m/s^2.
method : str, optional
    'exact' or 'thompson-vincent' (the approximation).

Returns
-------
numpy.ndarray
    Phi, between 0 and 1, shaped like omega.)doc");
}

}  // namespace ocean::python
