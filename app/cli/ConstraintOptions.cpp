#include "app/cli/ConstraintOptions.h"

#include "app/cli/Command.h"

namespace vl::cli {

namespace {

std::pair<std::string, std::string> splitPair(const std::string& text, const std::string& option) {
    const auto comma = text.find(',');
    if (comma == std::string::npos || comma == 0 || comma + 1 == text.size() ||
        text.find(',', comma + 1) != std::string::npos)
        throwUsage(option + " expects two viseme names as A,B, got '" + text + "'");
    return {text.substr(0, comma), text.substr(comma + 1)};
}

} // namespace

ConstraintNames ConstraintOptions::names() const {
    ConstraintNames c;
    c.pinned = pin;
    for (const auto& text : apart) c.apart.push_back(splitPair(text, "--apart"));
    for (const auto& text : together) c.together.push_back(splitPair(text, "--together"));
    return c;
}

std::string closureSetting(const ConstraintOptions& options) {
    return options.closure == "none" ? std::string() : options.closure;
}

void addConstraintOptions(CLI::App& command, ConstraintOptions& options, const char* closureDefault) {
    options.closure = closureDefault;
    command
        .add_option("--closure", options.closure,
                    "With the rest free, the lips-closed viseme keeps a key of its own: auto (PP or "
                    "viseme_PP when present), a viseme name, or none")
        ->default_str(closureDefault);
    command.add_option("--pin", options.pin, "Keep this viseme as its own key, a group of one (repeatable)");
    command.add_option("--apart", options.apart, "Never merge these two visemes: A,B (repeatable)");
    command.add_option("--together", options.together, "Always merge these two visemes: A,B (repeatable)");
    command
        .add_option(
            "--max-error-mm", options.maxErrorMm,
            "Use the smallest number of keys for which no viseme moves any vertex more than this many "
            "mm from its own shape (found and certified; replaces -m)")
        ->check(kPositive);
}

} // namespace vl::cli
