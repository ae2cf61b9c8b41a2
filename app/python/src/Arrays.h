#pragma once
// numpy arrays <-> the core's mesh arrays. Arrays from Python are checked (shape, finite values,
// triangle indices in range) with InputError naming the argument and the row, as a file reader would.
#include "core/mesh/Mesh.h"

#include <pybind11/numpy.h>

#include <string>
#include <string_view>
#include <vector>

namespace vl::python {

using Float64Array = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;
using IndexArray = pybind11::array_t<std::int64_t, pybind11::array::c_style | pybind11::array::forcecast>;

// An (N, 3) array of finite numbers.
std::vector<Vec3> positionsFrom(const Float64Array& array, std::string_view where);
// An (N, 2) array.
std::vector<Vec2> uvsFrom(const Float64Array& array, std::string_view where);
// A (T, 3) array of vertex indices in 0..vertexCount-1.
std::vector<Triangle> trianglesFrom(const IndexArray& array, std::size_t vertexCount, std::string_view where);
// A 1-D array of n numbers.
std::vector<double> valuesFrom(const Float64Array& array, std::string_view where);

pybind11::array_t<double> toArray(const std::vector<Vec3>& positions);
pybind11::array_t<double> toArray(const std::vector<Vec2>& uvs);
pybind11::array_t<std::int64_t> toArray(const std::vector<Triangle>& triangles);
pybind11::array_t<double> toArray(const std::vector<double>& values);

pybind11::bytes toBytes(const std::string& bytes);

} // namespace vl::python
