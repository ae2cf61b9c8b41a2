#include "core/common/AtomicFile.h"

#include "core/common/Error.h"
#include "core/common/Limits.h"

#include <cstdio>
#include <fstream>
#include <random>
#include <system_error>
#include <unistd.h>

namespace vl {

std::string readFileToString(const std::filesystem::path& path) {
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (!std::filesystem::exists(status)) throwInputError(path.string(), "file not found");
    if (std::filesystem::is_directory(status)) throwInputError(path.string(), "is a directory, not a file");
    // A FIFO or device would block or never end.
    if (!std::filesystem::is_regular_file(status)) throwInputError(path.string(), "not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throwInputError(path.string(), "cannot open file for reading");
    std::string data;
    in.seekg(0, std::ios::end);
    const auto size = in.tellg();
    in.seekg(0, std::ios::beg);
    if (size > 0) {
        if (static_cast<std::uintmax_t>(size) > limits::kMaxInputFileBytes)
            throwInputError(path.string(),
                            "file too large (" + std::to_string(static_cast<std::uintmax_t>(size)) +
                                " bytes; the limit is " + std::to_string(limits::kMaxInputFileBytes) + ")");
        try {
            data.resize(static_cast<std::size_t>(size));
        } catch (const std::bad_alloc&) {
            throwInputError(path.string(), "not enough memory to read the file");
        }
        in.read(data.data(), size);
    }
    if (!in) throwInputError(path.string(), "read error");
    return data;
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view contents) {
    const auto dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    std::random_device rd;
    const auto temp = dir / ("." + path.filename().string() + ".tmp" + std::to_string(rd() % 1000000));
    {
        std::FILE* f = std::fopen(temp.c_str(), "wb");
        if (!f) throwInputError(path.string(), "cannot create temporary file for writing");
        const bool ok = std::fwrite(contents.data(), 1, contents.size(), f) == contents.size() &&
                        std::fflush(f) == 0 && ::fsync(fileno(f)) == 0;
        std::fclose(f);
        if (!ok) {
            std::filesystem::remove(temp, ec);
            throwInputError(path.string(), "write failed (disk full?); the previous file is unchanged");
        }
    }
    std::filesystem::rename(temp, path, ec);
    if (ec) {
        std::filesystem::remove(temp, ec);
        throwInputError(path.string(), "cannot replace file: " + ec.message());
    }
}

} // namespace vl
