// The preset format (ocean/preset.hpp): built-in presets, exact round trips through JSON, errors
// that name the key's path in the document, and presets assembled in layers.
#include "ocean/preset.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using ocean::ErrorCode;
using ocean::SimulationConfig;
namespace preset = ocean::preset;

std::string error_of(std::string_view json) {
  const auto r = preset::from_json(json);
  EXPECT_FALSE(r.ok()) << json;
  if (r.ok()) return "";
  EXPECT_EQ(r.status().code(), ErrorCode::invalid_argument) << json;
  return r.status().message();
}

TEST(Preset, BuiltinsByName) {
  const std::vector<std::string_view> names = preset::builtin_names();
  ASSERT_EQ(names, (std::vector<std::string_view>{"calm", "moderate", "storm"}));
  for (const std::string_view name : names) {
    SCOPED_TRACE(std::string(name));
    EXPECT_FALSE(preset::builtin_json(name).empty());
    const auto config = preset::builtin(name);
    ASSERT_TRUE(config.ok()) << config.status().message();
    EXPECT_TRUE(ocean::validate(config.value()).ok());
  }
  EXPECT_TRUE(preset::builtin_json("hurricane").empty());
  const auto unknown = preset::builtin("hurricane");
  ASSERT_FALSE(unknown.ok());
  EXPECT_EQ(unknown.status().code(), ErrorCode::invalid_argument);
  EXPECT_NE(unknown.status().message().find("hurricane"), std::string::npos);
}

// to_json → from_json → to_json gives the same text: every number round-trips exactly, unset
// numbers (NaN) are null, deep water (infinite depth) is null, a swell survives.
TEST(Preset, RoundTripIsExact) {
  std::vector<SimulationConfig> configs = {SimulationConfig{}};
  for (const std::string_view name : preset::builtin_names())
    configs.push_back(preset::builtin(name).value());
  SimulationConfig odd;
  odd.choppiness = 0.1 + 0.2;  // not a short decimal
  odd.sea.wind_sea.direction_rad = 1.0 / 3.0;
  odd.seed = 1234567890123ull;
  configs.push_back(odd);
  for (const SimulationConfig& c : configs) {
    const std::string text = preset::to_json(c);
    const auto back = preset::from_json(text);
    ASSERT_TRUE(back.ok()) << back.status().message() << "\n" << text;
    EXPECT_EQ(preset::to_json(back.value()), text);
    EXPECT_EQ(back.value().choppiness, c.choppiness);
    EXPECT_EQ(back.value().seed, c.seed);
    EXPECT_EQ(back.value().sea.has_swell, c.sea.has_swell);
  }
  const std::string defaults = preset::to_json(SimulationConfig{});
  EXPECT_NE(defaults.find("\"depth_m\":null"), std::string::npos) << defaults;
  EXPECT_NE(defaults.find("\"swell\":null"), std::string::npos) << defaults;
  EXPECT_EQ(preset::to_json(SimulationConfig{}, 2).find('\n') != std::string::npos, true);
}

TEST(Preset, AbsentKeysKeepTheDefaults) {
  const auto empty = preset::from_json("{}");
  ASSERT_TRUE(empty.ok()) << empty.status().message();
  EXPECT_EQ(preset::to_json(empty.value()), preset::to_json(SimulationConfig{}));
  const auto some = preset::from_json(R"({"choppiness": 0.5, "normals": "analytic"})");
  ASSERT_TRUE(some.ok()) << some.status().message();
  EXPECT_EQ(some.value().choppiness, 0.5);
  EXPECT_EQ(some.value().normals, ocean::NormalMethod::analytic);
}

