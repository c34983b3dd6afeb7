#include "mutate/mutants.hpp"

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace pl::mutate {
namespace {

enum class Kind { ident, number, punct };

struct Token {
    Kind kind;
    size_t offset, length;
    int line, col;
    std::string_view text;
};

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Tokens of the code, without comments and preprocessor lines. A hand-written scanner: linear
// in the source, no regex (a long line must not cost more than its length).
std::vector<Token> tokenize(std::string_view s) {
    std::vector<Token> out;
    size_t i = 0;
    int line = 1;
    size_t line_start = 0;
    bool at_line_start = true;  // only whitespace so far on this line
    auto newline = [&](size_t at) { ++line, line_start = at + 1, at_line_start = true; };
    while (i < s.size()) {
        char c = s[i];
        if (c == '\n') { newline(i); ++i; continue; }
        if (std::isspace(static_cast<unsigned char>(c))) { ++i; continue; }
        if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') {
            while (i < s.size() && s[i] != '\n') ++i;
            continue;
        }
        if (c == '/' && i + 1 < s.size() && s[i + 1] == '*') {
            i += 2;
            while (i + 1 < s.size() && !(s[i] == '*' && s[i + 1] == '/')) {
                if (s[i] == '\n') newline(i);
                ++i;
            }
            i = i + 2 < s.size() ? i + 2 : s.size();
            continue;
        }
        if (c == '#' && at_line_start) {  // a directive, with its backslash continuations
            while (i < s.size() && s[i] != '\n') {
                if (s[i] == '\\' && i + 1 < s.size() && s[i + 1] == '\n') newline(++i);
                ++i;
            }
            continue;
        }
        at_line_start = false;
        Token t{Kind::punct, i, 1, line, static_cast<int>(i - line_start) + 1, {}};
        if (ident_start(c)) {
            size_t j = i;
            while (j < s.size() && ident_char(s[j])) ++j;
            t.kind = Kind::ident, t.length = j - i;
        } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                   (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
            size_t j = i;
            while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '.' ||
                                    ((s[j] == '+' || s[j] == '-') && (s[j - 1] == 'e' || s[j - 1] == 'E') &&
                                     !(s[i] == '0' && i + 1 < s.size() && (s[i + 1] == 'x' || s[i + 1] == 'X')))))
                ++j;
            t.kind = Kind::number, t.length = j - i;
        } else {
            static const char* const kLong[] = {"<<=", ">>=", "<=", ">=", "==", "!=", "&&", "||", "^^", "++", "--",
                                                "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<", ">>"};
            for (const char* op : kLong) {
                std::string_view o(op);
                if (s.substr(i, o.size()) == o) { t.length = o.size(); break; }
            }
        }
        t.text = s.substr(t.offset, t.length);
        out.push_back(t);
        i += t.length;
    }
    return out;
}

bool is_operand_end(const Token& t) {
    return t.kind == Kind::ident || t.kind == Kind::number || t.text == ")" || t.text == "]";
}

// Index of the ")" matching the "(" at `open`, or npos.
size_t matching_paren(const std::vector<Token>& toks, size_t open) {
    int depth = 0;
    for (size_t k = open; k < toks.size(); ++k) {
        if (toks[k].text == "(") ++depth;
        else if (toks[k].text == ")" && --depth == 0) return k;
    }
    return std::string_view::npos;
}

bool is_float_literal(std::string_view t) {
    if (t.size() > 1 && t[0] == '0' && (t[1] == 'x' || t[1] == 'X')) return false;
    return t.find_first_of(".eE") != std::string_view::npos;
}

// v * 1.1 (0 -> 0.1), written back as a float literal with the original suffix.
std::string nudge_float(std::string_view t) {
    size_t end = t.size();
    while (end > 0 && (t[end - 1] == 'f' || t[end - 1] == 'F' || t[end - 1] == 'l' || t[end - 1] == 'L')) --end;
    std::string body(t.substr(0, end)), suffix(t.substr(end));
    double v = std::strtod(body.c_str(), nullptr);
    double n = v == 0.0 ? 0.1 : v * 1.1;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.9g", n);
    std::string out = buf;
    if (out.find_first_of(".eE") == std::string::npos) out += ".0";
    return out + suffix;
}

bool swizzle_set(std::string_view name) {
    if (name.size() < 2 || name.size() > 4) return false;
    for (const char* set : {"xyzw", "rgba", "stpq"}) {
        bool all = true;
        for (char ch : name) all = all && std::string_view(set).find(ch) != std::string_view::npos;
        if (all) return true;
    }
    return false;
}

} // namespace

