// The ImGui panel of `ocean view` (see panel.hpp).
#include "view/panel.hpp"

#include <imgui.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <string_view>

#include "ocean/spectrum.hpp"

namespace ocean::cli::view {
namespace {

constexpr ImGuiSliderFlags kClamp = ImGuiSliderFlags_AlwaysClamp;
constexpr ImGuiSliderFlags kLog = ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic;

// A double slider; true while the value changes.
bool slider(const char* label, double& v, double lo, double hi, const char* format,
            ImGuiSliderFlags flags = kClamp) {
  return ImGui::SliderScalar(label, ImGuiDataType_Double, &v, &lo, &hi, format, flags);
}

// A simulation slider: `changed` is set once the edit is finished.
void sim_slider(const char* label, double& v, double lo, double hi, const char* format,
                bool& changed, ImGuiSliderFlags flags = kClamp) {
  slider(label, v, lo, hi, format, flags);
  changed = changed || ImGui::IsItemDeactivatedAfterEdit();
}

// The sliders' ranges: comfortable spans inside the library's ranges (kSeaStateParameters), so a
// slider at either end is always a valid sea.
struct SliderRange {
  std::string_view field;
  double lo, hi;  // in the field's unit
};
constexpr SliderRange kWindSlider{"wind_speed_mps", 0.5, 40.0};
constexpr SliderRange kFetchSliderKm{"fetch_m", 1.0, 2000.0};
constexpr SliderRange kHsSlider{"significant_wave_height_m", 0.1, 20.0};
constexpr SliderRange kTpSlider{"peak_period_s", 1.0, 25.0};
constexpr SliderRange kDepthSlider{"depth_m", 1.0, 1000.0};
constexpr bool inside(const SliderRange& r, double scale = 1.0) {
  const params::ParameterDoc& p = sea_state_parameter(r.field);
  return r.lo * scale >= p.lo && r.hi * scale <= p.hi;
}
static_assert(inside(kWindSlider) && inside(kFetchSliderKm, 1e3) && inside(kHsSlider) &&
              inside(kTpSlider) && inside(kDepthSlider));

void sea_section(PanelState& state, bool& changed) {
  SeaControls& s = state.sea;
  if (ImGui::Combo("spectrum", &s.model, kSpectrumModelLabels.data(),
                   static_cast<int>(kSpectrumModelLabels.size())))
    changed = true;
  const bool phillips = s.model == static_cast<int>(SpectrumModel::phillips);
  const bool jonswap_family = s.model == static_cast<int>(SpectrumModel::jonswap) ||
                              s.model == static_cast<int>(SpectrumModel::tma);
  ImGui::BeginDisabled(phillips);  // Phillips is defined by the wind only
  int form = s.from_wind || phillips ? 0 : 1;
  if (ImGui::RadioButton("from wind", &form, 0)) changed = true;
  ImGui::SameLine();
  if (ImGui::RadioButton("from Hs, Tp", &form, 1)) changed = true;
  s.from_wind = form == 0;
  ImGui::EndDisabled();
  if (s.from_wind || phillips) {
    sim_slider("wind speed", s.wind_speed_mps, kWindSlider.lo, kWindSlider.hi, "%.1f m/s", changed);
    ImGui::BeginDisabled(!jonswap_family);
    sim_slider("fetch", s.fetch_km, kFetchSliderKm.lo, kFetchSliderKm.hi, "%.0f km", changed, kLog);
    ImGui::EndDisabled();
  } else {
    sim_slider("Hs", s.hs_m, kHsSlider.lo, kHsSlider.hi, "%.2f m", changed);
    sim_slider("Tp", s.tp_s, kTpSlider.lo, kTpSlider.hi, "%.1f s", changed);
  }
  if (ImGui::Checkbox("deep water", &s.deep_water)) changed = true;
  ImGui::BeginDisabled(s.deep_water);
  sim_slider("depth", s.depth_m, kDepthSlider.lo, kDepthSlider.hi, "%.1f m", changed, kLog);
  ImGui::EndDisabled();
  sim_slider("direction", s.direction_deg, -180.0, 180.0, "%.0f deg", changed);
  sim_slider("choppiness", s.choppiness, 0.0, 3.0, "%.2f", changed);
}

void grid_section(PanelState& state, bool& changed) {
  SeaControls& s = state.sea;
  int index = 0;
  for (std::size_t i = 0; i < kPanelResolutions.size(); ++i)
    if (kPanelResolutions[i] == s.resolution) index = static_cast<int>(i);
  constexpr std::array<const char*, kPanelResolutions.size()> names = {"64", "128", "256", "512"};
  if (ImGui::Combo("resolution", &index, names.data(), static_cast<int>(names.size()))) {
    s.resolution = kPanelResolutions[static_cast<std::size_t>(index)];
    changed = true;
  }
  ImGui::SliderInt("cascades", &s.cascades, 1, kMaxPanelCascades, "%d", kClamp);
  changed = changed || ImGui::IsItemDeactivatedAfterEdit();
  for (int i = 0; i < s.cascades; ++i) {
    ImGui::PushID(i);
    char label[32];
    std::snprintf(label, sizeof label, "cascade %d", i + 1);
    const double step = 1.0, fast = 10.0;
    ImGui::InputScalar(label, ImGuiDataType_Double, &s.cascade_sizes_m[static_cast<std::size_t>(i)],
                       &step, &fast, "%.1f m");
    changed = changed || ImGui::IsItemDeactivatedAfterEdit();
    ImGui::PopID();
  }
  const std::int64_t one = 1, hundred = 100;
  ImGui::InputScalar("seed", ImGuiDataType_S64, &s.seed, &one, &hundred);
  changed = changed || ImGui::IsItemDeactivatedAfterEdit();
  sim_slider("loop period", s.loop_period_s, 0.0, 1000.0, "%.0f s", changed);
}

void shading_section(render::ShadingParams& sh) {
  slider("sun azimuth", sh.sun_azimuth_deg, -180.0, 180.0, "%.0f deg");
  slider("sun elevation", sh.sun_elevation_deg, -10.0, 90.0, "%.1f deg");
  slider("sun irradiance", sh.sun_irradiance, 1.0, 100.0, "%.1f", kLog);
  slider("sky brightness", sh.sky_brightness, 0.0, 4.0, "%.2f");
  slider("aerosol", sh.aerosol, 0.0, 10.0, "%.2f");
  slider("aerosol g", sh.aerosol_g, 0.0, 0.95, "%.2f");
  std::array<float, 3> colour{};
  for (std::size_t i = 0; i < 3; ++i) colour[i] = static_cast<float>(sh.water_colour[i]);
  if (ImGui::ColorEdit3("water colour", colour.data(), ImGuiColorEditFlags_Float)) {
    for (std::size_t i = 0; i < 3; ++i) sh.water_colour[i] = static_cast<double>(colour[i]);
  }
  slider("crest scatter", sh.crest_scatter, 0.0, 3.0, "%.2f");
  slider("foam brightness", sh.foam_brightness, 0.0, 4.0, "%.2f");
  slider("roughness", sh.roughness, 0.01, 1.0, "%.3f", kLog);
  slider("fog density", sh.fog_density_per_m, 0.0, 1e-3, "%.2e /m", kLog);
  slider("exposure", sh.exposure, 0.05, 10.0, "%.2f", kLog);
}

void view_section(PanelState& state, render::View& view, const PanelStats& stats,
                  PanelActions& actions) {
  if (ImGui::Combo("LOD preset", &state.quality, kQualityPresetLabels.data(),
                   static_cast<int>(kQualityPresetLabels.size()))) {
    view.quality = lod::quality_preset(static_cast<lod::QualityPreset>(state.quality));
    actions.quality_changed = true;
  }
  slider("ocean size", view.ocean_size_m, lod::kMinOceanSize_m, lod::kMaxOceanSize_m, "%.0f m",
         kLog);
  double fov_deg = view.camera.fov_y_rad * 180.0 / std::numbers::pi;
  if (slider("field of view", fov_deg, 10.0, 120.0, "%.0f deg"))
    view.camera.fov_y_rad = fov_deg * std::numbers::pi / 180.0;
  int mode = static_cast<int>(view.debug);
  ImGui::RadioButton("shaded", &mode, static_cast<int>(render::DebugView::shaded));
  ImGui::SameLine();
  ImGui::RadioButton("LOD colours", &mode, static_cast<int>(render::DebugView::lod_colours));
  ImGui::SameLine();
  ImGui::BeginDisabled(!stats.wireframe_available);
  ImGui::RadioButton("wireframe", &mode, static_cast<int>(render::DebugView::wireframe));
  ImGui::EndDisabled();
  view.debug = static_cast<render::DebugView>(mode);
  ImGui::BeginDisabled(!stats.taa_available);
  if (ImGui::Checkbox("temporal anti-aliasing", &state.taa)) actions.taa_changed = true;
  ImGui::EndDisabled();
  slider("time scale", state.time_scale, 0.0, 10.0, "%.2fx");
  ImGui::Checkbox("paused (Space)", &state.paused);
  ImGui::SameLine();
  if (ImGui::Button("reset camera")) actions.reset_camera = true;
  ImGui::SameLine();
  if (ImGui::Button("quit")) actions.quit = true;
}

void interaction_section(PanelState& state, PanelActions& actions) {
  if (ImGui::Checkbox("boat and its wake", &state.boat.on)) actions.boat_changed = true;
  ImGui::BeginDisabled(!state.boat.on);
  sim_slider("boat speed", state.boat.speed_mps, 1.0, 20.0, "%.1f m/s", actions.boat_changed);
  sim_slider("circle radius", state.boat.radius_m, 10.0, 500.0, "%.0f m", actions.boat_changed,
             kLog);
  ImGui::EndDisabled();
  if (ImGui::Combo("shallows", &state.shallows, kShallowsLabels.data(),
                   static_cast<int>(kShallowsLabels.size())))
    actions.shallows_changed = true;
}

void stats_section(const PanelStats& s) {
  ImGui::Text("frame %.1f ms (%.0f fps), CPU, median of 60", s.frame_ms,
              s.frame_ms > 0.0 ? 1000.0 / s.frame_ms : 0.0);
  ImGui::Text("patches %u  triangles %llu  draws %u", s.render.patches,
              static_cast<unsigned long long>(s.render.triangles), s.render.draw_calls);
  ImGui::Text("GPU %.2f ms  LOD select %.3f ms", s.render.gpu_ms, s.render.cpu_select_ms);
  ImGui::Text("%dx%d  t = %.1f s  backend %.*s", s.width, s.height, s.sim_time_s,
              static_cast<int>(s.backend.size()), s.backend.data());
  ImGui::Text("camera %.1f, %.1f, %.1f m", s.camera.x, s.camera.y, s.camera.z);
  ImGui::TextWrapped("%.*s", static_cast<int>(s.device.size()), s.device.data());
}

}  // namespace

PanelActions draw_panel(PanelState& state, render::View& view, const PanelStats& stats) {
  PanelActions actions;
  ImGui::SetNextWindowPos(ImVec2(8.0f, 8.0f), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(380.0f, 0.0f), ImGuiCond_FirstUseEver);
  if (!ImGui::Begin("ocean view")) {  // collapsed
    ImGui::End();
    return actions;
  }
  ImGui::PushItemWidth(-130.0f);
  bool sea_changed = false;
  if (ImGui::CollapsingHeader("Sea state", ImGuiTreeNodeFlags_DefaultOpen))
    sea_section(state, sea_changed);
  if (ImGui::CollapsingHeader("Grid")) grid_section(state, sea_changed);
  if (!state.error.empty()) {  // the last reconfiguration failed; the previous sea still runs
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.3f, 0.25f, 1.0f));
    ImGui::TextWrapped("%s", state.error.c_str());
    ImGui::PopStyleColor();
  }
  if (ImGui::CollapsingHeader("Boat and shallows")) interaction_section(state, actions);
  if (ImGui::CollapsingHeader("Shading")) shading_section(view.shading);
  if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen))
    view_section(state, view, stats, actions);
  if (ImGui::CollapsingHeader("Stats", ImGuiTreeNodeFlags_DefaultOpen)) stats_section(stats);
  ImGui::TextDisabled("WASD/arrows move, Q/E down/up, Shift fast,");
  ImGui::TextDisabled("right drag looks, F1 panel, Esc quits");
  ImGui::PopItemWidth();
  ImGui::End();
  actions.sea_changed = sea_changed;
  return actions;
}

}  // namespace ocean::cli::view
