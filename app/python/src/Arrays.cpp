#include "app/python/src/Arrays.h"

#include "core/common/Error.h"

#include <cmath>
#include <cstring>

namespace py = pybind11;

namespace vl::python {

namespace {

void requireColumns(const py::buffer_info& info, py::ssize_t columns, std::string_view where) {
    if (info.ndim != 2 || info.shape[1] != columns)
        throwInputError(where, "expected an array of shape (N, " + std::to_string(columns) + "), got " +
                                   std::to_string(info.ndim) + " dimensions");
}

template <typename Vector, int Columns>
std::vector<Vector> rowsFrom(const Float64Array& array, std::string_view where) {
    const py::buffer_info info = array.request();
    requireColumns(info, Columns, where);
    const auto* data = static_cast<const double*>(info.ptr);
    std::vector<Vector> rows(static_cast<std::size_t>(info.shape[0]));
    for (std::size_t i = 0; i < rows.size(); ++i)
        for (int c = 0; c < Columns; ++c) {
            const double value = data[i * Columns + static_cast<std::size_t>(c)];
            if (!std::isfinite(value))
                throwInputError(std::string(where) + "[" + std::to_string(i) + "]", "not a finite number");
            rows[i][c] = value;
        }
    return rows;
}

template <int Columns, typename Vector> py::array_t<double> rowsToArray(const std::vector<Vector>& rows) {
    py::array_t<double> array({static_cast<py::ssize_t>(rows.size()), py::ssize_t{Columns}});
    double* out = array.mutable_data();
    for (std::size_t i = 0; i < rows.size(); ++i)
        for (int c = 0; c < Columns; ++c) out[i * Columns + static_cast<std::size_t>(c)] = rows[i][c];
    return array;
}

} // namespace

std::vector<Vec3> positionsFrom(const Float64Array& array, std::string_view where) {
    return rowsFrom<Vec3, 3>(array, where);
}

std::vector<Vec2> uvsFrom(const Float64Array& array, std::string_view where) {
    return rowsFrom<Vec2, 2>(array, where);
}

std::vector<Triangle> trianglesFrom(const IndexArray& array, std::size_t vertexCount,
                                    std::string_view where) {
    const py::buffer_info info = array.request();
    requireColumns(info, 3, where);
    const auto* data = static_cast<const std::int64_t*>(info.ptr);
    std::vector<Triangle> triangles(static_cast<std::size_t>(info.shape[0]));
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (std::size_t c = 0; c < 3; ++c) {
            const std::int64_t index = data[t * 3 + c];
            if (index < 0 || static_cast<std::uint64_t>(index) >= vertexCount)
                throwInputError(std::string(where) + "[" + std::to_string(t) + "]",
                                "vertex index " + std::to_string(index) + " is outside 0.." +
                                    std::to_string(vertexCount) + " - 1");
            triangles[t][c] = static_cast<std::uint32_t>(index);
        }
    return triangles;
}

std::vector<double> valuesFrom(const Float64Array& array, std::string_view where) {
    const py::buffer_info info = array.request();
    if (info.ndim != 1) throwInputError(where, "expected a 1-D array");
    const auto* data = static_cast<const double*>(info.ptr);
    return std::vector<double>(data, data + info.shape[0]);
}

py::array_t<double> toArray(const std::vector<Vec3>& positions) {
    return rowsToArray<3>(positions);
}

py::array_t<double> toArray(const std::vector<Vec2>& uvs) {
    return rowsToArray<2>(uvs);
}

py::array_t<std::int64_t> toArray(const std::vector<Triangle>& triangles) {
    py::array_t<std::int64_t> array({static_cast<py::ssize_t>(triangles.size()), py::ssize_t{3}});
    std::int64_t* out = array.mutable_data();
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (std::size_t c = 0; c < 3; ++c) out[t * 3 + c] = triangles[t][c];
    return array;
}

py::array_t<double> toArray(const std::vector<double>& values) {
    py::array_t<double> array(static_cast<py::ssize_t>(values.size()));
    if (!values.empty()) std::memcpy(array.mutable_data(), values.data(), values.size() * sizeof(double));
    return array;
}

py::bytes toBytes(const std::string& bytes) {
    return py::bytes(bytes.data(), bytes.size());
}

} // namespace vl::python