TEST(Preset, ErrorsNameTheJsonPath) {
  EXPECT_EQ(error_of(R"({"sea": {"wind_sea": {"fetch_m": "far"}}})"),
            "sea.wind_sea.fetch_m: expected a number, got a string");
  EXPECT_EQ(error_of(R"({"sea": {"swell": {"bogus": 1}}})"), "sea.swell.bogus: unknown key");
  EXPECT_EQ(error_of(R"({"sea": {"wind_sea": {"spreading": {"alpha": true}}}})"),
            "sea.wind_sea.spreading.alpha: expected a number, got a boolean");
  EXPECT_EQ(error_of(R"({"foam": 3})"), "foam: expected an object");
  EXPECT_EQ(error_of(R"({"resolution": 2.5})"), "resolution: expected an integer, got a number");
  EXPECT_EQ(error_of(R"({"colour": "blue"})"), "colour: unknown key");
  EXPECT_EQ(error_of(R"({"sea": {"wind_sea": {"gamma": "big"}}})"),
            "sea.wind_sea.gamma: expected a number or \"auto\", got a string");
  EXPECT_EQ(error_of("[1, 2]"), "the document: expected an object");
  EXPECT_EQ(error_of("{\"seed\": "), "the document is not valid JSON");
  // Values the configuration rejects: the message of validate().
  EXPECT_NE(error_of(R"({"resolution": 100})").find("resolution = 100"), std::string::npos);
}

TEST(PresetDocument, LayersPresetThenOverrides) {
  preset::Document doc;
  ASSERT_TRUE(doc.merge_preset("storm").ok());
  const auto storm = doc.config();
  ASSERT_TRUE(storm.ok()) << storm.status().message();
  EXPECT_EQ(preset::to_json(storm.value()), preset::to_json(preset::builtin("storm").value()));

  ASSERT_TRUE(doc.set("normals=analytic").ok());          // a bare string
  ASSERT_TRUE(doc.set("sea.wind_sea.fetch_m=5e4").ok());  // a JSON number, dotted key
  ASSERT_TRUE(doc.set("foam.decay_per_s=0.25").ok());
  const auto changed = doc.config();
  ASSERT_TRUE(changed.ok()) << changed.status().message();
  EXPECT_EQ(changed.value().normals, ocean::NormalMethod::analytic);
  EXPECT_EQ(changed.value().sea.wind_sea.spectrum.fetch_m, 5e4);
  EXPECT_EQ(changed.value().foam.decay_per_s, 0.25);
  EXPECT_EQ(changed.value().resolution, storm.value().resolution);
}

TEST(PresetDocument, ErrorsNameTheCallersLabel) {
  preset::Document doc;
  const ocean::Status unknown = doc.merge_preset("hurricane", "--preset");
  EXPECT_EQ(unknown.code(), ErrorCode::invalid_argument);
  EXPECT_EQ(unknown.message(),
            "--preset = hurricane is neither a file nor a preset: must be calm, moderate, storm "
            "or a JSON file");
  EXPECT_EQ(doc.set("seed", "--set").message(), "--set 'seed': expected key=value");
  EXPECT_EQ(doc.set("=3", "--set").message(), "--set '=3': expected key=value");
  EXPECT_EQ(doc.set("sea..x=1", "--set").message(), "--set 'sea..x=1': empty key part");
  EXPECT_EQ(doc.set("seed.x=1", "--set").message(), "--set seed.x: 'x' is not inside an object");
  EXPECT_EQ(doc.set("seed", "override").message(), "override 'seed': expected key=value");
  // Unknown keys set by an override are found when the document is read.
  ASSERT_TRUE(doc.set("sea.wind_sea.fetch=1").ok());
  EXPECT_EQ(doc.config().status().message(), "sea.wind_sea.fetch: unknown key");
}

