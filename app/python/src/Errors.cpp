#include "app/python/src/Errors.h"

#include "core/common/Error.h"

#include <filesystem>

namespace py = pybind11;

namespace vl::python {

std::string culpritOf(std::string_view message) {
    // The first ": " ends the file (an element path such as /visemes/3 follows it as "file: /path"):
    // paths with ": " in them are rare enough that the message itself stays the full story.
    const auto colon = message.find(": ");
    if (colon == std::string_view::npos || colon == 0) return std::string(message);
    std::string culprit(message.substr(0, colon));
    // "file: /json/path: what" and "file:12: what" keep the element as part of the culprit.
    const std::string_view rest = message.substr(colon + 2);
    if (!rest.empty() && rest.front() == '/') {
        const auto next = rest.find(": ");
        if (next != std::string_view::npos) culprit += ": " + std::string(rest.substr(0, next));
    }
    return culprit;
}

namespace {

// Owned by the module (a static py::object would be destroyed after the interpreter).
PyObject* inputErrorType = nullptr;

void raiseInputError(const std::string& message, const std::string& culprit) {
    py::object error = py::reinterpret_borrow<py::object>(inputErrorType)(message);
    error.attr("culprit") = culprit;
    PyErr_SetObject(inputErrorType, error.ptr());
}

} // namespace

void registerErrors(py::module_& m) {
    static py::exception<InputError> type(m, "InputError", PyExc_ValueError);
    type.doc() = "Bad input: .culprit names the file and element (line, JSON path, mesh) at fault; the "
                 "message says what is wrong with it.";
    inputErrorType = type.ptr();
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const InputError& e) {
            raiseInputError(e.what(), culpritOf(e.what()));
        } catch (const std::filesystem::filesystem_error& e) {
            // A file vanishing or unreadable while listed: the path is the culprit.
            const std::string path = quoteInput(e.path1().string());
            raiseInputError(path + ": " + e.code().message(), path);
        }
    });
}

} // namespace vl::python
