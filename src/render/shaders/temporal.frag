#version 450
// Temporal anti-aliasing's blend (docs/rendering.md R.61): the frame, drawn with a sub-pixel
// jitter, into the history — the last result fetched where the pixel's surface point was a frame
// ago (the motion vectors of R.26, NDC now − previous, without the jitter) and clipped to the box
// of the frame's 3 × 3 neighbourhood, mean ± clip_sigmas standard deviations (Salvi 2016, "An
// excursion in temporal supersampling"). Colours are blended as c / (1 + L(c)) (Karis 2014, "High
// quality temporal supersampling"), so that a sun glint does not outweigh its neighbours. The
// frame's alpha is the share of current_weight it keeps (ocean.frag, sky.frag): 1 where the
// pixel resolves moving detail, 0 where it holds still (then steady_weight and steady_sigmas);
// the result's alpha is 1. A stereo frame's eyes (side by side) are blended each on its own.
layout(set = 0, binding = 0) uniform sampler2D frame_colour;  // nearest
layout(set = 0, binding = 1) uniform sampler2D history;       // bilinear, clamped
layout(set = 0, binding = 2) uniform sampler2D motion;        // nearest
layout(push_constant) uniform Push {
  float current_weight;  // the frame's share of the result
  float first_weight;    // 1/n over the history's first n frames (their mean)
  float clip_sigmas;     // the colour box's half-width, standard deviations of the neighbourhood
  float steady_weight;   // the frame's share where the picture stands still
  float steady_sigmas;   // the box's half-width where the picture stands still
  float eyes;            // 1, or 2: a stereo frame's eyes side by side, each its own picture
};
layout(location = 0) out vec4 colour;

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }
vec3 compress(vec3 c) { return c / (1.0 + luminance(c)); }
vec3 expand(vec3 c) { return c / max(1.0 - luminance(c), 1e-4); }

// h moved towards the box's centre until it lies inside the box.
vec3 clip_to_box(vec3 h, vec3 lo, vec3 hi) {
  vec3 centre = 0.5 * (lo + hi), half_size = 0.5 * (hi - lo) + 1e-6;
  vec3 v = h - centre;
  vec3 a = abs(v / half_size);
  float m = max(a.x, max(a.y, a.z));
  return m > 1.0 ? centre + v / m : h;
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  ivec2 size = textureSize(frame_colour, 0);
  // The pixel's eye: its columns [lo, hi); a stereo frame's eyes are pictures of their own.
  int eye_width = size.x / int(eyes + 0.5);
  int lo = (p.x / eye_width) * eye_width, hi = lo + eye_width;
  vec4 here = texelFetch(frame_colour, p, 0);
  vec3 m1 = vec3(0.0), m2 = vec3(0.0);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      ivec2 q = clamp(p + ivec2(dx, dy), ivec2(lo, 0), ivec2(hi - 1, size.y - 1));
      vec3 c = compress(max(texelFetch(frame_colour, q, 0).rgb, vec3(0.0)));
      m1 += c;
      m2 += c * c;
    }
  m1 /= 9.0;
  vec3 sigma = sqrt(max(m2 / 9.0 - m1 * m1, vec3(0.0)));
  vec3 now = compress(max(here.rgb, vec3(0.0)));
  // The pixel's centre in its eye's NDC (y up: the scene is drawn with a flipped viewport) a
  // frame ago.
  vec2 ndc = vec2((float(p.x - lo) + 0.5) / float(eye_width) * 2.0 - 1.0,
                  1.0 - (float(p.y) + 0.5) / float(size.y) * 2.0);
  vec2 moved = texelFetch(motion, p, 0).xy;
  vec2 before = ndc - moved;
  vec2 eye_uv = vec2(0.5 + 0.5 * before.x, 0.5 - 0.5 * before.y);
  bool off_screen = any(lessThan(eye_uv, vec2(0.0))) || any(greaterThan(eye_uv, vec2(1.0)));
  // Bilinear within the eye's columns, not across the seam.
  float x = clamp(float(lo) + eye_uv.x * float(eye_width), float(lo) + 0.5, float(hi) - 0.5);
  vec2 uv = vec2(x / float(size.x), eye_uv.y);
  float moving = clamp(here.a, 0.0, 1.0);
  float g = mix(steady_sigmas, clip_sigmas, moving);
  vec3 last = clip_to_box(compress(max(texture(history, uv).rgb, vec3(0.0))), m1 - g * sigma,
                          m1 + g * sigma);
  float pixel_weight = mix(steady_weight, current_weight, moving);
  float w = off_screen ? 1.0 : max(pixel_weight, first_weight);
  // w = 1 (a new history, or off screen) takes the frame alone: the history may be memory never
  // written, and a NaN in it would survive mix's zero weight.
  colour = vec4(expand(w >= 1.0 ? now : mix(last, now, w)), 1.0);
}
