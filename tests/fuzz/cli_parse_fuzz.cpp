// Fuzz target: the command line's number, list and vector parsers (apps/ocean: options.hpp,
// bench/parse.hpp, simulation_flags.hpp, view_flags.hpp, cli_common.hpp's to_params).
//
// Input: the first byte picks the parser (its value modulo the number of parsers, in the order
// of kParsers), the second byte (where used) picks an option of the tables below, and the rest
// is the text. The parsers that take several flags get one flag's text per line, in the order of
// the struct's fields. Every text gives a value or a one-line error, never a crash, UB or a leak,
// and a value obeys the rule it was parsed under (range, finiteness, count of items).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "bench/parse.hpp"
#include "cli_common.hpp"
#include "expect.hpp"
#include "options.hpp"
#include "simulation_flags.hpp"
#ifdef OCEAN_HAS_VULKAN
#include "view_flags.hpp"
#endif

namespace {

using namespace ocean::cli;
using ocean::Result;
using ocean::fuzz::expect;

// Options of every rule and echo, as the subcommands declare them.
constexpr NumberOption<double> kDoubles[] = {
    {.flag = "--depth"},
    {.flag = "--time", .accept = Accept::finite},
    {.flag = "--omega-ratio", .accept = Accept::positive},
    {.flag = "--omega", .accept = Accept::non_negative},
    {.flag = "--fov", .accept = Accept::in_range, .lo = 1.0, .hi = 170.0},
    {.flag = "--frame-interval",
     .accept = Accept::in_range,
     .lo = 0.0,
     .hi = 1000.0,
     .echo = Echo::text,
     .unit = "ms"},
    {.flag = "--frames",
     .accept = Accept::whole_in_range,
     .lo = 1.0,
     .hi = 1e6,
     .echo = Echo::quoted_text},
    {.flag = "--patch-size", .accept = Accept::in_range, .lo = 0.01, .hi = 1e6, .says = "sane"},
};
constexpr NumberOption<int> kInts[] = {
    {.flag = "--resolution", .accept = Accept::integer_in_range, .lo = 16, .hi = 2048},
    {.flag = "--threads", .accept = Accept::integer_in_range, .lo = 1, .hi = 256},
    {.flag = "--seeds", .accept = Accept::integer_in_range, .lo = 1, .hi = 1e5, .echo = Echo::text},
    {.flag = "--frames", .accept = Accept::whole_in_range, .lo = 1.0, .hi = 1e6},
};
constexpr NumberOption<std::uint64_t> kSeed{.flag = "--seed",
                                            .accept = Accept::integer_in_range,
                                            .lo = 0.0,
                                            .hi = 9e15,
                                            .echo = Echo::text};

template <class T, std::size_t N>
const T& pick(const T (&table)[N], unsigned char byte) {
  return table[byte % N];
}

// Whether `value` obeys the option's rule (what check() promises for an accepted value).
bool obeys(const NumberOption<double>& o, double value) {
  if (std::isnan(value)) return false;
  switch (o.accept) {
    case Accept::any_number: return true;
    case Accept::finite: return std::isfinite(value);
    case Accept::positive: return std::isfinite(value) && value > 0.0;
    case Accept::non_negative: return std::isfinite(value) && value >= 0.0;
    case Accept::in_range: return value >= o.lo && value <= o.hi;
    case Accept::whole_in_range:
    case Accept::integer_in_range:
      return value >= o.lo && value <= o.hi && value == std::floor(value);
  }
  return false;
}

template <class T>
NumberOption<double> as_double(const NumberOption<T>& o) {
  return {o.flag, o.accept, o.lo, o.hi, o.echo, o.unit, o.says};
}

std::vector<std::string> lines(std::string_view text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    out.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

// Whether the parser accepted its text; a refusal is one line.
template <class T>
bool accepted(const Result<T>& result, const char* parser) {
  if (!result.ok()) ocean::fuzz::expect_one_line(result.status(), parser);
  return result.ok();
}

// The i-th line, or "" past the end.
std::string line(const std::vector<std::string>& all, std::size_t i) {
  return i < all.size() ? all[i] : std::string();
}

void number(unsigned char, const std::string& text) {
  Result<double> v = parse_number("--hs", text);
  if (accepted(v, "parse_number")) expect(!std::isnan(v.value()), "parse_number gave NaN");
}

void number_list(unsigned char, const std::string& text) {
  Result<std::vector<double>> v = parse_number_list("--omega", text);
  if (!accepted(v, "parse_number_list")) return;
  const auto items = static_cast<std::size_t>(std::count(text.begin(), text.end(), ',')) + 1;
  expect(v.value().size() == items, "parse_number_list: not one value per item");
  for (double x : v.value()) expect(!std::isnan(x), "parse_number_list gave NaN");
}

void triple(unsigned char, const std::string& text) {
  Result<std::array<double, 3>> v = parse_triple("--camera", text);
  if (!accepted(v, "parse_triple")) return;
  for (double x : v.value()) expect(std::isfinite(x), "parse_triple gave a non-finite value");
}

void scalar(unsigned char which, const std::string& text) {
  const NumberOption<double>& d = pick(kDoubles, which);
  if (Result<double> v = parse(d, text); accepted(v, "parse<double>"))
    expect(obeys(d, v.value()), "parse<double> broke the rule of " + std::string(d.flag));
  const NumberOption<int>& i = pick(kInts, which);
  if (Result<int> v = parse(i, text); accepted(v, "parse<int>"))
    expect(obeys(as_double(i), v.value()), "parse<int> broke the rule of " + std::string(i.flag));
  if (Result<std::uint64_t> v = parse(kSeed, text); accepted(v, "parse<uint64_t>"))
    expect(obeys(as_double(kSeed), static_cast<double>(v.value())), "parse<uint64> broke --seed");
}

void list(unsigned char which, const std::string& text) {
  const NumberOption<double>& o = pick(kDoubles, which);
  Result<std::vector<double>> v = parse_list(o, text);
  if (!accepted(v, "parse_list")) return;
  for (double x : v.value())
    expect(obeys(o, x), "parse_list broke the rule of " + std::string(o.flag));
}

void int_list(unsigned char which, const std::string& text) {
  const NumberOption<int>& o = pick(kInts, which);
  const bool allow_all = (which & 0x80) != 0;
  Result<std::vector<int>> v = bench::parse_ints(o, text, allow_all);
  if (!accepted(v, "parse_ints")) return;
  expect(!v.value().empty(), "parse_ints gave an empty list");
  for (int x : v.value())
    expect((allow_all && x == 0) || obeys(as_double(o), x),
           "parse_ints broke " + std::string(o.flag));
}

void spectrum_flags(unsigned char, const std::string& text) {
  const std::vector<std::string> l = lines(text);
  SpectrumFlags f;
  std::string* fields[] = {&f.model,
                           &f.hs,
                           &f.tp,
                           &f.wind_speed,
                           &f.fetch,
                           &f.gamma,
                           &f.depth,
                           &f.gravity,
                           &f.depth_factor,
                           &f.fetch_law,
                           &f.normalization,
                           &f.phillips_amplitude,
                           &f.cutoff_length};
  for (std::size_t i = 0; i < std::size(fields); ++i) {
    if (i < l.size()) *fields[i] = l[i];
  }
  (void)accepted(to_params(f), "to_params");
}

void simulation_flags(unsigned char which, const std::string& text) {
  const std::vector<std::string> l = lines(text);
  SimulationFlags f;
  // Only the built-in presets: a path would read whatever file the text names.
  constexpr const char* kPresets[] = {"", "calm", "moderate", "storm"};
  f.preset_path = kPresets[which % 4];
  std::string* fields[] = {&f.resolution,     &f.seed,        &f.choppiness, &f.cascades,
                           &f.normals,        &f.loop_period, &f.sea.hs,     &f.sea.tp,
                           &f.sea.wind_speed, &f.sea.fetch};
  for (std::size_t i = 0; i < std::size(fields); ++i) *fields[i] = line(l, i);
  for (std::size_t i = std::size(fields); i < l.size(); ++i) f.set.push_back(l[i]);
  (void)accepted(resolve_config(f), "resolve_config");
}

#ifdef OCEAN_HAS_VULKAN
void view_flags(unsigned char which, const std::string& text) {
  const std::vector<std::string> l = lines(text);
  ViewFlags f;
  std::string* fields[] = {&f.width,   &f.height,     &f.camera, &f.target, &f.fov,
                           &f.quality, &f.ocean_size, &f.view,   &f.backend};
  for (std::size_t i = 0; i < std::size(fields); ++i) {
    if (i < l.size()) *fields[i] = l[i];
  }
  const int min_size = 1 + which % 64;
  ocean::render::SceneParams scene;
  ocean::render::View view;
  const ocean::Status parsed = parse_view_flags(f, min_size, scene, view);
  ocean::fuzz::expect_one_line(parsed, "parse_view_flags");
  if (!parsed.ok()) return;
  expect(scene.width >= min_size && scene.width <= 16384 && scene.height >= min_size &&
             scene.height <= 16384,
         "parse_view_flags: size out of range");
  expect(std::isfinite(view.camera.fov_y_rad) && std::isfinite(view.ocean_size_m),
         "parse_view_flags: non-finite view");
}
#endif

using Parser = void (*)(unsigned char, const std::string&);
constexpr Parser kParsers[] = {
    number,     number_list, triple, scalar, list, int_list, spectrum_flags, simulation_flags,
#ifdef OCEAN_HAS_VULKAN
    view_flags,
#endif
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 2, size - 2);
  pick(kParsers, data[0])(data[1], text);
  return 0;
}
