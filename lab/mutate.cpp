// `passlab mutate PRESET...`: can the preset's tests fail?
//
// Applies single-token mutations (mutate/mutants.hpp) to the preset's own shaders (and, with
// --library, to the passes/ files it reads), one at a time, and runs the preset's [[test]] cases
// on each in a fresh `passlab test --exercise` process, the mutated file in a scratch folder
// whose files shadow the preset's (the course-exercise mechanism). The user's files are never
// written. Per mutant it reports which case killed it and how: by an invariant (a probe or a
// check), by a golden alone, by the validation layer or a runaway, or not at all (a survivor,
// printed with file:line and the changed line). A mutant that does not compile is stillborn and
// does not count. Goldens are regression guards: a mutant that only a golden kills shows an
// invariant missing.
#include "child.hpp"
#include "verbs.hpp"

#include "mutate/mutants.hpp"
#include "util/paths.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace pl::lab {
namespace {

enum class Outcome { invariant, golden, runaway, other, survived, stillborn };

const char* outcome_name(Outcome o) {
    switch (o) {
    case Outcome::invariant: return "killed/invariant";
    case Outcome::golden: return "killed/golden-only";
    case Outcome::runaway: return "killed/runaway";
    case Outcome::other: return "killed/other";
    case Outcome::survived: return "SURVIVED";
    case Outcome::stillborn: return "stillborn";
    }
    return "?";
}

struct Verdict {
    Outcome outcome = Outcome::survived;
    std::vector<std::string> killers;  // cases that failed (for invariant kills: those with a failed check)
    std::string note;                  // first line of a build error, the runaway message ...
};

// The failed cases of a `passlab test` run, read from its output (lab/test.cpp's format: a
// "PASS|FAIL where: case (N ms)" line, then indented "FAIL what: detail" lines per failed check,
// "validation: ..." lines, and error text).
Verdict classify(const ChildResult& r, const std::string& mutated_file) {
    Verdict v;
    if (r.timed_out) return v.outcome = Outcome::runaway, v.note = "the test run exceeded its time limit", v;
    struct Case {
        std::string name;
        bool failed = false, golden = false, invariant = false, validation = false;
        std::string error;
    };
    std::vector<Case> cases;
    bool runaway = false;
    std::istringstream in(r.output);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("PASS ", 0) == 0 || line.rfind("FAIL ", 0) == 0) {
            Case c;
            c.failed = line[0] == 'F';
            size_t colon = line.find(": "), paren = line.rfind(" (");
            c.name = colon != std::string::npos && paren != std::string::npos && paren > colon
                         ? line.substr(colon + 2, paren - colon - 2) : line;
            cases.push_back(c);
            continue;
        }
        // test.cpp's last line when a device hung (its cases after the runaway ran on a fresh one).
        if (line.rfind("a runaway shader may still be running", 0) == 0) runaway = true;
        // test.cpp's closing summary (print_summary) follows every case: none of it is the last
        // case's error (it was read as one, so a golden-only kill of the last case was "other").
        if (line == "The following cases FAILED:" || line.rfind("goldens: ", 0) == 0) break;
        if (cases.empty()) continue;
        Case& c = cases.back();
        if (line.rfind("    FAIL golden", 0) == 0) c.golden = true;
        else if (line.rfind("    FAIL ", 0) == 0) c.invariant = true;
        else if (line.rfind("    validation:", 0) == 0) c.validation = true;
        else if (c.failed && !line.empty() && c.error.empty()) c.error = line;
    }
    for (const auto& c : cases) {
        // A compile error in the mutated file: the mutant is not a program.
        if (c.failed && c.error.find(mutated_file + ":") != std::string::npos && c.error.find("error") != std::string::npos)
            return v.outcome = Outcome::stillborn, v.note = c.error, v;
    }
    if (runaway) return v.outcome = Outcome::runaway, v.note = "a shader ran past the GPU time limit", v;
    for (const auto& c : cases)
        if (c.invariant) v.killers.push_back(c.name);
    if (!v.killers.empty()) return v.outcome = Outcome::invariant, v;
    for (const auto& c : cases)
        if (c.failed && (c.validation || !c.error.empty())) v.killers.push_back(c.name), v.note = c.error;
    if (!v.killers.empty()) {
        bool timeout = v.note.find("did not finish") != std::string::npos;
        return v.outcome = timeout ? Outcome::runaway : Outcome::other, v;
    }
    for (const auto& c : cases)
        if (c.golden) v.killers.push_back(c.name);
    if (!v.killers.empty()) return v.outcome = Outcome::golden, v;
    if (r.signal) return v.outcome = Outcome::other, v.note = std::string("passlab test crashed twice (") + strsignal(r.signal) + ")", v;
    if (r.exit_code != 0) return v.outcome = Outcome::other, v.note = "passlab test exited " + std::to_string(r.exit_code), v;
    return v;
}

