// Simulation presets (see preset.hpp).
#include "preset.hpp"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "builtin_presets.hpp"

namespace ocean::cli {

namespace {

using Json = nlohmann::ordered_json;

Json number_or_null(double v) { return std::isnan(v) ? Json(nullptr) : Json(v); }

std::string_view fetch_law_name(FetchLaw law) {
  return law == FetchLaw::hasselmann_1973 ? "hasselmann" : "cube-root";
}

Json wave_system_json(const WaveSystemParams& w) {
  const FrequencySpectrumParams& s = w.spectrum;
  return Json{
      {"model", to_string(s.model)},
      {"wind_speed_mps", number_or_null(s.wind_speed_mps)},
      {"fetch_m", number_or_null(s.fetch_m)},
      {"hs_m", number_or_null(s.significant_wave_height_m)},
      {"tp_s", number_or_null(s.peak_period_s)},
      {"gamma", std::isnan(s.gamma) ? Json("auto") : Json(s.gamma)},
      {"fetch_law", fetch_law_name(s.fetch_law)},
      {"normalization", s.normalization == JonswapNormalization::dnv ? "dnv" : "exact"},
      {"depth_m", std::isinf(s.depth_m) ? Json(nullptr) : Json(s.depth_m)},
      {"depth_factor", s.depth_factor == DepthFactor::exact ? "exact" : "thompson-vincent"},
      {"phillips_amplitude", number_or_null(s.phillips_amplitude)},
      {"cutoff_length_m", s.small_wave_cutoff_m},
      {"direction_deg", w.direction_rad * 180.0 / kPi},
      {"spreading", Json{{"model", to_string(w.spreading.model)},
                         {"s", number_or_null(w.spreading.s)},
                         {"alpha", w.spreading.alpha},
                         {"counter_wave_suppression", w.spreading.counter_wave_suppression}}}};
}

// Reads the keys of one JSON object, rejecting unknown keys and wrong types.
class ObjectReader {
 public:
  ObjectReader(const Json& object, std::string path) : object_(object), path_(std::move(path)) {
    if (!object_.is_object()) error_ = invalid_argument(where() + ": expected an object");
  }
  // Numbers; null leaves `out` unset (NaN) when allow_null.
  void number(const char* key, double& out, bool allow_null = false) {
    const Json* v = find(key);
    if (v == nullptr) return;
    if (v->is_null() && allow_null) {
      out = kUnset;
    } else if (v->is_number()) {
      out = v->get<double>();
    } else {
      fail(key, "expected a number");
    }
  }
  void integer(const char* key, long long& out) {
    const Json* v = find(key);
    if (v == nullptr) return;
    if (v->is_number_integer() || v->is_number_unsigned()) {
      out = v->get<long long>();
    } else {
      fail(key, "expected an integer");
    }
  }
  void boolean(const char* key, bool& out) {
    const Json* v = find(key);
    if (v == nullptr) return;
    if (v->is_boolean())
      out = v->get<bool>();
    else
      fail(key, "expected true or false");
  }
  void string(const char* key, std::string& out) {
    const Json* v = find(key);
    if (v == nullptr) return;
    if (v->is_string())
      out = v->get<std::string>();
    else
      fail(key, "expected a string");
  }
  const Json* child(const char* key) { return find(key); }
  [[nodiscard]] std::string path_of(const char* key) const { return join(key); }
  void fail(const char* key, const std::string& what) {
    if (error_.ok()) error_ = invalid_argument(join(key) + ": " + what + ", got " + type_of(key));
  }
  void adopt(const Status& s) {
    if (error_.ok() && !s.ok()) error_ = s;
  }
  Status finish() {
    if (!error_.ok() || !object_.is_object()) return error_;
    for (const auto& [key, value] : object_.items()) {
      if (!seen_.contains(key)) return invalid_argument(join(key.c_str()) + ": unknown key");
    }
    return error_;
  }

