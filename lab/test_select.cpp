#include "test_select.hpp"

#include "exec/build.hpp"
#include "verbs.hpp"
#include "graph/parse.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fnmatch.h>
#include <fstream>

#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace pl::lab {

namespace {

Error usage(const std::string& msg) {
    Error e = make_error(msg);
    e.code = ExitCode::usage;
    return e;
}

// A sub-path unique per preset folder: relative to the cwd when below it, as the case lines
// print it (so presets/aa/msaa and tests/graphs/msaa differ), else relative to the repository
// root, else the absolute path; ".." components cannot climb out of the output folder.
fs::path output_stem(const fs::path& dir) {
    std::error_code ec;
    const fs::path d = fs::weakly_canonical(dir, ec);
    for (const fs::path& base : {fs::current_path(ec), fs::weakly_canonical(exec::presets_dir().parent_path(), ec)}) {
        fs::path rel = d.lexically_relative(base);
        if (!rel.empty() && rel != "." && *rel.begin() != "..") return rel;
    }
    fs::path out;
    for (const auto& part : d.relative_path()) out /= part == ".." ? fs::path("_") : part;
    return out;
}

bool is_glob(const std::string& p) { return p.find_first_of("*?[") != std::string::npos; }

} // namespace

TestUnit make_unit(const fs::path& toml) {
    TestUnit u;
    u.toml = toml;
    u.where = fs::proximate(toml.parent_path()).string();
    u.stem = output_stem(toml.parent_path());
    auto desc = graph::parse_graph_file(toml);
    if (!desc) u.parse_failed = true;
    else
        for (const auto& t : desc->tests) u.all_cases.push_back(t.name);
    return u;
}

Status write_plan(const fs::path& file, const std::vector<TestUnit>& units) {
    nlohmann::ordered_json plan = nlohmann::ordered_json::array();
    for (const auto& u : units) {
        nlohmann::ordered_json j = {{"toml", u.toml.string()}};
        if (u.cases) j["cases"] = std::vector<std::string>(u.cases->begin(), u.cases->end());
        plan.push_back(j);
    }
    std::ofstream out(file, std::ios::trunc);
    out << plan.dump();
    out.close();
    if (!out) {
        Error e = make_error("cannot write " + file.string());
        e.code = ExitCode::environment;
        return e;
    }
    return ok_status();
}

Result<std::vector<TestUnit>> read_plan(const fs::path& file) {
    std::ifstream in(file);
    auto plan = nlohmann::ordered_json::parse(in, nullptr, false);
    if (plan.is_discarded() || !plan.is_array()) return make_error("malformed worker plan " + file.string());
    std::vector<TestUnit> units;
    for (const auto& j : plan) {
        if (!j.contains("toml") || !j["toml"].is_string()) return make_error("malformed worker plan " + file.string());
        TestUnit u = make_unit(j["toml"].get<std::string>());
        if (j.contains("cases")) u.cases = j["cases"].get<std::set<std::string>>();
        units.push_back(std::move(u));
    }
    return units;
}

Result<Shard> parse_shard(const std::string& s) {
    int k = 0, n = 0;
    char slash = 0, extra = 0;
    if (std::sscanf(s.c_str(), "%d%c%d%c", &k, &slash, &n, &extra) != 3 || slash != '/' || n < 1 || k < 1 || k > n)
        return usage("--shard expects K/N with 1 <= K <= N (e.g. 2/4), got '" + s + "'");
    return Shard{k - 1, n};
}

Result<Shard> shard_from(const std::string& flag) {
    if (const char* status = std::getenv("TEST_SHARD_STATUS_FILE"); status && *status) {
        std::ofstream touch(status, std::ios::app);  // "this runner shards" (Bazel's protocol)
    }
    if (!flag.empty()) return parse_shard(flag);
    const char* total = std::getenv("TEST_TOTAL_SHARDS");
    const char* index = std::getenv("TEST_SHARD_INDEX");
    if (!total || !*total) return Shard{};
    char* end = nullptr;
    long n = std::strtol(total, &end, 10);
    long i = index ? std::strtol(index, nullptr, 10) : -1;
    if (*end || n < 1 || i < 0 || i >= n)
        return usage("TEST_TOTAL_SHARDS=" + std::string(total) + " TEST_SHARD_INDEX=" + (index ? index : "(unset)") +
                     ": expected 0 <= index < total");
    return Shard{static_cast<int>(i), static_cast<int>(n)};
}

Result<std::vector<TestUnit>> collect_units(const std::vector<std::string>& targets) {
    std::vector<TestUnit> out;
    for (const auto& arg : targets) {
        auto tomls = collect_presets(arg);
        if (!tomls) return tomls.error();
        for (const auto& t : *tomls) out.push_back(make_unit(t));
    }
    return out;
}

Status select_cases(std::vector<TestUnit>& units, const std::vector<std::string>& patterns) {
    if (patterns.empty()) return ok_status();
    std::vector<std::string> every;
    for (const auto& u : units) every.insert(every.end(), u.all_cases.begin(), u.all_cases.end());
    bool some_unknown = std::any_of(units.begin(), units.end(), [](const TestUnit& u) { return u.parse_failed; });
    for (const auto& p : patterns)
        if (!is_glob(p) && std::find(every.begin(), every.end(), p) == every.end() && !some_unknown) {
            Error e = usage("--case " + p + ": no [[test]] of the selected presets is named '" + p + "'");
            std::sort(every.begin(), every.end());
            every.erase(std::unique(every.begin(), every.end()), every.end());
            suggest(e, p, every, every.size() <= 40 ? "cases" : "");
            return e;
        }
    for (auto& u : units) {
        std::set<std::string> chosen;
        for (const auto& name : u.all_cases)
            for (const auto& p : patterns)
                if (is_glob(p) ? fnmatch(p.c_str(), name.c_str(), 0) == 0 : p == name) chosen.insert(name);
        u.cases = chosen;
    }
    return ok_status();
}

void select_shard(std::vector<TestUnit>& units, const Shard& s) {
    if (s.total <= 1) return;
    size_t i = 0;
    for (auto& u : units) {
        if (u.parse_failed) {
            // One item: the build error is reported by exactly one shard.
            if (i++ % static_cast<size_t>(s.total) != static_cast<size_t>(s.index)) u.cases = std::set<std::string>{}, u.parse_failed = false;
            continue;
        }
        std::set<std::string> chosen;
        for (const auto& name : u.all_cases) {
            if (u.cases && !u.cases->count(name)) continue;
            if (i++ % static_cast<size_t>(s.total) == static_cast<size_t>(s.index)) chosen.insert(name);
        }
        u.cases = chosen;
    }
}

size_t selected_count(const std::vector<TestUnit>& units) {
    size_t n = 0;
    for (const auto& u : units) n += u.selected();
    return n;
}

} // namespace pl::lab
