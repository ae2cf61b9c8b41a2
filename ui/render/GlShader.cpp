#include "ui/render/GlShader.h"

#include "core/common/AtomicFile.h"

#include <cstdlib>
#include <stdexcept>
#include <utility>

namespace vl::ui {
namespace {

std::string infoLog(GLuint object, bool isProgram) {
    GLint length = 0;
    if (isProgram)
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    if (isProgram)
        glGetProgramInfoLog(object, length, nullptr, log.data());
    else
        glGetShaderInfoLog(object, length, nullptr, log.data());
    return log;
}

GLuint compile(GLenum type, const std::filesystem::path& file) {
    const std::string source = readFileToString(file);
    const GLuint shader = glCreateShader(type);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        const std::string log = infoLog(shader, false);
        glDeleteShader(shader);
        throw std::runtime_error(file.string() + ": shader compilation failed: " + log);
    }
    return shader;
}

} // namespace

GlShader::GlShader(const std::filesystem::path& dir, const std::string& name) {
    const GLuint vertex = compile(GL_VERTEX_SHADER, dir / (name + ".vert"));
    GLuint fragment = 0;
    try {
        fragment = compile(GL_FRAGMENT_SHADER, dir / (name + ".frag"));
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
    GLint ok = 0;
    glGetProgramiv(program_, GL_LINK_STATUS, &ok);
    if (!ok) {
        const std::string log = infoLog(program_, true);
        glDeleteProgram(program_);
        program_ = 0;
        throw std::runtime_error((dir / name).string() + ": shader link failed: " + log);
    }
}

GlShader::~GlShader() {
    if (program_) glDeleteProgram(program_);
}

GlShader::GlShader(GlShader&& other) noexcept : program_(std::exchange(other.program_, 0)) {}

GlShader& GlShader::operator=(GlShader&& other) noexcept {
    if (this != &other) {
        if (program_) glDeleteProgram(program_);
        program_ = std::exchange(other.program_, 0);
    }
    return *this;
}

std::filesystem::path shaderDirectory() {
    if (const char* env = std::getenv("VISEMELAB_SHADERS"); env && *env) return env;
    return VISEMELAB_SHADERS_DIR;
}

} // namespace vl::ui
