// src/waves/waveform.cpp — a pre-authored height map placed in the world (Mitchell 2005, §3.4):
// validation and bilinear sampling under its rotation, size and amplitude (W.10), and the
// frames of an animated one blended in time (W.16).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "ocean/waves.hpp"

namespace ocean::waves {

namespace {

bool same_size(const HeightMap& a, const HeightMap& b) {
  return a.rows == b.rows && a.cols == b.cols;
}

bool well_formed(const HeightMap* m) {
  return m != nullptr && m->rows >= 1 && m->cols >= 1 &&
         m->values.size() == static_cast<std::size_t>(m->rows) * static_cast<std::size_t>(m->cols);
}

// The map every frame of the waveform has the shape of: the still map or frame 0.
const HeightMap& shape_of(const Waveform& w) {
  return w.frames.empty() ? *w.map : *w.frames.front();
}

// Bilinear sample of `map` at sample coordinates (u, v), clamped to the edge cells.
double bilinear(const HeightMap& map, double u, double v) {
  const double uc = std::clamp(u, 0.0, map.cols - 1.0), vc = std::clamp(v, 0.0, map.rows - 1.0);
  const int c0 = std::min(static_cast<int>(uc), map.cols - 1);
  const int r0 = std::min(static_cast<int>(vc), map.rows - 1);
  const int c1 = std::min(c0 + 1, map.cols - 1), r1 = std::min(r0 + 1, map.rows - 1);
  const double fc = uc - c0, fr = vc - r0;
  const auto at = [&](int row, int col) {
    return static_cast<double>(
        map.values[static_cast<std::size_t>(row) * static_cast<std::size_t>(map.cols) +
                   static_cast<std::size_t>(col)]);
  };
  const double top = at(r0, c0) * (1.0 - fc) + at(r0, c1) * fc;
  const double bottom = at(r1, c0) * (1.0 - fc) + at(r1, c1) * fc;
  return top * (1.0 - fr) + bottom * fr;
}

}  // namespace

Status validate(const Waveform& w) {
  if (w.frames.empty() && !well_formed(w.map.get()))
    return invalid_argument("waveform has no height map");
  for (std::size_t i = 0; i < w.frames.size(); ++i) {
    if (!well_formed(w.frames[i].get()))
      return invalid_argument("waveform frame " + std::to_string(i) + " has no height map");
    if (!same_size(*w.frames[i], *w.frames[0])) {
      return invalid_argument(
          "waveform frame " + std::to_string(i) + " is " + std::to_string(w.frames[i]->rows) + "x" +
          std::to_string(w.frames[i]->cols) + ", frame 0 " + std::to_string(w.frames[0]->rows) +
          "x" + std::to_string(w.frames[0]->cols) + ": frames must be of one size");
    }
  }
  if (!w.frames.empty()) {
    if (Status s = require_in_range("fps_hz", w.fps_hz, 1e-3, 1000.0); !s.ok()) return s;
    if (w.frames.size() > static_cast<std::size_t>(kMaxSequenceFrames))
      return invalid_argument("waveform has " + std::to_string(w.frames.size()) +
                              " frames: at most " + std::to_string(kMaxSequenceFrames));
  }
  if (Status s = require_finite("x_m", w.x_m); !s.ok()) return s;
  if (Status s = require_finite("z_m", w.z_m); !s.ok()) return s;
  if (Status s = require_positive("size_m", w.size_m); !s.ok()) return s;
  if (Status s = require_in_range("size_m", w.size_m, 1e-3, 1e6); !s.ok()) return s;
  if (Status s = require_finite("amplitude_m", w.amplitude_m); !s.ok()) return s;
  if (Status s = require_in_range("amplitude_m", w.amplitude_m, -1e3, 1e3); !s.ok()) return s;
  return require_finite("rotation_deg", w.rotation_deg);
}

FramePair frame_pair(const Waveform& w, double time_s) {
  const std::size_t count = w.frames.size();
  if (count < 2) return {};
  // s = t·fps frames since frame 0 (W.16): frame ⌊s⌋ blended towards the next by s − ⌊s⌋.
  const double s = time_s * w.fps_hz;
  if (w.playback == Playback::hold) {
    if (!(s > 0.0)) return {};
    if (s >= static_cast<double>(count - 1)) return {count - 1, count - 1, 0.0};
    const auto i = static_cast<std::size_t>(s);
    return {i, i + 1, s - static_cast<double>(i)};
  }
  const double n = static_cast<double>(count);
  double wrapped = std::fmod(s, n);  // in (−n, n)
  if (wrapped < 0.0) wrapped += n;
  if (!(wrapped < n)) wrapped = 0.0;  // −ε + n rounds to n
  const auto i = std::min(static_cast<std::size_t>(wrapped), count - 1);
  return {i, (i + 1) % count, wrapped - static_cast<double>(i)};
}

double waveform_height(const Waveform& w, double x, double z, double time_s) {
  const HeightMap& shape = shape_of(w);
  const double r = w.rotation_deg * std::numbers::pi / 180.0;
  const double dx = x - w.x_m, dz = z - w.z_m;
  // World offset into the map's frame: turn by −rotation.
  const double ux = dx * std::cos(r) + dz * std::sin(r);
  const double uz = -dx * std::sin(r) + dz * std::cos(r);
  const double width = w.size_m, depth = w.size_m * shape.rows / shape.cols;
  // Sample coordinates: cell c covers [c, c + 1) of the map, its value sits at c + ½.
  const double u = (ux / width + 0.5) * shape.cols - 0.5;
  const double v = (uz / depth + 0.5) * shape.rows - 0.5;
  if (!(u >= -0.5 && u <= shape.cols - 0.5 && v >= -0.5 && v <= shape.rows - 0.5)) return 0.0;
  if (w.frames.empty()) return w.amplitude_m * bilinear(*w.map, u, v);  // (W.10)
  const FramePair f = frame_pair(w, time_s);
  double h = bilinear(*w.frames[f.first], u, v);
  if (f.blend > 0.0) h += f.blend * (bilinear(*w.frames[f.second], u, v) - h);  // (W.16)
  return w.amplitude_m * h;
}

}  // namespace ocean::waves
