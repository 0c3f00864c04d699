#include "region_export.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <glm/common.hpp>

#include "core/error.h"
#include "mesh/section_mesh.h"

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <tiny_gltf.h>  // the implementation is in assets/gltf_model.cpp

namespace terrasol {
namespace {

constexpr float kBlocksPer32 = 1.0f / 32.0f;

glm::vec3 quadCorner(const SectionPos& s, const PackedVertex& v) {
  return glm::vec3(s.x * 16, kMinY + s.section * 16, s.z * 16) +
         glm::vec3(static_cast<float>(v.x32()), static_cast<float>(v.y32()), static_cast<float>(v.z32())) *
             kBlocksPer32;
}

// The PNG bytes of an image (through a file: OpenImageIO writes files).
std::vector<unsigned char> pngBytes(const Image& image, const std::filesystem::path& beside) {
  const std::filesystem::path tmp = beside.string() + ".atlas.png";
  saveImage(tmp, image);
  const std::string text = readTextFile(tmp);
  std::filesystem::remove(tmp);
  return {text.begin(), text.end()};
}

// Appends `bytes` to the buffer, 4-byte aligned, as a new buffer view; returns its index.
int addView(tinygltf::Model& m, const void* bytes, std::size_t size, int target) {
  std::vector<unsigned char>& data = m.buffers[0].data;
  while (data.size() % 4) data.push_back(0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();
  view.byteLength = size;
  view.target = target;
  const auto* p = static_cast<const unsigned char*>(bytes);
  data.insert(data.end(), p, p + size);
  m.bufferViews.push_back(view);
  return static_cast<int>(m.bufferViews.size()) - 1;
}

int addAccessor(tinygltf::Model& m, int view, int componentType, int type, std::size_t count,
                std::vector<double> min = {}, std::vector<double> max = {}) {
  tinygltf::Accessor a;
  a.bufferView = view;
  a.componentType = componentType;
  a.type = type;
  a.count = count;
  a.minValues = std::move(min);
  a.maxValues = std::move(max);
  m.accessors.push_back(a);
  return static_cast<int>(m.accessors.size()) - 1;
}

struct LayerData {
  std::vector<float> positions, normals, uvs, colors;
  std::vector<std::uint32_t> indices;
  glm::vec3 lo{1e30f}, hi{-1e30f};
};

}  // namespace

glm::ivec3 quadBlock(const SectionPos& section, const PackedVertex* quad) {
  glm::vec3 centre(0.0f);
  for (int i = 0; i < 4; ++i) centre += quadCorner(section, quad[i]) * 0.25f;
  const FaceBasis& basis = kFaceBases[quad[0].face()];
  const glm::vec3 normal(basis.normal[0], basis.normal[1], basis.normal[2]);
  return glm::ivec3(glm::floor(centre - normal * 0.01f));
}

std::vector<SectionMesh> meshRegion(const World& world, const Region& region, const BlockMeshTable& table) {
  std::vector<SectionMesh> meshes;
  SectionSnapshot snapshot;
  const int s0 = sectionOf(std::clamp(region.min.y, kMinY, kMaxY - 1)),
            s1 = sectionOf(std::clamp(region.max.y, kMinY, kMaxY - 1));
  for (int cz = chunkOf(region.min.z); cz <= chunkOf(region.max.z); ++cz)
    for (int cx = chunkOf(region.min.x); cx <= chunkOf(region.max.x); ++cx)
      for (int s = s0; s <= s1; ++s) {
        SectionMesh mesh = meshFromWorld(world, {cx, s, cz}, table, snapshot);
        if (!mesh.empty()) meshes.push_back(std::move(mesh));
      }
  return meshes;
}

ExportStats exportRegion(const std::vector<SectionMesh>& meshes, const Region& region,
                         const BlockAtlas& atlas, const std::filesystem::path& file) {
  const glm::vec3 origin(region.min);
  LayerData layers[kMeshLayers];
  ExportStats stats;
  for (const SectionMesh& mesh : meshes) {
    for (int l = 0; l < kMeshLayers; ++l) {
      const PackedVertices& v = mesh.layers[static_cast<std::size_t>(l)].vertices;
      LayerData& out = layers[l];
      for (std::size_t q = 0; q + 3 < v.size(); q += 4) {
        if (!region.contains(quadBlock(mesh.pos, &v[q]))) continue;
        const auto base = static_cast<std::uint32_t>(out.positions.size() / 3);
        for (int i = 0; i < 4; ++i) {
          const PackedVertex& p = v[q + static_cast<std::size_t>(i)];
          const glm::vec3 pos = quadCorner(mesh.pos, p) - origin;
          out.lo = glm::min(out.lo, pos);
          out.hi = glm::max(out.hi, pos);
          const FaceBasis& basis = kFaceBases[p.face()];
          out.positions.insert(out.positions.end(), {pos.x, pos.y, pos.z});
          out.normals.insert(out.normals.end(), {basis.normal[0], basis.normal[1], basis.normal[2]});
          const int texture = std::min(p.texture(), static_cast<int>(atlas.atlas.textures.size()) - 1);
          const glm::vec4 rect = atlas.atlas.tileRect(
              texture >= 0 ? atlas.atlas.textures[static_cast<std::size_t>(texture)].firstTile : 0);
          out.uvs.push_back(rect.x + (rect.z - rect.x) * static_cast<float>(p.u()) / 16.0f);
          out.uvs.push_back(rect.y + (rect.w - rect.y) * static_cast<float>(p.v()) / 16.0f);
          const glm::vec3 tint =
              p.tint() == static_cast<int>(Tint::None) ? glm::vec3(1.0f) : glm::vec3(p.tintRgb()) / 255.0f;
          const glm::vec3 c = tint * (0.4f + 0.6f * static_cast<float>(p.ao()) / 3.0f);
          out.colors.insert(out.colors.end(), {c.r, c.g, c.b});
        }
        for (const std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u})
          out.indices.push_back(base + i);  // mesh_data.h's quads
        ++stats.quads;
      }
    }
  }

