// `passlab run --events FILE`: one JSON object per line (started, reload-started, reload-ok,
// reload-failed, frame-presented, counter-overflow, ...) with the time since start and the wall clock, so tests
// and the reload benchmark can follow what the live lab did.
#pragma once

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <fstream>
#include <string>

namespace pl::lab {

class EventLog {
  public:
    explicit EventLog(const std::string& file) : t0_(std::chrono::steady_clock::now()) {
        if (!file.empty()) out_.open(file, std::ios::trunc);
    }
    double now_ms() const { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0_).count(); }
    // One line: {"event": ..., "t_ms": ..., "wall_ms": ..., <fields>}. nlohmann-json escapes
    // every string (quotes, control characters as \uXXXX), so a GLSL message cannot break a line.
    void write(const std::string& event, const nlohmann::ordered_json& fields = nlohmann::ordered_json::object()) {
        if (!out_) return;
        // wall_ms (Unix epoch) lets a benchmark relate events to the moment it edited a file.
        auto wall = std::chrono::duration<double, std::milli>(std::chrono::system_clock::now().time_since_epoch()).count();
        nlohmann::ordered_json j = {{"event", event}, {"t_ms", tenth(now_ms())}, {"wall_ms", tenth(wall)}};
        j.update(fields);
        out_ << j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << "\n";
        out_.flush();
    }
    static double tenth(double ms) { return std::round(ms * 10.0) / 10.0; }

  private:
    std::ofstream out_;
    std::chrono::steady_clock::time_point t0_;
};

} // namespace pl::lab
