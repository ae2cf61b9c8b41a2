// visemelab.reduce_avatar: `visemelab avatar reduce` on bytes (core/project/AvatarReduceRun.h).
#include "app/python/src/Arrays.h"
#include "app/python/src/Bindings.h"
#include "app/python/src/Options.h"
#include "core/common/Error.h"
#include "core/gltf/GltfDocument.h"
#include "core/gltf/TargetNames.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/project/AvatarReduceRun.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <chrono>

namespace py = pybind11;

namespace vl::python {

namespace {

using Pairs = std::vector<std::pair<std::string, std::string>>;

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The avatar's reduced bytes and the JSON report `--report` writes (naming `output`).
py::tuple reduceAvatarBytes(const py::bytes& glb, int m, const std::string& name, const std::string& targets,
                            const std::optional<std::filesystem::path>& freqFile,
                            const std::optional<std::filesystem::path>& mapFile, const py::object& weights,
                            const std::string& names, bool targetNormals, int maxTargets, bool gltfpack,
                            const std::string& rest, const std::string& restViseme,
                            const std::vector<std::string>& pin, const Pairs& apart, const Pairs& together,
                            double maxErrorMm, const std::string& closure, const std::string& output) {
    if ((m > 0) == (maxErrorMm > 0)) throw py::value_error("give the number of keys m, or max_error_mm");
    if (names != "original" && names != "merged") throw py::value_error("names must be original or merged");
    if (rest != "free" && rest != "key") throw py::value_error("rest must be free or key");
    if (maxTargets < 0) throw py::value_error("max_targets must be >= 1 (0: no limit)");
    if (!targets.empty()) checkGlobPattern(targets, "targets");
    AvatarReduceRequest request;
    request.target = m;
    request.maxErrorMm = maxErrorMm;
    request.targets = targets;
    request.freqFile = freqFile.value_or(std::filesystem::path());
    request.mapFile = mapFile.value_or(std::filesystem::path());
    ReduceSettings weighting;
    applyWeights(weights, weighting);
    request.weightMode = weighting.weightMode;
    request.paintedWeights = std::move(weighting.paintedWeights);
    request.paintedWeightsSource = weighting.paintedWeightsSource;
    request.rest = rest == "key" ? RestChoice::Key : RestChoice::Free;
    request.restViseme = restViseme;
    request.constraints = ConstraintNames{pin, apart, together};
    request.closure = closure == "none" ? std::string() : closure;
    request.write.names = names == "merged" ? AvatarNames::Merged : AvatarNames::Original;
    request.write.targetNormals = targetNormals;
    request.write.maxTargets = maxTargets;
    request.gltfpack = gltfpack;
    std::string bytes(glb), reduced, report;
    {
        py::gil_scoped_release release;
        const std::filesystem::path assets = VISEMELAB_ASSETS_DIR;
        const BundledFrequencies bundled{loadFrequencyFile(defaultPhonemeTablePath(assets)),
                                         bundledPhonemeFrequencies(assets, "oculus")};
        ReduceTimings timings;
        const auto t0 = std::chrono::steady_clock::now();
        const GltfDocument doc =
            parseGltfDocument(std::move(bytes), name, std::filesystem::path(name).parent_path());
        const AvatarScan scan = scanAvatar(doc, {targets});
        std::string chosen;
        const FrequencySource frequencies = avatarReduceFrequencies(request, scan, bundled, chosen);
        timings.loadMs = millisecondsSince(t0);
        const auto t1 = std::chrono::steady_clock::now();
        AvatarReduceResult run = runAvatarReduce(doc, scan, frequencies, request);
        timings.reduceMs = millisecondsSince(t1);
        report =
            avatarReductionReport(run.reduction, scan, run.settings, request.write, timings, name, output);
        reduced = std::move(run.reduction.glb);
    }
    return py::make_tuple(toBytes(reduced), report);
}

} // namespace

void bindAvatar(py::module_& m) {
    m.def("reduce_avatar", &reduceAvatarBytes, py::arg("glb"), py::kw_only(), py::arg("m") = 0,
          py::arg("name") = "avatar.glb", py::arg("targets") = "", py::arg("freq_file") = py::none(),
          py::arg("map") = py::none(), py::arg("weights") = py::str("uniform"), py::arg("names") = "original",
          py::arg("target_normals") = true, py::arg("max_targets") = 0, py::arg("gltfpack") = false,
          py::arg("rest") = "free", py::arg("rest_viseme") = "", py::arg("pin") = std::vector<std::string>{},
          py::arg("apart") = Pairs{}, py::arg("together") = Pairs{}, py::arg("max_error_mm") = 0.0,
          py::arg("closure") = kClosureAuto, py::arg("output") = "reduced.glb",
          "Reduces an avatar's visemes (GLB/VRM bytes) to m keys as `visemelab avatar reduce` does, with its "
          "options: returns (the reduced avatar's bytes, the JSON report naming `name` and `output`). "
          "`name` is the input's name in messages and the report (external buffers of a .gltf resolve "
          "beside it)");
}

} // namespace vl::python