  tinygltf::Model m;
  m.asset.version = "2.0";
  m.asset.generator = "terrasol-export";
  m.buffers.resize(1);
  const std::vector<unsigned char> png = pngBytes(atlas.atlas.albedo[0], file);
  tinygltf::Image image;
  image.mimeType = "image/png";
  image.bufferView = addView(m, png.data(), png.size(), 0);
  m.images.push_back(image);
  tinygltf::Sampler sampler;
  sampler.magFilter = TINYGLTF_TEXTURE_FILTER_NEAREST;  // pixel art
  sampler.minFilter = TINYGLTF_TEXTURE_FILTER_NEAREST;
  m.samplers.push_back(sampler);
  tinygltf::Texture texture;
  texture.source = 0;
  texture.sampler = 0;
  m.textures.push_back(texture);
  const char* modes[kMeshLayers] = {"OPAQUE", "MASK", "BLEND"};
  const char* names[kMeshLayers] = {"opaque", "cutout", "translucent"};
  tinygltf::Mesh mesh;
  mesh.name = "region";
  for (int l = 0; l < kMeshLayers; ++l) {
    LayerData& d = layers[l];
    if (d.indices.empty()) continue;
    tinygltf::Material material;
    material.name = names[l];
    material.pbrMetallicRoughness.baseColorTexture.index = 0;
    material.pbrMetallicRoughness.metallicFactor = 0.0;
    material.alphaMode = modes[l];
    material.doubleSided = l != 0;  // plants and panes show both sides
    m.materials.push_back(material);
    const std::size_t n = d.positions.size() / 3;
    tinygltf::Primitive p;
    p.mode = TINYGLTF_MODE_TRIANGLES;
    p.material = static_cast<int>(m.materials.size()) - 1;
    p.attributes["POSITION"] =
        addAccessor(m, addView(m, d.positions.data(), d.positions.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                    TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n, {d.lo.x, d.lo.y, d.lo.z},
                    {d.hi.x, d.hi.y, d.hi.z});
    p.attributes["NORMAL"] =
        addAccessor(m, addView(m, d.normals.data(), d.normals.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                    TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
    p.attributes["TEXCOORD_0"] =
        addAccessor(m, addView(m, d.uvs.data(), d.uvs.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                    TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, n);
    p.attributes["COLOR_0"] =
        addAccessor(m, addView(m, d.colors.data(), d.colors.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER),
                    TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
    p.indices = addAccessor(
        m, addView(m, d.indices.data(), d.indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
        TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, d.indices.size());
    mesh.primitives.push_back(p);
    stats.vertices += n;
    stats.triangles += d.indices.size() / 3;
  }
  if (mesh.primitives.empty()) throw Error(file.string() + ": the region holds no visible block face");
  m.meshes.push_back(mesh);
  tinygltf::Node node;
  node.mesh = 0;
  node.name = "region";
  m.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes = {0};
  m.scenes.push_back(scene);
  m.defaultScene = 0;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToFile(&m, file.string(), /*embedImages=*/true, /*embedBuffers=*/true,
                                   /*prettyPrint=*/false, /*writeBinary=*/true)) {
    throw Error(file.string() + ": cannot write the glTF binary");
  }
  return stats;
}

}  // namespace terrasol
