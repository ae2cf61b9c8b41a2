#include "core/common/JsonDomBuilder.h"

#include "core/common/Error.h"

namespace vl {

namespace {

// ordered_map is a vector of pairs: appending through the vector skips its linear key search (keys
// are unique already: the builder refuses duplicates).
using MemberVector = std::vector<std::pair<const std::string, Json>>;

// What malloc adds to each block it hands out (glibc: 8 bytes of header, 16-byte granularity).
constexpr std::size_t kAllocationOverhead = 16;

// Heap bytes of a string beyond the 16 of its value: none while it fits the small-string buffer.
std::size_t stringBytes(std::size_t length) {
    return length < 16 ? 0 : length + 1 + 16;
}

// The document itself is "/" in messages.
std::string shownPath(std::string path) {
    return path.empty() ? "/" : path;
}

} // namespace

void JsonDomBuilder::charge(std::size_t bytes) {
    domBytes_ += bytes;
    if (domBytes_ > maxDomBytes_)
        throwInputError(std::string(source_) + ": " + shownPath(path(true)),
                        "JSON document too large to hold: its values would take more than " +
                            std::to_string(maxDomBytes_) + " bytes");
}

Json& JsonDomBuilder::slot() {
    if (frames_.empty()) return root_;
    Json& top = *frames_.back().container;
    if (top.is_array()) return top.get_ref<Json::array_t&>().emplace_back();
    return *pendingMember_;
}

bool JsonDomBuilder::addValue(Json value) {
    charge(sizeof(Json));
    slot() = std::move(value);
    return true;
}

bool JsonDomBuilder::null() {
    return addValue(nullptr);
}
bool JsonDomBuilder::boolean(bool value) {
    return addValue(value);
}
bool JsonDomBuilder::number_integer(Json::number_integer_t value) {
    return addValue(value);
}
bool JsonDomBuilder::number_unsigned(Json::number_unsigned_t value) {
    return addValue(value);
}
bool JsonDomBuilder::number_float(Json::number_float_t value, const std::string&) {
    return addValue(value);
}
bool JsonDomBuilder::string(Json::string_t& value) {
    charge(stringBytes(value.size()));
    return addValue(std::move(value));
}
bool JsonDomBuilder::binary(Json::binary_t&) {
    return addValue(nullptr); // JSON text has no binary values
}

bool JsonDomBuilder::start_object(std::size_t) {
    charge(sizeof(Json) + sizeof(Json::object_t) + kAllocationOverhead);
    Json& object = slot();
    object = Json::object();
    frames_.push_back({&object, {}});
    return true;
}

bool JsonDomBuilder::key(Json::string_t& value) {
    Frame& top = frames_.back();
    if (!top.keys.insert(value).second)
        throwInputError(std::string(source_) + ": " + jsonPathAppend(path(false), value),
                        "duplicate key \"" + quoteInput(value) + "\"");
    charge(2 * stringBytes(value.size()) + 32); // the member's key and the hash set's copy
    auto& members = static_cast<MemberVector&>(top.container->get_ref<Json::object_t&>());
    pendingMember_ = &members.emplace_back(std::move(value), nullptr).second;
    return true;
}

bool JsonDomBuilder::end_object() {
    frames_.pop_back();
    return true;
}

bool JsonDomBuilder::start_array(std::size_t) {
    charge(sizeof(Json) + sizeof(Json::array_t) + kAllocationOverhead);
    Json& array = slot();
    array = Json::array();
    frames_.push_back({&array, {}});
    return true;
}

bool JsonDomBuilder::end_array() {
    frames_.pop_back();
    return true;
}

bool JsonDomBuilder::parse_error(std::size_t, const std::string& lastToken,
                                 const nlohmann::detail::exception& error) {
    if (error.id == 406) // a literal such as 1e999 overflows a double
        throwInputError(std::string(source_) + ": " + shownPath(path(true)),
                        "number out of range: " + quoteInput(lastToken));
    // Drop nlohmann's "[json.exception.parse_error.101] " prefix; keep "parse error at line L, column
    // C: ...", its quote of the input capped.
    std::string message = error.what();
    if (const auto close = message.find("] ");
        message.starts_with("[json.exception") && close != std::string::npos)
        message.erase(0, close + 2);
    throwInputError(source_, "invalid JSON: " + quoteInput(message, 2 * kMaxQuotedInput));
}

std::string JsonDomBuilder::path(bool intoInnermost) const {
    std::string result;
    const std::size_t depth = intoInnermost || frames_.empty() ? frames_.size() : frames_.size() - 1;
    for (std::size_t i = 0; i < depth; ++i) {
        const Json& container = *frames_[i].container;
        if (container.is_object()) {
            const auto& members = container.get_ref<const Json::object_t&>();
            if (!members.empty()) result = jsonPathAppend(result, members.back().first);
        } else {
            // An outer array's last element holds the rest of the path; the innermost one's next
            // element is the one being parsed.
            const std::size_t size = container.size();
            const bool innermost = i + 1 == frames_.size(); // only reached when intoInnermost
            if (innermost)
                result = jsonPathAppend(result, size);
            else if (size > 0)
                result = jsonPathAppend(result, size - 1);
        }
    }
    return result;
}

} // namespace vl
