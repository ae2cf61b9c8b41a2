#include "core/io/JsonWrite.h"

#include <algorithm>

namespace vl {

namespace {

bool isScalar(const Json& v) {
    return !v.is_object() && !v.is_array();
}

bool isFlatArray(const Json& v) {
    return v.is_array() && std::all_of(v.begin(), v.end(), isScalar);
}

void indent(std::string& out, int level) {
    out.append(static_cast<std::size_t>(level) * 2, ' ');
}

void write(std::string& out, const Json& value, int level) {
    if (isScalar(value)) {
        out += value.dump(); // strings escaped, numbers in shortest round-trip form
    } else if (value.empty()) {
        out += value.is_object() ? "{}" : "[]";
    } else if (isFlatArray(value)) {
        out += '[';
        bool first = true;
        for (const auto& e : value) {
            if (!first) out += ", ";
            first = false;
            out += e.dump();
        }
        out += ']';
    } else if (value.is_array()) {
        out += "[\n";
        bool first = true;
        for (const auto& e : value) {
            if (!first) out += ",\n";
            first = false;
            indent(out, level + 1);
            write(out, e, level + 1);
        }
        out += '\n';
        indent(out, level);
        out += ']';
    } else {
        out += "{\n";
        bool first = true;
        for (const auto& [key, e] : value.items()) {
            if (!first) out += ",\n";
            first = false;
            indent(out, level + 1);
            out += Json(key).dump();
            out += ": ";
            write(out, e, level + 1);
        }
        out += '\n';
        indent(out, level);
        out += '}';
    }
}

} // namespace

std::string formatJsonPretty(const Json& value) {
    std::string out;
    write(out, value, 0);
    out += '\n';
    return out;
}

std::string compactJsonText(std::string_view json) {
    // Into a buffer of the input's size through a pointer, not a character at a time (`say --stdin`
    // compacts every track it answers).
    std::string out(json.size(), '\0');
    char* o = out.data();
    bool inString = false;
    for (std::size_t i = 0; i < json.size(); ++i) {
        const char c = json[i];
        if (inString) {
            *o++ = c;
            if (c == '\\' && i + 1 < json.size())
                *o++ = json[++i]; // the escaped character, a quote included
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
            *o++ = c;
        } else if (c != ' ' && c != '\t' && c != '\n' && c != '\r') {
            *o++ = c;
        }
    }
    out.resize(static_cast<std::size_t>(o - out.data()));
    return out;
}

} // namespace vl
