// Static HTML outputs: the test report (`passlab test --report DIR`) and the gallery.
#pragma once

#include "check/checks.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace pl::lab {

struct ReportEntry {
    std::string where;  // preset folder, relative
    check::CaseResult result;
};

// Writes DIR/index.html; images referenced are copied into DIR so the page is self-contained.
// Images already inside DIR are referenced where they are; others are copied under
// DIR/<preset folder>/. A file that cannot be written is an environment error.
// Failures first, linked from a summary; a filter (failed / all, family); an inspector for the
// images (zoom to texels, rendered/golden toggle, the diff's legend). `failures_only`: passing
// cases are counted but not listed, and their renders are removed from DIR (--report-failures-only).
Status write_report(const std::filesystem::path& dir, const std::vector<ReportEntry>& entries,
                    const std::string& device, double total_ms, bool failures_only = false);

// Text and attribute values of HTML and XML: the five entities; control characters other than
// tab and newline become U+FFFD.
std::string html_escape(const std::string& s);

} // namespace pl::lab
