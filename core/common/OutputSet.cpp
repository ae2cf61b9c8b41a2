#include "core/common/OutputSet.h"

#include "core/common/Error.h"
#include "core/common/FileWriting.h"
#include "core/common/InputRegistry.h"
#include "core/common/TextParsing.h"

#include <algorithm>
#include <fcntl.h>
#include <fstream>
#include <iterator>
#include <set>
#include <unistd.h>

namespace vl {

namespace {

constexpr std::string_view kManifestPrefix = ".visemelab-";
constexpr std::string_view kManifestSuffix = ".manifest";

// A name a set may write or a manifest may list for removal: one plain, visible file of the folder.
bool isPlainFileName(std::string_view name) {
    return !name.empty() && name != "." && name != ".." && !name.starts_with('.') &&
           name.find('/') == std::string_view::npos && name.find('\0') == std::string_view::npos &&
           name.find('\n') == std::string_view::npos;
}

bool isSetName(std::string_view name) {
    return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
               c == '_';
    });
}

} // namespace

OutputSet::OutputSet(std::filesystem::path folder, std::string setName)
    : folder_(folder.empty() ? std::filesystem::path(".") : std::move(folder)), setName_(std::move(setName)) {
    if (!isSetName(setName_)) throwInputError("output set", "invalid set name '" + setName_ + "'");
    refuseWritingIntoInputFolder(folder_);
    std::error_code ec;
    std::filesystem::create_directories(folder_, ec);
    if (ec) throwInputError(folder_.string(), "cannot create the output folder: " + ec.message());
    if (!std::filesystem::is_directory(folder_, ec))
        throwInputError(folder_.string(), "is not a folder; outputs go into a folder here");
    fileio::sweepStaleTemporaries(folder_);
}

OutputSet::~OutputSet() {
    if (!committed_) discardTemporaries();
}

void OutputSet::discardTemporaries() {
    std::error_code ec;
    for (const Staged& s : staged_)
        if (!s.unchanged()) std::filesystem::remove(s.temporary, ec);
}

void OutputSet::add(const std::string& fileName, std::string_view contents) {
    add(fileName, {contents});
}

void OutputSet::add(const std::string& fileName, std::initializer_list<std::string_view> parts) {
    const std::filesystem::path destination = folder_ / fileName;
    if (committed_) throwInputError(destination.string(), "the output set was already written");
    if (!isPlainFileName(fileName))
        throwInputError(destination.string(), "not a plain file name for an output of " + folder_.string());
    if (std::any_of(staged_.begin(), staged_.end(), [&](const Staged& s) { return s.name == fileName; }))
        throwInputError(destination.string(), "written twice by the same run");
    stage(fileName, parts);
}

void OutputSet::stage(const std::string& fileName, std::initializer_list<std::string_view> parts) {
    const std::filesystem::path destination = folder_ / fileName;
    refuseOverwritingInput(destination);
    Staged staged{fileName, fileio::writeTarget(destination), {}};
    const std::span<const std::string_view> contents(parts.begin(), parts.size());
    // A destination that already holds these bytes stays as it is (same inode, same time stamp):
    // comparing costs a read from the page cache, replacing costs a new inode, the writing, the
    // writeback and the old file's removal; and tools that watch the folder see only real changes.
    if (fileio::holdsExactly(staged.target, contents)) {
        staged_.push_back(std::move(staged));
        return;
    }
    const fileio::TemporaryFile temp = fileio::createTemporaryFor(staged.target, destination.string());
    staged.temporary = temp.path;
    staged_.push_back(staged); // from here the destructor removes the temporary on failure
    const bool ok = fileio::writeAll(temp.fd, contents);
    const std::string problem = ok ? std::string() : fileio::lastSystemError();
    // Start writing the data out now, without waiting: the device works on this file while the next
    // ones are formatted, and the barrier's fsync then mostly waits. Advisory, so errors are ignored
    // here; the fsync reports them.
    if (ok) (void)::sync_file_range(temp.fd, 0, 0, SYNC_FILE_RANGE_WRITE);
    ::close(temp.fd);
    if (!ok) throwInputError(destination.string(), "write failed (" + problem + "); no output was changed");
}

