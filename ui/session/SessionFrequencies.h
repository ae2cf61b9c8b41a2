#pragma once
// The session's frequency facet: the viseme frequencies (direct, or a phoneme table and map) as
// undoable edits, the phoneme map editor's edits, and the phoneme count of a corpus on a worker
// thread.
#include "core/document/Document.h"
#include "core/document/PhonemeMapCommands.h"
#include "core/phonetics/PhonemeCounting.h"
#include "core/phonetics/SpeechEngines.h"
#include "ui/session/BackgroundTask.h"
#include "ui/session/SessionCore.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vl::ui {

class SessionFrequencies {
  public:
    SessionFrequencies(SessionCore& core, decltype(SpeechEngines::transcriber) transcriber);

    // Normalised viseme frequencies from the current table (memoized; throws InputError when invalid).
    const std::vector<double>& values() const { return core_.inputs().frequencies(); }
    void setVisemeFrequency(int viseme, double value);   // direct mode
    void setPhonemeFrequency(int phoneme, double value); // phoneme mode
    void setPhonemeViseme(int phoneme, const std::string& viseme);
    void load(const std::filesystem::path& file);
    // A phoneme table plus a map, e.g. the bundled en-us table and a bundled map (checked first).
    void setSource(FrequencySource source, const std::string& actionName);
    // The bundled American English table with the bundled map `mapId` ("oculus", "mpeg4", ...).
    void useBundledPhonemeMap(const std::string& mapId);
    void useDirectFrequencies();
    void saveCsv(const std::filesystem::path& file) const;

    // --- the phoneme map editor (core/document/PhonemeMapCommands.h), each one undo step ---
    // The phoneme table a new map starts from: the current one, else the bundled en-us table.
    FrequencyTable startingPhonemeTable() const;
    void startPhonemeMap(FrequencyTable table, const PhonemeVisemeMap& start,
                         const std::vector<edit::MapAssignment>& assignment, const std::string& startName);
    void movePhonemes(const std::string& from, const std::string& to);
    void savePhonemeMap(const std::filesystem::path& file) const;

    // --- phoneme count ---
    // Counts the phonemes of a text file with espeak-ng on a worker thread; the counts replace the
    // phoneme table (the current map is kept, or the bundled Oculus map is used).
    void startPhonemeCount(const std::filesystem::path& corpus, const std::string& voice = "en-us");
    bool countRunning() const { return count_.running(); }
    double countProgress() const { return count_.progress(); }
    std::optional<double> countSecondsLeft() const { return count_.secondsLeft(); }
    void cancelCount() { count_.requestCancel(); }
    // For the session: collects a finished count (once per frame); waits for the worker.
    void poll();
    void wait() { count_.wait(); }

  private:
    SessionCore& core_;
    decltype(SpeechEngines::transcriber) transcriber_;
    BackgroundTask<PhonemeCountResult> count_;
    std::filesystem::path countCorpus_;
};

} // namespace vl::ui
