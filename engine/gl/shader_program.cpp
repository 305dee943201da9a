#include "shader_program.h"

#include <algorithm>
#include <initializer_list>
#include <string>
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

namespace {

// Links the compiled `shaders` (deleting them) into a program; a link error becomes core::Error
// naming `files`.
GLuint linkProgram(std::initializer_list<GLuint> shaders, const std::string& files) {
  const GLuint program = glCreateProgram();
  for (GLuint shader : shaders) glAttachShader(program, shader);
  glLinkProgram(program);
  for (GLuint shader : shaders) glDeleteShader(shader);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    glDeleteProgram(program);
    throw core::Error("shader program (" + files + ") failed to link: " + log);
  }
  return program;
}

}  // namespace

ShaderProgram::ShaderProgram(const ShaderSource& vertexSource, const ShaderSource& fragmentSource) {
  const GLuint vertex = compileShader(GL_VERTEX_SHADER, vertexSource);
  GLuint fragment = 0;
  try {
    fragment = compileShader(GL_FRAGMENT_SHADER, fragmentSource);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  program_ = linkProgram({vertex, fragment}, vertexSource.file + ", " + fragmentSource.file);
}

ShaderProgram::ShaderProgram(const ShaderSource& computeSource) {
  program_ = linkProgram({compileShader(GL_COMPUTE_SHADER, computeSource)}, computeSource.file);
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
