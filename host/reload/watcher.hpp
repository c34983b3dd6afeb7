// Watches files for changes the way editors save them. Watching a file itself loses the watch
// on the first save of editors that write a temporary file and rename it over the original
// (vim, JetBrains, VS Code), so we watch the folders (inotify IN_CLOSE_WRITE | IN_MOVED_TO |
// IN_CREATE | IN_DELETE) and filter by name.
#pragma once

#include <chrono>
#include <filesystem>
#include <map>
#include <set>
#include <vector>

namespace pl::reload {

class DirWatcher {
  public:
    DirWatcher();
    ~DirWatcher();
    DirWatcher(const DirWatcher&) = delete;
    DirWatcher& operator=(const DirWatcher&) = delete;

    // Replaces the watched set (after a reload the dependency list may differ).
    void watch(const std::vector<std::filesystem::path>& files);
    // Files changed since the last call. Waits up to `timeout` for a first event, then keeps
    // collecting while events arrive closer than `debounce` (editors write in bursts).
    std::set<std::filesystem::path> poll(std::chrono::milliseconds timeout, std::chrono::milliseconds debounce);
    bool ok() const { return fd_ >= 0; }

  private:
    bool read_events(std::set<std::filesystem::path>& out);
    int fd_ = -1;
    std::map<int, std::filesystem::path> dirs_;        // watch descriptor -> folder
    std::set<std::filesystem::path> files_;
};

} // namespace pl::reload