// Runs a `passlab test` child; one that a signal ended (a crash, in the driver as often as not)
// runs once more: a crash that does not repeat says nothing about the mutant (two runs that
// shared the machine with other jobs each saw one, and the next presets' baselines then failed),
// and one that does repeat is reported as the crash it is.
ChildResult run_test_child(const std::vector<std::string>& args, double timeout_s) {
    ChildResult r = run_self(args, timeout_s);
    if (r.signal) r = run_self(args, timeout_s);
    return r;
}

struct Source {
    fs::path path;  // the real file
    fs::path rel;   // its name as an overlay sees it: relative to the preset, or to passes/
    std::string display;
    std::string text;
};

struct Tally {
    int total = 0, stillborn = 0, invariant = 0, golden = 0, runaway = 0, other = 0, survived = 0;
    void add(Outcome o) {
        ++total;
        switch (o) {
        case Outcome::invariant: ++invariant; break;
        case Outcome::golden: ++golden; break;
        case Outcome::runaway: ++runaway; break;
        case Outcome::other: ++other; break;
        case Outcome::survived: ++survived; break;
        case Outcome::stillborn: ++stillborn; break;
        }
    }
    int killed() const { return invariant + golden + runaway + other; }
    Tally& operator+=(const Tally& t) {
        total += t.total, stillborn += t.stillborn, invariant += t.invariant, golden += t.golden;
        runaway += t.runaway, other += t.other, survived += t.survived;
        return *this;
    }
    void print(const char* label) const {
        std::printf("%s: %d mutants, %d stillborn; of %d that compile: killed %d (invariants %d, goldens only %d, "
                    "runaway %d, other %d), survived %d",
                    label, total, stillborn, total - stillborn, killed(), invariant, golden, runaway, other, survived);
        if (killed()) std::printf("; invariants kill %.0f%% of the killed", 100.0 * invariant / killed());
        std::printf("\n");
    }
};

// A child's failure images go to the scratch folder, never to ./test-failures.
std::vector<std::string> test_args(const fs::path& toml, const CommonOptions& c, const fs::path& scratch) {
    std::vector<std::string> a{"test", toml.parent_path().string(), "--timeout", std::to_string(c.timeout_s),
                               "--fail-dir", (scratch / "failures").string()};
    if (!c.device.empty()) a.insert(a.end(), {"--device", c.device});
    return a;
}

} // namespace

