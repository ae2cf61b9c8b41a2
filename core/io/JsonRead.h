#pragma once
// Strict reading of a JSON document with the JSON path (RFC 6901 pointer) of every element, so a
// loader can name exactly where a problem is: "/frequencies/phonemes/AA: expected a non-negative
// number, found string". Used by the project file; any module's plain structs can be read with it.
#include "core/common/JsonParse.h"
#include "core/mesh/Mesh.h"

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

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

} // namespace vl
