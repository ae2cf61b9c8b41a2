#pragma once
// Per-vertex weights w_k of the dissimilarity rho(A,B) = sum_k w_k |a_k - b_k|^2.
#include "core/common/EnumNames.h"
#include "core/mesh/Mesh.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vl {

enum class WeightMode { Uniform, Area, Painted };
template <> struct EnumNames<WeightMode> {
    static constexpr const char* what = "weight mode";
    static constexpr EnumName<WeightMode> names[] = {
        {WeightMode::Uniform, "uniform"}, {WeightMode::Area, "area"}, {WeightMode::Painted, "painted"}};
};

// uniform: all ones (the paper's rho1); area: summed incident triangle area of the neutral mesh
// (rho2); painted: `painted` as given. Validates count and that every weight is finite and >= 0 and
// not all zero; throws InputError naming `where` and the offending vertex.
std::vector<double> computeWeights(WeightMode mode, const MeshData& neutral,
                                   const std::vector<double>& painted = {},
                                   std::string_view where = "weights");

// Where a paint stroke starts: the weights the designer sees in `mode`, scaled so that the largest is
// 1 (the brush works in [0, 1]); painted weights of the right size are taken as they are. The metric
// is unchanged by the scale (the optimal grouping does not depend on it).
std::vector<double> weightsForPainting(WeightMode mode, const MeshData& neutral,
                                       const std::vector<double>& painted = {});

// Painted weights from a file: JSON (array, or object with a "weights" array) or plain text (one
// number per line or comma/space separated). Errors name the file and line/element.
std::vector<double> loadWeightsFile(const std::filesystem::path& path);

} // namespace vl
