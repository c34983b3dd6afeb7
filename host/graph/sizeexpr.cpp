#include "graph/sizeexpr.hpp"

#include <cctype>

namespace pl::graph {

namespace {

using Vec = std::vector<int64_t>;

struct Parser {
    const std::string& s;
    const SizeEnv& env;
    const SourceLoc& loc;
    size_t i = 0;
    std::optional<Error> err;

    Error fail(const std::string& msg, size_t at) {
        // loc points at the opening quote of the TOML string: +1 for the quote.
        SourceLoc l = loc;
        if (l.col > 0) l.col += static_cast<int>(at) + 1;
        Error e = make_error("size expression \"" + s + "\": " + msg, l);
        return e;
    }
    void ws() {
        while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    }
    static Vec bin(const Vec& a, const Vec& b, char op, bool& div0) {
        size_t n = std::max(a.size(), b.size());
        Vec r(n);
        for (size_t k = 0; k < n; ++k) {
            int64_t x = a.size() == 1 ? a[0] : a[k], y = b.size() == 1 ? b[0] : b[k];
            switch (op) {
            case '+': r[k] = x + y; break;
            case '-': r[k] = x - y; break;
            case '*': r[k] = x * y; break;
            case '/':
                if (y == 0) { div0 = true; return r; }
                r[k] = x / y - ((x % y != 0) && ((x < 0) != (y < 0)));
                break;
            case '%':
                if (y == 0) { div0 = true; return r; }
                r[k] = x % y;
                break;
            case 'c':  // ceil_div
                if (y == 0) { div0 = true; return r; }
                r[k] = (x + y - 1) / y;
                break;
            case 'm': r[k] = std::min(x, y); break;
            case 'M': r[k] = std::max(x, y); break;
            }
        }
        return r;
    }
    bool compatible(const Vec& a, const Vec& b) { return a.size() == 1 || b.size() == 1 || a.size() == b.size(); }

    std::optional<Vec> expr() {
        auto a = term();
        while (a) {
            ws();
            if (i < s.size() && (s[i] == '+' || s[i] == '-')) {
                char op = s[i++];
                size_t at = i;
                auto b = term();
                if (!b) return std::nullopt;
                if (!compatible(*a, *b)) { err = fail("vectors of different sizes", at); return std::nullopt; }
                bool d0 = false;
                a = bin(*a, *b, op, d0);
            } else break;
        }
        return a;
    }
    std::optional<Vec> term() {
        auto a = unary();
        while (a) {
            ws();
            if (i < s.size() && (s[i] == '*' || s[i] == '/' || s[i] == '%')) {
                char op = s[i++];
                size_t at = i;
                auto b = unary();
                if (!b) return std::nullopt;
                if (!compatible(*a, *b)) { err = fail("vectors of different sizes", at); return std::nullopt; }
                bool d0 = false;
                a = bin(*a, *b, op, d0);
                if (d0) { err = fail("division by zero", at); return std::nullopt; }
            } else break;
        }
        return a;
    }
    std::optional<Vec> unary() {
        ws();
        if (i < s.size() && s[i] == '-') {
            ++i;
            auto v = unary();
            if (v) for (auto& x : *v) x = -x;
            return v;
        }
        return primary();
    }
    std::optional<Vec> primary() {
        ws();
        if (i >= s.size()) { err = fail("unexpected end", i); return std::nullopt; }
        size_t at = i;
        if (std::isdigit(static_cast<unsigned char>(s[i]))) {
            int64_t v = 0;
            while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) {
                v = v * 10 + (s[i++] - '0');
                if (v > (int64_t(1) << 40)) { err = fail("number too large", at); return std::nullopt; }
            }
            return Vec{v};
        }
        if (s[i] == '(') {
            ++i;
            auto v = expr();
            ws();
            if (!v) return v;
            if (i >= s.size() || s[i] != ')') { err = fail("expected ')'", i); return std::nullopt; }
            ++i;
            return v;
        }
        if (std::isalpha(static_cast<unsigned char>(s[i])) || s[i] == '_') {
            std::string id;
            while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '_' || s[i] == '.')) id += s[i++];
            ws();
            if (id == "min" || id == "max" || id == "ceil_div") {
                if (i >= s.size() || s[i] != '(') { err = fail("expected '(' after " + id, i); return std::nullopt; }
                ++i;
                auto a = expr();
                if (!a) return a;
                ws();
                if (i >= s.size() || s[i] != ',') { err = fail("expected ','", i); return std::nullopt; }
                ++i;
                auto b = expr();
                if (!b) return b;
                ws();
                if (i >= s.size() || s[i] != ')') { err = fail("expected ')'", i); return std::nullopt; }
                ++i;
                bool d0 = false;
                auto r = bin(*a, *b, id == "min" ? 'm' : id == "max" ? 'M' : 'c', d0);
                if (d0) { err = fail("division by zero", at); return std::nullopt; }
                return r;
            }
            if (id == "view") return Vec{env.view_w, env.view_h};
            if (id == "view.w" || id == "view.x") return Vec{env.view_w};
            if (id == "view.h" || id == "view.y") return Vec{env.view_h};
            if (id.rfind("params.", 0) == 0) {
                auto p = env.params.find(id.substr(7));
                if (p != env.params.end()) return Vec{static_cast<int64_t>(p->second)};
            }
            std::vector<std::string> known = {"view", "view.w", "view.h", "min", "max", "ceil_div"};
            for (const auto& [k, v] : env.params) known.push_back("params." + k);
            Error e = fail("unknown name '" + id + "'", at);
            suggest(e, id, known, "names");
            err = e;
            return std::nullopt;
        }
        err = fail(std::string("unexpected '") + s[i] + "'", at);
        return std::nullopt;
    }
};

} // namespace

Result<std::vector<int64_t>> eval_size(const SizeExpr& e, const SizeEnv& env) {
    if (!e.literal.empty()) return e.literal;
    if (e.text.empty()) return make_error("empty size expression", e.loc);
    Parser p{e.text, env, e.loc};
    auto v = p.expr();
    p.ws();
    if (v && p.i < e.text.size()) return p.fail(std::string("unexpected '") + e.text[p.i] + "'", p.i);
    if (!v) return *p.err;
    return *v;
}

Result<int64_t> eval_scalar(const SizeExpr& e, const SizeEnv& env) {
    auto v = eval_size(e, env);
    if (!v) return v.error();
    if (v->size() != 1) return make_error("expected a single number, the expression gives a " + std::to_string(v->size()) + "-vector", e.loc);
    return (*v)[0];
}

Result<Extent> eval_extent(const SizeExpr& e, const SizeEnv& env, int dims) {
    auto v = eval_size(e, env);
    if (!v) return v.error();
    Extent x;
    const auto& a = *v;
    if (a.size() == 1) x.w = x.h = a[0], x.d = dims == 3 ? a[0] : 1;
    else if (a.size() == 2) x.w = a[0], x.h = a[1];
    else if (a.size() == 3) x.w = a[0], x.h = a[1], x.d = a[2];
    else return make_error("a size has 1 to 3 components", e.loc);
    if (dims < 3 && a.size() == 3) return make_error("a 2D size has 2 components, not 3", e.loc);
    return x;
}

} // namespace pl::graph
