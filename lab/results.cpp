#include "results.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace pl::lab {

namespace {

const char* golden_write_name(check::CheckResult::GoldenWrite w) {
    switch (w) {
    case check::CheckResult::GoldenWrite::written: return "written";
    case check::CheckResult::GoldenWrite::rewritten: return "rewritten";
    case check::CheckResult::GoldenWrite::none: break;
    }
    return "";
}

const char* status_of(const check::CaseResult& r) { return r.skipped ? "skipped" : r.passed ? "passed" : "failed"; }

json check_json(const check::CheckResult& c) {
    json j = {{"what", c.what}, {"passed", c.passed}, {"detail", c.detail}};
    if (!c.expected_file.empty()) j["expected"] = c.expected_file;
    if (!c.actual_file.empty()) j["actual"] = c.actual_file;
    if (!c.diff_file.empty()) j["diff"] = c.diff_file;
    if (c.golden_write != check::CheckResult::GoldenWrite::none) j["golden_write"] = golden_write_name(c.golden_write);
    return j;
}

std::string str_or(const json& j, const char* k) { return j.contains(k) && j[k].is_string() ? j[k].get<std::string>() : std::string(); }

Status env_error(const std::string& msg) {
    Error e = make_error(msg);
    e.code = ExitCode::environment;
    return e;
}

Status write_text(const fs::path& file, const std::string& text) {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    if (!out) return env_error("cannot write " + file.string());
    out << text;
    out.close();
    if (!out) return env_error("cannot write " + file.string() + " (disk full?)");
    return ok_status();
}

} // namespace

Counts count(const std::vector<ReportEntry>& entries) {
    Counts n;
    for (const auto& e : entries) {
        (e.result.skipped ? n.skipped : e.result.passed ? n.passed : n.failed)++;
        for (const auto& c : e.result.checks) {
            n.goldens_written += c.golden_write == check::CheckResult::GoldenWrite::written;
            n.goldens_rewritten += c.golden_write == check::CheckResult::GoldenWrite::rewritten;
        }
    }
    return n;
}

json to_json(const RunSummary& s) {
    Counts n = count(s.entries);
    json cases = json::array();
    for (const auto& e : s.entries) {
        const auto& r = e.result;
        json c = {{"preset", e.where}, {"name", r.name}, {"status", status_of(r)}, {"ms", r.ms}};
        if (r.skipped) c["skip_reason"] = r.skip_reason;
        if (!r.error.empty()) c["error"] = r.error;
        if (!r.hint.empty()) c["hint"] = r.hint;
        if (!r.image_file.empty()) c["image"] = r.image_file;
        c["validation"] = r.validation;
        json checks = json::array();
        for (const auto& ch : r.checks) checks.push_back(check_json(ch));
        c["checks"] = checks;
        cases.push_back(c);
    }
    return {{"device", s.device},
            {"ms", s.ms},
            {"passed", n.passed},
            {"failed", n.failed},
            {"skipped", n.skipped},
            {"goldens_written", n.goldens_written},
            {"goldens_rewritten", n.goldens_rewritten},
            {"cases", cases}};
}

Result<RunSummary> run_summary_from_json(const json& j) {
    try {
        RunSummary s;
        s.device = str_or(j, "device");
        s.ms = j.value("ms", 0.0);
        for (const auto& c : j.at("cases")) {
            ReportEntry e;
            e.where = c.at("preset").get<std::string>();
            auto& r = e.result;
            r.preset = e.where;
            r.name = c.at("name").get<std::string>();
            std::string status = c.at("status").get<std::string>();
            r.skipped = status == "skipped";
            r.passed = status == "passed";
            r.ms = c.value("ms", 0.0);
            r.skip_reason = str_or(c, "skip_reason");
            r.error = str_or(c, "error");
            r.hint = str_or(c, "hint");
            r.image_file = str_or(c, "image");
            if (c.contains("validation")) r.validation = c["validation"].get<std::vector<std::string>>();
            for (const auto& k : c.value("checks", json::array())) {
                check::CheckResult ch;
                ch.what = str_or(k, "what");
                ch.passed = k.value("passed", false);
                ch.detail = str_or(k, "detail");
                ch.expected_file = str_or(k, "expected");
                ch.actual_file = str_or(k, "actual");
                ch.diff_file = str_or(k, "diff");
                std::string w = str_or(k, "golden_write");
                ch.golden_write = w == "written" ? check::CheckResult::GoldenWrite::written
                                  : w == "rewritten" ? check::CheckResult::GoldenWrite::rewritten
                                                     : check::CheckResult::GoldenWrite::none;
                r.checks.push_back(ch);
            }
            s.entries.push_back(std::move(e));
        }
        return s;
    } catch (const json::exception& e) {
        return make_error(std::string("malformed results JSON: ") + e.what());
    }
}

