#pragma once
// Binding points shared by C++ and GLSL. Shaders see them only as injected #defines (slotDefines()),
// never as numbers copied by hand.

#include <vector>

#include "assets/shader_source.h"

namespace terrasol::slots {

// Vertex attribute locations.
inline constexpr int kAttribPosition = 0;
inline constexpr int kAttribNormal = 1;
inline constexpr int kAttribColor = 2;

// The block vertex (mesh/mesh_data.h PackedVertex) as one uvec4.
inline constexpr int kAttribPacked = 3;

// A prop's vertex (render/props.h): position and normal above, then these; light from a second buffer.
inline constexpr int kAttribTangent = 4;
inline constexpr int kAttribUv = 5;
inline constexpr int kAttribLight = 6;

// Far terrain's vertex (lod/lod_vertex.h): corner and height, the cell it follows, colour and face.
inline constexpr int kAttribLodCorner = 0;
inline constexpr int kAttribLodCell = 1;
inline constexpr int kAttribLodMaterial = 2;

// Fragment outputs of the forward passes.
inline constexpr int kOutColor = 0;
inline constexpr int kOutReflectionHit = 1;      // the reflection march's second target (hit or not, where)
inline constexpr int kOutReflectionSurface = 2;  // the march from water and glass: the normal it used
inline constexpr int kOutReactive = 1;  // the translucent pass's second target: what TAA's history lags

// Texture units of the block passes (the G-buffer targets use units 0..4 in the passes that read them).
inline constexpr int kUnitAtlasAlbedo = 0;
inline constexpr int kUnitAtlasNormal = 1;
inline constexpr int kUnitAtlasSpecular = 2;
inline constexpr int kUnitShadowMap = 6;
inline constexpr int kUnitTransmittance = 8;

// A prop material's textures (glTF metallic-roughness), after every unit the passes above use.
inline constexpr int kUnitPropBaseColor = 9;
inline constexpr int kUnitPropMetallicRoughness = 10;
inline constexpr int kUnitPropNormal = 11;
inline constexpr int kUnitPropEmissive = 12;
inline constexpr int kUnitPropOcclusion = 13;

// The reflection pass: the lit scene it reflects, and its own result the composite adds.
inline constexpr int kUnitReflectionScene = 14;
inline constexpr int kUnitReflection = 15;
inline constexpr int kUnitReflectionHits = 16;
inline constexpr int kUnitSsrDepth = 17;  // the depth a reflected ray is marched against
// The march from water and glass, for the debug views.
inline constexpr int kUnitSurfaceReflection = 18;
inline constexpr int kUnitSurfaceReflectionHits = 19;
// The cloud layer's map (the sky, lighting, reflection and translucent passes).
inline constexpr int kUnitClouds = 20;
inline constexpr int kUnitLodMask = 21;  // the chunks full detail covers (render/lod_meshes.h)

// A shader pack's samplers: OptiFine's units (0 the atlas, 1 the lightmap, ...) from here on.
inline constexpr int kUnitPackBase = 24;

// Shader storage buffers.
inline constexpr int kStorageTiles = 0;         // atlas tile of each texture id for the current frame
inline constexpr int kStoragePackEntities = 1;  // a shader pack's mc_Entity of each texture id

}  // namespace terrasol::slots

namespace terrasol {

// ATTRIB_POSITION, ATTRIB_NORMAL, ... for the preprocessor.
std::vector<ShaderDefine> slotDefines();

}  // namespace terrasol
