#include "core/batch/BatchResume.h"

#include "core/common/ContentHash.h"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

namespace vl::batch {

namespace {
constexpr const char* kStampHeader = "visemelab batch job 1";
}

std::filesystem::path stampPath(const std::filesystem::path& outFolder, const BatchJob& job) {
    return outFolder / ".visemelab-batch" / (job.id + ".done");
}

std::string formatStamp(const BatchJob& job, const std::vector<std::filesystem::path>& inputs) {
    std::string text = std::string(kStampHeader) + "\njob " + hashHex(job.hash) + "\n";
    for (const std::string& output : job.outputs()) text += "output " + output + "\n";
    std::set<std::string> seen;
    for (const auto& input : inputs) {
        std::error_code ec;
        const std::string absolute = std::filesystem::absolute(input, ec).lexically_normal().string();
        if (seen.insert(absolute).second) text += "input " + absolute + "\n";
    }
    return text;
}

bool jobIsDone(const std::filesystem::path& outFolder, const BatchJob& job) {
    std::ifstream in(stampPath(outFolder, job), std::ios::binary);
    if (!in) return false;
    std::string line;
    if (!std::getline(in, line) || line != kStampHeader) return false;
    if (!std::getline(in, line) || line != "job " + hashHex(job.hash)) return false;
    std::vector<std::string> outputs, inputs;
    while (std::getline(in, line)) {
        if (line.starts_with("output "))
            outputs.push_back(line.substr(7));
        else if (line.starts_with("input "))
            inputs.push_back(line.substr(6));
        else
            return false;
    }
    if (outputs != job.outputs()) return false;
    std::error_code ec;
    std::filesystem::file_time_type oldest = std::filesystem::file_time_type::max();
    for (const std::string& output : outputs) {
        const auto path = outFolder / output;
        if (!std::filesystem::is_regular_file(path, ec)) return false;
        const auto time = std::filesystem::last_write_time(path, ec);
        if (ec) return false;
        oldest = std::min(oldest, time);
    }
    for (const std::string& input : inputs) {
        const auto time = std::filesystem::last_write_time(input, ec);
        if (ec || time > oldest) return false;
    }
    return true;
}

} // namespace vl::batch