int mutate(const MutateOptions& o, const CommonOptions& c) {
    if (o.targets.empty()) {
        Error e = make_error("passlab mutate: name at least one preset");
        e.code = ExitCode::usage;
        return report(e);
    }
    std::vector<fs::path> presets;
    for (const auto& a : o.targets) {
        auto found = collect_presets(a);
        if (!found) return report(found.error());
        presets.insert(presets.end(), found->begin(), found->end());
    }
    std::error_code ec;
    // A fresh private folder (mkdtemp), never a predictable name another process could own.
    std::string tmpl = (fs::temp_directory_path(ec) / "passlab-mutate-XXXXXX").string();
    if (!mkdtemp(tmpl.data())) {
        Error e = make_error("passlab mutate: cannot create a scratch folder in " + fs::temp_directory_path(ec).string());
        e.code = ExitCode::environment;
        return report(e);
    }
    const fs::path scratch_root = tmpl;
    nlohmann::json log = nlohmann::json::array();
    Tally all;
    int baseline_failures = 0;
    for (const auto& toml : presets) {
        const fs::path dir = toml.parent_path();
        const std::string where = fs::proximate(dir, ec).string();
        // The baseline: every case must pass unmutated, or a kill would mean nothing.
        auto base = run_test_child(test_args(toml, c, scratch_root / "baseline"), o.child_timeout_s);
        fs::remove_all(scratch_root / "baseline", ec);
        if (base.exit_code != 0) {
            std::printf("mutate %s: skipped: its tests do not pass unmutated (exit %d%s%s); `passlab test %s` says:\n%s",
                        where.c_str(), base.exit_code, base.timed_out ? ", timed out" : "",
                        base.signal ? (std::string(", crashed twice: ") + strsignal(base.signal)).c_str() : "", where.c_str(),
                        base.output.c_str());
            ++baseline_failures;
            continue;
        }
        exec::BuildOptions bo;
        bo.cache_dir = cache_dir(c);
        auto built = exec::build_graph(toml, bo);
        if (!built) return report(built.error());
        std::vector<Source> sources;
        const fs::path lib = exec::passes_dir();
        for (const auto& dep : built->dependencies) {
            if (!is_shader_file(dep)) continue;
            Source s;
            s.path = dep;
            if (auto in_preset = path_within(dep, dir)) s.rel = *in_preset, s.display = s.rel.string();
            else if (auto in_lib = path_within(dep, lib); in_lib && o.library)
                s.rel = *in_lib, s.display = "passes/" + s.rel.string();
            else continue;
            std::ifstream f(dep, std::ios::binary);
            std::ostringstream ss;
            ss << f.rdbuf();
            s.text = ss.str();
            sources.push_back(std::move(s));
        }
        struct Candidate {
            size_t source;
            mutate::Mutant m;
        };
        std::vector<Candidate> pool;
        for (size_t i = 0; i < sources.size(); ++i)
            for (auto& m : mutate::find_mutants(sources[i].text)) pool.push_back({i, std::move(m)});
        size_t count = o.max > 0 ? std::min(pool.size(), static_cast<size_t>(o.max)) : pool.size();
        auto chosen = mutate::choose(pool.size(), count, o.seed);
        std::sort(chosen.begin(), chosen.end());  // pool order = file, then position: a readable report
        std::printf("mutate %s: %zu of %zu mutants in %zu file(s) (seed %llu)\n", where.c_str(), chosen.size(),
                    pool.size(), sources.size(), static_cast<unsigned long long>(o.seed));
        std::fflush(stdout);
        Tally tally;
        int k = 0;
        for (size_t idx : chosen) {
            const auto& cand = pool[idx];
            const Source& src = sources[cand.source];
            const fs::path scratch = scratch_root / std::to_string(k++);
            const fs::path file = scratch / "overlay" / src.rel;
            fs::create_directories(file.parent_path(), ec);
            {
                std::ofstream out(file, std::ios::binary);
                out << mutate::apply_mutant(src.text, cand.m);
                if (!out) {
                    Error e = make_error("passlab mutate: cannot write the scratch copy " + file.string());
                    e.code = ExitCode::environment;
                    fs::remove_all(scratch_root, ec);
                    return report(e);
                }
            }
            auto args = test_args(toml, c, scratch);
            args.insert(args.end(), {"--exercise", (scratch / "overlay").string()});
            auto r = run_test_child(args, o.child_timeout_s);
            fs::remove_all(scratch, ec);
            Verdict v = classify(r, src.rel.filename().string());
            tally.add(v.outcome);
            const std::string at = src.display + ":" + std::to_string(cand.m.line) + ":" + std::to_string(cand.m.col);
            std::printf("  %-18s %s  %s", outcome_name(v.outcome), at.c_str(), cand.m.op.c_str());
            if (!v.killers.empty()) {
                std::printf("  by %s", v.killers[0].c_str());
                if (v.killers.size() > 1) std::printf(" (+%zu)", v.killers.size() - 1);
            }
            std::printf("\n");
            if (v.outcome == Outcome::survived || o.verbose) {
                std::printf("      - %s\n      + %s\n", mutate::line_of(src.text, cand.m).c_str(),
                            mutate::mutated_line_of(src.text, cand.m).c_str());
            }
            if (o.verbose && !v.note.empty()) std::printf("      (%s)\n", v.note.c_str());
            std::fflush(stdout);
            log.push_back({{"preset", where}, {"file", src.display}, {"line", cand.m.line}, {"col", cand.m.col},
                           {"op", cand.m.op}, {"outcome", outcome_name(v.outcome)}, {"killed_by", v.killers},
                           {"before", mutate::line_of(src.text, cand.m)},
                           {"after", mutate::mutated_line_of(src.text, cand.m)}, {"note", v.note}});
        }
        tally.print(("  " + where).c_str());
        all += tally;
    }
    fs::remove_all(scratch_root, ec);
    if (presets.size() > 1) all.print("all");
    if (!o.json.empty()) {
        std::ofstream out(o.json);
        out << log.dump(2) << "\n";
        if (!out) {
            Error e = make_error("passlab mutate: cannot write " + o.json);
            e.code = ExitCode::environment;
            return report(e);
        }
        std::printf("json: %s\n", o.json.c_str());
    }
    if (baseline_failures) return 1;
    return all.survived ? 1 : 0;
}

} // namespace pl::lab
