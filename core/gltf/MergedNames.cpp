#include "core/gltf/MergedNames.h"

#include <algorithm>
#include <set>

namespace vl {
namespace {

bool separator(char c) {
    return c == '_' || c == '.' || c == '-' || c == ':' || c == ' ';
}

// The longest prefix every member shares that ends at a separator and leaves each member non-empty.
std::size_t sharedPrefix(const std::vector<std::string>& members) {
    std::size_t common = members.front().size();
    for (const std::string& m : members) {
        std::size_t i = 0;
        while (i < common && i < m.size() && m[i] == members.front()[i]) ++i;
        common = i;
    }
    for (const std::string& m : members) {
        if (m.empty()) return 0;
        if (common >= m.size()) common = m.size() - 1; // keep at least one byte of every member
    }
    while (common > 0 && !separator(members.front()[common - 1])) --common;
    return common;
}

// The readable name of a key in at most `limit` bytes.
std::string readableName(const std::vector<std::string>& members, std::size_t limit) {
    if (members.size() == 1) return members.front();
    const std::size_t prefix = sharedPrefix(members);
    std::vector<std::string> parts{members.front()};
    for (std::size_t i = 1; i < members.size(); ++i) parts.push_back(members[i].substr(prefix));
    std::string full = parts.front();
    for (std::size_t i = 1; i < parts.size(); ++i) full += "+" + parts[i];
    if (full.size() <= limit) return full;
    // Leading members while they fit beside "+<n> more" for the ones left out.
    std::string name = parts.front();
    std::size_t shown = 1;
    const auto more = [&](std::size_t left) { return "+" + std::to_string(left) + " more"; };
    while (shown + 1 < parts.size()) { // at least one left for "+<n> more"
        const std::string next = name + "+" + parts[shown];
        if (next.size() + more(parts.size() - shown - 1).size() > limit) break;
        name = next;
        ++shown;
    }
    const std::string suffix = more(parts.size() - shown);
    return utf8Prefix(name, limit - suffix.size()) + suffix;
}

} // namespace

std::string utf8Prefix(std::string_view text, std::size_t bytes) {
    if (text.size() <= bytes) return std::string(text);
    std::size_t end = bytes;
    while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end; // a continuation byte
    return std::string(text.substr(0, end));
}

std::vector<std::string> mergedTargetNames(const std::vector<std::vector<std::string>>& members,
                                           const std::vector<std::string>& taken) {
    std::set<std::string> used(taken.begin(), taken.end());
    std::vector<std::string> names;
    for (const auto& key : members) {
        std::string name = key.empty() ? std::string("key") : readableName(key, kMaxTargetNameBytes);
        // A one-member key's own name is its target's: only merged names are made unique.
        if (key.size() > 1)
            for (int n = 2; used.count(name); ++n) {
                const std::string tag = "~" + std::to_string(n);
                name = readableName(key, kMaxTargetNameBytes - tag.size()) + tag;
            }
        used.insert(name);
        names.push_back(name);
    }
    return names;
}

} // namespace vl
