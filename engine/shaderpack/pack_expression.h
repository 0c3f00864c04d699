#pragma once
// OptiFine's expression language, as shaders.properties writes custom uniforms, variables and
// `program.<name>.enabled` (OptiFineDoc shaders.properties, "Custom uniforms"): numbers, `true`,
// `false`, `pi`, names of uniforms and variables (a vector's component as `cameraPosition.y`), the
// operators `! - * / % + - < <= > >= == != && ||` with C's precedence, and the functions sin, cos,
// asin, acos, tan, atan, atan2, torad, todeg, min, max, clamp, abs, floor, ceil, exp, frac, log,
// pow, round, signum, sqrt, fmod, if, between, equals, in, smooth, vec2, vec3, vec4. Booleans are 1
// and 0. GL-free.

#include <functional>
#include <glm/vec4.hpp>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace terrasol {

// A scalar (size 1) or a vector of 2 to 4 components.
struct PackValue {
  int size = 1;
  glm::vec4 v{0.0f};
  float scalar() const { return v.x; }
  static PackValue of(float f) { return {1, glm::vec4(f, 0.0f, 0.0f, 0.0f)}; }
};

struct PackEvaluation {
  // The value of a uniform or variable by name; nothing for a name it does not know.
  std::function<std::optional<PackValue>(std::string_view)> lookUp;
  float frameTime = 0.0f;  // seconds since the last evaluation, for smooth()
};

class PackExpression {
 public:
  // Throws Error naming `where` (file and line) and what is wrong.
  static PackExpression parse(std::string_view text, const std::string& where);
  // Throws Error naming the expression's place for an unknown name or a wrong call. smooth() keeps
  // its state in the expression between evaluations.
  PackValue evaluate(const PackEvaluation& context) const;

  struct Node;

 private:
  std::shared_ptr<Node> root_;
  std::string where_;
};

}  // namespace terrasol
