#include "shaderpack/glsl_rewriter.h"

#include <algorithm>
#include <charconv>
#include <map>
#include <set>
#include <string_view>

#include "core/error.h"
#include "shaderpack/glsl_tokens.h"
#include "shaderpack/pack_directives.h"

namespace terrasol {
namespace {

using Tokens = std::vector<GlslToken>;

constexpr std::string_view kPrelude = "<shader pack prelude>";

// Legacy texture lookups and their 1.30+ overloads.
const std::map<std::string_view, std::string_view> kTextureFunctions = {
    {"texture1D", "texture"},
    {"texture2D", "texture"},
    {"texture3D", "texture"},
    {"textureCube", "texture"},
    {"texture2DLod", "textureLod"},
    {"texture3DLod", "textureLod"},
    {"textureCubeLod", "textureLod"},
    {"texture2DGrad", "textureGrad"},
    {"texture2DGradARB", "textureGrad"},
    {"texture2DProj", "textureProj"},
    {"texture2DProjLod", "textureProjLod"},
    {"texture2DOffset", "textureOffset"},
    {"texture2DLodOffset", "textureLodOffset"},
    {"texelFetch2D", "texelFetch"},
    {"texelFetch3D", "texelFetch"},
    {"shadow2D", "tsol_shadow2D"},
    {"shadow2DLod", "tsol_shadow2DLod"},
};

// The fixed-function state packs read, as uniforms of ours.
const std::map<std::string_view, std::string_view> kMatrices = {
    {"gl_ModelViewMatrix", "tsol_ModelViewMatrix"},
    {"gl_ProjectionMatrix", "tsol_ProjectionMatrix"},
    {"gl_ModelViewProjectionMatrix", "tsol_ModelViewProjectionMatrix"},
    {"gl_ModelViewMatrixInverse", "tsol_ModelViewMatrixInverse"},
    {"gl_ProjectionMatrixInverse", "tsol_ProjectionMatrixInverse"},
    {"gl_NormalMatrix", "tsol_NormalMatrix"},
    {"gl_TextureMatrix", "tsol_TextureMatrix"},
};

// The vertex inputs, filled by the stage's vertex reader.
const std::map<std::string_view, std::string_view> kVertexInputs = {
    {"gl_Vertex", "tsol_Vertex"},
    {"gl_Normal", "tsol_Normal"},
    {"gl_Color", "tsol_Color"},
    {"gl_MultiTexCoord0", "tsol_MultiTexCoord0"},
    {"gl_MultiTexCoord1", "tsol_MultiTexCoord1"},
    {"gl_MultiTexCoord2", "tsol_MultiTexCoord1"},  // an alias of the lightmap coordinate
    {"gl_MultiTexCoord3", "tsol_MidTexCoord"},
    {"ftransform", "tsol_ftransform"},
};

// The attributes OptiFine and Iris bind, and the input that fills each.
const std::map<std::string_view, std::string_view> kAttributes = {
    {"mc_Entity", "tsol_Entity"},     {"mc_midTexCoord", "tsol_MidTexCoord"}, {"at_tangent", "tsol_Tangent"},
    {"at_midBlock", "tsol_MidBlock"}, {"at_velocity", "tsol_Velocity"},
};

// Keywords of later GLSL that older packs use as names.
const std::set<std::string_view> kLaterKeywords = {
    "sample",   "smooth",   "patch",    "subroutine", "common",    "partition", "active",
    "filter",   "input",    "output",   "resource",   "buffer",    "shared",    "precise",
    "coherent", "volatile", "restrict", "readonly",   "writeonly",
};

constexpr std::string_view kVertexDeclarations =
    "vec4 tsol_Vertex;\n"
    "vec3 tsol_Normal;\n"
    "vec4 tsol_Color;\n"
    "vec4 tsol_MultiTexCoord0;\n"
    "vec4 tsol_MultiTexCoord1;\n"
    "vec4 tsol_Entity;\n"
    "vec4 tsol_MidTexCoord;\n"
    "vec4 tsol_Tangent;\n"
    "vec4 tsol_MidBlock;\n"
    "vec4 tsol_Velocity;\n";

constexpr std::string_view kMatrixDeclarations =
    "uniform mat4 tsol_ModelViewMatrix;\n"
    "uniform mat4 tsol_ProjectionMatrix;\n"
    "uniform mat4 tsol_ModelViewProjectionMatrix;\n"
    "uniform mat4 tsol_ModelViewMatrixInverse;\n"
    "uniform mat4 tsol_ProjectionMatrixInverse;\n"
    "uniform mat3 tsol_NormalMatrix;\n"
    "uniform mat4 tsol_TextureMatrix[4];\n";

constexpr std::string_view kShadowLookups =
    "vec4 tsol_shadow2D(sampler2DShadow s, vec3 c) { return vec4(texture(s, c)); }\n"
    "vec4 tsol_shadow2D(sampler2DShadow s, vec3 c, float bias) { return vec4(texture(s, c, bias)); }\n"
    "vec4 tsol_shadow2D(sampler2D s, vec3 c) { return vec4(step(c.z, texture(s, c.xy).r)); }\n"
    "vec4 tsol_shadow2DLod(sampler2DShadow s, vec3 c, float lod) { return vec4(textureLod(s, c, lod)); }\n"
    "vec4 tsol_shadow2DLod(sampler2D s, vec3 c, float lod) { return vec4(step(c.z, textureLod(s, c.xy, "
    "lod).r)); }\n";

struct Directive {
  std::string name;  // "version", "extension", "if", ...
  int line = 0;
};

// The directive a '#' token starts.
Directive directiveAt(const Tokens& tokens, std::size_t hash) {
  for (std::size_t i = hash + 1; i < tokens.size() && tokens[i].directive; ++i) {
    if (tokens[i].kind == GlslTokenKind::Newline) break;
    if (tokens[i].kind == GlslTokenKind::Identifier) return {tokens[i].text, tokens[hash].line};
    if (tokens[i].significant()) break;
  }
  return {"", tokens[hash].line};
}

bool startsDirective(const Tokens& tokens, std::size_t i) {
  if (!tokens[i].directive || !tokens[i].is("#")) return false;
  for (std::size_t j = i; j-- > 0;) {
    if (tokens[j].kind == GlslTokenKind::Newline) return true;
    if (tokens[j].significant()) return false;
  }
  return true;
}

// The significant tokens' indices around `i`.
std::size_t previousSignificant(const Tokens& tokens, std::size_t i) {
  while (i-- > 0)
    if (tokens[i].significant()) return i;
  return tokens.size();
}
std::size_t nextSignificant(const Tokens& tokens, std::size_t i) {
  for (++i; i < tokens.size(); ++i)
    if (tokens[i].significant()) return i;
  return tokens.size();
}

// A layout(...) qualifier ending at `close` (its ')'): the index of `layout`, or tokens.size().
std::size_t layoutBefore(const Tokens& tokens, std::size_t close) {
  if (close >= tokens.size() || !tokens[close].is(")")) return tokens.size();
  std::size_t i = close;
  int depth = 0;
  for (;; --i) {
    if (tokens[i].is(")")) ++depth;
    if (tokens[i].is("(") && --depth == 0) break;
    if (i == 0) return tokens.size();
  }
  const std::size_t name = previousSignificant(tokens, i);
  return name < tokens.size() && tokens[name].is("layout") ? name : tokens.size();
}

// `location = N` inside the layout(...) starting at `layout`; -1 when absent.
int layoutLocation(const Tokens& tokens, std::size_t layout, std::size_t close) {
  for (std::size_t i = layout; i < close; ++i) {
    if (!tokens[i].is("location")) continue;
    const std::size_t eq = nextSignificant(tokens, i);
    const std::size_t n = nextSignificant(tokens, eq);
    int value = -1;
    if (n < close && tokens[eq].is("=")) {
      const std::string& t = tokens[n].text;
      std::from_chars(t.data(), t.data() + t.size(), value);
    }
    return value;
  }
  return -1;
}

void blank(Tokens& tokens, std::size_t from, std::size_t to) {
  for (std::size_t i = from; i <= to; ++i)
    if (tokens[i].kind != GlslTokenKind::Newline) tokens[i].text.clear();
}

void appendLines(PreprocessedShader& out, std::string_view text, std::string_view file) {
  int n = 0;
  for (std::size_t start = 0; start < text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    out.text.append(text.substr(start, end - start)).push_back('\n');
    out.lines.push_back({std::string(file), ++n});
    start = end + 1;
  }
}

}  // namespace

RewrittenStage rewritePackStage(const PreprocessedShader& pack, const PackStageRewrite& how) {
  Tokens tokens = tokenizeGlsl(pack.text);
  RewrittenStage result;
  const auto fail = [&](int line, const std::string& what) {
    const SourceLocation at = pack.origin(line);
    throw Error(at.file + ":" + std::to_string(at.line) + ": " + what);
  };

  // #version, and the line after which the declarations go: after the last #extension, outside
  // any #if around it (extensions must precede code).
  std::size_t versionHash = tokens.size();
  int insertAfter = 0, depth = 0;
  bool extensionOpen = false;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    if (!startsDirective(tokens, i)) continue;
    const Directive d = directiveAt(tokens, i);
    if (d.name == "version" && versionHash == tokens.size()) {
      versionHash = i;
      insertAfter = d.line;
    } else if (d.name == "if" || d.name == "ifdef" || d.name == "ifndef") {
      ++depth;
    } else if (d.name == "endif") {
      depth = std::max(depth - 1, 0);
      if (extensionOpen && depth == 0) {
        insertAfter = d.line;
        extensionOpen = false;
      }
    } else if (d.name == "extension") {
      insertAfter = d.line;
      extensionOpen = depth > 0;
    }
  }
  if (versionHash == tokens.size()) fail(1, "no #version");
  {
    const std::size_t number = nextSignificant(tokens, nextSignificant(tokens, versionHash));
    if (number < tokens.size() && tokens[number].kind == GlslTokenKind::Number) {
      const std::string& t = tokens[number].text;
      std::from_chars(t.data(), t.data() + t.size(), result.packVersion);
    }
    std::size_t end = versionHash;
    while (end + 1 < tokens.size() && tokens[end + 1].kind != GlslTokenKind::Newline) ++end;
    blank(tokens, versionHash, end);
    tokens[versionHash].text = "#version 450 core";
  }
  const bool legacy = result.packVersion < 130;
  const bool vertex = how.stage == PackStage::Vertex;
  const bool fragment = how.stage == PackStage::Fragment;
  const bool wrapMain = vertex || (fragment && how.alphaTest);

