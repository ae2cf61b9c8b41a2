#include "core/common/AtomicFile.h"

#include "core/common/AtomicFileWriter.h"
#include "core/common/Error.h"
#include "core/common/InputRegistry.h"
#include "core/common/Limits.h"

#include <fstream>
#include <system_error>

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
    noteInputFile(path);
    return data;
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view contents) {
    AtomicFileWriter file(path);
    file.write(contents);
    file.commit();
}

} // namespace vl
