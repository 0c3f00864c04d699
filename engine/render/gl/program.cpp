#include "render/gl/program.h"

#include <algorithm>
#include <functional>

namespace terrasol {
namespace {

std::string infoLog(GLuint object, bool isProgram) {
  GLint length = 0;
  isProgram ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
            : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  isProgram ? glGetProgramInfoLog(object, length, nullptr, log.data())
            : glGetShaderInfoLog(object, length, nullptr, log.data());
  log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
  return log;
}

gl::Shader compileText(GLenum stage, const PreprocessedShader& pre, const std::string& name) {
  gl::Shader shader = gl::Shader::create(stage);
  const char* text = pre.text.c_str();
  glShaderSource(shader.id(), 1, &text, nullptr);
  glCompileShader(shader.id());
  GLint ok = GL_FALSE;
  glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
  if (!ok) throw ShaderError("cannot compile " + name + ":\n" + pre.mapLog(infoLog(shader.id(), false)));
  return shader;
}

gl::Shader compile(const ShaderPreprocessor& sources, const ShaderStageSource& stage,
                   const std::vector<ShaderDefine>& defines, std::vector<std::string>& declared) {
  const PreprocessedShader pre = sources.process(stage.file, defines);
  for (auto& name : declaredUniforms(pre.text)) declared.push_back(std::move(name));
  return compileText(stage.stage, pre, sources.displayName(stage.file));
}

void link(LinkedProgram& linked, const std::vector<gl::Shader>& shaders,
          const std::function<void(GLuint)>& beforeLink) {
  linked.program = gl::Program::create();
  const GLuint program = linked.program.id();
  for (const auto& shader : shaders) glAttachShader(program, shader.id());
  if (beforeLink) beforeLink(program);
  glLinkProgram(program);
  for (const auto& shader : shaders) glDetachShader(program, shader.id());
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) throw ShaderError("cannot link " + linked.name + ":\n" + infoLog(program, true));
}

}  // namespace

bool LinkedProgram::declares(std::string_view uniform) const {
  return std::find(declared.begin(), declared.end(), uniform) != declared.end();
}

LinkedProgram linkProgram(const ShaderPreprocessor& sources, const std::vector<ShaderStageSource>& stages,
                          const std::vector<ShaderDefine>& defines) {
  LinkedProgram linked;
  std::vector<gl::Shader> shaders;
  for (const auto& stage : stages) {
    shaders.push_back(compile(sources, stage, defines, linked.declared));
    linked.name += (linked.name.empty() ? "" : " + ") + sources.displayName(stage.file);
  }
  link(linked, shaders, {});
  return linked;
}

LinkedProgram linkPreprocessed(const std::vector<PreprocessedStage>& stages,
                               const std::function<void(GLuint)>& beforeLink) {
  LinkedProgram linked;
  std::vector<gl::Shader> shaders;
  for (const PreprocessedStage& stage : stages) {
    for (auto& name : declaredUniforms(stage.source->text)) linked.declared.push_back(std::move(name));
    shaders.push_back(compileText(stage.stage, *stage.source, stage.name));
    linked.name += (linked.name.empty() ? "" : " + ") + stage.name;
  }
  link(linked, shaders, beforeLink);
  return linked;
}

gl::Program buildProgram(const ShaderPreprocessor& sources, const std::vector<ShaderStageSource>& stages,
                         const std::vector<ShaderDefine>& defines) {
  return linkProgram(sources, stages, defines).program;
}

GLint gl::uniformLocation(const LinkedProgram& program, const char* name) {
  if (!program) return -1;
  if (!program.declares(name)) throw ShaderError(program.name + " declares no uniform " + name);
  return glGetUniformLocation(program.id(), name);
}

}  // namespace terrasol
