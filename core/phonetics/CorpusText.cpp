#include "core/phonetics/CorpusText.h"

#include "core/common/Error.h"
#include "core/common/InputRegistry.h"

#include <fstream>
#include <string>
#include <system_error>
#include <vector>

namespace vl {

namespace {

// A file is binary when more than this share of its bytes are invalid UTF-8 or control
// characters. Latin-1 prose stays far below it (a few accented letters per line), random or
// compressed data far above.
constexpr double kMaxSuspiciousShare = 0.10;
// The share is judged once this many bytes were seen (or at the end of a shorter file).
constexpr std::uint64_t kMinBytesToJudge = 4096;

bool isContinuation(unsigned char c) {
    return (c & 0xC0) == 0x80;
}

// Length of the well-formed UTF-8 sequence starting at text[i] (RFC 3629: no overlongs, no
// surrogates, nothing above U+10FFFF), or 0 when the bytes there are not one.
std::size_t utf8SequenceLength(std::string_view text, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char c = byte(i);
    if (c < 0x80) return 1;
    std::size_t length = 0;
    unsigned char low = 0x80, high = 0xBF; // allowed range of the second byte
    if (c >= 0xC2 && c <= 0xDF)
        length = 2;
    else if (c >= 0xE0 && c <= 0xEF) {
        length = 3;
        if (c == 0xE0) low = 0xA0;
        if (c == 0xED) high = 0x9F;
    } else if (c >= 0xF0 && c <= 0xF4) {
        length = 4;
        if (c == 0xF0) low = 0x90;
        if (c == 0xF4) high = 0x8F;
    } else {
        return 0;
    }
    if (i + length > text.size()) return 0;
    if (byte(i + 1) < low || byte(i + 1) > high) return 0;
    for (std::size_t k = 2; k < length; ++k)
        if (!isContinuation(byte(i + k))) return 0;
    return length;
}

bool isControl(unsigned char c) {
    return (c < 0x20 && c != '\t' && c != '\n' && c != '\v' && c != '\f' && c != '\r') || c == 0x7F;
}

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

bool endsClause(char c) {
    return c == '.' || c == '!' || c == '?' || c == ';' || c == ':';
}

// Collects bytes and hands them on in pieces cut at clause or word boundaries, checking that
// they are text on the way.
class CorpusChunker {
  public:
    CorpusChunker(std::string_view source, std::uint64_t totalBytes, std::size_t chunkBytes,
                  const CorpusChunkFn& fn)
        : source_(source), total_(totalBytes), chunkBytes_(chunkBytes < 16 ? 16 : chunkBytes), fn_(fn) {}

    void push(std::string_view data) {
        pending_.append(data);
        while (pending_.size() >= chunkBytes_) emit(cutPosition(), false);
    }

    CorpusStats finish() {
        if (!pending_.empty()) emit(pending_.size(), true);
        if (stats_.bytes == 0) throwInputError(source_, "empty file; expected UTF-8 text");
        if (!sawText_) throwInputError(source_, "contains only white space; expected UTF-8 text");
        return stats_;
    }

  private:
    // Where to cut pending_: after the last clause end or blank line in its second half, else
    // after its last line break or space, else (one giant word) at a character boundary.
    std::size_t cutPosition() const {
        const std::string_view p = pending_;
        const std::size_t half = p.size() / 2;
        for (std::size_t i = p.size() - 1; i > half; --i)
            if (isSpace(p[i]) && (endsClause(p[i - 1]) || (p[i] == '\n' && p[i - 1] == '\n'))) return i + 1;
        const auto lineBreak = p.rfind('\n');
        if (lineBreak != std::string_view::npos && lineBreak >= half) return lineBreak + 1;
        const auto space = p.find_last_of(" \t\n\r\v\f");
        if (space != std::string_view::npos) return space + 1;
        std::size_t cut = p.size() - 1; // the last byte may start a character that continues later
        while (cut > 0 && isContinuation(static_cast<unsigned char>(p[cut]))) --cut;
        return cut > 0 ? cut : p.size();
    }

