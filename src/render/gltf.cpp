// glTF 2.0 meshes (ocean/objects.hpp, load_gltf) read with tinygltf (Debian libtinygltf-dev):
// the triangle primitives of the default scene's node tree, transforms applied, with their
// metallic-roughness factors. Every accessor is bounds-checked against its buffer here (the
// parser does not), node trees are walked with a depth and visit limit (a malformed file may
// hold cycles), and images are never decoded (textures are not used).
//
// This work is based on: The Khronos Group, "glTF 2.0 Specification", 2021 — §3.5 (node
// transforms: matrix, or T·R·S), §3.6 (accessors, byte strides), §3.9 (metallic-roughness).
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "ocean/io.hpp"
#include "ocean/objects.hpp"

namespace ocean::render {

namespace {

using Mat4 = std::array<double, 16>;  // column-major
constexpr int kMaxDepth = 64;
constexpr std::size_t kMaxVisits = 100000;

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 c{};
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 4; ++row)
      for (int k = 0; k < 4; ++k) c[col * 4 + row] += a[k * 4 + row] * b[col * 4 + k];
  return c;
}

// §3.5: a node's matrix, or T·R·S from its translation, rotation (x, y, z, w) and scale.
Mat4 local_transform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    Mat4 m{};
    for (std::size_t i = 0; i < 16; ++i) m[i] = node.matrix[i];
    return m;
  }
  std::array<double, 3> t{0, 0, 0}, s{1, 1, 1};
  std::array<double, 4> q{1, 0, 0, 0};  // (w, x, y, z)
  if (node.translation.size() == 3)
    t = {node.translation[0], node.translation[1], node.translation[2]};
  if (node.scale.size() == 3) s = {node.scale[0], node.scale[1], node.scale[2]};
  if (node.rotation.size() == 4)
    q = {node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]};
  Mat4 m = model_matrix(t, q);
  for (int col = 0; col < 3; ++col)
    for (int row = 0; row < 3; ++row) m[col * 4 + row] *= s[static_cast<std::size_t>(col)];
  return m;
}

class Reader {
 public:
  Reader(const tinygltf::Model& model, std::string where)
      : model_(model), where_(std::move(where)) {}

  Status node(int index, const Mat4& parent, int depth) {
    if (index < 0 || static_cast<std::size_t>(index) >= model_.nodes.size())
      return bad("node " + std::to_string(index) + " does not exist");
    if (depth > kMaxDepth || ++visits_ > kMaxVisits)
      return bad("the node tree is deeper than 64 or has a cycle");
    const tinygltf::Node& n = model_.nodes[static_cast<std::size_t>(index)];
    const Mat4 world = multiply(parent, local_transform(n));
    if (n.mesh >= 0) {
      if (static_cast<std::size_t>(n.mesh) >= model_.meshes.size())
        return bad("mesh " + std::to_string(n.mesh) + " does not exist");
      for (const tinygltf::Primitive& p :
           model_.meshes[static_cast<std::size_t>(n.mesh)].primitives)
        if (Status s = primitive(p, world); !s.ok()) return s;
    }
    for (int child : n.children)
      if (Status s = node(child, world, depth + 1); !s.ok()) return s;
    return {};
  }

  std::vector<Mesh>& meshes() { return meshes_; }
  Status bad(const std::string& what) const { return invalid_argument(where_ + what); }

