#pragma once
// The SAX handler behind parseJsonStrict: builds an ordered_json document in one linear pass while
// refusing duplicate object keys (a hash set per open object) and documents whose tree would take
// more than limits::kMaxJsonDomBytes. nlohmann's callback parser rescanned the parent object for
// every element and ordered_map's emplace searches its keys linearly: both quadratic (600 KB of
// `[{},{},...]` took 9.5 CPU-s).
#include "core/common/JsonParse.h"
#include "core/common/Limits.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

namespace vl {

class JsonDomBuilder {
  public:
    explicit JsonDomBuilder(std::string_view source, std::size_t maxDomBytes = limits::kMaxJsonDomBytes)
        : source_(source), maxDomBytes_(maxDomBytes) {}

    // nlohmann's SAX interface (nlohmann::json_sax). Each throws InputError on a refused document.
    bool null();
    bool boolean(bool value);
    bool number_integer(Json::number_integer_t value);
    bool number_unsigned(Json::number_unsigned_t value);
    bool number_float(Json::number_float_t value, const std::string& literal);
    bool string(Json::string_t& value);
    bool binary(Json::binary_t& value);
    bool start_object(std::size_t elements);
    bool key(Json::string_t& value);
    bool end_object();
    bool start_array(std::size_t elements);
    bool end_array();
    [[noreturn]] bool parse_error(std::size_t position, const std::string& lastToken,
                                  const nlohmann::detail::exception& error);

    Json take() { return std::move(root_); }

  private:
    struct Frame {
        Json* container;
        std::unordered_set<std::string> keys; // objects only
    };

    Json& slot(); // where the next value goes
    bool addValue(Json value);
    void charge(std::size_t bytes);
    // RFC 6901 pointer of the element being parsed, or (intoInnermost false) of the innermost
    // container; empty for the document itself.
    std::string path(bool intoInnermost) const;

    std::string_view source_;
    Json root_;
    std::vector<Frame> frames_;
    Json* pendingMember_ = nullptr; // the member whose key was just read
    std::size_t maxDomBytes_;
    std::size_t domBytes_ = 0; // estimated bytes of the tree built so far
};

} // namespace vl