TEST(PresetDocument, ReadsFiles) {
  const fs::path dir = fs::temp_directory_path() / ("preset_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path good = dir / "good.json", bad = dir / "bad.json";
  std::ofstream(good) << R"({"choppiness": 0.7, "sea": {"wind_sea": {"wind_speed_mps": 9}}})";
  std::ofstream(bad) << "{ not json";
  preset::Document doc;
  ASSERT_TRUE(doc.merge_preset(good.string()).ok());
  const auto config = doc.config();
  ASSERT_TRUE(config.ok()) << config.status().message();
  EXPECT_EQ(config.value().choppiness, 0.7);
  EXPECT_EQ(config.value().sea.wind_sea.spectrum.wind_speed_mps, 9.0);

  const ocean::Status invalid = doc.merge_preset(bad.string());
  EXPECT_EQ(invalid.code(), ErrorCode::invalid_argument);
  EXPECT_EQ(invalid.message(), "preset '" + bad.string() + "' is not valid JSON");
  const ocean::Status missing = doc.merge_preset((dir / "missing.json").string());
  EXPECT_EQ(missing.code(), ErrorCode::io_error);
  EXPECT_EQ(missing.message().rfind("cannot read preset '", 0), 0u) << missing.message();
  // Failed merges leave the document as it was.
  EXPECT_EQ(preset::to_json(doc.config().value()), preset::to_json(config.value()));
  fs::remove_all(dir);
}

// null is a value in a preset ("unset"), in a file merged over the defaults as in a text read
// by from_json: a Pierson-Moskowitz sea given by its wind has no fetch (the spectrum's parameter
// check refuses one), so "fetch_m": null must not fall back to the default 100 km fetch; and
// "swell": null over a preset with swell leaves none.
TEST(PresetDocument, NullInAFileIsUnsetAsInFromJson) {
  const fs::path dir = fs::temp_directory_path() / ("preset_null_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string text =
      R"({"sea": {"wind_sea": {"model": "pierson-moskowitz", "wind_speed_mps": 12,)"
      R"( "fetch_m": null}, "swell": null}})";
  const fs::path file = dir / "pm.json";
  std::ofstream(file) << text;
  const auto direct = preset::from_json(text);
  ASSERT_TRUE(direct.ok()) << direct.status().message();
  EXPECT_TRUE(std::isnan(direct.value().sea.wind_sea.spectrum.fetch_m));

  preset::Document doc;
  ASSERT_TRUE(doc.merge_preset("calm").ok());
  ASSERT_TRUE(doc.config().value().sea.has_swell);  // calm has a swell for the null to remove
  ASSERT_TRUE(doc.merge_preset(file.string()).ok());
  const auto merged = doc.config();
  ASSERT_TRUE(merged.ok()) << merged.status().message();
  EXPECT_TRUE(std::isnan(merged.value().sea.wind_sea.spectrum.fetch_m));
  EXPECT_FALSE(merged.value().sea.has_swell);
  // Over the defaults alone the file is the text: the same configuration, key for key.
  preset::Document plain;
  ASSERT_TRUE(plain.merge_preset(file.string()).ok());
  ASSERT_TRUE(plain.config().ok()) << plain.config().status().message();
  EXPECT_EQ(preset::to_json(plain.config().value()), preset::to_json(direct.value()));
  fs::remove_all(dir);
}

TEST(Preset, BandRolesRoundTripAndBadOnesAreNamed) {
  SimulationConfig c;
  EXPECT_EQ(preset::to_json(c).find("band_roles"), std::string::npos);  // unset: not written
  c.band_roles = {ocean::BandRole::displace, ocean::BandRole::both, ocean::BandRole::shade};
  auto back = preset::from_json(preset::to_json(c));
  ASSERT_TRUE(back.ok()) << back.status().message();
  EXPECT_EQ(back.value().band_roles, c.band_roles);
  auto unknown = preset::from_json(R"({"band_roles": ["both", "glow", "shade"]})");
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.status().message().find("glow"), std::string::npos);
  auto count = preset::from_json(R"({"band_roles": ["both"]})");
  ASSERT_FALSE(count.ok());
  EXPECT_NE(count.status().message().find("one per cascade"), std::string::npos);
  EXPECT_FALSE(preset::from_json(R"({"band_roles": "shade"})").ok());
}

// The far field's noise map (SimulationConfig::far_noise): written only when on, exact round trip,
// bad values named by their path or by validate().
TEST(Preset, FarNoiseMapRoundTripsAndBadOnesAreNamed) {
  SimulationConfig c;
  EXPECT_EQ(preset::to_json(c).find("far_noise"), std::string::npos);  // off: not written
  c.far_noise = {.resolution = 256, .origin_m = {-1234.5, 0.1}, .size_m = 7777.25};
  auto back = preset::from_json(preset::to_json(c));
  ASSERT_TRUE(back.ok()) << back.status().message();
  EXPECT_EQ(back.value().far_noise.resolution, 256);
  EXPECT_EQ(back.value().far_noise.origin_m, c.far_noise.origin_m);
  EXPECT_EQ(back.value().far_noise.size_m, c.far_noise.size_m);
  EXPECT_NE(error_of(R"({"far_noise": {"resolution": 8}})").find("far_noise.resolution"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"far_noise": {"origin_m": [1]}})").find("far_noise.origin_m"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"far_noise": {"colour": 1}})").find("far_noise.colour: unknown key"),
            std::string::npos);
  preset::Document doc;
  ASSERT_TRUE(doc.set("far_noise.resolution=64").ok());
  ASSERT_TRUE(doc.config().ok()) << doc.config().status().message();
  EXPECT_EQ(doc.config().value().far_noise.resolution, 64);
}

}  // namespace

