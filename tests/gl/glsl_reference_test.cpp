// Rules written in both C++ and GLSL: the shaders' functions run in a compute shader on a grid of
// inputs and must agree with the C++ reference the rest of the tests check, so the copy that ships is
// the one tested. Octahedral normals (core/octahedral.h), LabPBR decoding (assets/labpbr.h), the
// lightmap (core/lightmap.h) and the packed block vertex (mesh/mesh_data.h, whose fields the shader
// gets as injected defines).

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/gtc/type_ptr.hpp>
#include <glm/vec4.hpp>
#include <iterator>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "assets/labpbr.h"
#include "core/error.h"
#include "core/lightmap.h"
#include "core/octahedral.h"
#include "core/paths.h"
#include "mesh/mesh_data.h"
#include "render/gl/program.h"
#include "render/shader_defines.h"
#include "support/gl_test.h"

namespace terrasol {
namespace {

class GlslReferenceTest : public testing::GlTest {};

// Runs `body` once per input in a compute shader that includes `library` (a file under shaders/).
// The body reads `x` (a vec4, or a uvec4 for glm::uvec4 inputs) and writes `outputs[i * per + k]`
// for its `per` results.
template <class Input>
std::vector<glm::vec4> runGlsl(const std::string& library, const std::string& body,
                               const std::vector<Input>& in, int per,
                               const std::function<void(GLuint)>& uniforms = {}) {
  static_assert(std::is_same_v<Input, glm::vec4> || std::is_same_v<Input, glm::uvec4>);
  const std::string type = std::is_same_v<Input, glm::uvec4> ? "uvec4" : "vec4";
  const std::string source = "#version 450 core\nlayout(local_size_x = 64) in;\n#include \"" + library +
                             "\"\nlayout(std430, binding = 0) readonly buffer Inputs { " + type +
                             " inputs[]; };\n" +
                             R"(layout(std430, binding = 1) writeonly buffer Outputs { vec4 outputs[]; };
uniform uint u_count;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= u_count) return;
  )" + type + R"( x = inputs[i];
  uint per = )" + std::to_string(per) +
                             "u;\n" + body + "\n}\n";
  const ShaderPreprocessor shaders([&](const std::string& path) -> std::optional<std::string> {
    if (path == "reference.comp") return source;
    const auto file = shaderDir() / path;
    if (!std::filesystem::exists(file)) return std::nullopt;
    return readTextFile(file);
  });
  const gl::Program program =
      buildProgram(shaders, {{GL_COMPUTE_SHADER, "reference.comp"}}, rendererDefines());
  const auto bytesIn = static_cast<GLsizeiptr>(in.size() * sizeof(Input));
  const auto bytesOut = bytesIn * per;
  gl::Buffer input = gl::Buffer::create(), output = gl::Buffer::create();
  glNamedBufferStorage(input.id(), bytesIn, in.data(), 0);
  // NaN everywhere first: an output the shader never writes fails every comparison.
  const std::vector<glm::vec4> unwritten(in.size() * static_cast<std::size_t>(per), glm::vec4(std::nanf("")));
  glNamedBufferStorage(output.id(), bytesOut, unwritten.data(), GL_DYNAMIC_STORAGE_BIT);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, input.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, output.id());
  glProgramUniform1ui(program.id(), glGetUniformLocation(program.id(), "u_count"),
                      static_cast<GLuint>(in.size()));
  if (uniforms) uniforms(program.id());
  glUseProgram(program.id());
  glDispatchCompute(static_cast<GLuint>((in.size() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<glm::vec4> out(in.size() * static_cast<std::size_t>(per));
  glGetNamedBufferSubData(output.id(), 0, bytesOut, out.data());
  glUseProgram(0);
  return out;
}

float largest(glm::vec3 a, glm::vec3 b) {
  return glm::length(a - b);
}

TEST_F(GlslReferenceTest, OctahedralEncodingMatchesTheCppReference) {
  // Decoding: a 101 x 101 grid over [-1, 1]^2, edges and the folded corners included.
  std::vector<glm::vec4> codes;
  for (int j = 0; j <= 100; ++j)
    for (int i = 0; i <= 100; ++i) codes.emplace_back(i / 50.0f - 1.0f, j / 50.0f - 1.0f, 0.0f, 0.0f);
  const auto decoded = runGlsl("lib/octahedral.glsl", "outputs[i] = vec4(octDecode(x.xy), 0.0);", codes, 1);
  float worst = 0.0f;
  for (std::size_t k = 0; k < codes.size(); ++k) {
    const glm::vec3 cpu(octDecode(glm::dvec2(codes[k].x, codes[k].y)));
    worst = std::max(worst, largest(glm::vec3(decoded[k]), cpu));
  }
  EXPECT_LT(worst, 1e-5f);

  // Encoding: directions over the whole sphere, the poles and the axes exactly included.
  std::vector<glm::vec4> directions;
  for (int j = 0; j <= 40; ++j)
    for (int i = 0; i < 80; ++i) {
      const double theta = j * 3.14159265358979 / 40.0, phi = i * 3.14159265358979 / 40.0;
      directions.emplace_back(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                              std::cos(theta), 0.0);
    }
  for (const glm::vec4 axis :
       {glm::vec4(0, 0, -1, 0), glm::vec4(0, 0, 1, 0), glm::vec4(1, 0, 0, 0), glm::vec4(0, -1, 0, 0)}) {
    directions.push_back(axis);
  }
  const auto encoded =
      runGlsl("lib/octahedral.glsl", "outputs[i] = vec4(octEncode(x.xyz), 0.0, 0.0);", directions, 1);
  worst = 0.0f;
  for (std::size_t k = 0; k < directions.size(); ++k) {
    const glm::vec2 cpu(octEncode(glm::dvec3(directions[k])));
    worst = std::max(worst, glm::length(glm::vec2(encoded[k]) - cpu));
  }
  EXPECT_LT(worst, 1e-5f);
  const glm::vec3 south(octDecode(glm::dvec2(encoded[directions.size() - 4])));
  EXPECT_LT(largest(south, glm::vec3(0, 0, -1)), 1e-6f) << "-z survives the round trip";
}

TEST_F(GlslReferenceTest, LabPbrNormalDecodingMatchesTheCppReferenceForEveryTexel) {
  std::vector<glm::vec4> texels;
  for (int g = 0; g < 256; ++g)
    for (int r = 0; r < 256; ++r) texels.emplace_back(r / 255.0f, g / 255.0f, 1.0f, 1.0f);
  const auto gpu = runGlsl("lib/labpbr.glsl", "outputs[i] = vec4(labpbrNormal(x), 0.0);", texels, 1);
  float worst = 0.0f;
  for (std::size_t k = 0; k < texels.size(); ++k) {
    const std::uint8_t rgba[4] = {static_cast<std::uint8_t>(k % 256), static_cast<std::uint8_t>(k / 256), 255,
                                  255};
    worst = std::max(worst, largest(glm::vec3(gpu[k]), labpbr::decodeNormal(rgba).normal));
  }
  EXPECT_LT(worst, 1e-5f) << "over all 65 536 red-green pairs";
}

TEST_F(GlslReferenceTest, LabPbrSpecularDecodingMatchesTheCppReferenceForEveryValue) {
  const glm::vec3 albedo(0.8f, 0.5f, 0.2f);
  std::vector<glm::vec4> texels;  // every byte in every channel at once: R smoothness, G F0, A emission
  for (int v = 0; v < 256; ++v) texels.emplace_back(v / 255.0f, v / 255.0f, 0.0f, v / 255.0f);
  const auto gpu = runGlsl("lib/labpbr.glsl", R"(
    Material m = labpbrMaterial(x, vec3(0.8, 0.5, 0.2));
    outputs[i * per] = vec4(m.smoothness, m.roughness, m.emission, m.metal ? 1.0 : 0.0);
    outputs[i * per + 1u] = vec4(m.f0, 0.0);)",
                           texels, 2);
  for (int v = 0; v < 256; ++v) {
    const std::uint8_t rgba[4] = {static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v), 0,
                                  static_cast<std::uint8_t>(v)};
    const labpbr::SpecularTexel cpu = labpbr::decodeSpecular(rgba, albedo);
    const glm::vec4 a = gpu[static_cast<std::size_t>(2 * v)], f0 = gpu[static_cast<std::size_t>(2 * v + 1)];
    EXPECT_NEAR(a.x, cpu.smoothness, 1e-6f) << v;
    EXPECT_NEAR(a.y, cpu.roughness, 1e-6f) << v;
    EXPECT_NEAR(a.z, cpu.emission, 1e-6f) << v;
    EXPECT_EQ(a.w == 1.0f, cpu.reflectance != labpbr::Reflectance::Dielectric) << v;
    EXPECT_LT(largest(glm::vec3(f0), cpu.f0), 1e-6f) << v;
  }
}

