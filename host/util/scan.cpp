#include "util/scan.hpp"

namespace pl::scan {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f' || c == '\r'; }

bool is_word_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

size_t skip_blanks(std::string_view s, size_t pos) {
    while (pos < s.size() && is_blank(s[pos])) ++pos;
    return pos;
}

std::optional<std::string_view> directive(std::string_view line, std::string_view* rest) {
    size_t p = skip_blanks(line);
    if (p >= line.size() || line[p] != '#') return std::nullopt;
    p = skip_blanks(line, p + 1);
    size_t start = p;
    while (p < line.size() && is_word_char(line[p])) ++p;
    if (rest) *rest = line.substr(p);
    return line.substr(start, p - start);
}

std::optional<std::string> include_name(std::string_view line) {
    std::string_view rest;
    if (directive(line, &rest) != "include") return std::nullopt;
    size_t p = skip_blanks(rest);
    if (p >= rest.size() || (rest[p] != '"' && rest[p] != '<')) return std::nullopt;
    size_t end = rest.find_first_of("\">", p + 1);
    if (end == std::string_view::npos || end == p + 1) return std::nullopt;
    return std::string(rest.substr(p + 1, end - p - 1));
}

bool is_pragma_once(std::string_view line) {
    std::string_view rest;
    if (directive(line, &rest) != "pragma") return false;
    if (rest.empty() || !is_blank(rest[0])) return false;
    size_t p = skip_blanks(rest);
    return rest.substr(p, 4) == "once" && (p + 4 >= rest.size() || !is_word_char(rest[p + 4]));
}

bool is_version(std::string_view line) { return directive(line) == "version"; }

size_t find_word(std::string_view s, std::string_view word) {
    if (word.empty()) return std::string_view::npos;
    for (size_t p = s.find(word); p != std::string_view::npos; p = s.find(word, p + 1)) {
        bool left = p == 0 || !is_word_char(s[p - 1]);
        bool right = p + word.size() >= s.size() || !is_word_char(s[p + word.size()]);
        if (left && right) return p;
    }
    return std::string_view::npos;
}

std::optional<unsigned long long> parse_decimal(std::string_view digits, unsigned long long max) {
    if (digits.empty()) return std::nullopt;
    unsigned long long v = 0;
    for (char c : digits) {
        if (c < '0' || c > '9') return std::nullopt;
        unsigned d = static_cast<unsigned>(c - '0');
        if (v > (max - d) / 10) return std::nullopt;
        v = v * 10 + d;
    }
    return v;
}

std::optional<long long> parse_integer(std::string_view text, long long lo, long long hi) {
    bool neg = !text.empty() && text[0] == '-';
    if (!text.empty() && (text[0] == '-' || text[0] == '+')) text.remove_prefix(1);
    unsigned long long limit = neg ? static_cast<unsigned long long>(-(lo + 1)) + 1 : static_cast<unsigned long long>(hi < 0 ? 0 : hi);
    if (neg && lo >= 0) return std::nullopt;
    auto v = parse_decimal(text, limit);
    if (!v) return std::nullopt;
    long long r = neg ? (*v == 0 ? 0 : -static_cast<long long>(*v - 1) - 1) : static_cast<long long>(*v);
    if (r < lo || r > hi) return std::nullopt;
    return r;
}

} // namespace pl::scan
