#include "core/io/JsonRead.h"

#include "core/common/Error.h"

#include <algorithm>
#include <cmath>

namespace vl {

namespace {

std::string describe(const Json& value) {
    if (value.is_number() || value.is_boolean() || value.is_null()) return quoteJson(value);
    if (value.is_string()) {
        auto text = quoteJson(value);
        if (text.size() > 40) text = text.substr(0, 37) + "...";
        return "string " + text;
    }
    return jsonTypeName(value);
}

} // namespace

void JsonNode::fail(std::string_view what) const {
    throwInputError(path_.empty() ? "/" : path_, what);
}

void JsonNode::expectObject() const {
    if (!value_->is_object()) fail("expected an object, found " + describe(*value_));
}

void JsonNode::allowOnly(std::initializer_list<std::string_view> allowed) const {
    expectObject();
    for (const auto& [key, value] : value_->items())
        if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
            throwInputError(jsonPathAppend(path_, key), "unknown field");
}

bool JsonNode::has(std::string_view key) const {
    expectObject();
    return value_->contains(key);
}

JsonNode JsonNode::operator[](std::string_view key) const {
    expectObject();
    const auto it = value_->find(key);
    if (it == value_->end()) throwInputError(jsonPathAppend(path_, key), "missing field");
    return JsonNode(*it, jsonPathAppend(path_, key));
}

std::vector<std::pair<std::string, JsonNode>> JsonNode::members() const {
    expectObject();
    std::vector<std::pair<std::string, JsonNode>> result;
    for (const auto& [key, value] : value_->items())
        result.emplace_back(key, JsonNode(value, jsonPathAppend(path_, key)));
    return result;
}

void JsonNode::expectArray() const {
    if (!value_->is_array()) fail("expected an array, found " + describe(*value_));
}

std::size_t JsonNode::size() const {
    expectArray();
    return value_->size();
}

void JsonNode::expectSize(std::size_t n) const {
    if (size() != n)
        fail("expected an array of " + std::to_string(n) + " elements, found " +
             std::to_string(value_->size()));
}

JsonNode JsonNode::operator[](std::size_t index) const {
    if (index >= size()) throwInputError(jsonPathAppend(path_, index), "missing array element");
    return JsonNode((*value_)[index], jsonPathAppend(path_, index));
}

std::vector<JsonNode> JsonNode::elements() const {
    expectArray();
    std::vector<JsonNode> result;
    result.reserve(value_->size());
    for (std::size_t i = 0; i < value_->size(); ++i)
        result.emplace_back((*value_)[i], jsonPathAppend(path_, i));
    return result;
}

std::string JsonNode::string() const {
    if (!value_->is_string()) fail("expected a string, found " + describe(*value_));
    return value_->get<std::string>();
}

std::string JsonNode::nonEmptyString() const {
    auto text = string();
    if (text.empty()) fail("expected a non-empty string");
    return text;
}

bool JsonNode::boolean() const {
    if (!value_->is_boolean()) fail("expected true or false, found " + describe(*value_));
    return value_->get<bool>();
}

double JsonNode::number() const {
    if (!value_->is_number()) fail("expected a number, found " + describe(*value_));
    const double v = value_->get<double>();
    // JSON has no NaN/Inf literals, but an overflowing literal such as 1e999 parses to infinity.
    if (!std::isfinite(v)) fail("expected a finite number, found " + quoteJson(*value_));
    return v;
}

double JsonNode::nonNegativeNumber() const {
    if (!value_->is_number()) fail("expected a non-negative number, found " + describe(*value_));
    const double v = number();
    if (v < 0.0) fail("expected a non-negative number, found " + quoteJson(*value_));
    return v;
}

std::int64_t JsonNode::integer() const {
    if (value_->is_number_unsigned()) {
        const auto u = value_->get<std::uint64_t>();
        if (u > static_cast<std::uint64_t>(INT64_MAX)) fail("integer out of range: " + quoteJson(*value_));
        return static_cast<std::int64_t>(u);
    }
    if (!value_->is_number_integer()) fail("expected an integer, found " + describe(*value_));
    return value_->get<std::int64_t>();
}

std::int64_t JsonNode::integerInRange(std::int64_t lo, std::int64_t hi) const {
    const auto v = integer();
    if (v < lo || v > hi)
        fail(std::to_string(v) + " is outside the allowed range " + std::to_string(lo) + ".." +
             std::to_string(hi));
    return v;
}

Vec3 JsonNode::vec3() const {
    expectSize(3);
    return Vec3((*this)[0].number(), (*this)[1].number(), (*this)[2].number());
}

Vec2 JsonNode::vec2() const {
    expectSize(2);
    return Vec2((*this)[0].number(), (*this)[1].number());
}

std::vector<double> JsonNode::numbers() const {
    std::vector<double> result;
    for (const auto& e : elements()) result.push_back(e.number());
    return result;
}

std::vector<double> JsonNode::nonNegativeNumbers() const {
    std::vector<double> result;
    for (const auto& e : elements()) result.push_back(e.nonNegativeNumber());
    return result;
}

} // namespace vl
