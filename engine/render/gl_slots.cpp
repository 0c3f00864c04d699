#include "render/gl_slots.h"

#include <string>

namespace terrasol {

std::vector<ShaderDefine> slotDefines() {
  auto define = [](const char* name, int value) { return ShaderDefine{name, std::to_string(value)}; };
  return {
      define("ATTRIB_POSITION", slots::kAttribPosition),
      define("ATTRIB_NORMAL", slots::kAttribNormal),
      define("ATTRIB_COLOR", slots::kAttribColor),
      define("ATTRIB_PACKED", slots::kAttribPacked),
      define("ATTRIB_TANGENT", slots::kAttribTangent),
      define("ATTRIB_UV", slots::kAttribUv),
      define("ATTRIB_LIGHT", slots::kAttribLight),
      define("ATTRIB_LOD_CORNER", slots::kAttribLodCorner),
      define("ATTRIB_LOD_CELL", slots::kAttribLodCell),
      define("ATTRIB_LOD_MATERIAL", slots::kAttribLodMaterial),
      define("OUT_COLOR", slots::kOutColor),
      define("OUT_REFLECTION_HIT", slots::kOutReflectionHit),
      define("OUT_REFLECTION_SURFACE", slots::kOutReflectionSurface),
      define("OUT_REACTIVE", slots::kOutReactive),
      define("UNIT_ATLAS_ALBEDO", slots::kUnitAtlasAlbedo),
      define("UNIT_ATLAS_NORMAL", slots::kUnitAtlasNormal),
      define("UNIT_ATLAS_SPECULAR", slots::kUnitAtlasSpecular),
      define("UNIT_SHADOW_MAP", slots::kUnitShadowMap),
      define("UNIT_TRANSMITTANCE", slots::kUnitTransmittance),
      define("UNIT_PROP_BASE_COLOR", slots::kUnitPropBaseColor),
      define("UNIT_PROP_METALLIC_ROUGHNESS", slots::kUnitPropMetallicRoughness),
      define("UNIT_PROP_NORMAL", slots::kUnitPropNormal),
      define("UNIT_PROP_EMISSIVE", slots::kUnitPropEmissive),
      define("UNIT_PROP_OCCLUSION", slots::kUnitPropOcclusion),
      define("UNIT_REFLECTION_SCENE", slots::kUnitReflectionScene),
      define("UNIT_REFLECTION", slots::kUnitReflection),
      define("UNIT_REFLECTION_HITS", slots::kUnitReflectionHits),
      define("UNIT_SSR_DEPTH", slots::kUnitSsrDepth),
      define("UNIT_SURFACE_REFLECTION", slots::kUnitSurfaceReflection),
      define("UNIT_SURFACE_REFLECTION_HITS", slots::kUnitSurfaceReflectionHits),
      define("UNIT_CLOUDS", slots::kUnitClouds),
      define("UNIT_LOD_MASK", slots::kUnitLodMask),
      define("STORAGE_TILES", slots::kStorageTiles),
      define("STORAGE_PACK_ENTITIES", slots::kStoragePackEntities),
  };
}

}  // namespace terrasol
