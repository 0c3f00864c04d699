#include "assets/gltf_model.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <limits>
#include <set>

#include "assets/model_normals.h"
#include "core/error.h"

// tinygltf's implementation lives here; images go through OpenImageIO (decodeImage), not stb.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <tiny_gltf.h>

namespace terrasol {
namespace {

constexpr std::size_t kMaxVertices = std::size_t{1} << 24;  // per model: a prop, not a world
constexpr int kMaxNodeDepth = 64;

std::string at(const char* array, std::size_t index) {
  std::string s = array;
  s += '[';
  s += std::to_string(index);
  s += ']';
  return s;
}

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  std::string message = where;
  message += ": ";
  message += what;
  throw Error(message);
}

// An accessor's elements, checked to lie inside its buffer view and buffer.
struct View {
  const std::uint8_t* data = nullptr;
  std::size_t stride = 0, count = 0;
  int componentType = 0, components = 0;
  bool normalized = false;
};

View viewOf(const tinygltf::Model& m, int index, const std::string& user) {
  if (index < 0 || static_cast<std::size_t>(index) >= m.accessors.size()) {
    fail(user, "accessor " + std::to_string(index) + " does not exist");
  }
  const std::string key = at("accessors", static_cast<std::size_t>(index));
  const tinygltf::Accessor& a = m.accessors[static_cast<std::size_t>(index)];
  if (a.sparse.isSparse) fail(key, "sparse accessors are not supported");
  if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= m.bufferViews.size()) {
    fail(key, "has no buffer view (accessors without data are not supported)");
  }
  const tinygltf::BufferView& bv = m.bufferViews[static_cast<std::size_t>(a.bufferView)];
  const std::string bvKey = at("bufferViews", static_cast<std::size_t>(a.bufferView));
  if (bv.buffer < 0 || static_cast<std::size_t>(bv.buffer) >= m.buffers.size())
    fail(bvKey, "names no buffer");
  const tinygltf::Buffer& buffer = m.buffers[static_cast<std::size_t>(bv.buffer)];
  if (bv.byteOffset > buffer.data.size() || bv.byteLength > buffer.data.size() - bv.byteOffset) {
    fail(bvKey, "reaches past the end of " + at("buffers", static_cast<std::size_t>(bv.buffer)) + " (" +
                    std::to_string(buffer.data.size()) + " bytes)");
  }
  const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
  const int size = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
  if (components <= 0 || size <= 0) fail(key, "has an unknown type or component type");
  if (a.count > kMaxVertices * 3)
    fail(key, "has " + std::to_string(a.count) + " elements, more than a prop may have");
  const std::size_t element = static_cast<std::size_t>(components) * static_cast<std::size_t>(size);
  const std::size_t stride = bv.byteStride ? bv.byteStride : element;
  if (stride < element) fail(bvKey, "has a byte stride smaller than the elements of " + key);
  const std::size_t bytes = a.count == 0 ? 0 : stride * (a.count - 1) + element;
  if (a.byteOffset > bv.byteLength || bytes > bv.byteLength - a.byteOffset) {
    fail(key, std::to_string(a.count) + " elements from byte " + std::to_string(a.byteOffset) +
                  " reach past the end of " + bvKey + " (" + std::to_string(bv.byteLength) + " bytes)");
  }
  return {buffer.data.data() + bv.byteOffset + a.byteOffset,
          stride,
          a.count,
          a.componentType,
          components,
          a.normalized};
}

