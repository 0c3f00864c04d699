#pragma once
// Compiling and linking GLSL programs from preprocessed sources; errors name the original file:line.

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "assets/shader_source.h"
#include "core/error.h"
#include "render/gl/object.h"

namespace terrasol {

class ShaderError : public Error {
 public:
  using Error::Error;
};

struct ShaderStageSource {
  GLenum stage;      // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, ...
  std::string file;  // relative to the shader root
};

// A linked program with its name and every uniform its sources declare, kept by the linker or not:
// what gl::Uniform checks a name against (render/gl/uniforms.h).
struct LinkedProgram {
  gl::Program program;
  std::string name;                   // "shaders/a.vert + shaders/a.frag"
  std::vector<std::string> declared;  // declaredUniforms() of every stage

  GLuint id() const { return program.id(); }
  explicit operator bool() const { return static_cast<bool>(program); }
  bool declares(std::string_view uniform) const;
};

// Preprocesses, compiles and links. Throws ShaderError whose message holds the driver's log with every
// position mapped back to "shaders/<file>:<line>", or Error from the preprocessor.
LinkedProgram linkProgram(const ShaderPreprocessor& sources, const std::vector<ShaderStageSource>& stages,
                          const std::vector<ShaderDefine>& defines);
// A stage already preprocessed (a shader pack's, rewritten), named `name` in messages.
struct PreprocessedStage {
  GLenum stage;
  const PreprocessedShader* source;
  std::string name;
};
// Compiles and links; `beforeLink` binds attribute or output locations. Throws ShaderError as above.
LinkedProgram linkPreprocessed(const std::vector<PreprocessedStage>& stages,
                               const std::function<void(GLuint)>& beforeLink = {});
// The same, for a program whose uniforms are set by hand.
gl::Program buildProgram(const ShaderPreprocessor& sources, const std::vector<ShaderStageSource>& stages,
                         const std::vector<ShaderDefine>& defines);

namespace gl {
// `name`'s location in `program`, or -1 where the linker removed it (or `program` is empty). Throws
// ShaderError naming both when the program's sources declare no such uniform.
GLint uniformLocation(const LinkedProgram& program, const char* name);
}  // namespace gl

}  // namespace terrasol
