// Machine-readable results of `passlab test`: JSON (--json FILE, also how -j workers hand their
// results to the parent) and JUnit XML (--junit FILE) as GitLab, Jenkins and GitHub reporters
// read it. All JSON goes through nlohmann-json.
#pragma once

#include "report.hpp"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace pl::lab {

struct RunSummary {
    std::vector<ReportEntry> entries;
    std::string device;
    double ms = 0.0;
};

struct Counts {
    int passed = 0, failed = 0, skipped = 0;
    int goldens_written = 0, goldens_rewritten = 0;
};
Counts count(const std::vector<ReportEntry>& entries);

nlohmann::ordered_json to_json(const RunSummary& s);
Result<RunSummary> run_summary_from_json(const nlohmann::ordered_json& j);

// Write FILE (folders must exist; errors are environment errors, exit 3).
Status write_json_file(const std::filesystem::path& file, const nlohmann::ordered_json& j);
Status write_junit(const std::filesystem::path& file, const RunSummary& s);

} // namespace pl::lab
