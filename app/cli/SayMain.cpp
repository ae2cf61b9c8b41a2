// visemelab-say: what the launcher (Launcher.c) runs for `visemelab say`. A sentence on a project
// whose speech faces are in the speech cache costs espeak-ng and the tracks; loading the libraries
// every command links (OpenMesh, Draco, TBB, tinygltf, libstdc++: a fifth of such a call) would cost
// more than the tracks. So this program links only what that path needs (app/CMakeLists.txt) and
// hands every other call, unchanged, to the commands (visemelab-cli beside it, execv: same process,
// arguments, exit status): an option it cannot parse or serve (--help, --avatar, --curve,
// --text-file, --glb, --html) or a project not in the cache (the commands compute its faces and fill
// the cache). The hand-over happens before anything is read from the standard input or written.
#include "app/cli/CommandMain.h"
#include "app/cli/ProcessMemory.h"
#include "app/cli/Say.h"
#include "core/common/OutputPolicy.h"
#include "core/project/SpeechCache.h"

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>
#include <unistd.h>

namespace {

// The commands' program, beside this one (the build whose speech cache entries this one reads).
std::filesystem::path commandsProgram() {
    char self[PATH_MAX];
    const ssize_t length = ::readlink("/proc/self/exe", self, sizeof self - 1);
    if (length <= 0) return "visemelab-cli";
    self[length] = '\0';
    return std::filesystem::path(self).parent_path() / "visemelab-cli";
}

// Replaces this process with the commands, given the same arguments.
[[noreturn]] void handOver(char** argv) {
    std::fflush(stdout);
    std::fflush(stderr);
    // `--out -` took the standard output (claimStandardOutput): given back as it was.
    if (const int data = vl::outputPolicy().standardOutputFd; data >= 0) {
        ::dup2(data, STDOUT_FILENO);
        ::close(data);
    }
    const std::filesystem::path cli = commandsProgram();
    ::execv(cli.c_str(), argv);
    std::fprintf(stderr, "visemelab: internal error: cannot run %s: %s\n", cli.c_str(), std::strerror(errno));
    std::_Exit(1);
}

// What only the commands do: avatars, the error curve (it reduces the project), the views.
bool needsTheCommands(const vl::cli::SayOptions& o) {
    return !o.avatar.empty() || o.curve || !o.textFile.empty() || !o.glb.empty() || !o.html.empty();
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2 || std::string_view(argv[1]) != "say") handOver(argv);
    vl::cli::tuneProcessMemory();
    CLI::App app{vl::cli::kAppDescription};
    vl::cli::GlobalOptions options;
    vl::cli::addGlobalOptions(app, options);
    vl::cli::CommandRunner run;
    vl::cli::SayHooks hooks;
    hooks.loadFace = [argv](const vl::cli::SayOptions& o, const std::optional<vl::PhonemeVisemeMap>& map) {
        if (needsTheCommands(o)) handOver(argv);
        auto faces = vl::readCachedProjectSpeechFaces(o.project, map ? &*map : nullptr,
                                                      vl::speechCacheFolder(), commandsProgram());
        if (!faces) handOver(argv);
        return vl::speakingProjectFace(std::move(*faces), o.project);
    };
    // Never reached: loadFace hands those calls over first.
    hooks.curve = [argv](const vl::cli::SayOptions&,
                         const std::optional<vl::PhonemeVisemeMap>&) -> vl::cli::SayHooks::Curve {
        handOver(argv);
    };
    hooks.views = [argv](const vl::cli::SayOptions&, const vl::SpeakingFace&, const vl::SpokenTrack&,
                         const std::string&) { handOver(argv); };
    vl::cli::addSayCommand(app, run, std::move(hooks));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError&) {
        handOver(argv); // the commands print the help, the version or the usage error
    }
    return vl::cli::runCommand(argc, argv, options, run);
}
