#pragma once
// What a model's file may leave out, computed from its triangles: flat normals, and tangents for its
// normal maps. Plain C++.

#include "assets/gltf_model.h"

namespace terrasol {

// `v` normalised, or `fallback` where it has no finite, non-zero length.
glm::vec3 safeNormalize(glm::vec3 v, glm::vec3 fallback);

// Flat normals: each triangle gets its own three vertices, facing its way.
void generateNormals(ModelMesh& mesh);
// Lengyel's per-triangle tangents from the UVs, summed per vertex and orthogonalised to the normal;
// without UVs (or where a triangle has no UV area) any direction across the normal.
void generateTangents(ModelMesh& mesh, bool hasUv);

}  // namespace terrasol