template <class T>
T readAs(const std::uint8_t* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// Component c of element i as a float (normalised integers mapped to [0, 1] or [-1, 1]).
float component(const View& v, std::size_t i, int c) {
  const std::uint8_t* p = v.data + i * v.stride;
  switch (v.componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return readAs<float>(p + 4 * c);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return p[c] / (v.normalized ? 255.0f : 1.0f);
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return v.normalized ? std::max(readAs<std::int8_t>(p + c) / 127.0f, -1.0f) : readAs<std::int8_t>(p + c);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return readAs<std::uint16_t>(p + 2 * c) / (v.normalized ? 65535.0f : 1.0f);
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return v.normalized ? std::max(readAs<std::int16_t>(p + 2 * c) / 32767.0f, -1.0f)
                          : readAs<std::int16_t>(p + 2 * c);
    default:
      return 0.0f;
  }
}

// An attribute's accessor, required to have `components` components per element and `count` elements.
const View* attribute(const tinygltf::Model& m, const tinygltf::Primitive& p, const char* name,
                      int components, std::size_t count, const std::string& where, View& out) {
  const auto it = p.attributes.find(name);
  if (it == p.attributes.end()) return nullptr;
  out = viewOf(m, it->second, where + ".attributes." + name);
  if (out.components != components) fail(where + ".attributes." + name, "has the wrong element type");
  if (count != 0 && out.count != count)
    fail(where + ".attributes." + name, "has a different count than POSITION");
  return &out;
}

ModelMesh readPrimitive(const tinygltf::Model& m, const tinygltf::Primitive& p, const std::string& where,
                        const glm::mat4& transform) {
  if (p.mode != TINYGLTF_MODE_TRIANGLES)
    fail(where, "only triangles are supported (mode " + std::to_string(p.mode) + ")");
  View positions, normals, tangents, uvs, indices;
  if (!attribute(m, p, "POSITION", 3, 0, where, positions)) fail(where, "has no POSITION");
  if (positions.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
    fail(where + ".attributes.POSITION", "must be floats");
  const std::size_t n = positions.count;
  const bool hasNormal = attribute(m, p, "NORMAL", 3, n, where, normals) != nullptr;
  const bool hasTangent = attribute(m, p, "TANGENT", 4, n, where, tangents) != nullptr;
  const bool hasUv = attribute(m, p, "TEXCOORD_0", 2, n, where, uvs) != nullptr;
  ModelMesh mesh;
  mesh.material = p.material;
  if (p.material >= static_cast<int>(m.materials.size())) fail(where + ".material", "does not exist");
  mesh.vertices.resize(n);
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(transform)));
  for (std::size_t i = 0; i < n; ++i) {
    ModelVertex& v = mesh.vertices[i];
    const glm::vec3 local(component(positions, i, 0), component(positions, i, 1), component(positions, i, 2));
    if (!std::isfinite(local.x) || !std::isfinite(local.y) || !std::isfinite(local.z)) {
      fail(where + ".attributes.POSITION", "holds a NaN or infinite coordinate");
    }
    v.position = glm::vec3(transform * glm::vec4(local, 1.0f));
    if (hasNormal) {
      v.normal = safeNormalize(normalMatrix * glm::vec3(component(normals, i, 0), component(normals, i, 1),
                                                        component(normals, i, 2)),
                               {0, 1, 0});
    }
    if (hasTangent) {
      const glm::vec3 t =
          glm::mat3(transform) *
          glm::vec3(component(tangents, i, 0), component(tangents, i, 1), component(tangents, i, 2));
      v.tangent = glm::vec4(safeNormalize(t, {1, 0, 0}), component(tangents, i, 3) < 0.0f ? -1.0f : 1.0f);
    }
    if (hasUv) v.uv = {component(uvs, i, 0), component(uvs, i, 1)};
  }
  if (p.indices >= 0) {
    indices = viewOf(m, p.indices, where + ".indices");
    const int type = indices.componentType;
    if (indices.components != 1 ||
        (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
         type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)) {
      fail(where + ".indices", "must be unsigned bytes, shorts or ints");
    }
    mesh.indices.resize(indices.count);
    for (std::size_t i = 0; i < indices.count; ++i) {
      const std::uint8_t* e = indices.data + i * indices.stride;
      const std::uint32_t index = type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? e[0]
                                  : type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? readAs<std::uint16_t>(e)
                                                                                   : readAs<std::uint32_t>(e);
      if (index >= n)
        fail(where + ".indices",
             "index " + std::to_string(index) + " is past the " + std::to_string(n) + " vertices");
      mesh.indices[i] = index;
    }
  } else {
    mesh.indices.resize(n);
    for (std::size_t i = 0; i < n; ++i) mesh.indices[i] = static_cast<std::uint32_t>(i);
  }
  if (mesh.indices.size() % 3 != 0) fail(where, "has a triangle list whose length is not a multiple of 3");
  if (glm::determinant(glm::mat3(transform)) < 0.0f) {  // a mirroring node: keep triangles front-facing
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
      std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
  }
  if (!hasNormal) generateNormals(mesh);
  if (!hasTangent) generateTangents(mesh, hasUv);
  return mesh;
}

