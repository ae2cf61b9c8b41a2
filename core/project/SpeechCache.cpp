#include "core/project/SpeechCache.h"

#include "core/common/AtomicFile.h"
#include "core/common/ContentHash.h"
#include "core/common/Error.h"
#include "core/common/InputRegistry.h"
#include "core/project/Project.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <link.h>
#include <optional>
#include <sys/stat.h>
#include <time.h>
#include <type_traits>

namespace vl {

namespace {

constexpr char kMagic[8] = {'V', 'L', 'S', 'P', 'E', 'E', 'C', 'H'};
constexpr std::uint32_t kFormatVersion = 3; // 2: the speech error basis; 3: the inputs' stamps

// Entries of another build are foreign: the solvers, maps or file formats may differ. The build is
// a program file by path, size and mtime.
std::string buildIdentity(const std::filesystem::path& build) {
    struct stat s {};
    if (build.empty() || ::stat(build.c_str(), &s) != 0) return {};
    return build.string() + '\n' + std::to_string(s.st_size) + '\n' + std::to_string(s.st_mtim.tv_sec) + '.' +
           std::to_string(s.st_mtim.tv_nsec);
}

class ByteWriter {
  public:
    void u64(std::uint64_t v) { raw(&v, sizeof v); }
    void f64(double v) { raw(&v, sizeof v); }
    void text(std::string_view s) {
        u64(s.size());
        out_.append(s);
    }
    template <class T> void array(const std::vector<T>& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        u64(v.size());
        raw(v.data(), v.size() * sizeof(T));
    }
    void texts(const std::vector<std::string>& v) {
        u64(v.size());
        for (const auto& s : v) text(s);
    }
    std::string take() { return std::move(out_); }

  private:
    void raw(const void* p, std::size_t n) { out_.append(static_cast<const char*>(p), n); }
    std::string out_;
};

// Reads what ByteWriter wrote; any length past the end makes ok() false and everything after empty.
class ByteReader {
  public:
    explicit ByteReader(std::string_view in) : in_(in) {}
    bool ok() const { return ok_; }
    bool atEnd() const { return ok_ && in_.empty(); }
    std::uint64_t u64() {
        std::uint64_t v = 0;
        raw(&v, sizeof v);
        return v;
    }
    double f64() {
        double v = 0;
        raw(&v, sizeof v);
        return v;
    }
    std::string text() {
        const std::uint64_t n = u64();
        if (!fits(n, 1)) return {};
        std::string s(in_.substr(0, n));
        in_.remove_prefix(n);
        return s;
    }
    template <class T> std::vector<T> array() {
        const std::uint64_t n = u64();
        if (!fits(n, sizeof(T))) return {};
        std::vector<T> v(n);
        raw(v.data(), n * sizeof(T));
        return v;
    }
    std::vector<std::string> texts() {
        const std::uint64_t n = u64();
        if (!fits(n, sizeof(std::uint64_t))) return {};
        std::vector<std::string> v(n);
        for (auto& s : v) s = text();
        return v;
    }