    void emit(std::size_t length, bool last) {
        std::string chunk = pending_.substr(0, length);
        pending_.erase(0, length);
        std::size_t start = 0;
        if (stats_.bytes == 0) start = checkStart(chunk);
        std::uint64_t suspicious = 0;
        for (std::size_t i = start; i < chunk.size();) {
            const auto c = static_cast<unsigned char>(chunk[i]);
            if (c == 0)
                throwInputError(source_, "binary file (NUL byte at offset " + std::to_string(offset_ + i) +
                                             "); expected UTF-8 text");
            const std::size_t sequence = utf8SequenceLength(chunk, i);
            if (sequence == 0 || isControl(c)) {
                chunk[i] = ' ';
                ++suspicious;
                ++i;
                continue;
            }
            if (!isSpace(chunk[i])) sawText_ = true;
            i += sequence;
        }
        offset_ += chunk.size();
        stats_.bytes += chunk.size() - start;
        stats_.replacedBytes += suspicious;
        if ((last || stats_.bytes >= kMinBytesToJudge) &&
            static_cast<double>(stats_.replacedBytes) >
                kMaxSuspiciousShare * static_cast<double>(stats_.bytes)) {
            const auto percent = 100 * stats_.replacedBytes / stats_.bytes;
            throwInputError(source_, "binary file, not UTF-8 text (" + std::to_string(percent) + "% of the " +
                                         std::to_string(stats_.bytes) +
                                         " bytes read are invalid UTF-8 or control characters)");
        }
        fn_(std::string_view(chunk).substr(start), offset_, total_);
    }

    // Skips a UTF-8 byte order mark; refuses UTF-16, which would otherwise look like binary.
    std::size_t checkStart(std::string_view chunk) const {
        if (chunk.starts_with("\xEF\xBB\xBF")) return 3;
        if (chunk.starts_with("\xFF\xFE") || chunk.starts_with("\xFE\xFF"))
            throwInputError(source_, "UTF-16 text; save it as UTF-8");
        return 0;
    }

    std::string source_;
    std::uint64_t total_;
    std::size_t chunkBytes_;
    const CorpusChunkFn& fn_;
    std::string pending_;
    std::uint64_t offset_ = 0; // bytes of the input handed on so far
    CorpusStats stats_;
    bool sawText_ = false;
};

} // namespace

CorpusStats forEachCorpusChunk(const std::filesystem::path& path, const CorpusChunkFn& chunk,
                               std::size_t chunkBytes) {
    const std::string source = path.string();
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throwInputError(source, "file not found");
    if (std::filesystem::is_directory(path, ec)) throwInputError(source, "is a directory, not a file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throwInputError(source, "cannot open file for reading");
    noteInputFile(path);
    const auto size = std::filesystem::is_regular_file(path, ec) ? std::filesystem::file_size(path, ec) : 0;
    CorpusChunker chunker(source, ec ? 0 : size, chunkBytes, chunk);
    std::vector<char> block(chunkBytes < 16 ? 16 : chunkBytes);
    while (in) {
        in.read(block.data(), static_cast<std::streamsize>(block.size()));
        const auto got = static_cast<std::size_t>(in.gcount());
        if (got > 0) chunker.push(std::string_view(block.data(), got));
    }
    if (in.bad()) throwInputError(source, "read error");
    return chunker.finish();
}

CorpusStats forEachTextChunk(std::string_view text, std::string_view source, const CorpusChunkFn& chunk,
                             std::size_t chunkBytes) {
    CorpusChunker chunker(source, text.size(), chunkBytes, chunk);
    for (std::size_t at = 0; at < text.size(); at += chunkBytes) chunker.push(text.substr(at, chunkBytes));
    return chunker.finish();
}

} // namespace vl