 private:
  // Where accessor a's element i starts, checked against its buffer.
  Result<const unsigned char*> element(int a, std::size_t bytes, std::size_t count) const {
    if (a < 0 || static_cast<std::size_t>(a) >= model_.accessors.size())
      return bad("accessor " + std::to_string(a) + " does not exist");
    const tinygltf::Accessor& acc = model_.accessors[static_cast<std::size_t>(a)];
    if (acc.bufferView < 0 || static_cast<std::size_t>(acc.bufferView) >= model_.bufferViews.size())
      return bad("accessor " + std::to_string(a) + " has no buffer view");
    const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(acc.bufferView)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model_.buffers.size())
      return bad("buffer view " + std::to_string(acc.bufferView) + " has no buffer");
    const std::vector<unsigned char>& data =
        model_.buffers[static_cast<std::size_t>(view.buffer)].data;
    const std::size_t stride = view.byteStride == 0 ? bytes : view.byteStride;
    const std::size_t start = view.byteOffset + acc.byteOffset;
    // Each product is bounded by the count check below before it can overflow.
    if (count == 0 || count > kMaxMeshElements || stride > 4096 || start > data.size() ||
        (count - 1) * stride + bytes > data.size() - start ||
        view.byteOffset + view.byteLength > data.size())
      return bad("accessor " + std::to_string(a) + " reaches outside its buffer");
    return data.data() + start;
  }

  Status vec3s(int a, std::vector<std::array<float, 3>>& out) const {
    const tinygltf::Accessor& acc = model_.accessors[static_cast<std::size_t>(a)];
    if (acc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || acc.type != TINYGLTF_TYPE_VEC3 ||
        acc.sparse.isSparse)
      return bad("accessor " + std::to_string(a) + " is not a dense float VEC3");
    Result<const unsigned char*> p = element(a, 12, acc.count);
    if (!p.ok()) return p.status();
    const auto& view = model_.bufferViews[static_cast<std::size_t>(acc.bufferView)];
    const std::size_t stride = view.byteStride == 0 ? 12 : view.byteStride;
    out.resize(acc.count);
    for (std::size_t i = 0; i < acc.count; ++i)
      std::memcpy(out[i].data(), p.value() + i * stride, 12);
    return {};
  }

  Status indices(int a, std::size_t vertices, std::vector<std::uint32_t>& out) const {
    if (a < 0) {  // non-indexed: 0, 1, 2, ...
      out.resize(vertices);
      for (std::size_t i = 0; i < vertices; ++i) out[i] = static_cast<std::uint32_t>(i);
      return {};
    }
    if (static_cast<std::size_t>(a) >= model_.accessors.size())
      return bad("accessor " + std::to_string(a) + " does not exist");
    const tinygltf::Accessor& acc = model_.accessors[static_cast<std::size_t>(a)];
    std::size_t size = 0;
    switch (acc.componentType) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: size = 1; break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: size = 2; break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: size = 4; break;
      default: return bad("index accessor " + std::to_string(a) + " is not unsigned integer");
    }
    if (acc.type != TINYGLTF_TYPE_SCALAR || acc.sparse.isSparse)
      return bad("index accessor " + std::to_string(a) + " is not a dense scalar");
    Result<const unsigned char*> p = element(a, size, acc.count);
    if (!p.ok()) return p.status();
    const auto& view = model_.bufferViews[static_cast<std::size_t>(acc.bufferView)];
    const std::size_t stride = view.byteStride == 0 ? size : view.byteStride;
    out.resize(acc.count);
    for (std::size_t i = 0; i < acc.count; ++i) {
      std::uint32_t v = 0;
      std::memcpy(&v, p.value() + i * stride, size);  // little-endian (glTF §3.6.2.1)
      out[i] = v;
    }
    return {};
  }

  Status primitive(const tinygltf::Primitive& p, const Mat4& world) {
    if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != -1) return {};  // points, lines, strips
    const auto position = p.attributes.find("POSITION");
    if (position == p.attributes.end()) return bad("a primitive has no POSITION");
    if (position->second < 0 ||
        static_cast<std::size_t>(position->second) >= model_.accessors.size())
      return bad("accessor " + std::to_string(position->second) + " does not exist");
    Mesh mesh;
    if (Status s = vec3s(position->second, mesh.positions); !s.ok()) return s;
    if (Status s = indices(p.indices, mesh.positions.size(), mesh.indices); !s.ok()) return s;
    mesh.indices.resize(mesh.indices.size() / 3 * 3);
    const auto normal = p.attributes.find("NORMAL");
    if (normal != p.attributes.end() && normal->second >= 0 &&
        static_cast<std::size_t>(normal->second) < model_.accessors.size()) {
      if (Status s = vec3s(normal->second, mesh.normals); !s.ok()) return s;
      if (mesh.normals.size() != mesh.positions.size())
        return bad("a primitive has " + std::to_string(mesh.normals.size()) + " normals for " +
                   std::to_string(mesh.positions.size()) + " positions");
    }
    if (p.material >= 0 && static_cast<std::size_t>(p.material) < model_.materials.size()) {
      const auto& pbr = model_.materials[static_cast<std::size_t>(p.material)].pbrMetallicRoughness;
      if (pbr.baseColorFactor.size() >= 3)
        for (std::size_t c = 0; c < 3; ++c)
          mesh.material.base_colour[c] = std::clamp(pbr.baseColorFactor[c], 0.0, 1.0);
      mesh.material.metallic = std::clamp(pbr.metallicFactor, 0.0, 1.0);
      mesh.material.roughness = std::clamp(pbr.roughnessFactor, 0.02, 1.0);
    }
    for (std::uint32_t i : mesh.indices)
      if (i >= mesh.positions.size()) return bad("index " + std::to_string(i) + " is out of range");
    transform(world, mesh);
    if (Status s = validate(mesh); !s.ok()) return bad(s.message());
    meshes_.push_back(std::move(mesh));
    return {};
  }

  // Positions by the matrix; normals by its cofactor matrix (the inverse transpose times the
  // determinant), renormalised; a mirroring transform reverses the winding. Missing normals are
  // the faces' own (flat shading).
  static void transform(const Mat4& m, Mesh& mesh) {
    const auto at = [&](int row, int col) { return m[static_cast<std::size_t>(col * 4 + row)]; };
    for (auto& p : mesh.positions) {
      const double x = p[0], y = p[1], z = p[2];
      for (int r = 0; r < 3; ++r)
        p[static_cast<std::size_t>(r)] =
            static_cast<float>(at(r, 0) * x + at(r, 1) * y + at(r, 2) * z + at(r, 3));
    }
    const double det = at(0, 0) * (at(1, 1) * at(2, 2) - at(1, 2) * at(2, 1)) -
                       at(0, 1) * (at(1, 0) * at(2, 2) - at(1, 2) * at(2, 0)) +
                       at(0, 2) * (at(1, 0) * at(2, 1) - at(1, 1) * at(2, 0));
    if (det < 0.0)
      for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
    if (mesh.normals.empty()) {
      std::vector<std::array<double, 3>> vertices(mesh.positions.size());
      for (std::size_t i = 0; i < vertices.size(); ++i)
        vertices[i] = {mesh.positions[i][0], mesh.positions[i][1], mesh.positions[i][2]};
      std::vector<std::array<std::uint32_t, 3>> triangles(mesh.indices.size() / 3);
      for (std::size_t t = 0; t < triangles.size(); ++t)
        triangles[t] = {mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]};
      mesh = flat_mesh(vertices, triangles, mesh.material);
      return;
    }
    const auto cof = [&](int r, int c) {
      const int r0 = (r + 1) % 3, r1 = (r + 2) % 3, c0 = (c + 1) % 3, c1 = (c + 2) % 3;
      return at(r0, c0) * at(r1, c1) - at(r0, c1) * at(r1, c0);
    };
    for (auto& n : mesh.normals) {
      const double x = n[0], y = n[1], z = n[2];
      double out[3];
      for (int r = 0; r < 3; ++r) out[r] = cof(r, 0) * x + cof(r, 1) * y + cof(r, 2) * z;
      double len = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
      if (!(len > 0.0)) len = 1.0, out[1] = 1.0;
      const double sign = det < 0.0 ? -1.0 : 1.0;
      for (std::size_t r = 0; r < 3; ++r) n[r] = static_cast<float>(sign * out[r] / len);
    }
  }

  const tinygltf::Model& model_;
  std::string where_;
  std::size_t visits_ = 0;
  std::vector<Mesh> meshes_;
};

