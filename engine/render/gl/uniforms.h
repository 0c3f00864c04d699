#pragma once
// Setting a program's uniforms by name (DSA: no program needs to be bound).

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "render/gl/object.h"

namespace terrasol::gl {

inline void setVec3(GLuint program, const char* name, glm::vec3 v) {
  glProgramUniform3fv(program, glGetUniformLocation(program, name), 1, glm::value_ptr(v));
}
inline void setMat4(GLuint program, const char* name, const glm::mat4& m) {
  glProgramUniformMatrix4fv(program, glGetUniformLocation(program, name), 1, GL_FALSE, glm::value_ptr(m));
}

}  // namespace terrasol::gl
