// view/panel.hpp — the Dear ImGui panel of `ocean view`: every simulation and shading
// parameter, the LOD preset, time and view mode, and the frame's statistics. It edits plain
// state (PanelState, render::View) and says what changed; the caller applies it (a new sea
// state needs Scene::reconfigure, a new LOD preset a Renderer::draw before the next record).
//
// Simulation widgets report a change when the edit is finished (slider released, text entered,
// combo picked), not on every drag step: a reconfiguration rebuilds the spectrum.
#pragma once

#include <string>
#include <string_view>

#include "ocean/render.hpp"
#include "view/interaction.hpp"
#include "view/sea_controls.hpp"

namespace ocean::cli::view {

struct PanelState {
  SeaControls sea;
  int quality = 1;          ///< lod::QualityPreset index
  double time_scale = 1.0;  ///< simulated seconds per real second
  bool paused = false;
  std::string error;  ///< the last failed reconfiguration, shown in the panel
  BoatControls boat;  ///< the circling boat and its wake
  int shallows = 0;   ///< Shallows index
  bool taa = false;   ///< temporal anti-aliasing (View::temporal_aa)
};

/// What the panel shows but does not edit.
struct PanelStats {
  std::string_view device;   ///< Vulkan device name
  std::string_view backend;  ///< cpu, vulkan or cuda
  double frame_ms = 0.0;     ///< CPU frame time, median of the last 60 frames
  double sim_time_s = 0.0;
  int width = 0, height = 0;  ///< rendered pixels
  render::RenderStats render;
  lod::Vec3 camera;
  bool wireframe_available = false;  ///< the device has fillModeNonSolid
  /// Temporal anti-aliasing can be drawn: motion vectors of uploaded frames on the flat sea.
  bool taa_available = false;
};

struct PanelActions {
  bool sea_changed = false;       ///< state.sea was edited: reconfigure the simulation
  bool quality_changed = false;   ///< view.quality is a new preset
  bool reset_camera = false;      ///< back to the --camera/--target pose
  bool boat_changed = false;      ///< state.boat was edited: make the wake's layer again
  bool shallows_changed = false;  ///< state.shallows is a new scene
  bool taa_changed = false;       ///< state.taa was switched
  bool quit = false;
};

/// Draws the panel (between ImGui::NewFrame and ImGui::Render).
PanelActions draw_panel(PanelState& state, render::View& view, const PanelStats& stats);

}  // namespace ocean::cli::view
