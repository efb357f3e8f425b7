// Typed number parameters (ocean/parameters.hpp).
#include "ocean/parameters.hpp"

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <version>

namespace ocean::params {

namespace {

bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// 'text' as excerpt writes it, built by appends (GCC 12 at -O3 reports a false -Wrestrict in the
// inlined copies of "'" + s + "'", GCC bug 105329).
std::string quoted(const std::string& text) {
  std::string out = "'";
  out.append(excerpt(text)).append("'");
  return out;
}

std::string integer_text(double v) { return std::to_string(static_cast<long long>(v)); }

std::string shown(const NumberOption<double>& o, double value, const std::string& text) {
  switch (o.echo) {
    case Echo::value: return format_number(value);
    case Echo::text: return excerpt(text);
    case Echo::quoted_text: return quoted(text);
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
  if (!o.unit.empty()) range.append(" ").append(o.unit);
  return range;
}

// std::from_chars for a double. emscripten 3.1.6's libc++ (the web page's build compiles this file)
// has no floating-point from_chars; there strtod reads the same forms in the C locale the page runs
// in, once the forms from_chars refuses and strtod takes (leading space or '+', hexadecimal) are
// refused first.
std::from_chars_result read_double(const char* first, const char* last, double& value) {
#if defined(__cpp_lib_to_chars)
  return std::from_chars(first, last, value);
#else
  const std::string text(first, last);
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])) || text[0] == '+' ||
      text.find_first_of("xX") != std::string::npos)
    return {first, std::errc::invalid_argument};
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  const std::errc ec = end == text.c_str() ? std::errc::invalid_argument
                       : errno == ERANGE   ? std::errc::result_out_of_range
                                           : std::errc();
  return {first + (end - text.c_str()), ec};
#endif
}

}  // namespace

Result<double> parse_number(std::string_view flag, const std::string& text) {
  double value = 0.0;
  const char* first = text.data();
  const char* last = text.data() + text.size();
  const auto [ptr, ec] = read_double(first, last, value);
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
    std::string message(o.flag);
    message.append(" = ").append(shown(o, value, text));
    message.append(" is out of range: must be ").append(requirement(o));
    return invalid_argument(message);
  }
  if (o.accept == Accept::whole_in_range && !integer)
    return invalid_argument(std::string(o.flag) + " = " + excerpt(text) +
                            " must be a whole number");
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

namespace {

// Every whole-word field name of `table` in `message` replaced by the member `name` of its row.
std::string with_names(std::string message, std::span<const ParameterDoc> table,
                       std::string_view ParameterDoc::*name) {
  for (const ParameterDoc& p : table) {
    const std::string_view replacement = p.*name;
    std::size_t pos = 0;
    while ((pos = message.find(p.field, pos)) != std::string::npos) {
      const std::size_t end = pos + p.field.size();
      // Not already a flag: "--gamma" stays as it is.
      const bool starts = pos == 0 || !(is_word_char(message[pos - 1]) || message[pos - 1] == '-');
      const bool ends = end == message.size() || !is_word_char(message[end]);
      if (starts && ends) {
        message.replace(pos, p.field.size(), replacement);
        pos += replacement.size();
      } else {
        pos = end;
      }
    }
  }
  return message;
}

bool is_placeholder_char(char c) { return (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'); }

}  // namespace

std::string with_flag_names(std::string message, std::span<const ParameterDoc> table) {
  return with_names(std::move(message), table, &ParameterDoc::flag);
}

std::string with_keyword_names(std::string message, std::span<const ParameterDoc> table) {
  message = with_names(std::move(message), table, &ParameterDoc::keyword);
  std::string out;
  out.reserve(message.size());
  for (std::size_t i = 0; i < message.size();) {
    const bool flag = message.compare(i, 2, "--") == 0 && i + 2 < message.size() &&
                      message[i + 2] >= 'a' && message[i + 2] <= 'z' &&
                      (i == 0 || !(is_word_char(message[i - 1]) || message[i - 1] == '-'));
    if (!flag) {
      out += message[i++];
      continue;
    }
    i += 2;
    while (i < message.size() && (is_word_char(message[i]) || message[i] == '-'))
      out += message[i] == '-' ? '_' : message[i], ++i;
    // "--fetch M" → "fetch=M", "--k K1,..." → "k=K1,...".
    if (i + 1 < message.size() && message[i] == ' ' && message[i + 1] >= 'A' &&
        message[i + 1] <= 'Z') {
      std::size_t j = i + 1;
      while (j < message.size() && is_placeholder_char(message[j])) ++j;
      if (j == message.size() || message[j] == ' ' || message[j] == ',' || message[j] == ')' ||
          message[j] == ':') {
        out += '=';
        ++i;
      }
    }
  }
  return out;
}

}  // namespace ocean::params
