// mips.wgsl — the mip chain of one cascade's normal/foam map, a layer of an rgba16float 2D-array
// texture: level 0 takes (n, foam) per texel from the simulation's buffers, each further level is
// the 2×2 box filter of the one above it. The averaged, unnormalised normals shorten where the
// slopes vary (Toksvig 2005); the renderer samples the chain trilinearly.
// Mirrors mips.comp and cpu::build_mips (src/backends/cpu/mips.cpp), without their roughness
// scaling and rgba8 packing.
//
// This work is based on:
//   - Aebi, VR Ocean, §3.9 and §4.4: eq. 52 (box filter of unnormalised normals).
//   - Toksvig, M. (2005) Mipmapping normal maps, J. Graphics Tools 10(3).
// Equations: docs/math.md (M.7.5).

@group(0) @binding(0) var<storage, read> surface: array<vec4f>;  // (n, J) per texel
@group(0) @binding(1) var<storage, read> foam: array<f32>;
@group(0) @binding(2) var level0: texture_storage_2d<rgba16float, write>;
@group(0) @binding(3) var source: texture_2d<f32>;                     // level m − 1
@group(0) @binding(4) var dest: texture_storage_2d<rgba16float, write>;  // level m

// Dispatch (N/8, N/8): (nx, ny, nz, foam) at texel (col, row).
@compute @workgroup_size(8, 8)
fn copy_level0(@builtin(global_invocation_id) id: vec3u) {
  let size = textureDimensions(level0);
  if (id.x >= size.x || id.y >= size.y) {
    return;
  }
  let i = id.y * size.x + id.x;
  textureStore(level0, id.xy, vec4f(surface[i].xyz, foam[i]));
}

// Dispatch (⌈size/8⌉, ⌈size/8⌉) with size the destination side: eq. 52.
@compute @workgroup_size(8, 8)
fn box_filter(@builtin(global_invocation_id) id: vec3u) {
  let size = textureDimensions(dest);
  if (id.x >= size.x || id.y >= size.y) {
    return;
  }
  let s = vec2i(2 * id.xy);
  let sum = textureLoad(source, s, 0) + textureLoad(source, s + vec2i(1, 0), 0) +
            textureLoad(source, s + vec2i(0, 1), 0) + textureLoad(source, s + vec2i(1, 1), 0);
  textureStore(dest, id.xy, 0.25 * sum);
}
