#include "reload/watcher.hpp"

#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace pl::reload {

DirWatcher::DirWatcher() { fd_ = inotify_init1(IN_NONBLOCK | IN_CLOEXEC); }

DirWatcher::~DirWatcher() {
    if (fd_ >= 0) close(fd_);
}

void DirWatcher::watch(const std::vector<fs::path>& files) {
    if (fd_ < 0) return;
    for (const auto& [wd, dir] : dirs_) inotify_rm_watch(fd_, wd);
    dirs_.clear();
    files_.clear();
    std::set<fs::path> dirs;
    std::error_code ec;
    for (const auto& f : files) {
        fs::path abs = fs::weakly_canonical(f, ec);
        files_.insert(abs);
        dirs.insert(abs.parent_path());
    }
    for (const auto& d : dirs) {
        int wd = inotify_add_watch(fd_, d.c_str(), IN_CLOSE_WRITE | IN_MOVED_TO | IN_CREATE | IN_DELETE);
        if (wd >= 0) dirs_[wd] = d;
    }
}

bool DirWatcher::read_events(std::set<fs::path>& out) {
    alignas(inotify_event) char buf[16384];
    bool any = false;
    for (;;) {
        ssize_t n = read(fd_, buf, sizeof buf);
        if (n <= 0) break;
        for (char* p = buf; p < buf + n;) {
            auto* e = reinterpret_cast<inotify_event*>(p);
            auto it = dirs_.find(e->wd);
            if (it != dirs_.end() && e->len > 0) {
                fs::path f = it->second / e->name;
                if (files_.count(f)) {
                    out.insert(f);
                    any = true;
                }
            }
            p += sizeof(inotify_event) + e->len;
        }
    }
    return any;
}

std::set<fs::path> DirWatcher::poll(std::chrono::milliseconds timeout, std::chrono::milliseconds debounce) {
    std::set<fs::path> changed;
    if (fd_ < 0) return changed;
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(timeout.count())) <= 0) return changed;
    read_events(changed);
    if (changed.empty()) return changed;
    // Debounce: a save is often several events (write, close, rename); wait until it is quiet.
    while (::poll(&p, 1, static_cast<int>(debounce.count())) > 0) read_events(changed);
    return changed;
}

} // namespace pl::reload