std::vector<Mutant> find_mutants(std::string_view src) {
    const auto toks = tokenize(src);
    std::vector<Mutant> out;
    auto add = [&](const Token& at, size_t length, std::string op, std::string repl) {
        out.push_back({std::move(op), at.offset, length, std::move(repl), at.line, at.col});
    };
    size_t skip_until = 0;  // tokens inside layout(...) are qualifiers, not code
    int bracket = 0;        // inside [...]: array sizes and constant indices
    for (size_t k = 0; k < toks.size(); ++k) {
        const Token& t = toks[k];
        const Token* prev = k > 0 ? &toks[k - 1] : nullptr;
        const Token* next = k + 1 < toks.size() ? &toks[k + 1] : nullptr;
        if (k < skip_until) continue;
        if (t.text == "[") ++bracket;
        if (t.text == "]" && bracket > 0) --bracket;
        if (t.kind == Kind::ident && t.text == "layout" && next && next->text == "(") {
            size_t close = matching_paren(toks, k + 1);
            skip_until = close == std::string_view::npos ? toks.size() : close + 1;
            continue;
        }
        const bool binary = prev && is_operand_end(*prev);
        if (t.kind == Kind::punct) {
            static const std::pair<std::string_view, std::string_view> kSwap[] = {
                {"*", "/"}, {"/", "*"}, {"<", ">"}, {">", "<"}, {"<=", ">="}, {">=", "<="}, {"==", "!="},
                {"!=", "=="}, {"&&", "||"}, {"||", "&&"}, {"+=", "-="}, {"-=", "+="}, {"*=", "/="}, {"/=", "*="}};
            for (const auto& [from, to] : kSwap)
                if (t.text == from) add(t, t.length, std::string(from) + " -> " + std::string(to), std::string(to));
            if ((t.text == "+" || t.text == "-") && binary)
                add(t, 1, t.text == "+" ? "+ -> -" : "- -> +", t.text == "+" ? "-" : "+");
            if (t.text == "-" && !binary && next && (next->kind != Kind::punct || next->text == "("))
                add(t, 1, "drop unary -", "");
            if (t.text == "." && prev && is_operand_end(*prev) && next && next->kind == Kind::ident &&
                swizzle_set(next->text)) {
                std::string rev(next->text.rbegin(), next->text.rend());
                if (rev != next->text) add(*next, next->length, "reverse swizzle", rev);
            }
        } else if (t.kind == Kind::ident) {
            const bool call = next && next->text == "(";
            if (call && (t.text == "min" || t.text == "max"))
                add(t, t.length, t.text == "min" ? "min -> max" : "max -> min", t.text == "min" ? "max" : "min");
            if (call && t.text == "normalize") add(t, t.length, "drop normalize", "");
            if (call && t.text == "clamp") {
                // clamp(x, lo, hi) -> (x): the first top-level argument in parentheses.
                size_t close = matching_paren(toks, k + 1);
                if (close == std::string_view::npos) continue;
                size_t comma = 0;
                int depth = 0;
                for (size_t j = k + 1; j < close && !comma; ++j) {
                    const auto& x = toks[j].text;
                    if (x == "(" || x == "[") ++depth;
                    else if (x == ")" || x == "]") --depth;
                    else if (x == "," && depth == 1) comma = j;
                }
                if (!comma) continue;
                size_t arg0 = toks[k + 2].offset, arg_end = toks[comma].offset;
                size_t end = toks[close].offset + 1;
                add(t, end - t.offset, "drop clamp", "(" + std::string(src.substr(arg0, arg_end - arg0)) + ")");
            }
            if (t.text == "true" || t.text == "false")
                add(t, t.length, t.text == "true" ? "true -> false" : "false -> true",
                    t.text == "true" ? "false" : "true");
        } else if (t.kind == Kind::number && bracket == 0) {
            if (is_float_literal(t.text)) {
                add(t, t.length, "nudge constant", nudge_float(t.text));
            } else if (t.text.find_first_not_of("0123456789") == std::string_view::npos) {
                add(t, t.length, "nudge constant", std::to_string(std::strtoll(std::string(t.text).c_str(), nullptr, 10) + 1));
            }
        }
    }
    return out;
}

std::string apply_mutant(std::string_view src, const Mutant& m) {
    std::string out(src.substr(0, m.offset));
    out += m.replacement;
    out += src.substr(m.offset + m.length);
    return out;
}

namespace {
// [begin, end) of the line holding byte `offset`, without its newline.
std::pair<size_t, size_t> line_range(std::string_view src, size_t offset) {
    size_t b = offset == 0 ? std::string_view::npos : src.rfind('\n', offset - 1);
    b = b == std::string_view::npos ? 0 : b + 1;
    size_t e = src.find('\n', offset);
    return {b, e == std::string_view::npos ? src.size() : e};
}
} // namespace

std::string line_of(std::string_view src, const Mutant& m) {
    auto [b, e] = line_range(src, m.offset);
    return std::string(src.substr(b, e - b));
}

std::string mutated_line_of(std::string_view src, const Mutant& m) {
    // From the first line of the mutant to the end of the line where its range ends (a clamp
    // may span lines).
    size_t b = line_range(src, m.offset).first;
    size_t e = line_range(src, m.offset + m.length).second;
    return std::string(src.substr(b, m.offset - b)) + m.replacement +
           std::string(src.substr(m.offset + m.length, e - (m.offset + m.length)));
}

std::vector<size_t> choose(size_t n, size_t count, uint64_t seed) {
    std::vector<size_t> idx(n);
    for (size_t i = 0; i < n; ++i) idx[i] = i;
    uint64_t state = seed;
    auto next = [&state]() {  // splitmix64
        uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    };
    for (size_t i = n; i > 1; --i) std::swap(idx[i - 1], idx[next() % i]);
    if (count < n) idx.resize(count);
    return idx;
}

} // namespace pl::mutate
