#pragma once
// Scratch files for the phonetics tests.
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <unistd.h>

namespace vl::test {

// A fresh directory under the system temp dir, removed again at the end of the test.
class PhoneticsScratch {
  public:
    explicit PhoneticsScratch(const std::string& name)
        : path_(std::filesystem::temp_directory_path() /
                ("visemelab-phonetics-" + name + "-" + std::to_string(::getpid()))) {
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~PhoneticsScratch() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    PhoneticsScratch(const PhoneticsScratch&) = delete;
    PhoneticsScratch& operator=(const PhoneticsScratch&) = delete;

    // Writes `bytes` verbatim to <dir>/<name> and returns its path.
    std::filesystem::path write(const std::string& name, std::string_view bytes) const {
        const auto file = path_ / name;
        std::ofstream(file, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        return file;
    }
    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
};

inline std::filesystem::path assetsDir() {
    return VISEMELAB_ASSETS_DIR;
}

} // namespace vl::test
