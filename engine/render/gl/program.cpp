#include "render/gl/program.h"

namespace terrasol {
namespace {

std::string infoLog(GLuint object, bool isProgram) {
  GLint length = 0;
  isProgram ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length) : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  isProgram ? glGetProgramInfoLog(object, length, nullptr, log.data())
            : glGetShaderInfoLog(object, length, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

gl::Shader compile(const ShaderPreprocessor& sources, const ShaderStageSource& stage,
                   const std::vector<ShaderDefine>& defines) {
  const PreprocessedShader pre = sources.process(stage.file, defines);
  gl::Shader shader = gl::Shader::create(stage.stage);
  const char* text = pre.text.c_str();
  glShaderSource(shader.id(), 1, &text, nullptr);
  glCompileShader(shader.id());
  GLint ok = GL_FALSE;
  glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
  if (!ok) {
    throw ShaderError("cannot compile " + sources.displayName(stage.file) + ":\n" +
                      pre.mapLog(infoLog(shader.id(), false)));
  }
  return shader;
}

}  // namespace

gl::Program buildProgram(const ShaderPreprocessor& sources, const std::vector<ShaderStageSource>& stages,
                         const std::vector<ShaderDefine>& defines) {
  std::vector<gl::Shader> shaders;
  std::string names;
  for (const auto& stage : stages) {
    shaders.push_back(compile(sources, stage, defines));
    names += (names.empty() ? "" : " + ") + sources.displayName(stage.file);
  }
  gl::Program program = gl::Program::create();
  for (const auto& shader : shaders) glAttachShader(program.id(), shader.id());
  glLinkProgram(program.id());
  for (const auto& shader : shaders) glDetachShader(program.id(), shader.id());
  GLint ok = GL_FALSE;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (!ok) throw ShaderError("cannot link " + names + ":\n" + infoLog(program.id(), true));
  return program;
}

}  // namespace terrasol
