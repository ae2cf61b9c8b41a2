// Writes a few small valid runtime packages (float/quantised, with/without (u,v)) into the folder
// given as argument: the seed corpus of the libFuzzer run (scripts/fuzz-runtime.sh).
#include "core/export/RuntimePackageWriter.h"
#include "tests/export/TestModels.h"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s CORPUS_DIR\n", argv[0]);
        return 2;
    }
    try {
        const std::filesystem::path dir = argv[1];
        std::filesystem::create_directories(dir);
        int index = 0;
        for (bool quantise : {false, true})
            for (bool uvs : {false, true}) {
                ++index;
                vl::writeRuntimePackage(
                    dir / ("seed" + std::to_string(index) + ".vlrt"),
                    vl::test::randomModel(4, 3, 3, uvs, 30 + static_cast<unsigned>(index)),
                    {.quantise = quantise});
            }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