 private:
  const Json* find(const char* key) {
    seen_.insert(key);
    if (!object_.is_object()) return nullptr;
    const auto it = object_.find(key);
    return it == object_.end() ? nullptr : &*it;
  }
  std::string join(const char* key) const { return path_.empty() ? key : path_ + "." + key; }
  std::string where() const { return path_.empty() ? "the document" : path_; }
  std::string type_of(const char* key) const {
    const auto it = object_.find(key);
    return it == object_.end() ? "nothing" : std::string("a ") + it->type_name();
  }
  const Json& object_;
  std::string path_;
  std::set<std::string> seen_;
  Status error_;
};

Status read_wave_system(const Json& doc, const std::string& path, WaveSystemParams& w) {
  ObjectReader r(doc, path);
  FrequencySpectrumParams& s = w.spectrum;
  std::string model(to_string(s.model));
  r.string("model", model);
  Result<SpectrumModel> m = parse_spectrum_model(model);
  if (!m.ok()) return invalid_argument(r.path_of("model") + ": " + m.status().message());
  s.model = m.value();
  r.number("wind_speed_mps", s.wind_speed_mps, true);
  r.number("fetch_m", s.fetch_m, true);
  r.number("hs_m", s.significant_wave_height_m, true);
  r.number("tp_s", s.peak_period_s, true);
  if (const Json* g = r.child("gamma")) {
    if (g->is_string() && g->get<std::string>() == "auto")
      s.gamma = kUnset;
    else if (g->is_number())
      s.gamma = g->get<double>();
    else
      r.fail("gamma", "expected a number or \"auto\"");
  }
  std::string fetch_law(fetch_law_name(s.fetch_law)), normalization = "dnv", depth_factor = "exact";
  if (s.normalization == JonswapNormalization::exact) normalization = "exact";
  if (s.depth_factor == DepthFactor::thompson_vincent) depth_factor = "thompson-vincent";
  r.string("fetch_law", fetch_law);
  r.string("normalization", normalization);
  r.string("depth_factor", depth_factor);
  if (const Json* d = r.child("depth_m")) {
    if (d->is_null())
      s.depth_m = kInfiniteDepth;
    else if (d->is_number())
      s.depth_m = d->get<double>();
    else
      r.fail("depth_m", "expected a number or null (deep water)");
  }
  r.number("phillips_amplitude", s.phillips_amplitude, true);
  r.number("cutoff_length_m", s.small_wave_cutoff_m);
  double direction_deg = w.direction_rad * 180.0 / kPi;
  r.number("direction_deg", direction_deg);
  w.direction_rad = direction_deg * kPi / 180.0;
  if (const Json* spreading = r.child("spreading")) {
    ObjectReader sr(*spreading, r.path_of("spreading"));
    std::string sm(to_string(w.spreading.model));
    sr.string("model", sm);
    Result<SpreadingModel> parsed = parse_spreading_model(sm);
    if (!parsed.ok())
      return invalid_argument(sr.path_of("model") + ": " + parsed.status().message());
    w.spreading.model = parsed.value();
    sr.number("s", w.spreading.s, true);
    sr.number("alpha", w.spreading.alpha);
    sr.boolean("counter_wave_suppression", w.spreading.counter_wave_suppression);
    r.adopt(sr.finish());
  }
  if (fetch_law == "hasselmann")
    s.fetch_law = FetchLaw::hasselmann_1973;
  else if (fetch_law == "cube-root")
    s.fetch_law = FetchLaw::cube_root;
  else
    r.fail("fetch_law", "expected \"hasselmann\" or \"cube-root\"");
  if (normalization == "dnv")
    s.normalization = JonswapNormalization::dnv;
  else if (normalization == "exact")
    s.normalization = JonswapNormalization::exact;
  else
    r.fail("normalization", "expected \"dnv\" or \"exact\"");
  if (depth_factor == "exact")
    s.depth_factor = DepthFactor::exact;
  else if (depth_factor == "thompson-vincent")
    s.depth_factor = DepthFactor::thompson_vincent;
  else
    r.fail("depth_factor", "expected \"exact\" or \"thompson-vincent\"");
  return r.finish();
}

}  // namespace

nlohmann::ordered_json to_json(const SimulationConfig& c) {
  Json sea{{"wind_sea", wave_system_json(c.sea.wind_sea)},
           {"swell", c.sea.has_swell ? wave_system_json(c.sea.swell) : Json(nullptr)},
           {"gravity_mps2", c.sea.dispersion.gravity_mps2}};
  return Json{{"sea", sea},
              {"resolution", c.resolution},
              {"cascades_m", c.cascade_patch_sizes_m},
              {"choppiness", c.choppiness},
              {"loop_period_s", c.loop_period_s},
              {"seed", c.seed},
              {"normals", to_string(c.normals)},
              {"roughness", c.roughness},
              {"blue_channel", c.blue_channel == BlueChannel::foam ? "foam" : "jacobian"},
              {"foam", Json{{"jacobian_start", c.foam.jacobian_start},
                            {"jacobian_full", c.foam.jacobian_full},
                            {"decay_per_s", c.foam.decay_per_s}}}};
}

Result<SimulationConfig> from_json(const nlohmann::ordered_json& document) {
  SimulationConfig c;
  ObjectReader r(document, "");
  if (const Json* sea = r.child("sea")) {
    ObjectReader sr(*sea, "sea");
    if (const Json* wind = sr.child("wind_sea")) {
      if (Status s = read_wave_system(*wind, "sea.wind_sea", c.sea.wind_sea); !s.ok()) return s;
    }
    if (const Json* swell = sr.child("swell"); swell != nullptr && !swell->is_null()) {
      c.sea.has_swell = true;
      c.sea.swell.spectrum = {.model = SpectrumModel::jonswap};
      c.sea.swell.spreading = {.model = SpreadingModel::cos2s, .s = 20.0};
      if (Status s = read_wave_system(*swell, "sea.swell", c.sea.swell); !s.ok()) return s;
    }
    double gravity = c.sea.dispersion.gravity_mps2;
    sr.number("gravity_mps2", gravity);
    c.sea.dispersion.gravity_mps2 = gravity;
    c.sea.wind_sea.spectrum.gravity_mps2 = gravity;
    c.sea.swell.spectrum.gravity_mps2 = gravity;
    if (Status s = sr.finish(); !s.ok()) return s;
  }
  long long resolution = c.resolution, seed = static_cast<long long>(c.seed);
  r.integer("resolution", resolution);
  r.integer("seed", seed);
  if (resolution < 0 || resolution > 1 << 20) resolution = -1;
  c.resolution = static_cast<int>(resolution);
  if (seed < 0)
    return invalid_argument("seed = " + std::to_string(seed) + " is out of range: must be >= 0");
  c.seed = static_cast<std::uint64_t>(seed);
  if (const Json* cascades = r.child("cascades_m")) {
    if (!cascades->is_array())
      return invalid_argument("cascades_m: expected an array of patch sizes in metres");
    c.cascade_patch_sizes_m.clear();
    for (const Json& v : *cascades) {
      if (!v.is_number())
        return invalid_argument("cascades_m: expected numbers, got a " +
                                std::string(v.type_name()));
      c.cascade_patch_sizes_m.push_back(v.get<double>());
    }
  }
  r.number("choppiness", c.choppiness);
  r.number("loop_period_s", c.loop_period_s);
  r.number("roughness", c.roughness);
  std::string normals(to_string(c.normals)), blue = "foam";
  r.string("normals", normals);
  r.string("blue_channel", blue);
  if (const Json* foam = r.child("foam")) {
    ObjectReader fr(*foam, "foam");
    fr.number("jacobian_start", c.foam.jacobian_start);
    fr.number("jacobian_full", c.foam.jacobian_full);
    fr.number("decay_per_s", c.foam.decay_per_s);
    r.adopt(fr.finish());
  }
  if (Status s = r.finish(); !s.ok()) return s;
  Result<NormalMethod> method = parse_normal_method(normals);
  if (!method.ok()) return method.status();
  c.normals = method.value();
  if (blue == "foam")
    c.blue_channel = BlueChannel::foam;
  else if (blue == "jacobian")
    c.blue_channel = BlueChannel::jacobian;
  else
    return invalid_argument("blue_channel = '" + blue + "' is unknown: must be foam or jacobian");
  if (Status s = validate(c); !s.ok()) return s;
  if (Result<SeaState> sea = SeaState::make(c.sea); !sea.ok()) return sea.status();
  return c;
}

void add_simulation_flags(CLI::App& command, SimulationFlags& f) {
  command.add_option("--preset", f.preset_path,
                     "calm, moderate, storm or a preset JSON file (see presets/)");
  command.add_option("--set", f.set, "override a preset key: --set sea.wind_sea.fetch_m=5e4");
  add_spectrum_flags(command, f.sea);
  command.add_option("--resolution", f.resolution,
                     "grid size N per cascade (power of two, 16-2048)");
  command.add_option("--seed", f.seed, "random seed (integer)");
  command.add_option("--choppiness", f.choppiness, "horizontal displacement lambda >= 0");
  command.add_option("--cascades", f.cascades, "patch sizes L1,L2,... in metres, largest first");
  command.add_option("--normals", f.normals, "central-difference | analytic | sobel");
  command.add_option("--loop-period", f.loop_period, "loop period T, s (0 = no loop)");
}

namespace {

Result<Json> read_preset(const std::filesystem::path& path) {
  // A bare name that is not a file selects a compiled-in preset.
  std::error_code ec;
  if (!path.has_parent_path() && !path.has_extension() && !std::filesystem::exists(path, ec)) {
    for (const BuiltinPreset& p : builtin_presets()) {
      if (path.string() == p.name) return Json::parse(p.json);
    }
    return invalid_argument("--preset = " + path.string() +
                            " is neither a file nor a preset: must be calm, moderate, storm or "
                            "a JSON file");
  }
  std::ifstream in(path);
  if (!in) {
    return io_error("cannot read preset '" + path.string() + "': " + std::strerror(errno));
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  Json doc = Json::parse(buffer.str(), nullptr, false);
  if (doc.is_discarded()) {
    return invalid_argument("preset '" + path.string() + "' is not valid JSON");
  }
  return doc;
}

Status apply_set(Json& doc, const std::string& assignment) {
  const std::size_t eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    return invalid_argument("--set '" + assignment + "': expected key=value");
  }
  const std::string key = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  Json value = Json::parse(text, nullptr, false);
  if (value.is_discarded()) value = text;  // a bare string: --set normals=analytic
  Json* node = &doc;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = key.find('.', start);
    const std::string part =
        key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (part.empty()) return invalid_argument("--set '" + assignment + "': empty key part");
    if (!node->is_object())
      return invalid_argument("--set " + key + ": '" + part + "' is not inside an object");
    if (dot == std::string::npos) {
      (*node)[part] = value;
      return {};
    }
    Json& next = (*node)[part];
    if (next.is_null()) next = Json::object();
    node = &next;
    start = dot + 1;
  }
}

}  // namespace