namespace {

// "far_field_range": a picture setting beside the configuration. Read by Document::picture();
// absent or null, unset; set through a preset or --set; bad values are one line from both
// picture() and config(), so `ocean render` refuses them before anything runs.
TEST(PresetDocument, FarFieldRangeIsAPictureSettingValidatedInOneLine) {
  preset::Document doc;
  ASSERT_TRUE(doc.picture().ok());
  EXPECT_FALSE(doc.picture().value().far_field_range_m.has_value());
  ASSERT_TRUE(doc.set("far_field_range=[800, 3000.5]").ok());
  ASSERT_TRUE(doc.config().ok()) << doc.config().status().message();
  const auto range = doc.picture().value().far_field_range_m;
  ASSERT_TRUE(range.has_value());
  EXPECT_EQ((*range)[0], 800.0);
  EXPECT_EQ((*range)[1], 3000.5);
  // The configuration ignores it, and to_json never writes it.
  EXPECT_EQ(preset::to_json(doc.config().value()), preset::to_json(SimulationConfig{}));
  ASSERT_TRUE(doc.set("far_field_range=null").ok());
  EXPECT_FALSE(doc.picture().value().far_field_range_m.has_value());

  for (const char* bad : {"[2500, 1000]", "[1000, 1000]", "[-1, 100]", "[100]", "[1, 2, 3]",
                          "[\"a\", 5]", "7", "{\"near\": 1}", "[0, 1e999]"}) {
    preset::Document d;
    ASSERT_TRUE(d.set(std::string("far_field_range=") + bad).ok()) << bad;
    const auto p = d.picture();
    ASSERT_FALSE(p.ok()) << bad;
    EXPECT_EQ(p.status().code(), ErrorCode::invalid_argument);
    EXPECT_EQ(p.status().message().rfind("far_field_range: ", 0), 0u) << p.status().message();
    EXPECT_EQ(p.status().message().find('\n'), std::string::npos);
    const auto c = d.config();
    ASSERT_FALSE(c.ok()) << bad;
    EXPECT_EQ(c.status().message(), p.status().message());
  }
  EXPECT_NE(error_of(R"({"far_field_range": [3, 2]})").find("0 <= DMIN < DMAX"), std::string::npos);
  EXPECT_TRUE(preset::from_json(R"({"far_field_range": [0, 2]})").ok());
}

// "underwater": {"scattering_per_m": b}, the water's turbidity: a picture setting read by
// Document::picture(), in [0, 10] 1/m; a bad value or an unknown key is one line naming the
// field, from picture() and config() alike.
TEST(PresetDocument, UnderwaterScatteringIsAPictureSettingValidatedInOneLine) {
  preset::Document doc;
  EXPECT_FALSE(doc.picture().value().scattering_per_m.has_value());
  ASSERT_TRUE(doc.set("underwater.scattering_per_m=0.45").ok());
  ASSERT_TRUE(doc.config().ok()) << doc.config().status().message();
  ASSERT_TRUE(doc.picture().value().scattering_per_m.has_value());
  EXPECT_EQ(*doc.picture().value().scattering_per_m, 0.45);
  EXPECT_EQ(preset::to_json(doc.config().value()), preset::to_json(SimulationConfig{}));
  ASSERT_TRUE(doc.set("underwater.scattering_per_m=0").ok());  // no scattering at all
  EXPECT_EQ(*doc.picture().value().scattering_per_m, 0.0);
  EXPECT_TRUE(preset::from_json(R"({"underwater": {"scattering_per_m": 10}})").ok());
  for (const char* bad : {R"({"underwater": {"scattering_per_m": -0.1}})",
                          R"({"underwater": {"scattering_per_m": 10.5}})",
                          R"({"underwater": {"scattering_per_m": "murky"}})",
                          R"({"underwater": {"turbidity": 1}})", R"({"underwater": 3})"}) {
    const std::string message = error_of(bad);
    EXPECT_EQ(message.rfind("underwater", 0), 0u) << bad << ": " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  EXPECT_NE(error_of(R"({"underwater": {"scattering_per_m": 11}})").find("[0, 10]"),
            std::string::npos);
}

}  // namespace
