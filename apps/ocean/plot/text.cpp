// Text for the plot module: DejaVu Sans found through fontconfig and drawn by cairo's FreeType
// backend, the '^' superscript markup, measuring and drawing (horizontal or upward).
//
// The face is looked up by family and weight, and cairo is then handed only the matched file
// with fixed rendering options (grayscale antialiasing, slight hinting, unhinted metrics), so a
// figure does not change with the machine's fontconfig settings, and a machine without DejaVu
// Sans gets a clear error instead of a silently substituted font.
#include <cairo-ft.h>
#include <fontconfig/fontconfig.h>

#include <numbers>
#include <string>
#include <string_view>
#include <vector>

#include "cairo_state.hpp"
#include "plot_internal.hpp"

namespace ocean::plot {

namespace {

constexpr const char* kFamily = "DejaVu Sans";
constexpr double kSuperscriptSize = 0.7;  // superscript em relative to the base text
constexpr double kSuperscriptRise = 0.4;  // superscript baseline above the base one, in base ems

const FcChar8* fc_text(const char* s) { return reinterpret_cast<const FcChar8*>(s); }

bool has_family(FcPattern* pattern, std::string_view family) {
  FcChar8* name = nullptr;
  for (int i = 0; FcPatternGetString(pattern, FC_FAMILY, i, &name) == FcResultMatch; ++i) {
    if (std::string_view(reinterpret_cast<const char*>(name)) == family) return true;
  }
  return false;
}

Result<cairo_font_face_t*> load_face(bool bold) {
  const std::string what = std::string(kFamily) + (bold ? " Bold" : "");
  const Status missing =
      unsupported("font '" + what + "' not found: install fonts-dejavu-core (fontconfig)");
  if (FcInit() == FcFalse) return missing;
  FcPattern* want = FcPatternCreate();
  FcPatternAddString(want, FC_FAMILY, fc_text(kFamily));
  FcPatternAddInteger(want, FC_WEIGHT, bold ? FC_WEIGHT_BOLD : FC_WEIGHT_REGULAR);
  FcPatternAddInteger(want, FC_SLANT, FC_SLANT_ROMAN);
  FcPatternAddInteger(want, FC_WIDTH, FC_WIDTH_NORMAL);
  FcConfigSubstitute(nullptr, want, FcMatchPattern);
  FcDefaultSubstitute(want);
  FcResult result = FcResultNoMatch;
  FcPattern* match = FcFontMatch(nullptr, want, &result);
  FcPatternDestroy(want);
  FcChar8* file = nullptr;
  int index = 0, weight = 0;
  const bool found = match != nullptr && has_family(match, kFamily) &&
                     FcPatternGetString(match, FC_FILE, 0, &file) == FcResultMatch &&
                     FcPatternGetInteger(match, FC_WEIGHT, 0, &weight) == FcResultMatch &&
                     (weight >= FC_WEIGHT_BOLD) == bold;
  if (!found) {
    if (match != nullptr) FcPatternDestroy(match);
    return missing;
  }
  (void)FcPatternGetInteger(match, FC_INDEX, 0, &index);
  FcPattern* use = FcPatternCreate();
  FcPatternAddString(use, FC_FILE, file);
  FcPatternAddInteger(use, FC_INDEX, index);
  FcPatternAddBool(use, FC_ANTIALIAS, FcTrue);
  FcPatternAddBool(use, FC_HINTING, FcTrue);
  FcPatternAddInteger(use, FC_HINT_STYLE, FC_HINT_SLIGHT);
  FcPatternAddInteger(use, FC_RGBA, FC_RGBA_NONE);
  FcPatternDestroy(match);
  cairo_font_face_t* face = cairo_ft_font_face_create_for_pattern(use);
  FcPatternDestroy(use);
  if (cairo_font_face_status(face) != CAIRO_STATUS_SUCCESS) {
    const Status s = Status(
        ErrorCode::internal,
        "cannot load font '" + what + "': " + cairo_status_to_string(cairo_font_face_status(face)));
    cairo_font_face_destroy(face);
    return s;
  }
  return face;
}

void use_font(cairo_t* cr, cairo_font_face_t* face, double size_px) {
  cairo_set_font_face(cr, face);
  cairo_set_font_size(cr, size_px);
  cairo_font_options_t* options = cairo_font_options_create();
  cairo_font_options_set_antialias(options, CAIRO_ANTIALIAS_GRAY);
  cairo_font_options_set_hint_style(options, CAIRO_HINT_STYLE_SLIGHT);
  cairo_font_options_set_hint_metrics(options, CAIRO_HINT_METRICS_OFF);
  cairo_set_font_options(cr, options);
  cairo_font_options_destroy(options);
}

struct Placed {
  const detail::TextRun* run;
  double size, rise, advance;
};

// Each run with its size, the height of its baseline above the text's, and its advance.
std::vector<Placed> place(cairo_t* cr, cairo_font_face_t* face,
                          const std::vector<detail::TextRun>& runs, double size) {
  std::vector<Placed> out;
  for (const detail::TextRun& r : runs) {
    const double s = r.superscript ? size * kSuperscriptSize : size;
    use_font(cr, face, s);
    cairo_text_extents_t e;
    cairo_text_extents(cr, r.text.c_str(), &e);
    out.push_back({&r, s, r.superscript ? size * kSuperscriptRise : 0.0, e.x_advance});
  }
  return out;
}

}  // namespace

namespace detail {

Result<cairo_font_face_t*> font_face(bool bold) {
  static const Result<cairo_font_face_t*> regular = load_face(false);
  static const Result<cairo_font_face_t*> heavy = load_face(true);
  return bold ? heavy : regular;
}

std::vector<TextRun> parse_markup(std::string_view s) {
  std::vector<TextRun> runs;
  const auto add = [&](std::string_view text, bool superscript) {
    if (text.empty()) return;
    if (runs.empty() || runs.back().superscript != superscript) runs.push_back({{}, superscript});
    runs.back().text.append(text);
  };
  const auto is_word = [](char c) {
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
  };
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '^' && i + 1 < s.size()) {
      if (s[i + 1] == '{') {
        const std::size_t close = s.find('}', i + 2);
        if (close != std::string_view::npos) {
          std::string_view group = s.substr(i + 2, close - i - 2);
          if (!group.empty() && group[0] == '-') {
            add("\u2212", true);
            group.remove_prefix(1);
          }
          add(group, true);
          i = close;
          continue;
        }
      } else {
        std::size_t k = i + 1;
        if (s[k] == '-' || s[k] == '+') ++k;
        if (k < s.size() && is_word(s[k])) {
          add(s[i + 1] == '-' ? "\u2212" : s.substr(i + 1, k - i - 1), true);
          const std::size_t start = k;
          while (k < s.size() && is_word(s[k])) ++k;
          add(s.substr(start, k - start), true);
          i = k - 1;
          continue;
        }
      }
    }
    add(s.substr(i, 1), false);
  }
  return runs;
}

}  // namespace detail

