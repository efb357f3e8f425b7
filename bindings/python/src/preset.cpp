// ocean.Preset: a preset assembled in layers (ocean/preset.hpp Document): defaults, built-in
// presets or preset files merged over them, then "key=value" overrides, as `ocean`'s --preset and
// --set flags build it (and with their labels in messages).
#include "ocean/preset.hpp"

#include <pybind11/stl.h>

#include <nlohmann/json.hpp>
#include <string>

#include "bindings.hpp"
#include "errors.hpp"
#include "integers.hpp"
#include "ocean/io.hpp"

namespace py = pybind11;

namespace ocean::python {
namespace {

// Preset.to_json's indent: 0 to 64 spaces a level, negative for one line. nlohmann::json 3.11.2
// keeps 512 spaces of indentation and doubles them once per level when a level needs more, so an
// indent above 512 reads past them; 64 is more than any reader needs.
constexpr params::NumberOption<double> kIndent{
    .flag = "indent", .lo = 0, .hi = 64, .says = "an integer in [0, 64], or negative for one line"};

// Sets every leaf of a JSON object (a value that is not an object) at its dotted key path.
void set_leaves(preset::Document& doc, const nlohmann::json& node, const std::string& prefix) {
  for (const auto& [key, value] : node.items()) {
    if (value.is_object() && !value.empty()) {
      set_leaves(doc, value, prefix + key + ".");
    } else {
      check(doc.set(prefix + key + "=" + value.dump(), "--set"));
    }
  }
}

// A preset from a document's text: its leaves set over the defaults, so that the result is the
// document itself. What unpickling and from_json do.
preset::Document from_text(const std::string& text) {
  take(preset::from_json(text));  // the document's own checks and messages first
  preset::Document doc;
  set_leaves(doc, nlohmann::json::parse(text), "");
  take(doc.config());
  return doc;
}

}  // namespace

SimulationConfig config_of(const py::object& preset) {
  if (preset.is_none()) return SimulationConfig{};
  if (py::isinstance<preset::Document>(preset))
    return take(preset.cast<const preset::Document&>().config());
  preset::Document doc;
  check(doc.merge_preset(py::str(preset).cast<std::string>(), "--preset"));
  return take(doc.config());
}

void bind_preset(py::module_& m) {
  py::class_<preset::Document>(m, "Preset",
                               "A simulation configuration assembled in layers: defaults, then "
                               "presets merged over them, then key=value overrides.")
      .def(py::init<>(), "The defaults (SimulationConfig{}).")
      .def(py::init([](const std::string& name_or_path) {
             preset::Document doc;
             check(doc.merge_preset(name_or_path, "--preset"));
             return doc;
           }),
           py::arg("name_or_path"),
           R"doc(The defaults with a built-in preset or a preset file merged over them.

Parameters
----------
name_or_path : str
    calm, moderate, storm, or the path of a preset file (JSON).)doc")
      .def_static("from_json", &from_text, py::arg("text"),
                  R"doc(The preset of a preset document's text (as Preset.to_json writes it).

Parameters
----------
text : str
    A preset document, possibly partial: merged over the defaults.

Returns
-------
Preset
    The preset; ValueError when the text is not a valid document.)doc")
      .def(py::pickle(
          [](const preset::Document& doc) { return preset::to_json(take(doc.config())); },
          [](const std::string& text) { return from_text(text); }))
      .def(
          "merge",
          [](preset::Document& doc, const std::string& name_or_path) -> preset::Document& {
            check(doc.merge_preset(name_or_path, "--preset"));
            return doc;
          },
          py::arg("name_or_path"), py::return_value_policy::reference_internal,
          R"doc(Merges a built-in preset or a preset file over this one (RFC 7386 merge patch).

Parameters
----------
name_or_path : str
    calm, moderate, storm, or the path of a preset file (JSON).

Returns
-------
Preset
    self.)doc")
      .def(
          "set",
          [](preset::Document& doc, const std::string& assignment) -> preset::Document& {
            // Tried on a copy: a failed assignment leaves the preset as it was.
            preset::Document trial = doc;
            check(trial.set(assignment, "--set"));
            take(trial.config());
            doc = std::move(trial);
            return doc;
          },
          py::arg("assignment"), py::return_value_policy::reference_internal,
          R"doc(Sets one key; the result must be a valid configuration.

Parameters
----------
assignment : str
    'dotted.key=value', the value JSON or a bare word, e.g. 'sea.wind_sea.wind_speed_mps=12'.

Returns
-------
Preset
    self; on ValueError the preset is unchanged.)doc")
      .def(
          "validate", [](const preset::Document& doc) { take(doc.config()); },
          "Raises ValueError when the layers do not make a valid configuration.")
      .def(
          "to_json",
          [](const preset::Document& doc, const Integer& indent) {
            const int spaces = indent.value < 0 ? -1 : static_cast<int>(in_range(indent, kIndent));
            return preset::to_json(take(doc.config()), spaces);
          },
          py::arg("indent") = 2,
          R"doc(The preset document: every key, in a fixed order.

Parameters
----------
indent : int, optional
    Spaces a level, 0 to 64 (ValueError beyond); a negative indent writes one line.

Returns
-------
str
    The JSON text.)doc")
      .def(
          "save",
          [](const preset::Document& doc, const std::string& path) {
            const std::string text = preset::to_json(take(doc.config()), 2) + "\n";
            check(io::write_bytes_atomically(path, {std::as_bytes(std::span(text))}));
          },
          py::arg("path"),
          R"doc(Writes the preset document to a file, atomically.

Parameters
----------
path : str or os.PathLike
    The file; OSError when it cannot be written (nothing half-written is left).)doc")
      .def_static(
          "builtin_names",
          [] {
            std::vector<std::string> names;
            for (std::string_view n : preset::builtin_names()) names.emplace_back(n);
            return names;
          },
          R"doc(The built-in presets.

Returns
-------
list of str
    calm, moderate, storm.)doc")
      .def("__repr__", [](const preset::Document& doc) {
        Result<SimulationConfig> c = doc.config();
        return c.ok() ? "ocean.Preset(" + preset::to_json(c.value()) + ")"
                      : "ocean.Preset(<invalid: " + c.status().message() + ">)";
      });
}

}  // namespace ocean::python
