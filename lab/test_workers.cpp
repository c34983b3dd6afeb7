#include "test_workers.hpp"
#include "results.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <optional>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace fs = std::filesystem;

namespace pl::lab {

int default_jobs() {
    unsigned n = std::thread::hardware_concurrency();
    return n ? static_cast<int>(n) : 1;
}

namespace {

Result<pid_t> spawn(const std::vector<std::string>& argv, const fs::path& out) {
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&fa, STDOUT_FILENO, STDERR_FILENO);
    std::vector<char*> cargv;
    for (const auto& a : argv) cargv.push_back(const_cast<char*>(a.c_str()));
    cargv.push_back(nullptr);
    pid_t pid = 0;
    // /proc/self/exe is this very executable even when a rebuild replaced the file meanwhile.
    int rc = posix_spawn(&pid, "/proc/self/exe", &fa, nullptr, cargv.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0) {
        Error e = make_error("cannot start a test worker (" + argv[0] + "): " + std::strerror(rc));
        e.code = ExitCode::environment;
        return e;
    }
    return pid;
}

} // namespace

Result<RunSummary> run_in_workers(const std::vector<TestUnit>& units, int jobs, const std::vector<std::string>& args) {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return make_error("cannot find the passlab executable (/proc/self/exe): " + ec.message());
    std::string tmpl = (fs::temp_directory_path(ec) / "passlab-test-XXXXXX").string();
    if (!mkdtemp(tmpl.data())) {
        Error e = make_error("cannot create a folder for the test workers in " + fs::temp_directory_path(ec).string());
        e.code = ExitCode::environment;
        return e;
    }
    const fs::path tmp = tmpl;
    // The workers are one shard's share already: they must not shard again.
    unsetenv("TEST_TOTAL_SHARDS");
    unsetenv("TEST_SHARD_INDEX");
    unsetenv("TEST_SHARD_STATUS_FILE");

    // One worker per job, each with a share of the presets balanced by case count (largest
    // first to the least loaded): a device and the validation layer start once per worker,
    // which costs about as much as a small preset's cases.
    std::vector<std::vector<size_t>> bins(static_cast<size_t>(jobs));
    std::vector<size_t> load(bins.size(), 0), order(units.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return units[a].selected() > units[b].selected(); });
    for (size_t i : order) {
        size_t k = static_cast<size_t>(std::min_element(load.begin(), load.end()) - load.begin());
        bins[k].push_back(i);
        load[k] += units[i].selected();
    }

    struct Worker {
        std::vector<size_t> units;
        fs::path out, json;
        std::ifstream tail;  // the output printed so far
        bool done = false;
    };
    std::vector<Worker> workers(bins.size());
    std::map<pid_t, size_t> running;
    for (size_t k = 0; k < bins.size(); ++k) {
        if (bins[k].empty()) continue;
        std::sort(bins[k].begin(), bins[k].end());
        Worker& w = workers[k];
        w.units = bins[k];
        w.out = tmp / (std::to_string(k) + ".out");
        w.json = tmp / (std::to_string(k) + ".json");
        std::vector<TestUnit> share;
        for (size_t i : w.units) share.push_back(units[i]);
        const fs::path plan = tmp / (std::to_string(k) + ".plan.json");
        if (auto s = write_plan(plan, share); !s) return s.error();
        std::vector<std::string> argv = {self.string(), "test", "-j", "1", "--worker-plan", plan.string(), "--worker-json", w.json.string()};
        argv.insert(argv.end(), args.begin(), args.end());
        auto pid = spawn(argv, w.out);
        if (!pid) return pid.error();
        running[*pid] = k;
        w.tail.open(w.out, std::ios::binary);
    }
    // Stream each worker's output as it comes, whole lines only (a case's lines are flushed
    // together), so a long suite shows progress and cases do not interleave mid-line.
    auto pump = [](Worker& w, bool all) {
        if (!w.tail.is_open()) return;
        w.tail.clear();
        std::string chunk((std::istreambuf_iterator<char>(w.tail)), std::istreambuf_iterator<char>());
        size_t keep = all ? chunk.size() : chunk.rfind('\n') + 1;  // npos + 1 == 0: nothing whole yet
        std::fwrite(chunk.data(), 1, keep, stdout);
        w.tail.seekg(-static_cast<std::streamoff>(chunk.size() - keep), std::ios::cur);
        std::fflush(stdout);
    };
    std::vector<RunSummary> results(workers.size());
    while (!running.empty()) {
        int status = 0;
        pid_t pid = waitpid(-1, &status, WNOHANG);
        if (pid < 0) break;
        if (pid == 0) {
            for (auto& [p, k] : running) pump(workers[k], false);
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
            continue;
        }
        auto it = running.find(pid);
        if (it == running.end()) continue;
        Worker& w = workers[it->second];
        running.erase(it);
        pump(w, true);
        std::ifstream in(w.json);
        std::optional<RunSummary> got;
        if (in) {
            auto j = nlohmann::ordered_json::parse(in, nullptr, false);
            if (!j.is_discarded())
                if (auto s = run_summary_from_json(j)) got = std::move(s.value());
        }
        // A failed "(worker)" entry: how the worker ended, after `what`.
        auto worker_failure = [&](const std::string& what) {
            ReportEntry e;
            e.where = units[w.units.front()].where;
            e.result.name = "(worker)";
            e.result.error = "the test worker for " + std::to_string(w.units.size()) + " preset(s) from " + e.where + " " +
                             what + " " +
                             (WIFEXITED(status) ? "exit code " + std::to_string(WEXITSTATUS(status))
                                                : "signal " + std::to_string(WTERMSIG(status)));
            return e;
        };
        if (!got) {
            // The worker died (a crash, or it ended itself after a GPU hang): a failed case says
            // so, so the run cannot pass.
            RunSummary s;
            ReportEntry e = worker_failure("ended with");
            e.result.error += " without results (its output is above)\n";
            s.entries.push_back(e);
            got = std::move(s);
        } else if (!WIFEXITED(status) || WEXITSTATUS(status) != (count(got->entries).failed ? 1 : 0)) {
            // Results, then an exit that does not match them: a worker returns 1 when a case
            // failed and 0 otherwise, so anything else happened after its results were written,
            // e.g. a sanitizer's report at exit (AddressSanitizer exits 1 on a leak) or a crash in
            // teardown. The run cannot pass on that either.
            ReportEntry e = worker_failure("wrote its results, then ended with");
            e.result.error += " (its output is above)\n";
            got->entries.push_back(e);
        }
        results[static_cast<size_t>(&w - workers.data())] = std::move(*got);
    }
    // Merged in the order the presets were given, whatever worker ran them.
    RunSummary merged;
    std::map<std::string, size_t> rank;
    for (size_t i = 0; i < units.size(); ++i) rank.emplace(units[i].where, i);
    for (auto& r : results) {
        if (merged.device.empty()) merged.device = r.device;
        for (auto& e : r.entries) merged.entries.push_back(std::move(e));
    }
    std::stable_sort(merged.entries.begin(), merged.entries.end(), [&](const ReportEntry& a, const ReportEntry& b) {
        return rank[a.where] < rank[b.where];
    });
    fs::remove_all(tmp, ec);
    return merged;
}

} // namespace pl::lab
