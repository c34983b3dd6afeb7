#include "warm_up.hpp"

#include "exec/executor.hpp"
#include "vk/context.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <iostream>
#include <spawn.h>
#include <string_view>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace pl::lab {

std::unique_ptr<WarmUpServer> WarmUpServer::start(const std::string& device, std::string& error) {
    int in[2], out[2];
    if (pipe2(in, O_CLOEXEC) != 0) return error = std::string("pipe: ") + std::strerror(errno), nullptr;
    if (pipe2(out, O_CLOEXEC) != 0) {
        close(in[0]), close(in[1]);
        return error = std::string("pipe: ") + std::strerror(errno), nullptr;
    }
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_adddup2(&fa, in[0], STDIN_FILENO);
    posix_spawn_file_actions_adddup2(&fa, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_addopen(&fa, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    std::vector<std::string> args = {"passlab", "warm-up-server"};
    if (!device.empty()) args.insert(args.end(), {"--device", device});
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    const int rc = posix_spawn(&pid, "/proc/self/exe", &fa, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    close(in[0]);
    close(out[1]);
    if (rc != 0) {
        close(in[1]), close(out[0]);
        error = std::string("cannot start the warm-up process: ") + std::strerror(rc);
        return nullptr;
    }
    // A write to a server that died must fail with EPIPE, not end the lab.
    std::signal(SIGPIPE, SIG_IGN);
    fcntl(out[0], F_SETFL, fcntl(out[0], F_GETFL) | O_NONBLOCK);
    std::unique_ptr<WarmUpServer> s(new WarmUpServer());
    s->pid_ = pid;
    s->to_ = in[1];
    s->from_ = out[0];
    return s;
}

WarmUpServer::~WarmUpServer() {
    if (to_ >= 0) close(to_);  // end of its input: it leaves after the job in hand
    if (pid_ > 0) {
        // It may be inside a runaway shader, which no driver call can stop: a short grace, then kill.
        for (int i = 0; i < 30 && waitpid(pid_, nullptr, WNOHANG) == 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
        if (waitpid(pid_, nullptr, WNOHANG) == 0) {
            kill(pid_, SIGKILL);
            waitpid(pid_, nullptr, 0);
        }
    }
    if (from_ >= 0) close(from_);
}

bool WarmUpServer::send(const std::filesystem::path& toml, const exec::BuildOptions& bo) {
    if (pid_ <= 0 || waiting_) return false;
    nlohmann::json job = {{"toml", toml.string()}, {"set", bo.set}, {"cache_dir", bo.cache_dir.string()}};
    if (bo.size) job["size"] = {(*bo.size)[0], (*bo.size)[1]};
    std::vector<std::string> overlays;
    for (const auto& d : bo.overlay_dirs) overlays.push_back(d.string());
    job["overlays"] = overlays;
    const std::string line = job.dump() + "\n";
    if (write(to_, line.data(), line.size()) != static_cast<ssize_t>(line.size())) {
        pid_ = waitpid(pid_, nullptr, WNOHANG) == pid_ ? -1 : pid_;
        return false;
    }
    waiting_ = true;
    return true;
}

std::optional<std::string> WarmUpServer::poll() {
    if (from_ < 0) return std::nullopt;
    char buf[4096];
    for (;;) {
        const ssize_t n = read(from_, buf, sizeof buf);
        if (n > 0) {
            partial_.append(buf, static_cast<size_t>(n));
            continue;
        }
        if (n == 0) {  // it ended (a hang it reported, or a crash): no more warm-ups
            close(from_);
            from_ = -1;
            if (pid_ > 0 && waitpid(pid_, nullptr, WNOHANG) == pid_) pid_ = -1;
        }
        break;
    }
    const auto nl = partial_.find('\n');
    if (nl == std::string::npos) return std::nullopt;
    std::string line = partial_.substr(0, nl);
    partial_.erase(0, nl + 1);
    waiting_ = false;
    return line;
}

std::set<std::string> warm_up_passes(const exec::CompiledGraph& g, std::map<std::string, size_t>& previous) {
    std::vector<std::string> changed;
    for (size_t i : g.order) {
        const exec::CompiledPass& cp = g.passes[i];
        if (cp.program.stages.empty()) continue;  // transfer kinds have no pipeline
        std::string bytes = std::to_string(static_cast<int>(cp.desc->kind));
        for (const auto& st : cp.program.stages)
            bytes.append(reinterpret_cast<const char*>(st.words.data()), st.words.size() * sizeof(uint32_t));
        const size_t h = std::hash<std::string_view>{}(bytes);
        auto [it, inserted] = previous.try_emplace(cp.desc->name, h);
        if (inserted || it->second != h) changed.push_back(cp.desc->name);
        it->second = h;
    }
    // The later half, rounded down: the lab's own half also pays for its executor's creation.
    return {changed.end() - static_cast<std::ptrdiff_t>(changed.size() / 2), changed.end()};
}

namespace {

// Only `keep` runs: every other pass is disabled, whatever its `enabled` says.
void keep_only(exec::CompiledGraph& g, const std::set<std::string>& keep) {
    for (auto& pd : g.desc.passes)
        if (!keep.count(pd.name)) {
            pd.enabled = false;
            pd.enabled_when = {};
        }
}

void answer(const nlohmann::json& j) {
    std::cout << j.dump() << std::endl;  // endl: the lab reads line by line
}

} // namespace

int warm_up_server(const std::string& device) {
    // Never outlive the lab, and never count in its simulated device losses (a test's N-th wait).
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    unsetenv("PASSLAB_SIMULATE_DEVICE_LOST");
    vk::ContextOptions co;
    co.verbose = false;
    co.device = device;
    auto ctx = vk::Context::create(co);
    std::map<std::string, size_t> previous;
    std::string line;
    while (std::getline(std::cin, line)) {
        const auto t0 = std::chrono::steady_clock::now();
        auto ms = [&] { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count(); };
        if (!ctx) {
            answer({{"ms", 0}, {"passes", nlohmann::json::array()}, {"error", ctx.error().message}});
            continue;
        }
        nlohmann::json job = nlohmann::json::parse(line, nullptr, false);
        if (job.is_discarded() || !job.contains("toml")) {
            answer({{"ms", 0}, {"passes", nlohmann::json::array()}, {"error", "not a job: " + line}});
            continue;
        }
        exec::BuildOptions bo;
        if (job.contains("size")) bo.size = std::array<int, 2>{job["size"][0].get<int>(), job["size"][1].get<int>()};
        bo.set = job.value("set", std::vector<std::string>{});
        bo.cache_dir = job.value("cache_dir", std::string());
        for (const auto& d : job.value("overlays", std::vector<std::string>{})) bo.overlay_dirs.push_back(d);
        auto g = exec::build_graph(job["toml"].get<std::string>(), bo);
        if (!g) {  // the lab reports the error itself
            answer({{"ms", ms()}, {"passes", nlohmann::json::array()}, {"error", g.error().message}});
            continue;
        }
        const auto names = warm_up_passes(*g, previous);
        nlohmann::json done = {{"passes", names}, {"error", ""}};
        if (!names.empty()) {
            keep_only(*g, names);
            auto ex = exec::Executor::create(**ctx, std::move(g.value()));
            if (!ex) done["error"] = ex.error().message;
            else {
                (*ex)->set_timestamps(false);
                if (auto s = (*ex)->render(exec::FrameInput{}); !s) done["error"] = s.error().message;
                if ((*ctx)->hung()) {
                    // A runaway shader: nothing on this device can be waited for; the lab's own
                    // watchdog reports it. Leave without destroying anything.
                    done["ms"] = ms();
                    answer(done);
                    std::_Exit(3);
                }
            }
        }
        done["ms"] = ms();
        answer(done);
    }
    return 0;
}

} // namespace pl::lab
