// The sea-state figure (see sea_state_figure.hpp).
#include "sea_state_figure.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace ocean::cli {

namespace {

constexpr plot::Rgb kBlack{20, 20, 20};
constexpr plot::Rgb kPalette[] = {{31, 119, 180}, {255, 127, 14},  {44, 160, 44},
                                  {214, 39, 40},  {148, 103, 189}, {140, 86, 75}};

std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> v(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = a + (b - a) * i / (n - 1);
  return v;
}

std::string fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

std::string describe(const FrequencySpectrumParams& p) {
  std::string text(to_string(p.model));
  if (!std::isnan(p.significant_wave_height_m)) {
    text += ", Hs = " + fixed(p.significant_wave_height_m, 2) +
            " m, Tp = " + fixed(p.peak_period_s, 1) + " s";
  } else {
    text += ", U = " + fixed(p.wind_speed_mps, 1) + " m/s";
    if (!std::isnan(p.fetch_m)) text += ", F = " + fixed(p.fetch_m / 1000.0, 0) + " km";
  }
  if (std::isfinite(p.depth_m)) text += ", h = " + fixed(p.depth_m, 1) + " m";
  return text;
}

plot::Series curve(std::string label, std::vector<double> x, std::vector<double> y, plot::Rgb color,
                   double width = 2.5, bool dashed = false) {
  return {.label = std::move(label),
          .x = std::move(x),
          .y = std::move(y),
          .color = color,
          .width_px = width,
          .dashed = dashed};
}

// Leaves room above the data for the legend box in the upper-right corner.
void leave_legend_room(plot::Axes& axes, double factor) {
  double top = 0.0;
  for (const plot::Series& series : axes.series) {
    for (double y : series.y) {
      if (std::isfinite(y)) top = std::max(top, y);
    }
  }
  if (top > 0.0) axes.y_max = top * factor;
}

plot::Axes spectra_panel(const FrequencySpectrum& chosen) {
  const FrequencySpectrumParams& cp = chosen.params();
  const double wp = chosen.peak_omega();
  const std::vector<double> omega = linspace(0.02 * wp, 4.0 * wp, 600);
  plot::Axes axes{
      .title = "Frequency spectra S(ω)", .x_label = "ω, rad/s", .y_label = "S, m^2·s/rad"};
  axes.x_min = 0.0;
  axes.y_min = 0.0;
  // The other families for the same sea state, for comparison.
  std::vector<FrequencySpectrumParams> others;
  const bool hs_form = !std::isnan(cp.significant_wave_height_m);
  for (SpectrumModel m : {SpectrumModel::pierson_moskowitz, SpectrumModel::jonswap,
                          SpectrumModel::tma, SpectrumModel::phillips}) {
    if (m == cp.model || (hs_form && m == SpectrumModel::phillips)) continue;
    FrequencySpectrumParams q = cp;
    q.model = m;
    q.depth_m =
        m == SpectrumModel::tma ? (std::isfinite(cp.depth_m) ? cp.depth_m : 10.0) : kInfiniteDepth;
    const bool jonswap_family = m == SpectrumModel::jonswap || m == SpectrumModel::tma;
    if (!hs_form && jonswap_family && std::isnan(q.fetch_m)) q.fetch_m = kDefaultFetchM;
    if (!jonswap_family) {
      q.fetch_m = kUnset;
      q.gamma = kUnset;
    }
    if (m != SpectrumModel::phillips) {
      q.phillips_amplitude = kUnset;
      q.small_wave_cutoff_m = 0.0;
    }
    others.push_back(q);
  }
  std::size_t color = 0;
  for (const FrequencySpectrumParams& q : others) {
    Result<FrequencySpectrum> s = FrequencySpectrum::make(q);
    if (!s.ok()) continue;  // a comparison that does not apply to this sea state is left out
    std::vector<double> y;
    for (double w : omega) y.push_back(s.value()(w));
    axes.series.push_back(curve(describe(q), omega, y, kPalette[color++ % 6], 2.0, true));
  }
  std::vector<double> y;
  for (double w : omega) y.push_back(chosen(w));
  axes.series.push_back(
      curve(describe(cp) + " (Hs " + fixed(chosen.hs_m(), 2) + " m)", omega, y, kBlack, 3.5));
  leave_legend_room(axes, 1.45);
  return axes;
}

plot::Axes spreading_panel(const FrequencySpectrum& chosen) {
  const FrequencySpectrumParams& cp = chosen.params();
  const double wind = std::isnan(cp.wind_speed_mps)
                          ? 0.877 * cp.gravity_mps2 / chosen.peak_omega()  // PM-equivalent wind
                          : cp.wind_speed_mps;
  const SpreadingContext context{
      .omega_p = chosen.peak_omega(), .wind_speed_mps = wind, .gravity_mps2 = cp.gravity_mps2};
  const std::vector<double> degrees = linspace(-180.0, 180.0, 721);
  plot::Axes axes{
      .title = "Directional spreading D(θ) at ω = ωp", .x_label = "θ, °", .y_label = "D, 1/rad"};
  axes.x_min = -180.0;
  axes.x_max = 180.0;
  axes.y_min = 0.0;
  const struct {
    SpreadingParams params;
    const char* label;
  } models[] = {
      {{.model = SpreadingModel::power_cosine}, "power-cosine, α = 1 (s = 6, σ = 0.01)"},
      {{.model = SpreadingModel::cos2s, .s = 10.0}, "cos-2s, s = 10"},
      {{.model = SpreadingModel::mitsuyasu}, "Mitsuyasu 1975"},
      {{.model = SpreadingModel::hasselmann}, "Hasselmann 1980"},
      {{.model = SpreadingModel::donelan_banner}, "Donelan-Banner"},
  };
  std::size_t color = 0;
  for (const auto& m : models) {
    Result<Spreading> d = Spreading::make(m.params, context);
    if (!d.ok()) continue;
    std::vector<double> y;
    for (double deg : degrees) y.push_back(d.value()(chosen.peak_omega(), deg * kPi / 180.0));
    axes.series.push_back(curve(m.label, degrees, y, kPalette[color++ % 6]));
  }
  leave_legend_room(axes, 1.5);
  return axes;
}

plot::Axes depth_factor_panel() {
  const std::vector<double> omega_h = linspace(0.01, 3.0, 300);
  const double g = kDefaultGravity;
  const double depth = 10.0;
  std::vector<double> exact;
  std::vector<double> tv;
  for (double wh : omega_h) {
    const double omega = wh * std::sqrt(g / depth);
    exact.push_back(tma_depth_factor(omega, depth, g, DepthFactor::exact));
    tv.push_back(tma_depth_factor(omega, depth, g, DepthFactor::thompson_vincent));
  }
  plot::Axes axes{.title = "TMA depth factor Φ(ωh)", .x_label = "ωh = ω·√(h/g)", .y_label = "Φ"};
  axes.x_min = 0.0;
  axes.y_min = 0.0;
  axes.y_max = 1.1;
  axes.series.push_back(curve("exact (Kitaigorodskii)", omega_h, exact, kPalette[0], 3.0));
  axes.series.push_back(curve("Thompson-Vincent", omega_h, tv, kPalette[1], 2.5, true));
  return axes;
}

plot::Axes dispersion_panel() {
  const std::vector<double> period = linspace(1.0, 20.0, 400);
  plot::Axes axes{.title = "Dispersion: wavelength against period",
                  .x_label = "T, s",
                  .y_label = "wavelength, m"};
  axes.x_min = 0.0;
  axes.y_min = 0.0;
  const double depths[] = {kInfiniteDepth, 50.0, 10.0, 3.0};
  std::size_t color = 0;
  for (double h : depths) {
    const Dispersion d = Dispersion::make({.depth_m = h}).value();
    std::vector<double> length;
    for (double t : period) length.push_back(2.0 * kPi / d.wavenumber(2.0 * kPi / t));
    const std::string label = std::isinf(h) ? "deep water" : "h = " + fixed(h, 0) + " m";
    axes.series.push_back(curve(label, period, length, kPalette[color++ % 6]));
  }
  leave_legend_room(axes, 1.4);
  return axes;
}

}  // namespace

Result<plot::Figure> make_sea_state_figure(const FrequencySpectrumParams& params) {
  Result<FrequencySpectrum> chosen = FrequencySpectrum::make(params);
  if (!chosen.ok()) return chosen.status();
  const FrequencySpectrum& s = chosen.value();
  plot::Figure figure{.width_px = 1800, .height_px = 1200, .rows = 2, .cols = 2};
  figure.title = "Sea state: " + describe(params) + "  —  Hs = " + fixed(s.hs_m(), 2) +
                 " m, Tp = " + fixed(2.0 * kPi / s.peak_omega(), 2) + " s";
  figure.panels = {spectra_panel(s), spreading_panel(s), depth_factor_panel(), dispersion_panel()};
  return figure;
}

}  // namespace ocean::cli
