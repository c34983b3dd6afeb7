#include "grade_results.hpp"

#include <nlohmann/json.hpp>

#include <cmath>

using json = nlohmann::ordered_json;

namespace pl::lab {

bool shows_figures(const check::CaseResult& r) { return r.visibility == "visible"; }

std::string case_text(const check::CaseResult& r) {
    std::string t;
    if (r.skipped) return "not graded: " + r.skip_reason + "\n";
    if (!r.error.empty()) t += r.error;
    for (const auto& ch : r.checks) {
        t += std::string("    ") + (ch.passed ? "ok   " : "FAIL ") + ch.what + ": " + ch.detail + "\n";
        if (!ch.passed && !ch.diff_file.empty())
            t += "         images: " + ch.actual_file + " (yours), " + ch.expected_file + " (reference), " +
                 ch.diff_file + " (difference)\n";
    }
    for (const auto& v : r.validation) t += "    validation: " + v + "\n";
    if (!r.passed && !r.hint.empty()) t += "    hint: " + r.hint + "\n";
    return t;
}

Score score_of(const GradeSummary& s) {
    Score sc;
    for (const auto& r : s.cases) {
        if (r.skipped) {
            ++sc.skipped;
            continue;
        }
        sc.max_score += r.weight;
        if (r.passed && s.not_graded.empty()) {
            ++sc.passed;
            sc.score += r.weight;
        } else {
            ++sc.failed;
        }
    }
    return sc;
}

namespace {

const char* status_of(const check::CaseResult& r, const GradeSummary& s) {
    if (r.skipped) return "skipped";
    return r.passed && s.not_graded.empty() ? "passed" : "failed";
}

double case_score(const check::CaseResult& r, const GradeSummary& s) {
    return !r.skipped && r.passed && s.not_graded.empty() ? r.weight : 0.0;
}

std::string summary_line(const Score& sc) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "%d of %d cases pass, score %g of %g", sc.passed, sc.passed + sc.failed, sc.score,
                  sc.max_score);
    return buf;
}

} // namespace

json grade_json(const GradeSummary& s) {
    Score sc = score_of(s);
    json cases = json::array();
    for (const auto& r : s.cases) {
        json c = {{"name", r.name},
                  {"status", status_of(r, s)},
                  {"score", case_score(r, s)},
                  {"max_score", r.skipped ? 0.0 : r.weight},
                  {"visibility", r.visibility}};
        if (r.skipped) c["skip_reason"] = r.skip_reason;
        if (shows_figures(r)) {
            if (!r.error.empty()) c["error"] = r.error;
            if (!r.passed && !r.hint.empty()) c["hint"] = r.hint;
            c["validation"] = r.validation;
            json checks = json::array();
            for (const auto& ch : r.checks) {
                json k = {{"what", ch.what}, {"passed", ch.passed}, {"detail", ch.detail}};
                if (!ch.actual_file.empty()) k["yours"] = ch.actual_file;
                if (!ch.expected_file.empty()) k["reference"] = ch.expected_file;
                if (!ch.diff_file.empty()) k["difference"] = ch.diff_file;
                checks.push_back(k);
            }
            c["checks"] = checks;
        }
        cases.push_back(c);
    }
    json j = {{"preset", s.preset},
              {"exercise", s.exercise},
              {"device", s.device},
              {"graded", s.not_graded.empty()},
              {"score", sc.score},
              {"max_score", sc.max_score},
              {"passed", sc.passed},
              {"failed", sc.failed},
              {"skipped", sc.skipped},
              {"seconds", s.seconds}};
    if (!s.not_graded.empty()) j["not_graded"] = s.not_graded;
    j["cases"] = cases;
    return j;
}

json gradescope_json(const GradeSummary& s) {
    // https://gradescope-autograders.readthedocs.io/en/latest/specs/ : tests[] with name, score,
    // max_score, status, output, visibility; a total score; output for the whole submission.
    // Hidden cases keep their full output: Gradescope itself withholds it from the student.
    Score sc = score_of(s);
    json tests = json::array();
    for (const auto& r : s.cases) {
        json t = {{"name", r.name},
                  {"score", case_score(r, s)},
                  {"max_score", r.skipped ? 0.0 : r.weight},
                  {"visibility", r.visibility}};
        // A skipped case (missing device feature) was not run: no status rather than a pass.
        if (!r.skipped) t["status"] = r.passed && s.not_graded.empty() ? "passed" : "failed";
        std::string out = s.not_graded.empty() ? case_text(r) : s.not_graded;
        if (!out.empty()) t["output"] = out;
        tests.push_back(t);
    }
    std::string output = "passlab grade " + s.preset + ": " + summary_line(sc);
    if (!s.device.empty()) output += " (" + s.device + ")";
    if (!s.not_graded.empty()) output += "\n" + s.not_graded;
    return {{"score", sc.score},
            {"execution_time", static_cast<int>(std::lround(s.seconds))},
            {"output", output},
            {"visibility", "visible"},
            {"stdout_visibility", "hidden"},
            {"tests", tests}};
}

} // namespace pl::lab