TEST_F(GlslReferenceTest, TheShadersLightmapIsTheCppTableAtWholeLevels) {
  std::vector<glm::vec4> levels;
  for (int sky = 0; sky < 16; ++sky)
    for (int block = 0; block < 16; ++block) levels.emplace_back(block / 15.0f, sky / 15.0f, 0.0f, 0.0f);
  for (const std::int64_t ticks : {0, 6000, 12500, 18000, 23000}) {
    const DayState day = dayStateAt(ticks, 0.0f);
    const LightmapColours colours = lightmapColours(day, ticks);
    const auto gpu = runGlsl(
        "lib/lighting.glsl", "outputs[i] = vec4(lightmapAt(x.x, x.y), 0.0);", levels, 1, [&](GLuint program) {
          glProgramUniform3fv(program, glGetUniformLocation(program, "u_lightmapSky"), 1,
                              glm::value_ptr(colours.sky));
          glProgramUniform3fv(program, glGetUniformLocation(program, "u_lightmapBlock"), 1,
                              glm::value_ptr(colours.block));
          glProgramUniform1f(program, glGetUniformLocation(program, "u_lightmapFloor"), colours.floor);
        });
    const Lightmap table = buildLightmap(day, ticks);
    float worst = 0.0f;
    for (int sky = 0; sky < 16; ++sky)
      for (int block = 0; block < 16; ++block) {
        worst = std::max(
            worst, largest(glm::vec3(gpu[static_cast<std::size_t>(sky * 16 + block)]), table.at(block, sky)));
      }
    EXPECT_LT(worst, 1e-5f) << "at tick " << ticks;
  }
}

