#pragma once
// Reading a text corpus of any length in pieces small enough for the transcriber, cut where a
// cut changes no pronunciation (after a sentence, else at a line break or a space), and refusing
// files that are not text.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string_view>

namespace vl {

struct CorpusStats {
    std::uint64_t bytes = 0;         // bytes read (after a UTF-8 byte order mark)
    std::uint64_t replacedBytes = 0; // stray bytes that are not UTF-8, passed on as spaces
};

// chunk: text of one piece (valid UTF-8); bytesDone / bytesTotal for progress (bytesTotal is 0
// when the size is unknown, e.g. for a pipe).
using CorpusChunkFn =
    std::function<void(std::string_view chunk, std::uint64_t bytesDone, std::uint64_t bytesTotal)>;

constexpr std::size_t kDefaultCorpusChunkBytes = 64 * 1024;

// Throws InputError naming the file when it is missing, empty, holds no text but white space,
// or is binary: a NUL byte, UTF-16, or more than 10% of its bytes invalid UTF-8 or control characters.
CorpusStats forEachCorpusChunk(const std::filesystem::path& path, const CorpusChunkFn& chunk,
                               std::size_t chunkBytes = kDefaultCorpusChunkBytes);

// The same for text in memory; `source` names it in errors.
CorpusStats forEachTextChunk(std::string_view text, std::string_view source, const CorpusChunkFn& chunk,
                             std::size_t chunkBytes = kDefaultCorpusChunkBytes);

} // namespace vl