Status write_json_file(const fs::path& file, const json& j) { return write_text(file, j.dump(2) + "\n"); }

Status write_junit(const fs::path& file, const RunSummary& s) {
    // One <testsuite> per preset folder, in run order; one <testcase> per case.
    std::vector<std::string> order;
    for (const auto& e : s.entries)
        if (std::find(order.begin(), order.end(), e.where) == order.end()) order.push_back(e.where);
    Counts total = count(s.entries);
    char secs[32];
    auto seconds = [&](double ms) {
        std::snprintf(secs, sizeof secs, "%.3f", ms / 1000.0);
        return std::string(secs);
    };
    std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    x += "<testsuites name=\"passlab\" tests=\"" + std::to_string(s.entries.size()) + "\" failures=\"" + std::to_string(total.failed) +
         "\" skipped=\"" + std::to_string(total.skipped) + "\" time=\"" + seconds(s.ms) + "\">\n";
    for (const auto& where : order) {
        std::vector<const check::CaseResult*> cases;
        for (const auto& e : s.entries)
            if (e.where == where) cases.push_back(&e.result);
        int failures = 0, skipped = 0;
        double ms = 0;
        for (const auto* r : cases) failures += !r->passed && !r->skipped, skipped += r->skipped, ms += r->ms;
        x += "  <testsuite name=\"" + html_escape(where) + "\" tests=\"" + std::to_string(cases.size()) + "\" failures=\"" +
             std::to_string(failures) + "\" errors=\"0\" skipped=\"" + std::to_string(skipped) + "\" time=\"" + seconds(ms) + "\">\n";
        for (const auto* r : cases) {
            x += "    <testcase classname=\"" + html_escape(where) + "\" name=\"" + html_escape(r->name) + "\" time=\"" + seconds(r->ms) + "\">\n";
            if (r->skipped) {
                x += "      <skipped message=\"" + html_escape(r->skip_reason) + "\"/>\n";
            } else if (!r->passed) {
                // The message is the first reason (a failing figure); the body has all of them.
                std::string first, body;
                if (!r->error.empty()) first = r->error.substr(0, r->error.find('\n')), body += r->error;
                for (const auto& c : r->checks)
                    if (!c.passed) {
                        std::string line = c.what + ": " + c.detail;
                        if (first.empty()) first = line;
                        body += line + "\n";
                    }
                for (const auto& v : r->validation) {
                    if (first.empty()) first = "validation: " + v;
                    body += "validation: " + v + "\n";
                }
                if (!r->hint.empty()) body += "hint: " + r->hint + "\n";
                x += "      <failure message=\"" + html_escape(first) + "\" type=\"passlab\">" + html_escape(body) + "</failure>\n";
            }
            // Attachments in the [[ATTACHMENT|path]] convention (Jenkins junit-attachments,
            // GitLab): absolute paths, the rendered image first.
            std::vector<std::string> files;
            if (!r->image_file.empty()) files.push_back(r->image_file);
            for (const auto& c : r->checks)
                for (const auto* f : {&c.actual_file, &c.expected_file, &c.diff_file})
                    if (!f->empty()) files.push_back(*f);
            if (!files.empty()) {
                x += "      <system-out>";
                std::error_code ec;
                for (const auto& f : files) x += "[[ATTACHMENT|" + html_escape(fs::absolute(f, ec).string()) + "]]\n";
                x += "</system-out>\n";
            }
            x += "    </testcase>\n";
        }
        x += "  </testsuite>\n";
    }
    x += "</testsuites>\n";
    return write_text(file, x);
}

} // namespace pl::lab
