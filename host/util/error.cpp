#include "util/error.hpp"

#include <algorithm>
#include <fstream>

namespace pl {

std::string SourceLoc::str() const {
    if (file.empty()) return {};
    std::string s = file;
    if (line > 0) {
        s += ":" + std::to_string(line);
        if (col > 0) s += ":" + std::to_string(col);
    }
    return s;
}

std::string Error::format() const {
    std::string out;
    if (loc.known()) out += loc.str() + ": ";
    out += "error: " + message;
    if (!pass.empty() || !resource.empty()) {
        out += " [";
        if (!pass.empty()) out += "pass '" + pass + "'";
        if (!pass.empty() && !resource.empty()) out += ", ";
        if (!resource.empty()) out += "resource '" + resource + "'";
        out += "]";
    }
    out += "\n";
    if (!source_line.empty()) {
        out += "    " + source_line + "\n";
        if (loc.col > 0) {
            // Keep tabs so the caret lines up under the offending column in a terminal.
            std::string pad;
            for (int i = 0; i + 1 < loc.col && i < static_cast<int>(source_line.size()); ++i)
                pad += source_line[static_cast<size_t>(i)] == '\t' ? '\t' : ' ';
            out += "    " + pad + "^\n";
        }
    }
    if (!hint.empty()) out += "    hint: " + hint + "\n";
    for (const auto& n : notes) out += "    note: " + n + "\n";
    return out;
}

Error make_error(std::string message, SourceLoc loc) {
    Error e;
    e.message = std::move(message);
    e.loc = std::move(loc);
    if (e.loc.line > 0) e.source_line = read_source_line(e.loc.file, e.loc.line);
    return e;
}

std::string read_source_line(const std::string& file, int line) {
    std::ifstream in(file);
    if (!in || line <= 0) return {};
    std::string s;
    for (int i = 1; std::getline(in, s); ++i) {
        if (i == line) {
            if (i == 1 && s.rfind("\xEF\xBB\xBF", 0) == 0) s.erase(0, 3);  // UTF-8 BOM
            if (!s.empty() && s.back() == '\r') s.pop_back();
            return s;
        }
    }
    return {};
}

int edit_distance(const std::string& a, const std::string& b) {
    std::vector<int> prev(b.size() + 1), cur(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) prev[j] = static_cast<int>(j);
    for (size_t i = 1; i <= a.size(); ++i) {
        cur[0] = static_cast<int>(i);
        for (size_t j = 1; j <= b.size(); ++j) {
            int sub = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub});
        }
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

std::string nearest_name(const std::string& wanted, const std::vector<std::string>& candidates) {
    std::string best;
    int best_d = 1 << 30;
    for (const auto& c : candidates) {
        int d = edit_distance(wanted, c);
        if (d < best_d) {
            best_d = d;
            best = c;
        }
    }
    // A suggestion further than a third of the name away is noise, not help.
    int limit = std::max(2, static_cast<int>(wanted.size()) / 3);
    return best_d <= limit ? best : std::string{};
}

void suggest(Error& e, const std::string& wanted, const std::vector<std::string>& candidates, const std::string& label,
             const std::string& empty_note, char quote) {
    std::string near = nearest_name(wanted, candidates);
    if (!near.empty()) e.hint = std::string("did you mean ") + quote + near + quote + "?";
    if (label.empty()) return;
    if (candidates.empty()) {
        if (!empty_note.empty()) e.notes.push_back(empty_note);
        return;
    }
    std::string all;
    for (const auto& c : candidates) all += (all.empty() ? "" : ", ") + c;
    e.notes.push_back(label + ": " + all);
}

} // namespace pl