std::vector<std::filesystem::path> OutputSet::commit() {
    if (committed_) throwInputError(folder_.string(), "the output set was already written");
    // The manifest is staged last, so it goes through the same barrier and is renamed after every
    // output it lists.
    const std::size_t outputs = staged_.size();
    const std::filesystem::path manifest = manifestPath(folder_, setName_);
    const std::vector<std::string> previous = readManifest(manifest);
    std::string text = "# Files the last '" + setName_ +
                       "' run of VisemeLab wrote into this folder; the next "
                       "run removes those it does not write again.\n";
    for (const Staged& s : staged_) text += s.name + "\n";
    stage(manifest.filename().string(), {text});
    // The barrier: every new file is on disk before the first one replaces an old one.
    for (const Staged& s : staged_) {
        if (s.unchanged()) continue; // made durable when compared
        const int fd = ::open(s.temporary.c_str(), O_RDONLY | O_CLOEXEC);
        const bool ok = fd >= 0 && ::fsync(fd) == 0;
        const std::string problem = ok ? std::string() : fileio::lastSystemError();
        if (fd >= 0) ::close(fd);
        if (!ok)
            throwInputError((folder_ / s.name).string(),
                            "cannot flush the file to disk (" + problem + "); no output was changed");
    }
    std::set<std::filesystem::path> folders;
    std::vector<std::filesystem::path> written;
    for (std::size_t i = 0; i < staged_.size(); ++i) {
        const Staged& s = staged_[i];
        std::error_code ec;
        if (!s.unchanged()) std::filesystem::rename(s.temporary, s.target, ec);
        if (ec) {
            committed_ = true; // the temporaries left are removed here, the renamed ones are outputs now
            for (std::size_t j = i; j < staged_.size(); ++j)
                if (!staged_[j].unchanged()) std::filesystem::remove(staged_[j].temporary, ec);
            throwInputError((folder_ / s.name).string(),
                            "cannot replace the file: " + ec.message() + " (" + std::to_string(i) + " of " +
                                std::to_string(outputs) + " outputs were written)");
        }
        folders.insert(s.target.has_parent_path() ? s.target.parent_path() : std::filesystem::path("."));
        if (i < outputs) written.push_back(folder_ / s.name);
    }
    committed_ = true;
    for (const auto& folder : folders) fileio::syncFolder(folder);
    staged_.pop_back(); // the manifest: not an output of the set
    removeStaleOutputs(previous);
    return written;
}

void OutputSet::removeStaleOutputs(const std::vector<std::string>& previous) {
    std::set<std::string> keep;
    for (const Staged& s : staged_) keep.insert(s.name);
    // Files another set of the folder claims now stay: two kinds of output may share a folder.
    std::error_code ec;
    const std::string own = manifestPath(folder_, setName_).filename().string();
    for (std::filesystem::directory_iterator it(folder_, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name != own && name.starts_with(kManifestPrefix) && name.ends_with(kManifestSuffix))
            for (auto& listed : readManifest(it->path())) keep.insert(std::move(listed));
    }
    for (const std::string& name : previous) {
        if (keep.count(name) || !isPlainFileName(name)) continue;
        const std::filesystem::path stale = folder_ / name;
        std::error_code ignored;
        const auto status = std::filesystem::symlink_status(stale, ignored);
        if (!std::filesystem::is_regular_file(status) && !std::filesystem::is_symlink(status)) continue;
        try {
            refuseOverwritingInput(stale); // an input of this run is never removed
        } catch (const OutputOverwritesInputError&) {
            continue;
        }
        std::filesystem::remove(stale, ignored);
    }
}

std::filesystem::path OutputSet::manifestPath(const std::filesystem::path& folder, std::string_view setName) {
    return folder / (std::string(kManifestPrefix) + std::string(setName) + std::string(kManifestSuffix));
}

std::vector<std::string> OutputSet::readManifest(const std::filesystem::path& manifest) {
    // Read directly, not as an input of the run (the set rewrites it); an unreadable or oversized
    // manifest only means stale files stay.
    std::error_code ec;
    if (!std::filesystem::is_regular_file(manifest, ec) ||
        std::filesystem::file_size(manifest, ec) > (1u << 20))
        return {};
    std::ifstream in(manifest, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::string> names;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string_view line = trim(std::string_view(text).substr(start, end - start));
        start = end + 1;
        if (!line.empty() && !line.starts_with('#')) names.emplace_back(line);
    }
    return names;
}

} // namespace vl
