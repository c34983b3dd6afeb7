#include "course.hpp"

#include "graph/course_docs.hpp"
#include "graph/toml_reader.hpp"
#include "util/files.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <set>

namespace fs = std::filesystem;

namespace pl::lab {

Result<std::vector<CourseUnit>> load_course(const fs::path& file) {
    auto text = read_file_capped(file, 1 << 20, "course file");
    if (!text) return text.error();
    toml::table root;
    try {
        root = toml::parse(*text, file.string());
    } catch (const toml::parse_error& err) {
        const auto& s = err.source();
        return make_error("invalid TOML: " + std::string(err.description()),
                          {file.string(), static_cast<int>(s.begin.line), static_cast<int>(s.begin.column)});
    }
    graph::TableReader top(root, file.string(), "course.toml");
    if (auto s = top.finish({"unit"}); !s) return s.error();
    const toml::array* units = root["unit"].as_array();
    if (!units) return top.error("course.toml: expected [[unit]] tables", top.loc());
    std::vector<CourseUnit> out;
    std::set<std::string> seen;
    for (const auto& n : *units) {
        const toml::table* t = n.as_table();
        if (!t) return top.error("course.toml: [[unit]] must be a table", top.loc_of(n));
        graph::TableReader r(*t, file.string(), "[[unit]]");
        CourseUnit u;
        for (auto [key, out_str] : {std::pair{"family", &u.family}, {"title", &u.title}, {"checks", &u.checks}}) {
            if (auto s = r.str(key, *out_str); !s) return s.error();
            if (out_str->empty()) return r.error(std::string("[[unit]]: '") + key + "' is required", r.loc());
        }
        if (auto s = r.strings("lectures", u.lectures); !s) return s.error();
        for (const auto& c : u.lectures)
            if (auto p = graph::parse_citation(c); !p)
                return r.error("[[unit]] " + u.family + ": lectures: " + p.error().message, r.value_loc("lectures"));
        if (auto s = r.strings("requires", u.requires_units); !s) return s.error();
        for (const auto& q : u.requires_units)
            if (!seen.count(q))
                return r.error("[[unit]] " + u.family + ": requires '" + q +
                                   "', which is not an earlier unit (units are listed in teaching order)",
                               r.value_loc("requires"));
        if (auto s = r.finish(); !s) return s.error();
        if (!seen.insert(u.family).second)
            return r.error("[[unit]]: family '" + u.family + "' is listed twice", r.value_loc("family"));
        out.push_back(std::move(u));
    }
    return out;
}

LecturePos lecture_pos(const std::vector<std::string>& sources) {
    LecturePos best;
    for (const auto& s : sources) {
        auto c = graph::parse_citation(s);
        if (!c || c->ranges.empty()) continue;
        LecturePos p{std::atoi(c->doc->id), c->ranges.front().first};
        if (p < best) best = p;
    }
    return best;
}

namespace {

// TODO blocks in one file: "TODO 3" counts once per number, each unnumbered "TODO:" once.
void count_todos(const fs::path& f, std::set<int>& numbered, int& unnumbered) {
    std::ifstream in(f);
    std::string line;
    while (std::getline(in, line)) {
        for (size_t at = line.find("TODO"); at != std::string::npos; at = line.find("TODO", at + 4)) {
            size_t i = at + 4;
            if (i < line.size() && line[i] == ' ' && i + 1 < line.size() && std::isdigit(static_cast<unsigned char>(line[i + 1])))
                numbered.insert(std::atoi(line.c_str() + i + 1));
            else if (i < line.size() && line[i] == ':')
                ++unnumbered;
        }
    }
}

} // namespace

ExerciseInfo exercise_info(const fs::path& preset_dir) {
    ExerciseInfo info;
    std::error_code ec;
    const fs::path ex = preset_dir / "exercise";
    if (!fs::is_directory(ex, ec)) return info;
    info.present = true;
    std::set<int> numbered;
    int unnumbered = 0;
    for (const auto& f : files_under(ex))
        if (f.extension() != ".md") count_todos(f, numbered, unnumbered);
    info.todos = static_cast<int>(numbered.size()) + unnumbered;
    const fs::path mistakes = preset_dir / "mistakes";
    if (fs::is_directory(mistakes, ec))
        for (const auto& d : fs::directory_iterator(mistakes, ec))
            info.mistakes += d.is_directory(ec);
    info.minutes = 15 + 15 * info.todos;
    return info;
}

} // namespace pl::lab
