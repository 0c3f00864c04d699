// glTF models (assets/gltf_model.h): the Khronos samples of the third-party test data (support/test_data.h)
// load in every form, missing normals and tangents are generated, and bad files end in an Error naming the
// file and the place, never a crash.

#include <gtest/gtest.h>

#include <fstream>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "assets/gltf_model.h"
#include "core/error.h"
#include "support/error_of.h"
#include "support/gltf_box.h"
#include "support/test_data.h"
#include "support/world_support.h"

namespace terrasol {
namespace {

// The Khronos samples, where present (after TERRASOL_SKIP_WITHOUT_TEST_DATA).
std::filesystem::path models() {
  return testing::testData() / "gltf";
}

std::string errorOf(const std::filesystem::path& file) {
  return testing::errorOf([&] { loadModel(file); });
}

// A copy of a sample's folder to break one thing in.
std::filesystem::path copyOf(const std::string& sample, const std::string& name) {
  const auto dir = testing::scratchDir("gltf_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::copy(models() / sample, dir, std::filesystem::copy_options::recursive);
  return dir;
}

nlohmann::json readJson(const std::filesystem::path& file) {
  return nlohmann::json::parse(readTextFile(file));
}
void writeJson(const std::filesystem::path& file, const nlohmann::json& j) {
  std::ofstream(file) << j.dump();
}

// The error loading the tests' own box (support/gltf_box.h: accessors 0 indices, 1 positions,
// 2 normals; buffer box.bin) after `edit` changed its JSON.
template <class Edit>
std::string errorAfter(const std::string& name, Edit&& edit) {
  const auto file = testing::writeBoxGltf(testing::scratchDir("gltf_" + name));
  nlohmann::json j = readJson(file);
  edit(j);
  writeJson(file, j);
  return errorOf(file);
}

TEST(GltfModel, ParentNodesMoveTheirChildren) {
  TERRASOL_SKIP_WITHOUT_TEST_DATA();
  // The textured box's root node turns it; a translation added to that node moves the child's mesh.
  const auto dir = copyOf("BoxTextured/glTF", "moved");
  nlohmann::json j = readJson(dir / "BoxTextured.gltf");
  j["nodes"][0]["matrix"][12] = 10.0;
  j["nodes"][0]["matrix"][13] = -4.0;
  writeJson(dir / "BoxTextured.gltf", j);
  const Model moved = loadModel(dir / "BoxTextured.gltf");
  EXPECT_NEAR(moved.min.x, 9.5f, 1e-5f);
  EXPECT_NEAR(moved.max.x, 10.5f, 1e-5f);
  EXPECT_NEAR(moved.min.y, -4.5f, 1e-5f);
  // The root's rotation (y up to z) turns the child's normals: the box's +y face points along -z or +z.
  const Model box = loadModel(models() / "BoxTextured" / "glTF" / "BoxTextured.gltf");
  const Model raw = [&] {
    nlohmann::json r = readJson(dir / "BoxTextured.gltf");
    r["nodes"][0].erase("matrix");
    writeJson(dir / "BoxTextured.gltf", r);
    return loadModel(dir / "BoxTextured.gltf");
  }();
  for (std::size_t i = 0; i < 24; ++i) {
    const glm::vec3 n = raw.meshes[0].vertices[i].normal, turned = box.meshes[0].vertices[i].normal;
    EXPECT_NEAR(turned.x, n.x, 1e-5f);
    EXPECT_NEAR(std::abs(turned.z), std::abs(n.y), 1e-5f) << "vertex " << i;
  }
}

TEST(GltfModel, TheBoxLoadsWithItsMaterialAndRightAngledTangents) {
  TERRASOL_SKIP_WITHOUT_TEST_DATA();
  const Model box = loadModel(models() / "Box" / "glTF-Embedded" / "Box.gltf");
  ASSERT_EQ(box.meshes.size(), 1u);
  EXPECT_EQ(box.meshes[0].vertices.size(), 24u);
  EXPECT_EQ(box.meshes[0].indices.size(), 36u);
  EXPECT_FALSE(box.meshes[0].generatedNormals);
  EXPECT_TRUE(box.meshes[0].generatedTangents);  // no TANGENT and no UV: any tangent at right angles
  for (const ModelVertex& v : box.meshes[0].vertices) {
    EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(v.normal, glm::vec3(v.tangent)), 0.0f, 1e-5f);
  }
  EXPECT_NEAR(box.min.y, -0.5f, 1e-6f);
  EXPECT_NEAR(box.max.z, 0.5f, 1e-6f);
  ASSERT_EQ(box.materials.size(), 1u);
  EXPECT_EQ(box.materials[0].baseColorImage, -1);
  EXPECT_GT(box.materials[0].baseColor.r, 0.5f);  // the red factor-only material
}

TEST(GltfModel, TheTexturedBoxIsTheSameInAllThreeForms) {
  TERRASOL_SKIP_WITHOUT_TEST_DATA();
  const Model separate = loadModel(models() / "BoxTextured" / "glTF" / "BoxTextured.gltf");
  const Model binary = loadModel(models() / "BoxTextured" / "glTF-Binary" / "BoxTextured.glb");
  const Model embedded = loadModel(models() / "BoxTextured" / "glTF-Embedded" / "BoxTextured.gltf");
  for (const Model* m : {&separate, &binary, &embedded}) {
    ASSERT_EQ(m->meshes.size(), 1u);
    EXPECT_EQ(m->meshes[0].vertices.size(), 24u);
    ASSERT_EQ(m->materials.size(), 1u);
    ASSERT_EQ(m->materials[0].baseColorImage, 0);
    ASSERT_EQ(m->images.size(), 1u);
    EXPECT_GT(m->images[0].width, 0);
    EXPECT_EQ(m->images[0].rgba.size(),
              static_cast<std::size_t>(m->images[0].width * m->images[0].height * 4));
  }
  for (std::size_t i = 0; i < 24; ++i) {
    EXPECT_EQ(separate.meshes[0].vertices[i].position, binary.meshes[0].vertices[i].position);
    EXPECT_EQ(separate.meshes[0].vertices[i].uv, embedded.meshes[0].vertices[i].uv);
  }
  EXPECT_EQ(separate.images[0].rgba, binary.images[0].rgba);
  EXPECT_EQ(separate.images[0].rgba, embedded.images[0].rgba);
}

TEST(GltfModel, TheCubeHasItsMetallicRoughnessTextureAndTangents) {
  TERRASOL_SKIP_WITHOUT_TEST_DATA();
  const Model cube = loadModel(models() / "Cube" / "glTF" / "Cube.gltf");
  ASSERT_FALSE(cube.meshes.empty());
  ASSERT_EQ(cube.materials.size(), 1u);
  EXPECT_GE(cube.materials[0].baseColorImage, 0);
  EXPECT_GE(cube.materials[0].metallicRoughnessImage, 0);
  EXPECT_NE(cube.materials[0].baseColorImage, cube.materials[0].metallicRoughnessImage);
  EXPECT_FALSE(cube.meshes[0].generatedTangents);
}

TEST(GltfModel, MissingNormalsAreFlatAndTangentsFollowTheUvs) {
  TERRASOL_SKIP_WITHOUT_TEST_DATA();
  const auto dir = copyOf("BoxTextured/glTF", "no_normals");
  nlohmann::json j = readJson(dir / "BoxTextured.gltf");
  j["meshes"][0]["primitives"][0]["attributes"].erase("NORMAL");
  writeJson(dir / "BoxTextured.gltf", j);
  const Model m = loadModel(dir / "BoxTextured.gltf");
  const ModelMesh& mesh = m.meshes[0];
  EXPECT_TRUE(mesh.generatedNormals);
  EXPECT_TRUE(mesh.generatedTangents);
  EXPECT_EQ(mesh.vertices.size(), 36u) << "flat: each triangle its own vertices";
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    const ModelVertex &a = mesh.vertices[mesh.indices[t]], &b = mesh.vertices[mesh.indices[t + 1]],
                      &c = mesh.vertices[mesh.indices[t + 2]];
    const glm::vec3 face = glm::normalize(glm::cross(b.position - a.position, c.position - a.position));
    EXPECT_NEAR(glm::dot(face, a.normal), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(a.normal, glm::vec3(a.tangent)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(glm::vec3(a.tangent)), 1.0f, 1e-5f);
    // Along the tangent, u grows: moving from a to b changes u by the tangent's share of the step.
    const float du = b.uv.x - a.uv.x, along = glm::dot(glm::vec3(a.tangent), b.position - a.position);
    if (std::abs(du) > 1e-6f && std::abs(b.uv.y - a.uv.y) < 1e-6f) {
      EXPECT_GT(du * along, 0.0f);
    }
  }
}

TEST(GltfModel, BadFilesNameTheFileAndThePlace) {
  {  // a missing buffer file
    const auto file = testing::writeBoxGltf(testing::scratchDir("gltf_missing_bin"));
    std::filesystem::remove(file.parent_path() / "box.bin");
    const std::string e = errorOf(file);
    EXPECT_NE(e.find("box.gltf"), std::string::npos) << e;
    EXPECT_NE(e.find("box.bin"), std::string::npos) << e;
  }
  {  // an accessor reaching past its buffer view
    const std::string e =
        errorAfter("long_accessor", [](nlohmann::json& j) { j["accessors"][2]["count"] = 100000; });
    EXPECT_NE(e.find("accessors[2]"), std::string::npos) << e;
  }
  {  // an index past the vertices: every vertex attribute 3 long, the indices still up to 23
    const std::string e = errorAfter("bad_index", [](nlohmann::json& j) {
      for (std::size_t a : {1u, 2u}) j["accessors"][a]["count"] = 3;
    });
    EXPECT_NE(e.find("indices"), std::string::npos) << e;
    EXPECT_NE(e.find("past the 3 vertices"), std::string::npos) << e;
  }
  {  // a required extension we do not have
    const std::string e = errorAfter("required_extension", [](nlohmann::json& j) {
      j["extensionsUsed"] = {"KHR_draco_mesh_compression"};
      j["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    });
    EXPECT_NE(e.find("KHR_draco_mesh_compression"), std::string::npos) << e;
    EXPECT_NE(e.find("not supported"), std::string::npos) << e;
  }
  {  // a node that is its own ancestor
    const std::string e = errorAfter("cycle", [](nlohmann::json& j) {
      j["nodes"] = {{{"children", {1}}}, {{"mesh", 0}, {"children", {0}}}};
    });
    EXPECT_NE(e.find("nodes["), std::string::npos) << e;
  }
  {  // malformed JSON
    const auto file = testing::writeBoxGltf(testing::scratchDir("gltf_malformed"));
    std::ofstream(file, std::ios::trunc) << "{ \"asset\": ";
    EXPECT_NE(errorOf(file).find("box.gltf"), std::string::npos);
  }
  EXPECT_NE(errorOf(testing::scratchDir("gltf_nowhere") / "nowhere.glb").find("nowhere.glb"),
            std::string::npos);
}

// The samples' own files broken: an image and a binary container.
TEST(GltfModel, BadSampleFilesNameTheFileAndThePlace) {
  TERRASOL_SKIP_WITHOUT_TEST_DATA();
  {  // a corrupt image
    const auto dir = copyOf("BoxTextured/glTF", "corrupt_image");
    std::ofstream(dir / "CesiumLogoFlat.png", std::ios::binary | std::ios::trunc)
        << "\x89PNG\r\n\x1a\n but not really";
    const std::string e = errorOf(dir / "BoxTextured.gltf");
    EXPECT_NE(e.find("BoxTextured.gltf"), std::string::npos) << e;
    EXPECT_NE(e.find("images[0]"), std::string::npos) << e;
  }
  {  // malformed JSON and a truncated .glb
    const auto dir = copyOf("BoxTextured", "truncated");
    std::ofstream(dir / "glTF" / "BoxTextured.gltf", std::ios::trunc) << "{ \"asset\": ";
    EXPECT_NE(errorOf(dir / "glTF" / "BoxTextured.gltf").find("BoxTextured.gltf"), std::string::npos);
    const std::string glb = readTextFile(dir / "glTF-Binary" / "BoxTextured.glb");
    std::ofstream(dir / "glTF-Binary" / "BoxTextured.glb", std::ios::binary | std::ios::trunc)
        << glb.substr(0, glb.size() / 2);
    EXPECT_NE(errorOf(dir / "glTF-Binary" / "BoxTextured.glb").find("BoxTextured.glb"), std::string::npos);
  }
}

}  // namespace
}  // namespace terrasol
