#include "shaderpack/shader_properties.h"

#include <algorithm>

#include "core/error.h"

namespace terrasol {

const ShaderProperties::Entry* ShaderProperties::find(std::string_view key) const {
  for (auto it = entries.rbegin(); it != entries.rend(); ++it)
    if (it->key == key) return &*it;
  return nullptr;
}

bool ShaderProperties::programEnabled(std::string_view program, const PackEvaluation& context) const {
  const auto found = programSwitches.find(program);
  return found == programSwitches.end() || found->second.evaluate(context).scalar() != 0.0f;
}

ShaderProperties parseShaderProperties(std::string_view text, const std::string& file, PackMacros macros) {
  ShaderProperties p;
  for (const KeptLine& kept : propertyLines(text, file, macros)) {
    const std::string& line = kept.text;
    const std::string where = file + ":" + std::to_string(kept.number);
    if (trimmed(line).empty() || line.starts_with('!')) continue;
    const auto eq = line.find('=');
    if (eq == std::string::npos) throw Error(where + ": '" + line + "': expected key = value");
    ShaderProperties::Entry e{std::string(trimmed(std::string_view(line).substr(0, eq))),
                              std::string(trimmed(std::string_view(line).substr(eq + 1))), where};
    for (const std::string_view kind : {"uniform.", "variable."}) {
      if (!e.key.starts_with(kind)) continue;
      const std::string rest = e.key.substr(kind.size());
      const auto dot = rest.find('.');
      const std::string type = rest.substr(0, dot);
      constexpr std::string_view kTypes[] = {"float", "int", "bool", "vec2", "vec3", "vec4"};
      if (dot == std::string::npos || dot + 1 == rest.size() ||
          std::find(std::begin(kTypes), std::end(kTypes), type) == std::end(kTypes))
        throw Error(where + ": '" + e.key + "': expected " + std::string(kind) +
                    "<float|int|bool|vec2|vec3|vec4>.<name>");
      p.customs.push_back(
          {kind == "uniform.", type, rest.substr(dot + 1), PackExpression::parse(e.value, where), where});
    }
    constexpr std::string_view kProgram = "program.", kEnabled = ".enabled";
    if (e.key.starts_with(kProgram) && e.key.ends_with(kEnabled) &&
        e.key.size() > kProgram.size() + kEnabled.size())
      p.programSwitches.insert_or_assign(
          e.key.substr(kProgram.size(), e.key.size() - kProgram.size() - kEnabled.size()),
          PackExpression::parse(e.value, where));
    p.entries.push_back(std::move(e));
  }
  return p;
}

}  // namespace terrasol
