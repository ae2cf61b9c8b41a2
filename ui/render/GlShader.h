#pragma once
// A linked GLSL program built from two files of the shaders/ folder.
#include <epoxy/gl.h>

#include <filesystem>
#include <string>

namespace vl::ui {

class GlShader {
  public:
    GlShader() = default;
    // Compiles <dir>/<name>.vert and <dir>/<name>.frag; throws std::runtime_error with the file name
    // and the driver's log on failure.
    GlShader(const std::filesystem::path& dir, const std::string& name);
    ~GlShader();
    GlShader(const GlShader&) = delete;
    GlShader& operator=(const GlShader&) = delete;
    GlShader(GlShader&& other) noexcept;
    GlShader& operator=(GlShader&& other) noexcept;

    GLuint id() const { return program_; }
    GLint uniform(const char* name) const { return glGetUniformLocation(program_, name); }

  private:
    GLuint program_ = 0;
};

// Where the shaders are: $VISEMELAB_SHADERS when set, else the source folder baked in at build time.
std::filesystem::path shaderDirectory();

} // namespace vl::ui
