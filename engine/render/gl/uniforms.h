#pragma once
// A program's uniforms, typed and named once: each pass lists its programs' uniforms in small tables
// (structs of Uniform) built right after the link, so setting one looks nothing up by name.
//
// A misspelt name fails where the table is built: a name that no source of the program declares
// throws ShaderError naming the program and the uniform, in every build type. A declared uniform the
// linker removed (unused in this variant, or inside an #ifdef its defines leave out) is fine: its
// location is -1 and setting it does nothing, as GL does for -1. The check reads the sources, never
// what a driver's optimiser kept, so it cannot throw on one driver and pass on another.

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <type_traits>
#include <utility>

#include "render/gl/program.h"

namespace terrasol::gl {

inline void write(GLuint p, GLint at, const float* v, GLsizei n) {
  glProgramUniform1fv(p, at, n, v);
}
inline void write(GLuint p, GLint at, const int* v, GLsizei n) {
  glProgramUniform1iv(p, at, n, v);
}
inline void write(GLuint p, GLint at, const glm::vec2* v, GLsizei n) {
  glProgramUniform2fv(p, at, n, glm::value_ptr(*v));
}
inline void write(GLuint p, GLint at, const glm::vec3* v, GLsizei n) {
  glProgramUniform3fv(p, at, n, glm::value_ptr(*v));
}
inline void write(GLuint p, GLint at, const glm::vec4* v, GLsizei n) {
  glProgramUniform4fv(p, at, n, glm::value_ptr(*v));
}
inline void write(GLuint p, GLint at, const glm::ivec2* v, GLsizei n) {
  glProgramUniform2iv(p, at, n, glm::value_ptr(*v));
}
inline void write(GLuint p, GLint at, const glm::ivec3* v, GLsizei n) {
  glProgramUniform3iv(p, at, n, glm::value_ptr(*v));
}
inline void write(GLuint p, GLint at, const glm::mat3* v, GLsizei n) {
  glProgramUniformMatrix3fv(p, at, n, GL_FALSE, glm::value_ptr(*v));
}
inline void write(GLuint p, GLint at, const glm::mat4* v, GLsizei n) {
  glProgramUniformMatrix4fv(p, at, n, GL_FALSE, glm::value_ptr(*v));
}

// One uniform of type T (bool for GLSL bool). Default-constructed, or from an empty program (a
// variant not built), it sets nothing.
template <class T>
class Uniform {
 public:
  Uniform() = default;
  Uniform(const LinkedProgram& program, const char* name)
      : program_(program.id()), location_(uniformLocation(program, name)) {}

  void set(const T& value) const {
    if (location_ < 0) return;
    if constexpr (std::is_same_v<T, bool>) {
      glProgramUniform1i(program_, location_, value ? 1 : 0);
    } else {
      write(program_, location_, &value, 1);
    }
  }
  // The first `count` elements of a uniform array.
  void set(const T* values, int count) const {
    if (location_ >= 0) write(program_, location_, values, count);
  }

 private:
  GLuint program_ = 0;
  GLint location_ = -1;
};

// A program and its table of uniforms (a struct constructible from the linked program), built together.
template <class Table>
struct ProgramWith {
  ProgramWith() = default;
  explicit ProgramWith(LinkedProgram linked) : program(std::move(linked)), u(program) {}

  GLuint id() const { return program.id(); }
  explicit operator bool() const { return static_cast<bool>(program); }

  LinkedProgram program;
  Table u;
};

}  // namespace terrasol::gl
