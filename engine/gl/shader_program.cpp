#include "shader_program.h"

#include <algorithm>
#include <utility>

#include "core/error.h"
#include "embedded_shaders.h"

namespace voxflame::gl {

GLuint compileShader(GLenum stage, const ShaderSource& source) {
  const GLuint shader = glCreateShader(stage);
  const char* text = source.text.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    const char* kind = stage == GL_VERTEX_SHADER ? "vertex" : stage == GL_COMPUTE_SHADER ? "compute" : "fragment";
    throw core::Error(source.file + ": " + kind + " shader failed to compile: " + log);
  }
  return shader;
}

ShaderSource embeddedShader(std::string_view name) {
  const std::string file = "engine/gl/shaders/" + std::string(name);
  const auto bytes = embeddedShaderFile(file);
  if (!bytes) throw core::Error("no shader '" + file + "' was built into voxflame");
  return {file, std::string(reinterpret_cast<const char*>(bytes->data()), bytes->size())};
}

ShaderProgram::ShaderProgram(const ShaderSource& vertexSource, const ShaderSource& fragmentSource) {
  const GLuint vertex = compileShader(GL_VERTEX_SHADER, vertexSource);
  GLuint fragment = 0;
  try {
    fragment = compileShader(GL_FRAGMENT_SHADER, fragmentSource);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  program_ = glCreateProgram();
  glAttachShader(program_, vertex);
  glAttachShader(program_, fragment);
  glLinkProgram(program_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(program_, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program_, length, nullptr, log.data());
    glDeleteProgram(program_);
    program_ = 0;
    throw core::Error("shader program (" + vertexSource.file + ", " + fragmentSource.file + ") failed to link: " + log);
  }
}

ShaderProgram::~ShaderProgram() {
  if (program_) glDeleteProgram(program_);
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept : program_(std::exchange(other.program_, 0)) {}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
  if (this != &other) {
    if (program_) glDeleteProgram(program_);
    program_ = std::exchange(other.program_, 0);
  }
  return *this;
}

}  // namespace voxflame::gl
