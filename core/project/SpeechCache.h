#pragma once
// `say` without a fixed cost per call (issue 33): a project's speech faces (its full and reduced
// models and vertex weights, core/project/ProjectSpeech.h) kept in a cache file, so a sentence costs
// the speech engine and the track instead of parsing the project, reading every mesh and reducing
// again. An entry is used only when the same build of VisemeLab wrote it and every file its
// computation read (the project, its meshes, its avatar) still has the same bytes (XXH3); anything
// else recomputes and replaces it. Entries are written atomically; a cache that cannot be written
// (read-only home, full disk) only costs the time it would have saved.
#include "core/project/ProjectSpeech.h"
#include "core/speech/SpeechErrorBasis.h"

#include <filesystem>
#include <memory>
#include <optional>

namespace vl {

struct ProjectSpeechFaces {
    SpeechFaces faces;
    bool metres = false;    // the project's lengths are glTF metres (an avatar project)
    bool fromCache = false; // read from a valid cache entry
    // The speech error basis of the faces (made once, with the entry; read back with it).
    std::shared_ptr<const SpeechErrorBasis> basis;
};

// $VISEMELAB_CACHE_DIR, else $XDG_CACHE_HOME/visemelab, else $HOME/.cache/visemelab; empty (no
// caching) when VISEMELAB_CACHE_DIR is "off" or no home is known.
std::filesystem::path speechCacheFolder();

// The program file whose build the entries this process writes belong to: the file holding this
// code (the CLI's commands, the editor, the Python module). An entry is read only by the same build.
std::filesystem::path speechCacheBuildFile();

// The entry `build` (a speechCacheBuildFile()) wrote for the project and map, when it is valid (as
// cachedProjectSpeechFaces reads it; its files noted likewise); nullopt when there is none, nothing
// computed. For `visemelab-say`, which reads the entries of the commands beside it.
std::optional<ProjectSpeechFaces> readCachedProjectSpeechFaces(const std::filesystem::path& projectFile,
                                                               const PhonemeVisemeMap* map,
                                                               const std::filesystem::path& cacheFolder,
                                                               const std::filesystem::path& build);

// projectSpeechFaces(loadProject(projectFile), map) and their speech error basis, through the cache
// in `cacheFolder` (empty: no cache). Either way the project's files are noted as inputs and references of
// the run (core/common/InputRegistry.h), so outputs are refused exactly as without the cache. Throws what
// loadProject and projectSpeechFaces throw; a damaged or foreign cache entry is recomputed, never an
// error.
ProjectSpeechFaces cachedProjectSpeechFaces(const std::filesystem::path& projectFile,
                                            const PhonemeVisemeMap* map = nullptr,
                                            const std::filesystem::path& cacheFolder = speechCacheFolder());

} // namespace vl