// Textures are not used: accept every image without decoding it.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                const unsigned char*, int, void*) {
  return true;
}

// tinygltf's test for a buffer file, without opening it (tinygltf's own opens the file, and the
// open of a FIFO waits for a writer for ever).
bool file_exists(const std::string& path, void* /*user_data*/) {
  std::error_code ec;
  return std::filesystem::exists(path, ec);
}

// tinygltf's file reads (a .gltf's neighbouring .bin buffers) under the same limit as the file
// itself: a buffer named /dev/zero or a FIFO is refused, not read until memory runs out.
// `user_data` is the Status that load_gltf reports when the read fails.
bool read_bounded_buffer(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                         void* user_data) {
  const Result<std::string> bytes = io::read_bounded(
      path, {.max_bytes = kMaxGltfFileBytes, .what = "glTF buffer", .regular_only = true});
  if (!bytes.ok()) {
    if (err != nullptr) *err = bytes.status().message();
    *static_cast<Status*>(user_data) = bytes.status();
    return false;
  }
  out->assign(bytes.value().begin(), bytes.value().end());
  return true;
}

}  // namespace

Result<std::vector<Mesh>> load_gltf(const std::filesystem::path& path) {
  const std::string where = "cannot read '" + excerpt(path.string()) + "': ";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    return io_error(where +
                    (std::filesystem::exists(path, ec) ? "not a regular file" : "no such file"));
  tinygltf::Model model;
  std::string err, warn;
  bool loaded = false;
  Status buffer_read;  // the first refused buffer file
  try {
    const Result<std::string> bytes = io::read_bounded(
        path, {.max_bytes = kMaxGltfFileBytes, .what = "glTF file", .regular_only = true});
    if (!bytes.ok()) return bytes.status();
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skip_image, nullptr);
    loader.SetFsCallbacks({.FileExists = &file_exists,
                           .ExpandFilePath = &tinygltf::ExpandFilePath,
                           .ReadWholeFile = &read_bounded_buffer,
                           .WriteWholeFile = &tinygltf::WriteWholeFile,
                           .user_data = &buffer_read});
    const std::string ext = path.extension().string();
    const std::string base_dir = path.parent_path().string();
    const std::string& text = bytes.value();
    loaded = ext == ".gltf"
                 ? loader.LoadASCIIFromString(&model, &err, &warn, text.data(),
                                              static_cast<unsigned int>(text.size()), base_dir)
                 : loader.LoadBinaryFromMemory(&model, &err, &warn,
                                               reinterpret_cast<const unsigned char*>(text.data()),
                                               static_cast<unsigned int>(text.size()), base_dir);
  } catch (const std::exception& e) {
    err = e.what();
  } catch (...) {
    err = "the parser failed";
  }
  if (!loaded && !buffer_read.ok()) return buffer_read;
  if (!loaded) {
    std::string first = err.substr(0, err.find('\n'));
    if (first.empty()) first = "not a glTF 2.0 file";
    return invalid_argument(where + excerpt(first));
  }
  Reader reader(model, where);
  const Mat4 identity{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  if (!model.scenes.empty()) {
    const std::size_t s = model.defaultScene >= 0 &&
                                  static_cast<std::size_t>(model.defaultScene) < model.scenes.size()
                              ? static_cast<std::size_t>(model.defaultScene)
                              : 0;
    for (int n : model.scenes[s].nodes)
      if (Status st = reader.node(n, identity, 0); !st.ok()) return st;
  } else {
    for (std::size_t n = 0; n < model.nodes.size(); ++n)
      if (Status st = reader.node(static_cast<int>(n), identity, 0); !st.ok()) return st;
  }
  if (reader.meshes().empty()) return reader.bad("it holds no triangles");
  return std::move(reader.meshes());
}

}  // namespace ocean::render
