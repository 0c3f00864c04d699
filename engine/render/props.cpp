#include "render/props.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/error.h"
#include "render/gl_slots.h"

namespace terrasol {
namespace {

// Trilinear with mipmaps and repeat: glTF's defaults for a sampler-less texture.
gl::Texture makeTexture(const Image& image, GLenum format) {
  gl::Texture texture = gl::Texture::create(GL_TEXTURE_2D);
  const int levels = 1 + static_cast<int>(std::floor(std::log2(std::max(image.width, image.height))));
  glTextureStorage2D(texture.id(), levels, format, image.width, image.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  // Rows top first, as glTF's uv (0, 0) is the image's top left: uv maps straight to GL's t.
  glTextureSubImage2D(texture.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                      image.rgba.data());
  glGenerateTextureMipmap(texture.id());  // sRGB formats are filtered in linear light
  glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
  return texture;
}

gl::Texture solid(std::uint8_t r, std::uint8_t g, std::uint8_t b, GLenum format) {
  Image image(1, 1);
  image.rgba = {r, g, b, 255};
  return makeTexture(image, format);
}

}  // namespace

Props::Props()
    : white_(solid(255, 255, 255, GL_RGBA8)),
      whiteSrgb_(solid(255, 255, 255, GL_SRGB8_ALPHA8)),
      flatNormal_(solid(128, 128, 255, GL_RGBA8)) {}

int Props::addModel(const Model& model) {
  GpuModel gpu;
  std::vector<ModelVertex> vertices;
  std::vector<std::uint32_t> indices;
  for (const ModelMesh& mesh : model.meshes) {
    const int material = mesh.material >= 0 ? mesh.material : static_cast<int>(model.materials.size());
    gpu.meshes.push_back({static_cast<GLsizei>(mesh.indices.size()), indices.size() * sizeof(std::uint32_t),
                          static_cast<GLint>(vertices.size()), material});
    vertices.insert(vertices.end(), mesh.vertices.begin(), mesh.vertices.end());
    indices.insert(indices.end(), mesh.indices.begin(), mesh.indices.end());
  }
  gpu.vertexCount = vertices.size();

  // Each image once per colour space it is used in: base colour and emissive are sRGB, the rest not.
  std::vector<GLuint> linear(model.images.size(), 0), srgb(model.images.size(), 0);
  auto texture = [&](int image, bool isSrgb, GLuint fallback) -> GLuint {
    if (image < 0 || static_cast<std::size_t>(image) >= model.images.size()) return fallback;
    GLuint& id = (isSrgb ? srgb : linear)[static_cast<std::size_t>(image)];
    if (!id) {
      gpu.textures.push_back(
          makeTexture(model.images[static_cast<std::size_t>(image)], isSrgb ? GL_SRGB8_ALPHA8 : GL_RGBA8));
      id = gpu.textures.back().id();
    }
    return id;
  };
  std::vector<ModelMaterial> materials = model.materials;
  materials.emplace_back();  // glTF's default material, for meshes without one
  for (const ModelMaterial& m : materials) {
    Material material;
    material.params = m;
    material.baseColor = texture(m.baseColorImage, true, whiteSrgb_.id());
    material.metallicRoughness = texture(m.metallicRoughnessImage, false, white_.id());
    material.normal = texture(m.normalImage, false, flatNormal_.id());
    material.emissive = texture(m.emissiveImage, true, whiteSrgb_.id());
    material.occlusion = texture(m.occlusionImage, false, white_.id());
    material.hasNormalMap = m.normalImage >= 0;
    gpu.materials.push_back(material);
  }

  gpu.vertices = gl::Buffer::create();
  gpu.indices = gl::Buffer::create();
  glNamedBufferStorage(
      gpu.vertices.id(),
      static_cast<GLsizeiptr>(std::max<std::size_t>(vertices.size(), 1) * sizeof(ModelVertex)),
      vertices.empty() ? nullptr : vertices.data(), 0);
  glNamedBufferStorage(
      gpu.indices.id(),
      static_cast<GLsizeiptr>(std::max<std::size_t>(indices.size(), 1) * sizeof(std::uint32_t)),
      indices.empty() ? nullptr : indices.data(), 0);
  gpu.layout = gl::VertexArray::create();
  const GLuint vao = gpu.layout.id();
  glVertexArrayVertexBuffer(vao, 0, gpu.vertices.id(), 0, sizeof(ModelVertex));
  glVertexArrayElementBuffer(vao, gpu.indices.id());
  const struct {
    int location, size;
    std::size_t offset;
  } attributes[] = {{slots::kAttribPosition, 3, offsetof(ModelVertex, position)},
                    {slots::kAttribNormal, 3, offsetof(ModelVertex, normal)},
                    {slots::kAttribTangent, 4, offsetof(ModelVertex, tangent)},
                    {slots::kAttribUv, 2, offsetof(ModelVertex, uv)}};
  for (const auto& a : attributes) {
    glEnableVertexArrayAttrib(vao, static_cast<GLuint>(a.location));
    glVertexArrayAttribFormat(vao, static_cast<GLuint>(a.location), a.size, GL_FLOAT, GL_FALSE,
                              static_cast<GLuint>(a.offset));
    glVertexArrayAttribBinding(vao, static_cast<GLuint>(a.location), 0);
  }
  // Binding 1: the instance's light, bound per draw.
  glEnableVertexArrayAttrib(vao, slots::kAttribLight);
  glVertexArrayAttribFormat(vao, slots::kAttribLight, 2, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao, slots::kAttribLight, 1);
  models_.push_back(std::move(gpu));
  return static_cast<int>(models_.size()) - 1;
}

int Props::place(int model, const Placement& placement, std::span<const glm::vec2> light) {
  if (model < 0 || static_cast<std::size_t>(model) >= models_.size())
    throw Error("no prop model " + std::to_string(model));
  Instance instance;
  instance.model = model;
  instance.placement = placement;
  instances_.push_back(std::move(instance));
  ++generation_;
  relight(static_cast<int>(instances_.size()) - 1, light);
  return static_cast<int>(instances_.size()) - 1;
}

void Props::relight(int index, std::span<const glm::vec2> light) {
  Instance& instance = instances_.at(static_cast<std::size_t>(index));
  const std::size_t vertices = models_[static_cast<std::size_t>(instance.model)].vertexCount;
  if (light.size() != vertices) {
    throw Error("prop light: " + std::to_string(light.size()) + " values for " + std::to_string(vertices) +
                " vertices");
  }
  instance.light = gl::Buffer::create();  // a fresh buffer: immutable storage, and no stall on the old one
  glNamedBufferStorage(instance.light.id(),
                       static_cast<GLsizeiptr>(std::max<std::size_t>(vertices, 1) * sizeof(glm::vec2)),
                       light.empty() ? nullptr : light.data(), 0);
}

void Props::remove(int index) {
  instances_.erase(instances_.begin() + index);
  ++generation_;
}

PropNeeds Props::needs() const {
  PropNeeds needs;
  for (const Instance& instance : instances_) {
    const GpuModel& model = models_[static_cast<std::size_t>(instance.model)];
    needs.any = true;
    for (const Mesh& mesh : model.meshes) {
      const Material& m = model.materials[static_cast<std::size_t>(mesh.material)];
      needs.mask = needs.mask || m.params.alphaMode == AlphaMode::Mask;
      needs.blend = needs.blend || m.params.alphaMode == AlphaMode::Blend;
      needs.normalMaps = needs.normalMaps || m.hasNormalMap;
    }
  }
  return needs;
}

void Props::bindMaterial(const Material& m) const {
  glBindTextureUnit(slots::kUnitPropBaseColor, m.baseColor);
  glBindTextureUnit(slots::kUnitPropMetallicRoughness, m.metallicRoughness);
  glBindTextureUnit(slots::kUnitPropNormal, m.normal);
  glBindTextureUnit(slots::kUnitPropEmissive, m.emissive);
  glBindTextureUnit(slots::kUnitPropOcclusion, m.occlusion);
}

}  // namespace terrasol
