// What `passlab grade` hands to a course platform: its own JSON (--json FILE) and Gradescope's
// autograder results.json (--json FILE --format gradescope). Both come from one GradeSummary so
// the console, the file and the platform never disagree about a score.
#pragma once

#include "check/checks.hpp"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace pl::lab {

struct GradeSummary {
    std::string preset, exercise, device;
    std::vector<check::CaseResult> cases;
    // Set when nothing could be graded (the student's files do not build, or shadow nothing):
    // every case then scores 0 and carries this as its output.
    std::string not_graded;
    double seconds = 0.0;
};

// A case's figures, images and hint are shown only when its visibility is "visible": the other
// levels grade it but keep what it measured from the student (Gradescope shows them later).
bool shows_figures(const check::CaseResult& r);
// The human-readable account of one case: check lines with figures, validation messages, the
// error, the hint. Exactly what the console prints under the case's PASS/FAIL line.
std::string case_text(const check::CaseResult& r);

struct Score {
    double score = 0.0, max_score = 0.0;
    int passed = 0, failed = 0, skipped = 0;
};
// A skipped case (a device feature is missing) counts neither way: it is not the student's fault.
Score score_of(const GradeSummary& s);

nlohmann::ordered_json grade_json(const GradeSummary& s);
nlohmann::ordered_json gradescope_json(const GradeSummary& s);

} // namespace pl::lab
