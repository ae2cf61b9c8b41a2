// Writes sample .glb files for the Khronos validator test (tests/export/CMakeLists.txt): a small
// textured face with 16-bit indices, a 66,000-vertex one with 32-bit indices, and the bundled
// sample's reduction (assets/sample/sample.vlproj).
#include "core/export/Export.h"
#include "core/export/GltfExport.h"
#include "core/project/Project.h"
#include "core/project/ProjectRun.h"
#include "tests/export/TestModels.h"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUT_DIR\n", argv[0]);
        return 2;
    }
    try {
        const std::filesystem::path dir = argv[1];
        std::filesystem::create_directories(dir);
        vl::writeGlb(dir / "small_textured.glb", vl::test::randomModel(12, 10, 5, true, 41));
        vl::writeGlb(dir / "large_uint32.glb", vl::test::randomModel(300, 220, 2, false, 42));
        // The bundled sample's reduced face; a placeholder copy keeps the validator's file list fixed.
        const std::filesystem::path sample =
            std::filesystem::path(VISEMELAB_ASSETS_DIR) / "sample" / "sample.vlproj";
        if (std::filesystem::exists(sample)) {
            vl::writeGlb(dir / "sample_reduced.glb", vl::projectReducedModel(vl::loadProject(sample)));
        } else {
            std::fprintf(stderr, "no %s: validating a synthetic face in its place\n", sample.c_str());
            std::filesystem::copy_file(dir / "small_textured.glb", dir / "sample_reduced.glb",
                                       std::filesystem::copy_options::overwrite_existing);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
