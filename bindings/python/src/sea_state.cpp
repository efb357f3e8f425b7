// ocean.SeaState: the wave systems of a preset (wind sea and optional swell) with their
// wave-vector spectrum F(kx, kz) (ocean/spectrum.hpp SeaState, docs/math.md M.5.1).
#include <pybind11/stl.h>

#include <cmath>
#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "errors.hpp"
#include "ocean/plan.hpp"

namespace py = pybind11;

namespace ocean::python {

void bind_sea_state(py::module_& m) {
  py::class_<SeaState>(m, "SeaState",
                       "The sea of a preset: wave systems (wind sea, swell) and dispersion.")
      .def(py::init([](const py::object& preset) {
             return SeaState(take(SimulationPlan::make(config_of(preset))).sea());
           }),
           py::arg("preset") = py::none(),
           R"doc(The sea of a preset.

Parameters
----------
preset : Preset, str or None, optional
    An ocean.Preset, a built-in name or a preset file; None: the defaults.)doc")
      .def(
          "wave_vector_spectrum",
          [](const SeaState& s, const DoubleArray& kx, const DoubleArray& kz) {
            if (kx.ndim() != kz.ndim() ||
                !std::equal(kx.shape(), kx.shape() + kx.ndim(), kz.shape())) {
              raise(invalid_argument("kx and kz must have one shape"));
            }
            DoubleArray f = empty_like(kx);
            for (py::ssize_t i = 0; i < kx.size(); ++i) {
              const double x = kx.data()[i];
              const double z = kz.data()[i];
              check(require_finite("kx", x));
              check(require_finite("kz", z));
              f.mutable_data()[i] = s.wave_vector_spectrum(x, z);
            }
            return f;
          },
          py::arg("kx"), py::arg("kz"),
          R"doc(The wave-vector spectrum F(kx, kz), summed over the wave systems.

Parameters
----------
kx, kz : array_like of float
    Wave-vector components, rad/m, of one shape.

Returns
-------
numpy.ndarray
    F, m^4: the height variance per unit wave-vector area, shaped like kx.)doc")
      .def_property_readonly("variance_m2", &SeaState::variance_m2, "m0 of all systems, m^2.")
      .def_property_readonly(
          "hs_m", [](const SeaState& s) { return 4.0 * std::sqrt(s.variance_m2()); },
          "Significant wave height 4 sqrt(m0), m.")
      .def_property_readonly(
          "systems",
          [](const SeaState& s) {
            py::list out;
            for (const WaveSystem& w : s.systems()) {
              py::dict d;
              d["model"] = std::string(to_string(w.spectrum().params().model));
              d["spreading"] = std::string(to_string(w.spreading().params().model));
              d["direction_rad"] = w.direction_rad();
              d["peak_omega"] = w.spectrum().peak_omega();
              d["hs_m"] = w.spectrum().hs_m();
              d["gamma"] = w.spectrum().gamma();
              out.append(d);
            }
            return out;
          },
          "One dict per wave system: model, spreading, direction_rad, peak_omega, hs_m, gamma.");
}

}  // namespace ocean::python
