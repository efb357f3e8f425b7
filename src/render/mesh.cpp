// The renderer's geometry: the static patch mesh of src/lod (one vertex grid, the 16 stitching
// index lists and the skirt's indices in device-local buffers) and the horizon skirt's
// per-frame vertices.
#include "state.hpp"

namespace ocean::render {

Status build_patch_buffers(Renderer::State& st, int vertices) {
  Result<lod::PatchMeshes> meshes = lod::build_patch_meshes(vertices);
  if (!meshes.ok()) return meshes.status();
  Result<lod::SkirtMesh> skirt = lod::build_skirt(lod::kMinOceanSize_m, -1.0, kSkirtTessellation);
  if (!skirt.ok()) return skirt.status();
  std::vector<std::uint16_t> all;
  for (int c = 0; c < lod::kConfigurations; ++c) {
    st.index_first[static_cast<std::size_t>(c)] = static_cast<std::uint32_t>(all.size());
    const auto& list = meshes.value().indices[static_cast<std::size_t>(c)];
    st.index_count[static_cast<std::size_t>(c)] = static_cast<std::uint32_t>(list.size());
    all.insert(all.end(), list.begin(), list.end());
  }
  st.skirt_first = static_cast<std::uint32_t>(all.size());
  const std::size_t per_copy = skirt.value().positions_xz.size() / 2;
  for (std::size_t r = 0; r < 4; ++r) {
    for (std::uint16_t i : skirt.value().triangles)
      all.push_back(static_cast<std::uint16_t>(r * per_copy + i));
  }
  st.skirt_count = static_cast<std::uint32_t>(all.size()) - st.skirt_first;
  vk::destroy_buffer(*st.ctx, st.patch_vertices);
  vk::destroy_buffer(*st.ctx, st.indices);
  const auto& pos = meshes.value().positions_xz;
  Result<vk::Buffer> vb = vk::create_static_buffer(
      *st.ctx, st.commands, std::as_bytes(std::span(pos)), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  if (!vb.ok()) return vb.status();
  st.patch_vertices = vb.value();
  Result<vk::Buffer> ib = vk::create_static_buffer(
      *st.ctx, st.commands, std::as_bytes(std::span(all)), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  if (!ib.ok()) return ib.status();
  st.indices = ib.value();
  st.vertices = vertices;
  return {};
}

Status write_skirt_vertices(Renderer::State& st, const View& view, double extent_m) {
  // Skirt vertices relative to this frame's origin, the grid centre (R.16).
  if (st.skirt_size != view.ocean_size_m || st.skirt_extent != extent_m) {
    Result<lod::SkirtMesh> skirt =
        lod::build_skirt(view.ocean_size_m, extent_m, kSkirtTessellation);
    if (!skirt.ok()) return skirt.status();
    st.skirt = std::move(skirt).value();
    st.skirt_size = view.ocean_size_m, st.skirt_extent = extent_m;
  }
  auto* sv = static_cast<float*>(st.skirt_vertices.mapped);
  const std::size_t count = st.skirt.positions_xz.size() / 2;
  for (std::size_t r = 0; r < 4; ++r) {
    const auto [c, s] = st.skirt.rotations[r];
    for (std::size_t i = 0; i < count; ++i) {
      const float x = st.skirt.positions_xz[2 * i];
      const float z = st.skirt.positions_xz[2 * i + 1];
      sv[(r * count + i) * 2] = c * x + s * z;
      sv[(r * count + i) * 2 + 1] = -s * x + c * z;
    }
  }
  return {};
}

Status Renderer::prepare(const View& view) {
  State& st = *state_;
  if (view.quality.vertices == st.vertices) return {};
  if (Status s = lod::validate(view.quality); !s.ok()) return s;
  return build_patch_buffers(st, view.quality.vertices);
}

}  // namespace ocean::render
