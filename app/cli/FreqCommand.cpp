// `visemelab freq`: phoneme frequencies of a text corpus (espeak-ng), printed and written as a table.
#include "app/cli/Command.h"
#include "app/cli/Progress.h"
#include "core/common/Error.h"
#include "core/phonetics/EspeakTranscriber.h"
#include "core/phonetics/PhonemeCounting.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/phonetics/PhonemeTableIO.h"

#include <cstdio>
#include <filesystem>
#include <memory>

namespace vl::cli {

namespace {

struct FreqOptions {
    std::string corpus;
    std::string voice = "en-us";
    std::string out;
    std::string map;
    bool quiet = false;
};

void reportSkipped(const PhonemeCountResult& result) {
    if (result.corpus.replacedBytes > 0)
        std::fprintf(stderr, "visemelab: note: %llu bytes that are not UTF-8 text were read as spaces\n",
                     static_cast<unsigned long long>(result.corpus.replacedBytes));
    if (result.skippedSymbols.empty()) return;
    std::size_t total = 0;
    std::string list;
    for (const auto& [symbol, count] : result.skippedSymbols) {
        total += count;
        list += " " + symbol + " (" + std::to_string(count) + ")";
    }
    std::fprintf(stderr, "visemelab: note: %zu phonemes with no ARPAbet equivalent were left out:%s\n", total,
                 list.c_str());
}

int runFreq(const FreqOptions& o) {
    const std::filesystem::path out = o.out;
    if (!o.map.empty() && !out.empty() && out.extension() != ".json") {
        std::fprintf(stderr, "visemelab: error: --map needs a .json output (a CSV table holds no map)\n");
        return kExitUsage;
    }
    auto transcriber = makeEspeakTranscriber(o.voice);
    PhonemeVisemeMap map;
    if (!o.map.empty()) map = loadPhonemeMapFile(o.map);

    ProgressLine progress("transcribing " + std::filesystem::path(o.corpus).filename().string());
    const auto fraction = progress.callback();
    const auto result =
        countPhonemesInFile(o.corpus, *transcriber, [&](std::uint64_t done, std::uint64_t total) {
            if (fraction && total > 0) fraction(static_cast<double>(done) / static_cast<double>(total));
        });
    progress.finish();
    reportSkipped(result);

    if (!o.map.empty()) {
        std::vector<std::string> phonemes;
        for (const auto& [phoneme, count] : result.counts.entries) phonemes.push_back(phoneme);
        checkMapCovers(map, phonemes, o.map);
    }
    if (!o.quiet) {
        std::printf("%s", formatPhonemeTableText(result.counts).c_str());
        std::printf("%llu phonemes in %llu bytes of text (%s, voice %s)\n",
                    static_cast<unsigned long long>(result.phonemeTotal),
                    static_cast<unsigned long long>(result.corpus.bytes),
                    result.notation == PhonemeNotation::Arpabet ? "ARPAbet" : "IPA", o.voice.c_str());
    }
    if (!out.empty()) {
        const PhonemeTableInfo info{o.voice, std::filesystem::path(o.corpus).filename().string()};
        savePhonemeTable(out, result.counts, info, o.map.empty() ? nullptr : &map);
        std::fprintf(stderr, "Wrote %s\n", out.string().c_str());
    }
    return kExitOk;
}

} // namespace

void addFreqCommand(CLI::App& app, CommandRunner& run) {
    auto options = std::make_shared<FreqOptions>();
    auto* cmd = app.add_subcommand("freq", "Phoneme frequencies of a text corpus (espeak-ng transcription)");
    cmd->add_option("corpus", options->corpus, "UTF-8 text file of any length")->required();
    cmd->add_option("--voice", options->voice,
                    "espeak-ng voice: en-us (default), en-gb, ... give ARPAbet; "
                    "other languages (de, fr, ...) give IPA symbols");
    cmd->add_option("--out", options->out,
                    "Write the table: table.csv (phoneme,count,frequency,ipa) or "
                    "table.json (with --map: usable as reduce --freq-file)");
    cmd->add_option("--map", options->map,
                    "Phoneme -> viseme map to check and store with a .json table "
                    "(e.g. assets/phonemes/map_oculus.csv)");
    cmd->add_flag("--quiet", options->quiet, "Do not print the table");
    cmd->callback([options, &run] { run = [options] { return runFreq(*options); }; });
}

} // namespace vl::cli
