#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/preview/Renderer.h"

#include <stb_image_write.h>

#include <string>

namespace vl::preview {

void writePng(const std::filesystem::path& path, const Image& image) {
    if (image.width < 1 || image.height < 1 ||
        image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4)
        throwInputError(path.string(), "image buffer does not match its size");
    std::string bytes;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                   static_cast<std::size_t>(size));
    };
    if (!stbi_write_png_to_func(append, &bytes, image.width, image.height, 4, image.rgba.data(),
                                image.width * 4))
        throwInputError(path.string(), "PNG encoding failed");
    writeFileAtomically(path, bytes);
}

} // namespace vl::preview
