#version 450 core
// A shader pack's vertex inputs from a section's block vertex (engine/mesh/mesh_data.h), as OptiFine
// feeds terrain: gl_Vertex in player space (camera-relative world), the atlas UV of the face's
// texture, the lightmap coordinate as light x 16, the tint times vanilla's ambient occlusion as the
// colour, mc_Entity from block.properties by texture. Spliced after the rewrite's declarations
// (engine/shaderpack/glsl_rewriter.h).

#include "lib/atlas_uv.glsl"
#include "lib/block_vertex.glsl"

layout(location = ATTRIB_PACKED) in uvec4 tsol_packed;
uniform vec3 u_sectionOffset;  // the section's minimum corner minus the camera (computed in double)
uniform bool tsol_oldLighting;  // shaders.properties oldLighting: vanilla's shade by face in gl_Color

layout(std430, binding = STORAGE_PACK_ENTITIES) readonly buffer tsol_EntityIds {
  vec2 tsol_entityIds[];  // mc_Entity.xy of each texture id
};

const vec3 tsol_faceNormals[10] = FACE_NORMALS;
const vec3 tsol_faceTangents[10] = FACE_TANGENTS;
const vec3 tsol_faceUps[10] = FACE_UPS;
const float tsol_faceShade[10] = PACK_FACE_SHADE;

void tsol_readVertex() {
  BlockVertex v = unpackBlockVertex(tsol_packed);
  vec2 tile = atlasTile(v.texture);
  vec2 tileSize = float(u_atlasGrid.z) / u_atlasSize;
  tsol_Vertex = vec4(u_sectionOffset + v.position, 1.0);
  tsol_Normal = tsol_faceNormals[v.face];
  // Vanilla's smooth lighting shades a corner by its open cells, 0.2 for each solid one of four.
  float ao = 0.4 + 0.6 * v.ao;
  float shade = tsol_oldLighting ? tsol_faceShade[v.face] : 1.0;
  tsol_Color = vec4((v.tint == TINT_NONE ? vec3(1.0) : v.tintColour) * ao * shade, 1.0);
  tsol_MultiTexCoord0 = vec4(tile + v.uv * tileSize, 0.0, 1.0);
  tsol_MultiTexCoord1 = vec4(vec2(v.blockLight, v.skyLight) * PACK_LIGHT_SCALE, 0.0, 1.0);
  tsol_Entity = vec4(tsol_entityIds[v.texture], 0.0, 0.0);
  tsol_MidTexCoord = vec4(tile + 0.5 * tileSize, 0.0, 1.0);
  tsol_Tangent = vec4(tsol_faceTangents[v.face], 1.0);
  // From the corner to the block's centre, x64: across the face by its UV, half a block inwards.
  vec3 toCentre = tsol_faceTangents[v.face] * (0.5 - v.uv.x) + tsol_faceUps[v.face] * (v.uv.y - 0.5) -
                  0.5 * tsol_Normal;
  tsol_MidBlock = vec4(toCentre * 64.0, 0.0);
  tsol_Velocity = vec4(0.0);
}