TextExtent Canvas::measure(std::string_view text, const Font& font) const {
  if (text.empty() || !(font.size_px > 0.0)) return {};
  Result<cairo_font_face_t*> face = detail::font_face(font.bold);
  if (!face.ok()) return {};  // Canvas::make checked the font
  cairo_t* cr = impl_->cr;
  cairo_save(cr);
  const std::vector<detail::TextRun> runs = detail::parse_markup(text);
  TextExtent out;
  for (const Placed& p : place(cr, face.value(), runs, font.size_px)) {
    use_font(cr, face.value(), p.size);
    cairo_font_extents_t fe;
    cairo_font_extents(cr, &fe);
    out.width += p.advance;
    out.ascent = std::max(out.ascent, p.rise + fe.ascent);
    out.descent = std::max(out.descent, fe.descent - p.rise);
  }
  use_font(cr, face.value(), font.size_px);
  cairo_text_extents_t cap;
  cairo_text_extents(cr, "H", &cap);
  out.cap = -cap.y_bearing;
  cairo_restore(cr);
  return out;
}

void Canvas::text(Point at, std::string_view text, const Font& font, Rgb color, Anchor anchor,
                  bool upward) {
  if (text.empty() || !(font.size_px > 0.0)) return;
  Result<cairo_font_face_t*> face = detail::font_face(font.bold);
  if (!face.ok()) return;
  cairo_t* cr = impl_->cr;
  cairo_save(cr);
  const std::vector<detail::TextRun> runs = detail::parse_markup(text);
  const std::vector<Placed> placed = place(cr, face.value(), runs, font.size_px);
  double width = 0.0;
  for (const Placed& p : placed) width += p.advance;
  cairo_translate(cr, at.x, at.y);
  if (upward) cairo_rotate(cr, -0.5 * std::numbers::pi);
  double pen = anchor == Anchor::start ? 0.0 : anchor == Anchor::centre ? -0.5 * width : -width;
  cairo_set_source_rgb(cr, color.r / 255.0, color.g / 255.0, color.b / 255.0);
  for (const Placed& p : placed) {
    use_font(cr, face.value(), p.size);
    cairo_move_to(cr, pen, -p.rise);
    cairo_show_text(cr, p.run->text.c_str());
    pen += p.advance;
  }
  cairo_restore(cr);
}

}  // namespace ocean::plot
