// Typed number options (see options.hpp).
#include "options.hpp"

#include <charconv>

namespace ocean::cli {

namespace {

std::string integer_text(double v) { return std::to_string(static_cast<long long>(v)); }

std::string shown(const NumberOption<double>& o, double value, const std::string& text) {
  switch (o.echo) {
    case Echo::value: return format_number(value);
    case Echo::text: return excerpt(text);
    case Echo::quoted_text: return "'" + excerpt(text) + "'";
  }
  return excerpt(text);
}

std::string requirement(const NumberOption<double>& o) {
  if (!o.says.empty()) return std::string(o.says);
  std::string range;
  if (o.accept == Accept::integer_in_range)
    range = "an integer in [" + integer_text(o.lo) + ", " + integer_text(o.hi) + "]";
  else
    range = "in [" + format_number(o.lo) + ", " + format_number(o.hi) + "]";
  if (!o.unit.empty()) range += " " + std::string(o.unit);
  return range;
}

}  // namespace

Result<double> parse_number(std::string_view flag, const std::string& text) {
  double value = 0.0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (text.empty() || ec != std::errc() || ptr != last) {
    return invalid_argument(std::string(flag) + " = '" + excerpt(text) + "' is not a number");
  }
  if (std::isnan(value)) return require_finite(flag, value);  // NaN is never a valid value
  return value;
}

Result<std::vector<double>> parse_number_list(std::string_view flag, const std::string& text) {
  std::vector<double> values;
  if (text.empty()) return invalid_argument(std::string(flag) + " is empty: give W1,W2,...");
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::size_t end = comma == std::string::npos ? text.size() : comma;
    Result<double> v = parse_number(flag, text.substr(start, end - start));
    if (!v.ok()) return v.status();
    values.push_back(v.value());
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return values;
}

Result<std::array<double, 3>> parse_triple(std::string_view flag, const std::string& text) {
  Result<std::vector<double>> v = parse_number_list(flag, text);
  if (!v.ok()) return v.status();
  if (v.value().size() != 3) {
    return invalid_argument(std::string(flag) + " = " + excerpt(text) +
                            " must be three numbers X,Y,Z");
  }
  for (double c : v.value()) {
    if (Status s = require_finite(flag, c); !s.ok()) return s;
  }
  return std::array<double, 3>{v.value()[0], v.value()[1], v.value()[2]};
}

Status check(const NumberOption<double>& o, double value, const std::string& text) {
  switch (o.accept) {
    case Accept::any_number: return {};
    case Accept::finite: return require_finite(o.flag, value);
    case Accept::positive: return require_positive(o.flag, value);
    case Accept::non_negative: return require_non_negative(o.flag, value);
    case Accept::in_range:
    case Accept::whole_in_range:
    case Accept::integer_in_range: break;
  }
  const bool integer = value == std::floor(value);
  const bool in_range = value >= o.lo && value <= o.hi;
  if (!in_range || (o.accept == Accept::integer_in_range && !integer)) {
    return invalid_argument(std::string(o.flag) + " = " + shown(o, value, text) +
                            " is out of range: must be " + requirement(o));
  }
  if (o.accept == Accept::whole_in_range && !integer)
    return invalid_argument(std::string(o.flag) + " = " + excerpt(text) +
                            " must be a whole number");
  return {};
}

Status refuse_empty_values(const CLI::App& command) {
  for (const CLI::Option* option : command.get_options()) {
    if (option->get_items_expected_min() == 0) continue;  // a switch: no value
    for (const std::string& value : option->results()) {
      if (value.empty())
        return invalid_argument(option->get_name() +
                                " is empty: give a value or leave the flag out");
    }
  }
  for (const CLI::App* sub : command.get_subcommands()) {
    if (Status s = refuse_empty_values(*sub); !s.ok()) return s;
  }
  return {};
}

Result<std::vector<double>> parse_list(const NumberOption<double>& option,
                                       const std::string& text) {
  Result<std::vector<double>> values = parse_number_list(option.flag, text);
  if (!values.ok()) return values.status();
  for (double v : values.value()) {
    if (Status s = check(option, v, format_number(v)); !s.ok()) return s;
  }
  return values;
}

}  // namespace ocean::cli
