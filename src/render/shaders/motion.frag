#version 450
// Motion vectors of the water (docs/rendering.md R.26): the NDC position of the pixel's surface
// point now minus where the same point (the same undisplaced label, the previous frame's
// displacement and camera) was a frame ago. Clip positions are interpolated perspective-
// correctly and divided here. The renderer turns NDC into pixels when reading back.
layout(location = 3) in vec4 clip_now;
layout(location = 4) in vec4 clip_previous;
layout(location = 0) out vec2 motion;

void main() { motion = clip_now.xy / clip_now.w - clip_previous.xy / clip_previous.w; }
