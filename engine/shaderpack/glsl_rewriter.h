#pragma once
// Shader packs' GLSL, as OptiFine runs it on a compatibility context (`#version 120` to `460
// compatibility`), rewritten into the `450 core` GLSL Terrasol's context compiles. A token rewrite,
// no parser: what packs write is mapped one name at a time, and the source keeps its lines, so a
// driver's message still names the pack's file and line.
//
//   #version N [profile]              -> #version 450 core
//   attribute / varying               -> in / out (vertex), in (fragment)
//   gl_Vertex, gl_Normal, gl_Color,   -> tsol_* globals the vertex stage's input reader fills before
//   gl_MultiTexCoord0..3, mc_Entity,     the pack's main runs (main is renamed, and a main that reads
//   mc_midTexCoord, at_tangent, ...      the vertex and calls it is appended); attributes the pack
//                                        declares keep its type (vec2 or vec4 mc_Entity alike)
//   gl_*Matrix, ftransform()          -> tsol_* uniforms the renderer sets, MVP * gl_Vertex
//   gl_FragData[i], gl_FragColor      -> tsol_FragData[i], an output array from location 0
//   texture2D, texture2DLod, ...      -> texture, textureLod, ... ; shadow2D -> vec4(texture(...))
//   sampler `texture` (GLSL < 1.30)   -> gtexture (a function's name from 1.30 on)
//   newer keywords used as names      -> tsol_<name> (`sample`, `smooth`, `filter`, ... in old GLSL)
//   gl_FrontColor / gl_Color (frag), gl_TexCoord[], gl_Fog -> varyings and a uniform of their own
//
// Fragment stages drawn with an alpha test get a main that discards below `tsol_alphaTestRef` after
// the pack's, as OptiFine's fixed-function alpha test did. GL-free.

#include <string>
#include <vector>

#include "assets/shader_source.h"

namespace terrasol {

enum class PackStage { Vertex, Geometry, Fragment };

struct PackStageRewrite {
  PackStage stage = PackStage::Vertex;
  // Vertex: GLSL (no #version) defining `void tsol_readVertex()`, which fills the tsol_* inputs the
  // rewrite declares; placed after those declarations, before the pack's code.
  const PreprocessedShader* vertexReader = nullptr;
  bool alphaTest = false;  // fragment: discard below tsol_alphaTestRef after the pack's main
};

// An attribute the pack's vertex stage declares, by Terrasol's name for it.
struct PackAttribute {
  std::string name;  // as the pack declares it: "mc_Entity"
  std::string type;  // "vec4", "vec2", ...
};

// A fragment output the pack declares itself (core-style packs).
struct PackFragmentOutput {
  std::string name;
  int location = -1;  // from its layout qualifier; -1: none given
};

struct RewrittenStage {
  PreprocessedShader source;
  int packVersion = 0;                      // the pack's #version number
  std::vector<PackAttribute> attributes;    // vertex: the pack's attributes Terrasol provides
  bool fragData = false;                    // writes gl_FragData / gl_FragColor
  int fragDataCount = 0;                    // 1 + the highest gl_FragData index written
  std::vector<PackFragmentOutput> outputs;  // fragment: declared outputs
};

// Throws Error naming the pack's file and line: no #version, or an alpha-tested stage whose colour
// output cannot be found.
RewrittenStage rewritePackStage(const PreprocessedShader& pack, const PackStageRewrite& how);

}  // namespace terrasol
