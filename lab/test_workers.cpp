#include "test_workers.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
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

struct Running {
    size_t unit;
    fs::path out, json;
};

std::string slurp(const fs::path& f) {
    std::ifstream in(f, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

Result<pid_t> spawn(const std::vector<std::string>& argv, const fs::path& out) {
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&fa, STDOUT_FILENO, STDERR_FILENO);
    std::vector<char*> cargv;
    for (const auto& a : argv) cargv.push_back(const_cast<char*>(a.c_str()));
    cargv.push_back(nullptr);
    pid_t pid = 0;
    int rc = posix_spawn(&pid, argv[0].c_str(), &fa, nullptr, cargv.data(), environ);
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

    std::vector<std::optional<RunSummary>> results(units.size());
    std::map<pid_t, Running> running;
    size_t next = 0;
    RunSummary merged;
    auto start_one = [&](size_t i) -> Status {
        const TestUnit& u = units[i];
        Running r{i, tmp / (std::to_string(i) + ".out"), tmp / (std::to_string(i) + ".json")};
        std::vector<std::string> argv = {self.string(), "test", u.toml.string(), "-j", "1", "--worker-json", r.json.string()};
        argv.insert(argv.end(), args.begin(), args.end());
        if (u.cases)
            for (const auto& c : *u.cases) argv.insert(argv.end(), {"--case", c});
        auto pid = spawn(argv, r.out);
        if (!pid) return pid.error();
        running[*pid] = r;
        return ok_status();
    };
    auto finish = [&](const Running& r, int status) {
        std::fputs(slurp(r.out).c_str(), stdout);
        std::fflush(stdout);
        std::ifstream in(r.json);
        std::optional<RunSummary> got;
        if (in) {
            auto j = nlohmann::ordered_json::parse(in, nullptr, false);
            if (!j.is_discarded())
                if (auto s = run_summary_from_json(j)) got = std::move(s.value());
        }
        if (!got) {
            // The worker died (a crash, or it ended itself after a GPU hang): one failed case
            // says so, so the run cannot pass.
            RunSummary s;
            ReportEntry e;
            e.where = units[r.unit].where;
            e.result.name = "(worker)";
            e.result.error = "the test worker for " + units[r.unit].where + " ended with " +
                             (WIFEXITED(status) ? "exit code " + std::to_string(WEXITSTATUS(status))
                                                : "signal " + std::to_string(WTERMSIG(status))) +
                             " without results (its output is above)\n";
            s.entries.push_back(e);
            got = std::move(s);
        }
        results[r.unit] = std::move(got);
    };
    while (next < units.size() || !running.empty()) {
        while (next < units.size() && static_cast<int>(running.size()) < jobs)
            if (auto s = start_one(next++); !s) return s.error();
        int status = 0;
        pid_t pid = waitpid(-1, &status, 0);
        if (pid < 0) break;
        auto it = running.find(pid);
        if (it == running.end()) continue;
        Running r = it->second;
        running.erase(it);
        finish(r, status);
    }
    for (auto& r : results) {
        if (!r) continue;
        if (merged.device.empty()) merged.device = r->device;
        for (auto& e : r->entries) merged.entries.push_back(std::move(e));
    }
    fs::remove_all(tmp, ec);
    return merged;
}

} // namespace pl::lab
