#pragma once
// Strict reading of a JSON document with the JSON path (RFC 6901 pointer) of every element, so a
// loader can name exactly where a problem is: "/frequencies/phonemes/AA: expected a non-negative
// number, found string". Used by the project file; any module's plain structs can be read with it.
#include "core/mesh/Mesh.h"

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

// Object keys keep their file order, so a save of a loaded document lists them as the user did.
using Json = nlohmann::ordered_json;

// Parses text; syntax errors and duplicate object keys (which nlohmann would silently merge) are
// InputErrors naming `source` and the position / the JSON path.
Json parseJsonStrict(std::string_view text, std::string_view source);

// A JSON value together with its path. Accessors throw InputError "<path>: <what>".
class JsonNode {
  public:
    JsonNode(const Json& value, std::string path) : value_(&value), path_(std::move(path)) {}

    const Json& json() const { return *value_; }
    const std::string& path() const { return path_; }
    [[noreturn]] void fail(std::string_view what) const;

    bool isNull() const { return value_->is_null(); }
    bool isObject() const { return value_->is_object(); }
    bool isArray() const { return value_->is_array(); }
    bool isString() const { return value_->is_string(); }

    // Objects. requireKeys/allowOnly check the key set; child access by key.
    void expectObject() const;
    // Fails naming the first key not in `allowed` ("unknown field").
    void allowOnly(std::initializer_list<std::string_view> allowed) const;
    bool has(std::string_view key) const;
    JsonNode operator[](std::string_view key) const; // fails "missing field" when absent
    std::vector<std::pair<std::string, JsonNode>> members() const;

    // Arrays.
    void expectArray() const;
    std::size_t size() const; // of an array (fails otherwise)
    void expectSize(std::size_t n) const;
    JsonNode operator[](std::size_t index) const;
    std::vector<JsonNode> elements() const;

    // Scalars.
    std::string string() const;
    std::string nonEmptyString() const;
    bool boolean() const;
    double number() const;            // finite
    double nonNegativeNumber() const; // finite and >= 0
    std::int64_t integer() const;     // integral JSON number (no fraction, no exponent tricks)
    std::int64_t integerInRange(std::int64_t lo, std::int64_t hi) const;

    // Fixed-size numeric tuples and arrays of them (mesh data).
    Vec3 vec3() const;
    Vec2 vec2() const;
    std::vector<double> numbers() const;            // array of finite numbers
    std::vector<double> nonNegativeNumbers() const; // array of finite numbers >= 0

  private:
    const Json* value_;
    std::string path_;
};

// "number", "string", "object", ... for messages.
std::string jsonTypeName(const Json& value);

// Appends an object key to a JSON path, escaping '~' and '/' as RFC 6901 requires.
std::string jsonPathAppend(std::string_view path, std::string_view key);
std::string jsonPathAppend(std::string_view path, std::size_t index);

} // namespace vl