glm::mat4 localMatrix(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    glm::mat4 m;
    for (int i = 0; i < 16; ++i)
      glm::value_ptr(m)[i] = static_cast<float>(node.matrix[static_cast<std::size_t>(i)]);
    return m;
  }
  glm::mat4 m(1.0f);
  if (node.translation.size() == 3) {
    m = glm::translate(m, glm::vec3(node.translation[0], node.translation[1], node.translation[2]));
  }
  if (node.rotation.size() == 4) {
    const glm::quat q(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                      static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
    m *= glm::mat4_cast(glm::normalize(q));
  }
  if (node.scale.size() == 3) m = glm::scale(m, glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
  return m;
}

void addNode(const tinygltf::Model& m, int index, const glm::mat4& parent, int depth, std::set<int>& path,
             Model& out) {
  const std::string key = at("nodes", static_cast<std::size_t>(std::max(index, 0)));
  if (index < 0 || static_cast<std::size_t>(index) >= m.nodes.size()) fail(key, "does not exist");
  if (depth > kMaxNodeDepth) fail(key, "is nested more than " + std::to_string(kMaxNodeDepth) + " deep");
  if (!path.insert(index).second) fail(key, "is its own ancestor (the node graph has a cycle)");
  const tinygltf::Node& node = m.nodes[static_cast<std::size_t>(index)];
  const glm::mat4 transform = parent * localMatrix(node);
  if (node.mesh >= 0) {
    if (static_cast<std::size_t>(node.mesh) >= m.meshes.size()) fail(key + ".mesh", "does not exist");
    const tinygltf::Mesh& mesh = m.meshes[static_cast<std::size_t>(node.mesh)];
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      out.meshes.push_back(
          readPrimitive(m, mesh.primitives[p],
                        at("meshes", static_cast<std::size_t>(node.mesh)) + at(".primitives", p), transform));
      if (out.vertexCount() > kMaxVertices) fail(key, "the model has more vertices than a prop may have");
    }
  }
  for (const int child : node.children) addNode(m, child, transform, depth + 1, path, out);
  path.erase(index);
}

int imageOf(const tinygltf::Model& m, int texture, const std::string& where) {
  if (texture < 0) return -1;
  if (static_cast<std::size_t>(texture) >= m.textures.size())
    fail(where, "texture " + std::to_string(texture) + " does not exist");
  const int source = m.textures[static_cast<std::size_t>(texture)].source;
  if (source >= static_cast<int>(m.images.size()))
    fail(at("textures", static_cast<std::size_t>(texture)), "names no image");
  return source;
}

ModelMaterial readMaterial(const tinygltf::Model& m, const tinygltf::Material& mat, const std::string& key) {
  ModelMaterial out;
  const auto& pbr = mat.pbrMetallicRoughness;
  if (pbr.baseColorFactor.size() == 4) {
    out.baseColor = {pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2],
                     pbr.baseColorFactor[3]};
  }
  out.baseColorImage = imageOf(m, pbr.baseColorTexture.index, key + ".baseColorTexture");
  out.metallic = static_cast<float>(std::clamp(pbr.metallicFactor, 0.0, 1.0));
  out.roughness = static_cast<float>(std::clamp(pbr.roughnessFactor, 0.0, 1.0));
  out.metallicRoughnessImage =
      imageOf(m, pbr.metallicRoughnessTexture.index, key + ".metallicRoughnessTexture");
  out.normalImage = imageOf(m, mat.normalTexture.index, key + ".normalTexture");
  out.normalScale = static_cast<float>(mat.normalTexture.scale);
  out.occlusionImage = imageOf(m, mat.occlusionTexture.index, key + ".occlusionTexture");
  out.occlusionStrength = static_cast<float>(std::clamp(mat.occlusionTexture.strength, 0.0, 1.0));
  if (mat.emissiveFactor.size() == 3)
    out.emissive = {mat.emissiveFactor[0], mat.emissiveFactor[1], mat.emissiveFactor[2]};
  out.emissiveImage = imageOf(m, mat.emissiveTexture.index, key + ".emissiveTexture");
  if (mat.alphaMode == "MASK")
    out.alphaMode = AlphaMode::Mask;
  else if (mat.alphaMode == "BLEND")
    out.alphaMode = AlphaMode::Blend;
  else if (mat.alphaMode != "OPAQUE" && !mat.alphaMode.empty())
    fail(key + ".alphaMode", "unknown mode \"" + mat.alphaMode + "\"");
  out.alphaCutoff = static_cast<float>(mat.alphaCutoff);
  out.doubleSided = mat.doubleSided;
  return out;
}

