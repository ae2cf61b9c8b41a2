#pragma once
// Internal to core/project: vector fields (core/deform) as JSON.
//   {"sampled": null | {"width": W, "height": H, "samples": [[x, y, z], ...]}
//                    | {"builtin": "bundled" | "retarget", "width": W, "height": H},
//    "influences": [{"centre": [u, v], "radii": [a, b], "plateau": [a, b], "rotation": r,
//                    "direction": [x, y, z], "magnitude": m, "falloff": "smoothstep"}, ...]}
// A grid bit-identical to a built-in face geometry image (face::makeFaceGeometry) is written as a
// reference, which keeps a project with the bundled face small (a 257 x 257 grid is 66,049 vectors).
#include "core/deform/VectorField.h"
#include "core/io/JsonRead.h"

namespace vl {

Json vectorFieldToJson(const VectorField& field);
VectorField vectorFieldFromJson(const JsonNode& node);

} // namespace vl