  std::set<std::string_view> used;  // prelude pieces the pack needs
  bool skipLine = false;            // #version, #extension, #pragma and #line lines pass untouched
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    GlslToken& t = tokens[i];
    if (t.kind == GlslTokenKind::Newline) {
      skipLine = skipLine && t.directive;
      continue;
    }
    if (startsDirective(tokens, i)) {
      const std::string name = directiveAt(tokens, i).name;
      skipLine = name == "version" || name == "extension" || name == "pragma" || name == "line";
    }
    if (skipLine || t.kind != GlslTokenKind::Identifier) continue;
    const std::string original = t.text;

    if (vertex && kAttributes.contains(original) && !t.directive) {
      // `attribute vec4 mc_Entity;` / `layout(...) in vec2 mc_Entity;`: a global the reader fills.
      const std::size_t type = previousSignificant(tokens, i);
      const std::size_t qualifier = previousSignificant(tokens, type);
      const std::size_t end = nextSignificant(tokens, i);
      if (qualifier < tokens.size() && end < tokens.size() && tokens[end].is(";") &&
          (tokens[qualifier].is("attribute") || tokens[qualifier].is("in"))) {
        result.attributes.push_back({original, tokens[type].text});
        tokens[qualifier].text.clear();
        const std::size_t layout = layoutBefore(tokens, previousSignificant(tokens, qualifier));
        if (layout < tokens.size()) blank(tokens, layout, previousSignificant(tokens, qualifier));
      }
      continue;
    }
    if (fragment && original == "out" && !t.directive) {
      // `[layout(location = N)] out vec4 name;`
      const std::size_t type = nextSignificant(tokens, i);
      const std::size_t name = nextSignificant(tokens, type);
      if (name < tokens.size() && tokens[name].kind == GlslTokenKind::Identifier) {
        const std::size_t close = previousSignificant(tokens, i);
        const std::size_t layout = layoutBefore(tokens, close);
        result.outputs.push_back(
            {tokens[name].text, layout < tokens.size() ? layoutLocation(tokens, layout, close) : -1});
      }
      continue;
    }

