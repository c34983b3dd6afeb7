// `passlab run --events FILE`: one JSON object per line (started, reload-started, reload-ok,
// reload-failed, frame-presented, counter-overflow, ...) with the time since start and the wall clock, so tests
// and the reload benchmark can follow what the live lab did.
#pragma once

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>

namespace pl::lab {

inline std::string json_string(const std::string& s) {
    std::string o = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') o += '\\', o += c;
        else if (c == '\n') o += "\\n";
        else if (static_cast<unsigned char>(c) < 0x20) o += ' ';
        else o += c;
    }
    return o + "\"";
}

class EventLog {
  public:
    explicit EventLog(const std::string& file) : t0_(std::chrono::steady_clock::now()) {
        if (!file.empty()) out_.open(file, std::ios::trunc);
    }
    double now_ms() const { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0_).count(); }
    void write(const std::string& event, const std::string& fields = "") {
        if (!out_) return;
        char t[64];
        // wall_ms (Unix epoch) lets a benchmark relate events to the moment it edited a file.
        auto wall = std::chrono::duration<double, std::milli>(std::chrono::system_clock::now().time_since_epoch()).count();
        std::snprintf(t, sizeof t, "%.1f,\"wall_ms\":%.1f", now_ms(), wall);
        out_ << "{\"event\":\"" << event << "\",\"t_ms\":" << t << (fields.empty() ? "" : "," + fields) << "}\n";
        out_.flush();
    }

  private:
    std::ofstream out_;
    std::chrono::steady_clock::time_point t0_;
};

} // namespace pl::lab
