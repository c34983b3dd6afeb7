// The course documents the presets cite, and citations of them ("000 L893-898").
//
// A user of passlab does not have the documents' files; docs/references.md says what each one
// is. The table here gives each its short id (the first three characters of its file name, the
// form citations use), the file name, a human name for `passlab list` and the gallery, and its
// length in lines, so that a citation past the end of a document is an error at the preset's
// TOML value instead of a dangling reference.
#pragma once

#include "util/error.hpp"

#include <string>
#include <vector>

namespace pl::graph {

struct CourseDoc {
    const char* id;     // "000"
    const char* file;   // "000_c9f7e5de708ecbb3.txt"
    const char* name;   // "Schmalstieg, Real-Time Rendering (lecture slides)"
    int lines;          // length of the text version
};

const std::vector<CourseDoc>& course_docs();
const CourseDoc* find_course_doc(const std::string& id);

// One citation: a document and line ranges within it.
struct Citation {
    const CourseDoc* doc = nullptr;
    std::vector<std::pair<int, int>> ranges;  // inclusive, 1-based
};

// Parses "000 L893-898" or "002 L1568-1648, L1652" (the id, then one or more ranges separated by
// commas; a range of one line is "L42"). Errors say what is wrong (unknown id with a suggestion,
// a range past the document's end, a reversed range); the caller adds the location.
Result<Citation> parse_citation(const std::string& text);

// "Schmalstieg, Real-Time Rendering (lecture slides) L893-898" for display.
std::string describe(const Citation& c);

} // namespace pl::graph
