#include "child.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

namespace pl::lab {

std::string find_on_path(const std::string& name) {
    if (name.find('/') != std::string::npos) return access(name.c_str(), X_OK) == 0 ? name : std::string();
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/bin:/bin";
    for (size_t start = 0; start <= dirs.size();) {
        size_t end = dirs.find(':', start);
        if (end == std::string::npos) end = dirs.size();
        std::string dir = dirs.substr(start, end - start);
        std::string full = (dir.empty() ? "." : dir) + "/" + name;
        if (access(full.c_str(), X_OK) == 0) return full;
        start = end + 1;
    }
    return {};
}

ChildResult run_self(const std::vector<std::string>& args, double timeout_s) {
    char exe[4096];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0) {
        ChildResult r;
        r.error = "cannot find the passlab executable (/proc/self/exe)";
        return r;
    }
    exe[n] = '\0';
    return run_program(exe, args, timeout_s);
}

ChildResult run_program(const std::string& program, const std::vector<std::string>& args, double timeout_s) {
    ChildResult r;
    std::string exe = find_on_path(program);
    if (exe.empty()) return r.error = "'" + program + "' is not installed (not found on PATH)", r;
    int fds[2];
    if (pipe(fds) != 0) return r.error = std::string("pipe: ") + std::strerror(errno), r;
    std::vector<std::string> argv_s{exe};
    argv_s.insert(argv_s.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : argv_s) argv.push_back(a.data());
    argv.push_back(nullptr);

    pid_t pid = fork();
    if (pid < 0) return r.error = std::string("fork: ") + std::strerror(errno), r;
    if (pid == 0) {
        setpgid(0, 0);  // its own group, so a kill reaches any process it starts
        dup2(fds[1], 1);
        dup2(fds[1], 2);
        close(fds[0]);
        close(fds[1]);
        execv(exe.c_str(), argv.data());
        _exit(127);
    }
    setpgid(pid, pid);
    close(fds[1]);
    fcntl(fds[0], F_SETFL, O_NONBLOCK);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    char buf[65536];
    for (;;) {
        auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
        if (left <= 0) {
            kill(-pid, SIGKILL);
            r.timed_out = true;
            break;
        }
        pollfd p{fds[0], POLLIN, 0};
        int pr = poll(&p, 1, static_cast<int>(std::min<long long>(left, 1000)));
        if (pr < 0 && errno != EINTR) break;
        if (pr <= 0) continue;
        ssize_t got = read(fds[0], buf, sizeof buf);
        if (got > 0) {
            // Bounded: a mutant that prints without end must not exhaust memory.
            if (r.output.size() < (16u << 20)) r.output.append(buf, static_cast<size_t>(got));
            continue;
        }
        if (got == 0) break;  // EOF: the child closed its output (it is ending)
        if (errno != EAGAIN && errno != EINTR) break;
    }
    close(fds[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    if (!r.timed_out && WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
    if (!r.timed_out && WIFSIGNALED(status)) r.signal = WTERMSIG(status);
    return r;
}

} // namespace pl::lab