  private:
    bool fits(std::uint64_t count, std::size_t size) {
        if (ok_ && count <= in_.size() / size) return true;
        ok_ = false;
        return false;
    }
    void raw(void* p, std::size_t n) {
        if (!fits(n, 1) || n == 0) return; // an empty array's data() may be null: no memcpy
        std::memcpy(p, in_.data(), n);
        in_.remove_prefix(n);
    }
    std::string_view in_;
    bool ok_ = true;
};

void writeModel(ByteWriter& w, const ReducedModel& m) {
    w.array(m.neutral.positions);
    w.array(m.neutral.uvs);
    w.array(m.neutral.triangles);
    w.u64(m.keys.size());
    for (const KeyMesh& k : m.keys) {
        w.text(k.name);
        w.texts(k.members);
        w.f64(k.frequency);
        w.array(k.positions);
    }
    w.texts(m.resting);
    w.u64(m.phonemeToKey.size());
    for (const auto& [phoneme, key] : m.phonemeToKey) {
        w.text(phoneme);
        w.u64(static_cast<std::uint64_t>(static_cast<std::int64_t>(key)));
    }
    w.u64(m.phonemeFrequencies.size());
    for (const auto& [phoneme, frequency] : m.phonemeFrequencies) {
        w.text(phoneme);
        w.f64(frequency);
    }
}

ReducedModel readModel(ByteReader& r) {
    ReducedModel m;
    m.neutral.positions = r.array<Vec3>();
    m.neutral.uvs = r.array<Vec2>();
    m.neutral.triangles = r.array<Triangle>();
    for (std::uint64_t k = r.u64(); r.ok() && k > 0; --k) {
        KeyMesh key;
        key.name = r.text();
        key.members = r.texts();
        key.frequency = r.f64();
        key.positions = r.array<Vec3>();
        m.keys.push_back(std::move(key));
    }
    m.resting = r.texts();
    for (std::uint64_t k = r.u64(); r.ok() && k > 0; --k) {
        std::string phoneme = r.text();
        m.phonemeToKey.emplace_back(std::move(phoneme), static_cast<int>(static_cast<std::int64_t>(r.u64())));
    }
    for (std::uint64_t k = r.u64(); r.ok() && k > 0; --k) {
        std::string phoneme = r.text();
        m.phonemeFrequencies.emplace_back(std::move(phoneme), r.f64());
    }
    return m;
}

// The entry's identity: which project, which map, which build. Stored whole in the entry too, so a
// hash collision of the file name is a miss, not a wrong answer.
std::string entryKey(const std::filesystem::path& project, const PhonemeVisemeMap* map,
                     const std::filesystem::path& build) {
    std::string key = buildIdentity(build);
    if (key.empty()) return {};
    key += '\n' + project.string() + '\n';
    if (map)
        for (const auto& [phoneme, viseme] : map->entries) key += phoneme + '\t' + viseme + '\n';
    else
        key += "project map\n";
    return key;
}

// What stat says of an input: a file whose stamp is the one recorded, and whose last change (ctime)
// was well before the entry was written, has the bytes it had then (any write since would have moved
// its ctime past the entry's time), so its bytes need not be read and hashed again. A change within
// the margin of the entry's writing (the clock the file system stamps with is coarse) is checked by
// its bytes: git's "racily clean" rule.
struct FileStamp {
    std::uint64_t device = 0, inode = 0, size = 0;
    std::int64_t modified = 0, changed = 0; // ns since the epoch
    bool operator==(const FileStamp&) const = default;
};
constexpr std::int64_t kRacyMarginNs = 2'000'000'000;

std::optional<FileStamp> stampOf(const std::filesystem::path& file) {
    struct stat s {};
    if (::stat(file.c_str(), &s) != 0) return std::nullopt;
    const auto ns = [](const timespec& t) { return std::int64_t(t.tv_sec) * 1'000'000'000 + t.tv_nsec; };
    return FileStamp{std::uint64_t(s.st_dev), std::uint64_t(s.st_ino), std::uint64_t(s.st_size),
                     ns(s.st_mtim), ns(s.st_ctim)};
}

std::int64_t nowNs() {
    timespec t{};
    ::clock_gettime(CLOCK_REALTIME, &t);
    return std::int64_t(t.tv_sec) * 1'000'000'000 + t.tv_nsec;
}

// The stamp of an input as its bytes were hashed, or none (its bytes are then checked on every read):
// the stamp is taken now, so the bytes are hashed again between two stats that must agree (the
// computation read them earlier, perhaps long before).
FileStamp stampAsHashed(const InputWatch::Read& input) {
    const auto before = stampOf(input.file);
    if (!before) return {};
    try {
        if (contentHash(readFileBytes(input.file).view()) != input.hash) return {};
    } catch (const InputError&) {
        return {};
    }
    return stampOf(input.file) == before ? *before : FileStamp{};
}

struct Entry {
    std::vector<InputWatch::Read> read;
    std::vector<std::filesystem::path> referenced;
    ProjectSpeechFaces faces;
};

std::string encodeEntry(std::string_view key, const Entry& entry) {
    ByteWriter w;
    w.text(std::string_view(kMagic, sizeof kMagic));
    w.u64(kFormatVersion);
    w.text(key);
    w.u64(static_cast<std::uint64_t>(nowNs())); // before the stamps: a change while writing is racy
    w.u64(entry.read.size());
    for (const InputWatch::Read& input : entry.read) {
        w.text(input.file.string());
        w.u64(input.hash);
        const FileStamp stamp = stampAsHashed(input);
        for (const std::uint64_t field : {stamp.device, stamp.inode, stamp.size,
                                          std::uint64_t(stamp.modified), std::uint64_t(stamp.changed)})
            w.u64(field);
    }
    w.u64(entry.referenced.size());
    for (const auto& file : entry.referenced) w.text(file.string());
    w.u64(entry.faces.metres ? 1 : 0);
    writeModel(w, entry.faces.faces.full);
    writeModel(w, entry.faces.faces.reduced);
    w.array(entry.faces.faces.weights);
    const SpeechErrorBasis::Stored basis = entry.faces.basis->stored();
    w.array(basis.mouth);
    w.array(basis.gram);
    w.u64(basis.lengths.size());
    for (const auto& level : basis.lengths) w.array(level);
    std::string bytes = w.take();
    const std::uint64_t check = contentHash(bytes);
    bytes.append(reinterpret_cast<const char*>(&check), sizeof check);
    return bytes;
}

// The entry when it is whole, of this build and key, and every input it lists has the bytes it had.
// Reading the inputs notes them as inputs of the run, as computing would.
std::optional<Entry> decodeEntry(std::string_view bytes, std::string_view key) {
    if (bytes.size() < sizeof(std::uint64_t)) return std::nullopt;
    std::uint64_t check = 0;
    std::memcpy(&check, bytes.data() + bytes.size() - sizeof check, sizeof check);
    bytes.remove_suffix(sizeof check);
    if (contentHash(bytes) != check) return std::nullopt;
    ByteReader r(bytes);
    if (r.text() != std::string_view(kMagic, sizeof kMagic) || r.u64() != kFormatVersion || r.text() != key)
        return std::nullopt;
    const auto written = static_cast<std::int64_t>(r.u64());
    Entry entry;
    for (std::uint64_t k = r.u64(); r.ok() && k > 0; --k) {
        const std::filesystem::path file = r.text();
        const std::uint64_t hash = r.u64();
        FileStamp stamp;
        stamp.device = r.u64();
        stamp.inode = r.u64();
        stamp.size = r.u64();
        stamp.modified = static_cast<std::int64_t>(r.u64());
        stamp.changed = static_cast<std::int64_t>(r.u64());
        if (!r.ok()) return std::nullopt;
        if (stamp.changed != 0 && stamp.changed + kRacyMarginNs < written && stampOf(file) == stamp) {
            noteInputFile(file); // the bytes it had: an input of the run all the same
        } else {
            try {
                if (contentHash(readFileBytes(file).view()) != hash) return std::nullopt;
            } catch (const InputError&) {
                return std::nullopt; // gone or unreadable: computing names the problem
            }
        }
        entry.read.push_back({file, hash, true});
    }
    for (std::uint64_t k = r.u64(); r.ok() && k > 0; --k) entry.referenced.emplace_back(r.text());
    entry.faces.metres = r.u64() != 0;
    entry.faces.faces.full = readModel(r);
    entry.faces.faces.reduced = readModel(r);
    entry.faces.faces.weights = r.array<double>();
    SpeechErrorBasis::Stored basis;
    basis.mouth = r.array<std::size_t>();
    basis.gram = r.array<double>();
    for (std::uint64_t k = r.u64(); r.ok() && k > 0; --k) basis.lengths.push_back(r.array<double>());
    if (!r.atEnd()) return std::nullopt;
    const SpeechFaces& faces = entry.faces.faces;
    try {
        entry.faces.basis =
            std::make_shared<const SpeechErrorBasis>(faces.full, faces.reduced, faces.weights, basis);
    } catch (const InputError&) {
        return std::nullopt; // does not fit its faces: computing again
    }
    return entry;
}

// Read without clearing the buffer first: an entry is about 2 MB, and it is all overwritten.
std::optional<FileBytes> readIfPresent(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) return std::nullopt;
    try {
        return readFileBytes(file);
    } catch (const InputError&) {
        return std::nullopt;
    }
}

// The entry's file and key for a project, map and build (empty when there is no cache).
struct EntryFile {
    std::string key;
    std::filesystem::path file;
};
EntryFile entryFile(const std::filesystem::path& projectFile, const PhonemeVisemeMap* map,
                    const std::filesystem::path& cacheFolder, const std::filesystem::path& build) {
    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(projectFile, ec).lexically_normal();
    EntryFile where;
    if (cacheFolder.empty() || ec) return where;
    where.key = entryKey(absolute, map, build);
    if (!where.key.empty()) where.file = cacheFolder / "speech" / (hashHex(contentHash(where.key)) + ".bin");
    return where;
}

// The faces of a valid entry, its referenced files noted as the run's references.
std::optional<ProjectSpeechFaces> readEntry(const std::filesystem::path& file, std::string_view key) {
    const auto bytes = readIfPresent(file);
    if (!bytes) return std::nullopt;
    auto entry = decodeEntry(bytes->view(), key);
    if (!entry) return std::nullopt;
    for (const auto& referenced : entry->referenced) noteReferencedFile(referenced);
    entry->faces.fromCache = true;
    return std::move(entry->faces);
}

} // namespace

std::filesystem::path speechCacheFolder() {
    if (const char* dir = std::getenv("VISEMELAB_CACHE_DIR"); dir && *dir)
        return std::string_view(dir) == "off" ? std::filesystem::path() : std::filesystem::path(dir);
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        return std::filesystem::path(xdg) / "visemelab";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "visemelab";
    return {};
}

std::filesystem::path speechCacheBuildFile() {
    Dl_info info{};
    link_map* object = nullptr;
    if (::dladdr1(reinterpret_cast<void*>(&speechCacheFolder), &info, reinterpret_cast<void**>(&object),
                  RTLD_DL_LINKMAP) == 0 ||
        object == nullptr)
        return {};
    // The main program's own name is empty (dladdr would give argv[0], which may be a launcher or
    // a bare name found on PATH).
    if (object->l_name && *object->l_name) return object->l_name;
    std::error_code ec;
    return std::filesystem::read_symlink("/proc/self/exe", ec);
}

std::optional<ProjectSpeechFaces> readCachedProjectSpeechFaces(const std::filesystem::path& projectFile,
                                                               const PhonemeVisemeMap* map,
                                                               const std::filesystem::path& cacheFolder,
                                                               const std::filesystem::path& build) {
    const EntryFile where = entryFile(projectFile, map, cacheFolder, build);
    if (where.file.empty()) return std::nullopt;
    return readEntry(where.file, where.key);
}

ProjectSpeechFaces cachedProjectSpeechFaces(const std::filesystem::path& projectFile,
                                            const PhonemeVisemeMap* map,
                                            const std::filesystem::path& cacheFolder) {
    const EntryFile where = entryFile(projectFile, map, cacheFolder, speechCacheBuildFile());
    if (!where.file.empty())
        if (auto faces = readEntry(where.file, where.key)) return std::move(*faces);

    Entry entry;
    {
        const InputWatch watch;
        const Project project = loadProject(projectFile);
        entry.faces.faces = projectSpeechFaces(project, map);
        entry.faces.metres = project.avatar.isSet();
        const SpeechFaces& faces = entry.faces.faces;
        entry.faces.basis =
            std::make_shared<const SpeechErrorBasis>(faces.full, faces.reduced, faces.weights);
        entry.read = watch.read();
        entry.referenced = watch.referenced();
    }
    // Hashed as they were read: a file changed while it was read gives an entry that never matches.
    const bool complete = std::all_of(entry.read.begin(), entry.read.end(),
                                      [](const InputWatch::Read& input) { return input.hashed; });
    if (!where.file.empty() && complete) {
        try {
            writeFileAtomically(where.file, encodeEntry(where.key, entry));
        } catch (const std::exception&) {
            // No cache this time (read-only or full disk).
        }
    }
    return std::move(entry.faces);
}

} // namespace vl
