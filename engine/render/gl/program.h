#pragma once
// Compiling and linking GLSL programs from preprocessed sources; errors name the original file:line.

#include <string>
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

// Preprocesses, compiles and links. Throws ShaderError whose message holds the driver's log with every
// position mapped back to "shaders/<file>:<line>", or Error from the preprocessor.
gl::Program buildProgram(const ShaderPreprocessor& sources, const std::vector<ShaderStageSource>& stages,
                         const std::vector<ShaderDefine>& defines);

}  // namespace terrasol
