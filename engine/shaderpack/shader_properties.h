#pragma once
// A shader pack's `shaders.properties`: `key = value` lines (a trailing `\` joins lines) under the
// conditionals every `.properties` file may use. Kept in file order, a later line overriding an
// earlier one's key; custom uniforms and variables (`uniform.<type>.<name>`, `variable.<type>.<name>`)
// parsed as expressions, in the order they are evaluated each frame. GL-free.

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "shaderpack/pack_conditions.h"
#include "shaderpack/pack_expression.h"

namespace terrasol {

struct PackCustom {
  bool uniform = true;  // false: a variable, which expressions read but programs do not
  std::string type;     // float, int, bool, vec2, vec3, vec4
  std::string name;
  PackExpression expression;
  std::string where;  // file:line
};

struct ShaderProperties {
  struct Entry {
    std::string key, value, where;
  };
  std::vector<Entry> entries;
  std::vector<PackCustom> customs;
  // `program.<name>.enabled`, parsed once, by program name (the last line's).
  std::map<std::string, PackExpression, std::less<>> programSwitches;

  // The last line with this key, or nothing.
  const Entry* find(std::string_view key) const;
  // `program.<name>.enabled`, evaluated; true without one.
  bool programEnabled(std::string_view program, const PackEvaluation& context) const;
};

// Throws Error naming `file` and the line: a line without '=', a malformed conditional, a custom
// uniform of an unknown type or with a malformed expression.
ShaderProperties parseShaderProperties(std::string_view text, const std::string& file, PackMacros macros);

}  // namespace terrasol
