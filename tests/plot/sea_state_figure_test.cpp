// The sea-state figure of `ocean spectrum --plot`: every panel's legend covers none of its curves
// (for the default sea state and a few others), and the figure renders at its size.
#include "sea_state_figure.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "plot.hpp"
#include "plot_internal.hpp"

namespace ocean::cli {
namespace {

bool meets_a_curve(const plot::Axes& ax, const plot::PanelLayout& l) {
  const plot::Box& b = *l.legend;
  for (const plot::Series& s : ax.series) {
    const double reach = 0.5 * s.width_px;
    const plot::Box near{b.x0 - reach, b.y0 - reach, b.x1 + reach, b.y1 + reach};
    for (std::size_t i = 1; i < s.x.size(); ++i) {
      // Points a log axis or a gap leaves out are not drawn.
      if (!std::isfinite(s.y[i - 1]) || !std::isfinite(s.y[i])) continue;
      const plot::Point p{l.x(s.x[i - 1]), l.y(s.y[i - 1])}, q{l.x(s.x[i]), l.y(s.y[i])};
      if (plot::detail::segment_meets_box(p, q, near)) return true;
    }
  }
  return false;
}

TEST(SeaStateFigure, LegendsCoverNoCurve) {
  std::vector<FrequencySpectrumParams> seas(4);
  seas[0].wind_speed_mps = 10.0;  // `ocean spectrum --plot`'s default sea state
  seas[0].fetch_m = 100e3;
  seas[1].model = SpectrumModel::tma;
  seas[1].wind_speed_mps = 12.0;
  seas[1].fetch_m = 50e3;
  seas[1].depth_m = 10.0;
  seas[2].model = SpectrumModel::pierson_moskowitz;
  seas[2].wind_speed_mps = 15.0;
  seas[3].significant_wave_height_m = 3.0;
  seas[3].peak_period_s = 9.0;
  for (const FrequencySpectrumParams& sea : seas) {
    Result<plot::Figure> figure = make_sea_state_figure(sea);
    ASSERT_TRUE(figure.ok()) << figure.status().message();
    Result<std::vector<plot::PanelLayout>> layout = plot::layout(figure.value());
    ASSERT_TRUE(layout.ok()) << layout.status().message();
    ASSERT_EQ(layout.value().size(), 4U);
    for (std::size_t i = 0; i < 4; ++i) {
      const plot::PanelLayout& l = layout.value()[i];
      ASSERT_TRUE(l.legend.has_value()) << "panel " << i;
      EXPECT_FALSE(meets_a_curve(figure.value().panels[i], l))
          << figure.value().title << ": the legend of panel " << i << " covers a curve";
    }
  }
}

TEST(SeaStateFigure, RendersAtItsSize) {
  FrequencySpectrumParams sea;
  sea.wind_speed_mps = 10.0;
  sea.fetch_m = 100e3;
  Result<plot::Figure> figure = make_sea_state_figure(sea);
  ASSERT_TRUE(figure.ok());
  Result<plot::Image> image = plot::render(figure.value());
  ASSERT_TRUE(image.ok()) << image.status().message();
  EXPECT_EQ(image.value().width, figure.value().width_px);
  EXPECT_EQ(image.value().height, figure.value().height_px);
}

}  // namespace
}  // namespace ocean::cli
