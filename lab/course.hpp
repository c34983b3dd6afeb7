// The course path (presets/course.toml): the preset families as units in the order the course
// documents teach them, each with its lectures, prerequisites and what its exercises check.
// `passlab list --course` prints it with every preset in lecture order and its exercise status;
// docs/course.md is that output (a test keeps the two equal).
#pragma once

#include "util/error.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace pl::lab {

struct CourseUnit {
    std::string family, title, checks;
    std::vector<std::string> lectures;  // citations, as in [preset] sources
    std::vector<std::string> requires_units;  // families of earlier units
};

// Parses and validates FILE: every citation must parse, every prerequisite must be an earlier
// unit, no family twice. Errors name FILE:line:col.
Result<std::vector<CourseUnit>> load_course(const std::filesystem::path& file);

// Where a preset sits within its unit: its earliest citation (document, then line); presets
// without citations sort last.
struct LecturePos {
    int doc = 1000, line = 0;
    bool operator<(const LecturePos& o) const { return doc != o.doc ? doc < o.doc : line < o.line; }
};
LecturePos lecture_pos(const std::vector<std::string>& sources);

// What a student is asked to do in a preset's exercise/: its TODO blocks (numbered "TODO N"
// count once each, unnumbered "TODO:" each) and mistake folders.
struct ExerciseInfo {
    bool present = false;
    int todos = 0;
    int mistakes = 0;
    int minutes = 0;  // the estimate docs/course.md states: 15 to read + 15 per TODO
};
ExerciseInfo exercise_info(const std::filesystem::path& preset_dir);

} // namespace pl::lab