// Every field at 0 and at its largest in all 32 768 combinations, then random vertices.
std::vector<PackedVertex> verticesToUnpack() {
  using V = PackedVertex;
  const BitField fields[] = {V::kX,    V::kY,    V::kZ,       V::kTexture,    V::kFace,
                             V::kTint, V::kRole, V::kAo,      V::kBlockLight, V::kSkyLight,
                             V::kU,    V::kV,    V::kTintRed, V::kTintGreen,  V::kTintBlue};
  constexpr int kFields = static_cast<int>(std::size(fields));
  const auto vertex = [&](auto valueOf) {
    int f[kFields];
    for (int k = 0; k < kFields; ++k) f[k] = valueOf(k, static_cast<int>(fields[k].mask()));
    PackedVertex v{V::packPosition(f[0], f[1], f[2]), V::packMaterial(f[3], f[4], f[5]),
                   V::kAo.pack(f[7]) | V::kBlockLight.pack(f[8]) | V::kSkyLight.pack(f[9]),
                   V::packUv(f[10], f[11])};
    v.setRole(static_cast<QuadRole>(f[6]));
    v.setTintRgb(glm::u8vec3(f[12], f[13], f[14]));
    return v;
  };
  std::vector<PackedVertex> vertices;
  for (int corner = 0; corner < 1 << kFields; ++corner) {
    vertices.push_back(vertex([&](int k, int max) { return corner >> k & 1 ? max : 0; }));
  }
  std::mt19937 random(7);
  for (int n = 0; n < 4096; ++n) {
    vertices.push_back(vertex([&](int, int max) { return std::uniform_int_distribution(0, max)(random); }));
  }
  return vertices;
}