    if (auto f = kTextureFunctions.find(original); f != kTextureFunctions.end()) {
      t.text = f->second;
      if (original.starts_with("shadow2D")) used.insert("shadow");
    } else if (auto m = kMatrices.find(original); m != kMatrices.end()) {
      t.text = m->second;
    } else if (auto v = kVertexInputs.find(original); vertex && v != kVertexInputs.end()) {
      t.text = v->second;
    } else if (original == "gl_FragData" && fragment) {
      t.text = "tsol_FragData";
      result.fragData = true;
      const std::size_t open = nextSignificant(tokens, i);
      const std::size_t index = nextSignificant(tokens, open);
      int n = kPackMaxDrawBuffers - 1;  // an index that is not a number may be any
      if (open < tokens.size() && tokens[open].is("[") && index < tokens.size() &&
          tokens[index].kind == GlslTokenKind::Number) {
        const std::string& digits = tokens[index].text;
        std::from_chars(digits.data(), digits.data() + digits.size(), n);
      }
      result.fragDataCount = std::clamp(std::max(result.fragDataCount, n + 1), 1, kPackMaxDrawBuffers);
    } else if (original == "gl_FragColor" && fragment) {
      t.text = "tsol_FragData[0]";
      result.fragData = true;
      result.fragDataCount = std::max(result.fragDataCount, 1);
    } else if ((original == "gl_FrontColor" && vertex) || (original == "gl_Color" && fragment)) {
      t.text = "tsol_FrontColor";
      used.insert("frontColor");
    } else if (original == "gl_TexCoord" && (vertex || fragment)) {
      t.text = "tsol_TexCoord";
      used.insert("texCoord");
    } else if (original == "gl_Fog") {
      t.text = "tsol_Fog";
      used.insert("fog");
    } else if (original == "attribute" && vertex) {
      t.text = "in";
    } else if (original == "varying" && (vertex || fragment)) {
      t.text = vertex ? "out" : "in";
    } else if (original == "main" && wrapMain) {
      t.text = "tsol_packMain";
    } else if (legacy && original == "texture") {
      t.text = "gtexture";
    } else if (legacy && kLaterKeywords.contains(original)) {
      t.text = "tsol_" + original;
    }
  }

  // Declarations, then the vertex reader, after the insertion line.
  std::string declarations;
  if (vertex) {
    declarations += kVertexDeclarations;
    declarations += "vec4 tsol_ftransform() { return tsol_ModelViewProjectionMatrix * tsol_Vertex; }\n";
  }
  declarations.insert(0, kMatrixDeclarations);
  if (used.contains("shadow")) declarations += kShadowLookups;
  if (used.contains("frontColor"))
    declarations += vertex ? "out vec4 tsol_FrontColor;\n" : "in vec4 tsol_FrontColor;\n";
  if (used.contains("texCoord"))
    declarations += vertex ? "out vec4 tsol_TexCoord[4];\n" : "in vec4 tsol_TexCoord[4];\n";
  if (used.contains("fog")) {
    declarations +=
        "struct tsol_FogParameters { vec4 color; float density, start, end, scale; };\n"
        "uniform tsol_FogParameters tsol_Fog;\n";
  }
  if (result.fragData)
    declarations +=
        "layout(location = 0) out vec4 tsol_FragData[" + std::to_string(kPackMaxDrawBuffers) + "];\n";
  if (fragment && how.alphaTest) declarations += "uniform float tsol_alphaTestRef;\n";

  std::string epilogue;
  if (vertex) {
    epilogue = "void main() {\n  tsol_readVertex();\n";
    for (const PackAttribute& a : result.attributes)
      epilogue += "  " + a.name + " = " + a.type + "(" + std::string(kAttributes.at(a.name)) + ");\n";
    epilogue += "  tsol_packMain();\n}\n";
  } else if (fragment && how.alphaTest) {
    std::string colour;
    if (result.fragData) {
      colour = "tsol_FragData[0]";
    } else {
      for (const PackFragmentOutput& o : result.outputs)
        if (o.location == 0 || (o.location < 0 && result.outputs.size() == 1)) colour = o.name;
    }
    if (colour.empty()) fail(insertAfter, "an alpha-tested program without an output at location 0");
    epilogue = "void main() {\n  tsol_packMain();\n  if (" + colour + ".a < tsol_alphaTestRef) discard;\n}\n";
  }

  // Join: the pack's lines up to the insertion line, the prelude, the rest, the epilogue.
  PreprocessedShader& out = result.source;
  std::size_t split = 0;
  for (; split < tokens.size(); ++split)
    if (tokens[split].kind == GlslTokenKind::Newline && tokens[split].line == insertAfter) break;
  const Tokens head(tokens.begin(),
                    tokens.begin() + static_cast<std::ptrdiff_t>(std::min(split + 1, tokens.size())));
  const Tokens tail(tokens.begin() + static_cast<std::ptrdiff_t>(std::min(split + 1, tokens.size())),
                    tokens.end());
  out.text = joinTokens(head);
  if (!out.text.empty() && out.text.back() != '\n') out.text.push_back('\n');
  out.lines.assign(pack.lines.begin(),
                   pack.lines.begin() + std::min<std::size_t>(insertAfter, pack.lines.size()));
  appendLines(out, declarations, kPrelude);
  if (vertex && how.vertexReader) {
    const PreprocessedShader& reader = *how.vertexReader;
    out.text += reader.text;
    if (!out.text.empty() && out.text.back() != '\n') out.text.push_back('\n');
    out.lines.insert(out.lines.end(), reader.lines.begin(), reader.lines.end());
  }
  out.text += joinTokens(tail);
  if (!out.text.empty() && out.text.back() != '\n') out.text.push_back('\n');
  out.lines.insert(out.lines.end(),
                   pack.lines.begin() + std::min<std::size_t>(insertAfter, pack.lines.size()),
                   pack.lines.end());
  appendLines(out, epilogue, kPrelude);
  return result;
}

}  // namespace terrasol
