// The preset format: SimulationConfig ⇄ JSON document (see ocean/preset.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "json_format.hpp"
#include "object_reader.hpp"
#include "ocean/plan.hpp"
#include "ocean/preset.hpp"

namespace ocean::preset {

namespace detail {

namespace {

Json number_or_null(double v) { return std::isnan(v) ? Json(nullptr) : Json(v); }

Json wave_system_json(const WaveSystemParams& w) {
  const FrequencySpectrumParams& s = w.spectrum;
  return Json{
      {"model", to_string(s.model)},
      {"wind_speed_mps", number_or_null(s.wind_speed_mps)},
      {"fetch_m", number_or_null(s.fetch_m)},
      {"hs_m", number_or_null(s.significant_wave_height_m)},
      {"tp_s", number_or_null(s.peak_period_s)},
      {"gamma", std::isnan(s.gamma) ? Json("auto") : Json(s.gamma)},
      {"fetch_law", name_of(kFetchLawNames, s.fetch_law)},
      {"normalization", name_of(kJonswapNormalizationNames, s.normalization)},
      {"depth_m", std::isinf(s.depth_m) ? Json(nullptr) : Json(s.depth_m)},
      {"depth_factor", name_of(kDepthFactorNames, s.depth_factor)},
      {"phillips_amplitude", number_or_null(s.phillips_amplitude)},
      {"cutoff_length_m", s.small_wave_cutoff_m},
      {"direction_deg", w.direction_rad * 180.0 / kPi},
      {"spreading", Json{{"model", to_string(w.spreading.model)},
                         {"s", number_or_null(w.spreading.s)},
                         {"alpha", w.spreading.alpha},
                         {"counter_wave_suppression", w.spreading.counter_wave_suppression}}}};
}

Status read_wave_system(const Json& doc, const std::string& path, WaveSystemParams& w) {
  ObjectReader r(doc, path);
  FrequencySpectrumParams& s = w.spectrum;
  std::string model(to_string(s.model));
  r.string("model", model);
  // The name parsers echo an unknown name through excerpt(): short and one line.
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
  std::string fetch_law(name_of(kFetchLawNames, s.fetch_law));
  std::string normalization(name_of(kJonswapNormalizationNames, s.normalization));
  std::string depth_factor(name_of(kDepthFactorNames, s.depth_factor));
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
  if (std::optional<FetchLaw> law = value_of(kFetchLawNames, fetch_law))
    s.fetch_law = *law;
  else
    r.fail("fetch_law", "expected " + name_list(kFetchLawNames, ", ", " or ", "\""));
  if (std::optional<JonswapNormalization> n = value_of(kJonswapNormalizationNames, normalization))
    s.normalization = *n;
  else
    r.fail("normalization",
           "expected " + name_list(kJonswapNormalizationNames, ", ", " or ", "\""));
  if (std::optional<DepthFactor> d = value_of(kDepthFactorNames, depth_factor))
    s.depth_factor = *d;
  else
    r.fail("depth_factor", "expected " + name_list(kDepthFactorNames, ", ", " or ", "\""));
  return r.finish();
}

}  // namespace

Json to_value(const SimulationConfig& c) {
  Json sea{{"wind_sea", wave_system_json(c.sea.wind_sea)},
           {"swell", c.sea.has_swell ? wave_system_json(c.sea.swell) : Json(nullptr)},
           {"gravity_mps2", c.sea.dispersion.gravity_mps2}};
  Json document{{"sea", sea},
                {"resolution", c.resolution},
                {"cascades_m", c.cascade_patch_sizes_m},
                {"choppiness", c.choppiness},
                {"loop_period_s", c.loop_period_s},
                {"seed", c.seed},
                {"normals", to_string(c.normals)},
                {"roughness", c.roughness},
                {"blue_channel", name_of(kBlueChannelNames, c.blue_channel)},
                {"foam", Json{{"source", name_of(kFoamSourceNames, c.foam.source)},
                              {"breaking_acceleration", c.foam.breaking_acceleration},
                              {"jacobian_start", c.foam.jacobian_start},
                              {"jacobian_full", c.foam.jacobian_full},
                              {"decay_per_s", c.foam.decay_per_s}}}};
  if (!c.band_roles.empty()) {  // written only when set: every band both otherwise
    Json roles = Json::array();
    for (BandRole role : c.band_roles) roles.push_back(std::string(to_string(role)));
    document["band_roles"] = roles;
  }
  if (c.far_noise.resolution > 0) {  // written only when on: no map otherwise
    document["far_noise"] = Json{{"resolution", c.far_noise.resolution},
                                 {"origin_m", c.far_noise.origin_m},
                                 {"size_m", c.far_noise.size_m}};
  }
  return document;
}

Result<SimulationConfig> from_value(const Json& document) {
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
  if (resolution < std::numeric_limits<int>::min() || resolution > std::numeric_limits<int>::max())
    return invalid_argument("resolution = " + std::to_string(resolution) +
                            " is out of range: must be a power of two in [16, 2048]");
  c.resolution = static_cast<int>(resolution);  // validate() checks the range, naming the value
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
  if (const Json* roles = r.child("band_roles")) {
    if (!roles->is_array())
      return invalid_argument(
          "band_roles: expected an array of \"both\", \"displace\" or "
          "\"shade\", one per cascade");
    for (const Json& v : *roles) {
      std::optional<BandRole> role;
      if (v.is_string()) role = value_of(kBandRoleNames, v.get<std::string>());
      if (!role)
        return invalid_argument("band_roles: '" + excerpt(v.dump()) + "' is unknown: must be " +
                                name_list(kBandRoleNames, ", ", " or "));
      c.band_roles.push_back(*role);
    }
  }
  r.number("choppiness", c.choppiness);
  r.number("loop_period_s", c.loop_period_s);
  r.number("roughness", c.roughness);
  std::string normals(to_string(c.normals)), blue(name_of(kBlueChannelNames, c.blue_channel));
  r.string("normals", normals);
  r.string("blue_channel", blue);
  if (const Json* foam = r.child("foam")) {
    ObjectReader fr(*foam, "foam");
    std::string source(name_of(kFoamSourceNames, c.foam.source));
    fr.string("source", source);
    if (std::optional<FoamSource> f = value_of(kFoamSourceNames, source)) {
      c.foam.source = *f;
    } else {
      return invalid_argument("foam.source = '" + excerpt(source) + "' is unknown: must be " +
                              name_list(kFoamSourceNames, ", ", " or "));
    }
    fr.number("breaking_acceleration", c.foam.breaking_acceleration);
    fr.number("jacobian_start", c.foam.jacobian_start);
    fr.number("jacobian_full", c.foam.jacobian_full);
    fr.number("decay_per_s", c.foam.decay_per_s);
    r.adopt(fr.finish());
  }
  if (const Json* noise = r.child("far_noise"); noise != nullptr && !noise->is_null()) {
    ObjectReader nr(*noise, "far_noise");
    long long n = c.far_noise.resolution;
    nr.integer("resolution", n);
    if (n < std::numeric_limits<int>::min() || n > std::numeric_limits<int>::max())
      return invalid_argument("far_noise.resolution = " + std::to_string(n) +
                              " is out of range: must be 0 (off) or in [16, 4096]");
    c.far_noise.resolution = static_cast<int>(n);  // validate() checks the range
    nr.number("size_m", c.far_noise.size_m);
    if (const Json* origin = nr.child("origin_m")) {
      if (!origin->is_array() || origin->size() != 2 || !(*origin)[0].is_number() ||
          !(*origin)[1].is_number())
        nr.fail("origin_m", "expected [x, z] in metres");
      else
        c.far_noise.origin_m = {(*origin)[0].get<double>(), (*origin)[1].get<double>()};
    }
    r.adopt(nr.finish());
  }
  r.child("far_field_range");  // picture settings: picture_from_value reads them
  r.child("underwater");
  if (Status s = r.finish(); !s.ok()) return s;
  if (Result<PictureSettings> picture = picture_from_value(document); !picture.ok())
    return picture.status();
  Result<NormalMethod> method = parse_normal_method(normals);
  if (!method.ok()) return method.status();
  c.normals = method.value();
  if (std::optional<BlueChannel> b = value_of(kBlueChannelNames, blue))
    c.blue_channel = *b;
  else
    return invalid_argument("blue_channel = '" + excerpt(blue) + "' is unknown: must be " +
                            name_list(kBlueChannelNames, ", ", " or "));
  if (Result<SimulationPlan> plan = SimulationPlan::make(c); !plan.ok()) return plan.status();
  return c;
}

// "underwater": {"scattering_per_m": b}: the water's turbidity (render::Underwater).
static Status underwater_from_value(const Json& document, PictureSettings& p) {
  const auto it = document.find("underwater");
  if (it == document.end() || it->is_null()) return {};
  if (!it->is_object())
    return invalid_argument("underwater: expected an object, got " + excerpt(it->dump()));
  for (const auto& [key, value] : it->items()) {
    if (key != "scattering_per_m")
      return invalid_argument("underwater." + excerpt(key) +
                              ": unknown key: must be scattering_per_m");
    if (value.is_null()) continue;
    if (!value.is_number())
      return invalid_argument("underwater.scattering_per_m: expected a number, got " +
                              excerpt(value.dump()));
    const double b = value.get<double>();
    if (!std::isfinite(b) || b < 0.0 || b > kMaxScatteringPerM)
      return invalid_argument("underwater.scattering_per_m = " + format_number(b) +
                              " is out of range: must be in [0, " +
                              format_number(kMaxScatteringPerM) + "] 1/m");
    p.scattering_per_m = b;
  }
  return {};
}

Result<PictureSettings> picture_from_value(const Json& document) {
  PictureSettings p;
  if (!document.is_object()) return p;
  if (Status s = underwater_from_value(document, p); !s.ok()) return s;
  const auto it = document.find("far_field_range");
  if (it == document.end() || it->is_null()) return p;
  const Json& range = *it;
  if (!range.is_array() || range.size() != 2 || !range[0].is_number() || !range[1].is_number())
    return invalid_argument(
        "far_field_range: expected [DMIN, DMAX], two distances in metres, got " +
        excerpt(range.dump()));
  const double near = range[0].get<double>(), far = range[1].get<double>();
  if (!std::isfinite(near) || !std::isfinite(far) || near < 0.0 || !(near < far))
    return invalid_argument("far_field_range: [" + format_number(near) + ", " + format_number(far) +
                            "] must be finite distances with 0 <= DMIN < DMAX");
  p.far_field_range_m = std::array<double, 2>{near, far};
  return p;
}

Parsed parse_bounded(std::string_view text, int max_depth) {
  // The callback sees each object and array as it starts, at its depth (0 for the outermost);
  // refusing one discards it unbuilt, with everything inside it.
  bool too_deep = false;
  const auto guard = [&](int depth, Json::parse_event_t event, Json& /*value*/) {
    if (event != Json::parse_event_t::object_start && event != Json::parse_event_t::array_start)
      return true;
    if (depth < max_depth) return true;
    too_deep = true;
    return false;
  };
  Parsed parsed{.value = Json::parse(text, guard, false)};
  if (too_deep)
    parsed.outcome = Parse::too_deep;
  else if (parsed.value.is_discarded())
    parsed.outcome = Parse::not_json;
  return parsed;
}

}  // namespace detail

std::string to_json(const SimulationConfig& config, int indent) {
  return detail::to_value(config).dump(std::min(indent, kMaxPresetIndent));
}

Result<SimulationConfig> from_json(std::string_view text) {
  if (text.size() > kMaxPresetBytes)
    return invalid_argument("the document is larger than " + std::to_string(kMaxPresetBytes) +
                            " bytes (1 MiB), the most a preset may hold");
  const detail::Parsed parsed = detail::parse_bounded(text, kMaxPresetDepth);
  if (parsed.outcome == detail::Parse::too_deep)
    return invalid_argument("the document nests deeper than " + std::to_string(kMaxPresetDepth) +
                            " levels");
  if (parsed.outcome == detail::Parse::not_json)
    return invalid_argument("the document is not valid JSON");
  return detail::from_value(parsed.value);
}

}  // namespace ocean::preset