bool decodeGltfImage(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int,
                     const unsigned char* bytes, int size, void*) {
  try {
    const std::string name = image->uri.empty() ? at("images", static_cast<std::size_t>(index)) : image->uri;
    const Image decoded = decodeImage(std::vector<std::uint8_t>(bytes, bytes + std::max(size, 0)), name);
    image->width = decoded.width;
    image->height = decoded.height;
    image->component = 4;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image = decoded.rgba;
    return true;
  } catch (const Error& e) {
    if (err) *err += at("images", static_cast<std::size_t>(index)) + ": " + e.what() + "\n";
    return false;
  }
}

Model convert(const tinygltf::Model& m) {
  for (const std::string& ext : m.extensionsRequired) {
    fail("extensionsRequired", "\"" + ext + "\" is required by the model and not supported");
  }
  Model out;
  for (std::size_t i = 0; i < m.materials.size(); ++i)
    out.materials.push_back(readMaterial(m, m.materials[i], at("materials", i)));
  for (const tinygltf::Image& image : m.images) {
    Image copy(image.width, image.height);
    copy.rgba = image.image;
    out.images.push_back(std::move(copy));
  }
  std::set<int> path;
  std::vector<int> roots;
  if (!m.scenes.empty()) {
    const std::size_t scene =
        m.defaultScene >= 0 && static_cast<std::size_t>(m.defaultScene) < m.scenes.size()
            ? static_cast<std::size_t>(m.defaultScene)
            : 0;
    roots = m.scenes[scene].nodes;
  } else {
    std::vector<bool> child(m.nodes.size(), false);
    for (const auto& node : m.nodes)
      for (int c : node.children)
        if (c >= 0 && static_cast<std::size_t>(c) < child.size()) child[static_cast<std::size_t>(c)] = true;
    for (std::size_t i = 0; i < m.nodes.size(); ++i)
      if (!child[i]) roots.push_back(static_cast<int>(i));
  }
  for (const int root : roots) addNode(m, root, glm::mat4(1.0f), 0, path, out);
  if (out.meshes.empty()) fail("scenes", "the model has no mesh to show");
  out.min = glm::vec3(std::numeric_limits<float>::max());
  out.max = glm::vec3(std::numeric_limits<float>::lowest());
  for (const ModelMesh& mesh : out.meshes)
    for (const ModelVertex& v : mesh.vertices) {
      out.min = glm::min(out.min, v.position);
      out.max = glm::max(out.max, v.position);
    }
  return out;
}

}  // namespace

std::size_t Model::vertexCount() const {
  std::size_t n = 0;
  for (const ModelMesh& m : meshes) n += m.vertices.size();
  return n;
}

Model parseModel(const std::vector<std::uint8_t>& bytes, const std::string& name,
                 const std::filesystem::path& baseDir) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(decodeGltfImage, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
  bool ok = false;
  try {
    ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                              static_cast<unsigned int>(bytes.size()), baseDir.string())
                : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                             static_cast<unsigned int>(bytes.size()), baseDir.string());
  } catch (const std::exception& e) {  // tinygltf lets some of nlohmann's exceptions through
    err = e.what();
  }
  if (!ok) {
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    throw Error(name + ": cannot load the glTF model: " + (err.empty() ? std::string("unknown error") : err));
  }
  try {
    return convert(model);
  } catch (const Error& e) {
    throw Error(name + ": " + e.what());
  }
}

Model loadModel(const std::filesystem::path& file) {
  const std::string text = readTextFile(file);
  return parseModel(std::vector<std::uint8_t>(text.begin(), text.end()), file.string(), file.parent_path());
}

}  // namespace terrasol