Result<SimulationConfig> resolve_config(const SimulationFlags& f) {
  Json doc = to_json(SimulationConfig{});
  if (!f.preset_path.empty()) {
    Result<Json> preset = read_preset(f.preset_path);
    if (!preset.ok()) return preset.status();
    doc.merge_patch(preset.value());
  }
  for (const std::string& assignment : f.set) {
    if (Status s = apply_set(doc, assignment); !s.ok()) return s;
  }
  Result<SimulationConfig> parsed = from_json(doc);
  if (!parsed.ok()) return parsed.status();
  SimulationConfig c = std::move(parsed).value();
  // Explicit sea-state flags replace the preset's wind sea.
  const SpectrumFlags& s = f.sea;
  const bool any_sea_flag = !s.hs.empty() || !s.tp.empty() || !s.wind_speed.empty() ||
                            !s.fetch.empty() || !s.gamma.empty() || !s.depth.empty() ||
                            s.model != SpectrumFlags{}.model;
  if (any_sea_flag) {
    Result<FrequencySpectrumParams> spectrum = to_params(s);
    if (!spectrum.ok()) return spectrum.status();
    c.sea.wind_sea.spectrum = spectrum.value();
    c.sea.dispersion.gravity_mps2 = spectrum.value().gravity_mps2;
    c.sea.dispersion.depth_m = kInfiniteDepth;
  }
  const std::pair<const std::string*, const char*> numbers[] = {{&f.choppiness, "--choppiness"},
                                                                {&f.loop_period, "--loop-period"}};
  for (const auto& [text, flag] : numbers) {
    if (text->empty()) continue;
    Result<double> v = parse_number(flag, *text);
    if (!v.ok()) return v.status();
    (text == &f.choppiness ? c.choppiness : c.loop_period_s) = v.value();
  }
  if (!f.resolution.empty()) {
    Result<double> v = parse_number("--resolution", f.resolution);
    if (!v.ok()) return v.status();
    if (v.value() != std::floor(v.value()) || std::abs(v.value()) > 1e6) {
      return invalid_argument("--resolution = " + f.resolution +
                              " is out of range: must be a power of two in [16, 2048]");
    }
    c.resolution = static_cast<int>(v.value());
  }
  if (!f.seed.empty()) {
    Result<double> v = parse_number("--seed", f.seed);
    if (!v.ok()) return v.status();
    if (v.value() < 0 || v.value() != std::floor(v.value()) || v.value() > 9e15) {
      return invalid_argument("--seed = " + f.seed + " is out of range: must be an integer >= 0");
    }
    c.seed = static_cast<std::uint64_t>(v.value());
  }
  if (!f.cascades.empty()) {
    Result<std::vector<double>> sizes = parse_number_list("--cascades", f.cascades);
    if (!sizes.ok()) return sizes.status();
    c.cascade_patch_sizes_m = sizes.value();
  }
  if (!f.normals.empty()) {
    Result<NormalMethod> m = parse_normal_method(f.normals);
    if (!m.ok()) return Status(m.status().code(), "--normals: " + m.status().message());
    c.normals = m.value();
  }
  if (Status st = validate(c); !st.ok()) return st;
  if (Result<SeaState> sea = SeaState::make(c.sea); !sea.ok()) return sea.status();
  return c;
}

}  // namespace ocean::cli