// What C++ packs, lib/block_vertex.glsl unpacks to the same fields: its shifts and masks are the
// injected ones, so a field the shader reads with the wrong shift or mask shows here.
TEST_F(GlslReferenceTest, TheShaderUnpacksEveryFieldOfThePackedVertexAsCppPacksIt) {
  using V = PackedVertex;
  const std::vector<PackedVertex> vertices = verticesToUnpack();
  std::vector<glm::uvec4> words;
  for (const PackedVertex& v : vertices) words.emplace_back(v.position, v.material, v.light, v.uv);
  const auto gpu = runGlsl("lib/block_vertex.glsl", R"(
    BlockVertex v = unpackBlockVertex(x);
    outputs[i * per] = vec4(v.position, float(v.texture));
    outputs[i * per + 1u] = vec4(float(v.face), float(v.tint), v.merged ? 1.0 : 0.0, v.ao);
    outputs[i * per + 2u] = vec4(v.blockLight, v.skyLight, v.uv);
    outputs[i * per + 3u] = vec4(v.tintColour, 0.0);)",
                           words, 4);
  constexpr const char* kNames[15] = {"x",    "y",      "z",        "texture",     "face",
                                      "tint", "merged", "ao",       "block light", "sky light",
                                      "u",    "v",      "tint red", "tint green",  "tint blue"};
  const float steps = static_cast<float>(V::kPositionSteps), uvSteps = static_cast<float>(V::kUvSteps);
  const float aoMax = static_cast<float>(V::kAo.mask());
  int wrong[15] = {};
  std::string first[15];
  for (std::size_t n = 0; n < vertices.size(); ++n) {
    const PackedVertex& v = vertices[n];
    const auto f = [](int value) { return static_cast<float>(value); };
    const float cells = f(v.cellsLit() * V::kCellLight);
    const float cpu[15] = {f(v.x32()) / steps,
                           f(v.y32()) / steps,
                           f(v.z32()) / steps,
                           f(v.texture()),
                           f(v.face()),
                           f(v.tint()),
                           v.role() == QuadRole::Merged ? 1.0f : 0.0f,
                           f(v.ao()) / aoMax,
                           f(V::kBlockLight.get(v.light)) / cells,
                           f(V::kSkyLight.get(v.light)) / cells,
                           f(v.u()) / uvSteps,
                           f(v.v()) / uvSteps,
                           f(v.tintRgb().r) / 255.0f,
                           f(v.tintRgb().g) / 255.0f,
                           f(v.tintRgb().b) / 255.0f};
    for (int k = 0; k < 15; ++k) {
      const float shader = gpu[n * 4 + static_cast<std::size_t>(k / 4)][k % 4];
      if (std::abs(shader - cpu[k]) <= 1e-6f) continue;
      if (wrong[k]++ == 0) {
        first[k] = "GLSL " + std::to_string(shader) + ", C++ " + std::to_string(cpu[k]) + " for words " +
                   std::to_string(v.position) + " " + std::to_string(v.material) + " " +
                   std::to_string(v.light) + " " + std::to_string(v.uv);
      }
    }
  }
  for (int k = 0; k < 15; ++k) {
    EXPECT_EQ(wrong[k], 0) << kNames[k] << " differs in " << wrong[k] << " of " << vertices.size()
                           << " vertices, first: " << first[k];
  }
}

}  // namespace
}  // namespace terrasol
