// Which cases a `passlab test` run executes: the presets named on the command line, their
// [[test]] names (parsed, no shader compiled), `--case` names or glob patterns, and a shard
// (`--shard K/N`, or Bazel's / GoogleTest's TEST_TOTAL_SHARDS and TEST_SHARD_INDEX).
#pragma once

#include "util/error.hpp"

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace pl::lab {

struct TestUnit {
    std::filesystem::path toml;
    std::string where;                       // the folder as printed (relative to the cwd)
    std::filesystem::path stem;              // unique output sub-path (e.g. presets/aa/msaa)
    std::vector<std::string> all_cases;      // every [[test]] name, in file order
    bool parse_failed = false;               // its cases are unknown: it runs to report the error
    std::optional<std::set<std::string>> cases;  // the selection; unset = all
    size_t selected() const { return parse_failed ? 1 : cases ? cases->size() : all_cases.size(); }
};

struct Shard {
    int index = 0, total = 1;  // 0-based index
};
// "K/N" with 1 <= K <= N; errors are usage errors.
Result<Shard> parse_shard(const std::string& s);
// --shard wins; otherwise TEST_TOTAL_SHARDS / TEST_SHARD_INDEX; TEST_SHARD_STATUS_FILE is
// touched to tell the engine that sharding is supported.
Result<Shard> shard_from(const std::string& flag);

// One preset, parsed for its case names.
TestUnit make_unit(const std::filesystem::path& toml);
// A -j worker's share: the presets and their selected cases, as a JSON file.
Status write_plan(const std::filesystem::path& file, const std::vector<TestUnit>& units);
Result<std::vector<TestUnit>> read_plan(const std::filesystem::path& file);

// Every preset.toml under the targets (preset folders, .toml files, names, trees), parsed.
Result<std::vector<TestUnit>> collect_units(const std::vector<std::string>& targets);
// Applies --case (exact names or globs with * ? [..]); an exact name no preset has is a usage
// error with "did you mean".
Status select_cases(std::vector<TestUnit>& units, const std::vector<std::string>& patterns);
// Keeps every total-th case from index (the flat order of all selected cases).
void select_shard(std::vector<TestUnit>& units, const Shard& s);
size_t selected_count(const std::vector<TestUnit>& units);

} // namespace pl::lab
