// A recursive-descent evaluator over the expression text. No AST: expressions are a few tokens
// long and evaluated once per (re)build, and evaluating while parsing keeps errors next to the
// token that caused them. One evaluator serves integer sizes (int64_t: floor division, overflow
// checks) and float expressions (double: camera values), so both have the same grammar, names
// and error messages; the few differences are the `if constexpr (kFloat)` branches.
#include "graph/sizeexpr.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <type_traits>

namespace pl::graph {

namespace {

int64_t floor_div(int64_t x, int64_t y) { return x / y - ((x % y != 0) && ((x < 0) != (y < 0))); }
int64_t floor_mod(int64_t x, int64_t y) { return x - floor_div(x, y) * y; }

bool is_float_function(const std::string& id) {
    for (const char* f : {"sin", "cos", "tan", "sqrt", "abs", "radians", "normalize"})
        if (id == f) return true;
    return false;
}

template <class T>
class Evaluator {
    using Vec = std::vector<T>;
    static constexpr bool kFloat = std::is_same_v<T, double>;

  public:
    Evaluator(const std::string& text, const SourceLoc& loc, const SizeEnv& env) : s_(text), env_(env), loc_(loc) {}

    Result<Vec> run() {
        auto v = expr();
        if (!v) return *err_;
        ws();
        if (i_ < s_.size()) {
            if (s_[i_] == ')') return fail("unbalanced ')'", i_);
            if (std::isdigit(static_cast<unsigned char>(s_[i_])) || std::isalpha(static_cast<unsigned char>(s_[i_])))
                return fail("expected an operator (+ - * / % or a comparison) before '" + word_at(i_) + "'", i_);
            return fail("unexpected '" + std::string(1, s_[i_]) + "'", i_);
        }
        return *v;
    }

  private:
    const std::string& s_;
    const SizeEnv& env_;
    const SourceLoc& loc_;
    size_t i_ = 0;
    std::optional<Error> err_;

    Error fail(const std::string& msg, size_t at) {
        SourceLoc l = loc_;
        if (l.col > 0) l.col += static_cast<int>(at) + 1;  // +1: the opening quote
        return make_error(std::string(kFloat ? "expression" : "size expression") + " \"" + s_ + "\": " + msg, l);
    }
    std::nullopt_t set(Error e) {
        err_ = std::move(e);
        return std::nullopt;
    }
    void ws() {
        while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
    }
    bool ident_char(char c) const { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.'; }
    std::string word_at(size_t at) const {
        size_t e = at;
        while (e < s_.size() && ident_char(s_[e])) ++e;
        return s_.substr(at, std::max<size_t>(e - at, 1));
    }

    // Component-wise a OP b, scalars broadcast. `at` is the column of the right operand.
    std::optional<Vec> apply(const Vec& a, const Vec& b, char op, size_t op_at, size_t at) {
        if (a.size() != 1 && b.size() != 1 && a.size() != b.size())
            return set(fail("cannot combine a " + std::to_string(a.size()) + "-vector with a " + std::to_string(b.size()) + "-vector",
                            op_at));
        size_t n = std::max(a.size(), b.size());
        Vec r(n);
        for (size_t k = 0; k < n; ++k) {
            T x = a.size() == 1 ? a[0] : a[k], y = b.size() == 1 ? b[0] : b[k];
            if constexpr (kFloat) {
                if (op == 'l' && !(x > 0)) return set(fail("log2 needs a value > 0", at));
                if (!apply_float(x, y, op, r[k])) return set(fail("division by zero", at));
                if (!std::isfinite(r[k])) return set(fail("the value is too large", op_at));
            } else {
                bool overflow = false;
                switch (op) {
                case '+': overflow = __builtin_add_overflow(x, y, &r[k]); break;
                case '-': overflow = __builtin_sub_overflow(x, y, &r[k]); break;
                case '*': overflow = __builtin_mul_overflow(x, y, &r[k]); break;
                case '/':
                case '%':
                case 'c':
                    if (y == 0) return set(fail("division by zero", at));
                    if (x == INT64_MIN && y == -1) overflow = true;
                    else if (op == '/') r[k] = floor_div(x, y);
                    else if (op == '%') r[k] = floor_mod(x, y);
                    else r[k] = -floor_div(-x, y);  // ceil(x / y); x > INT64_MIN here
                    break;
                case 'l':  // log2(x): one operand, the other is a dummy
                    if (x < 1) return set(fail("log2 needs a value of at least 1, not " + std::to_string(x), at));
                    r[k] = 63 - __builtin_clzll(static_cast<uint64_t>(x));  // floor(log2(x))
                    break;
                case 'm': r[k] = std::min(x, y); break;
                case 'M': r[k] = std::max(x, y); break;
                }
                if (overflow) return set(fail("the value is too large", op_at));
            }
        }
        return r;
    }

    // Real arithmetic; false on division by zero. % and ceil_div floor like their integer forms.
    static bool apply_float(double x, double y, char op, double& r) {
        switch (op) {
        case '+': r = x + y; return true;
        case '-': r = x - y; return true;
        case '*': r = x * y; return true;
        case 'm': r = std::min(x, y); return true;
        case 'M': r = std::max(x, y); return true;
        case 'l': r = std::log2(x); return true;  // x > 0: checked by the caller
        default: break;
        }
        if (y == 0) return false;
        r = op == '/' ? x / y : op == '%' ? x - std::floor(x / y) * y : std::ceil(x / y);
        return true;
    }

    // Skips blanks and consumes `c`; else the error (at `at`, or where `c` was expected).
    bool expect(char c, const std::string& msg, size_t at = std::string::npos) {
        ws();
        if (i_ < s_.size() && s_[i_] == c) return ++i_, true;
        set(fail(msg, at == std::string::npos ? i_ : at));
        return false;
    }

    // Float expressions only: sin cos tan sqrt abs radians normalize, per component except
    // normalize (the vector divided by its length).
    std::optional<Vec> call1(const std::string& fn, size_t at) {
        if (!expect('(', fn + " takes one argument: " + fn + "(x)", at)) return std::nullopt;
        auto a = expr();
        if (!a || !expect(')', "expected ')' to close " + fn + "(")) return std::nullopt;
        Vec r = *a;
        if (fn == "normalize") {
            double len = 0;
            for (T x : r) len += x * x;
            if (!(len > 0)) return set(fail("normalize of a zero vector", at));
            for (T& x : r) x /= std::sqrt(len);
            return r;
        }
        for (T& x : r) {
            if (fn == "sqrt" && x < 0) return set(fail("sqrt of a negative value", at));
            x = fn == "sin" ? std::sin(x) : fn == "cos" ? std::cos(x) : fn == "tan" ? std::tan(x)
              : fn == "sqrt" ? std::sqrt(x) : fn == "abs" ? std::fabs(x) : x * (3.14159265358979323846 / 180.0);
        }
        return r;
    }

    // The loosest level: one optional comparison, 1 if it holds and 0 if not, per component.
    // Comparisons do not chain ("a < b < c" is an error, not the (a < b) < c that C reads), and
    // an enum param compares with an option's quoted name: "params.show == 'taa'".
    std::optional<Vec> expr() {
        ws();
        const size_t left_at = i_;
        auto a = sum();
        if (!a) return a;
        ws();
        const size_t op_at = i_;
        const std::string op = comparison_at(i_);
        if (op.empty()) {
            if (i_ < s_.size() && s_[i_] == '=') return set(fail("'=' is not an operator: compare with ==", i_));
            return a;
        }
        i_ += op.size();
        ws();
        const size_t at = i_;
        std::optional<Vec> b;
        if (i_ < s_.size() && (s_[i_] == '\'' || s_[i_] == '"')) b = option_index(trimmed(left_at, op_at), at);
        else b = sum();
        if (!b) return b;
        if (a->size() != 1 && b->size() != 1 && a->size() != b->size())
            return set(fail("cannot compare a " + std::to_string(a->size()) + "-vector with a " + std::to_string(b->size()) + "-vector",
                            op_at));
        Vec r(std::max(a->size(), b->size()));
        for (size_t k = 0; k < r.size(); ++k) {
            T x = a->size() == 1 ? (*a)[0] : (*a)[k], y = b->size() == 1 ? (*b)[0] : (*b)[k];
            bool holds = op == "==" ? x == y : op == "!=" ? x != y : op == "<" ? x < y : op == "<=" ? x <= y : op == ">" ? x > y : x >= y;
            r[k] = holds ? T(1) : T(0);
        }
        ws();
        if (!comparison_at(i_).empty())
            return set(fail("comparisons do not chain: write \"a < b\" and \"b < c\" as a product, (a < b) * (b < c)", i_));
        return r;
    }

    // The comparison operator at `at`, or "" (two-character operators first).
    std::string comparison_at(size_t at) const {
        if (at >= s_.size()) return "";
        if (at + 1 < s_.size() && s_[at + 1] == '=' && (s_[at] == '=' || s_[at] == '!' || s_[at] == '<' || s_[at] == '>'))
            return s_.substr(at, 2);
        if (s_[at] == '<' || s_[at] == '>') return std::string(1, s_[at]);
        return "";
    }

    std::string trimmed(size_t from, size_t to) const {
        while (from < to && std::isspace(static_cast<unsigned char>(s_[from]))) ++from;
        while (to > from && std::isspace(static_cast<unsigned char>(s_[to - 1]))) --to;
        return s_.substr(from, to - from);
    }

    // 'option' (or "option") after `left`, which must name an enum param: the option's index.
    std::optional<Vec> option_index(const std::string& left, size_t at) {
        const char quote = s_[i_++];
        const size_t end = s_.find(quote, i_);
        if (end == std::string::npos) return set(fail("the quoted name has no closing " + std::string(1, quote), at));
        const std::string name = s_.substr(i_, end - i_);
        i_ = end + 1;
        auto p = left.rfind("params.", 0) == 0 ? env_.options.find(left.substr(7)) : env_.options.end();
        if (p == env_.options.end()) {
            Error e = fail("a quoted name compares with an enum param, as in \"params.mode == 'fast'\"; '" + left + "' is not one", at);
            std::vector<std::string> enums;
            for (const auto& [k, v] : env_.options) enums.push_back("params." + k);
            if (!enums.empty()) suggest(e, left, enums, "enum params");
            return set(std::move(e));
        }
        const auto& opts = p->second;
        for (size_t k = 0; k < opts.size(); ++k)
            if (opts[k] == name) return Vec{T(static_cast<int64_t>(k))};
        Error e = fail("'" + name + "' is not an option of " + left, at + 1);
        suggest(e, name, opts, "options");
        return set(std::move(e));
    }

    std::optional<Vec> sum() {
        auto a = term();
        while (a) {
            ws();
            if (i_ >= s_.size() || (s_[i_] != '+' && s_[i_] != '-')) break;
            size_t op_at = i_;
            char op = s_[i_++];
            ws();
            size_t at = i_;
            auto b = term();
            if (!b) return b;
            a = apply(*a, *b, op, op_at, at);
        }
        return a;
    }

    std::optional<Vec> term() {
        auto a = unary();
        while (a) {
            ws();
            if (i_ >= s_.size() || (s_[i_] != '*' && s_[i_] != '/' && s_[i_] != '%')) break;
            size_t op_at = i_;
            char op = s_[i_++];
            ws();
            size_t at = i_;
            auto b = unary();
            if (!b) return b;
            a = apply(*a, *b, op, op_at, at);
        }
        return a;
    }

    // Every nesting (parenthesis, call argument, unary sign) passes through unary(): a bound
    // there keeps recursion finite; 10,000 nested '(' overflowed the stack before.
    static constexpr int kMaxDepth = 100;
    int depth_ = 0;
    struct DepthGuard {
        int& d;
        ~DepthGuard() { --d; }
    };

    std::optional<Vec> unary() {
        DepthGuard guard{++depth_};
        if (depth_ > kMaxDepth) return set(fail("nested more than " + std::to_string(kMaxDepth) + " deep", i_));
        ws();
        if (i_ < s_.size() && s_[i_] == '-') {
            size_t at = i_++;
            auto v = unary();
            if (v)
                for (auto& x : *v) {
                    if constexpr (!kFloat)
                        if (x == INT64_MIN) return set(fail("the value is too large", at));
                    x = -x;
                }
            return v;
        }
        if (i_ < s_.size() && s_[i_] == '+') {  // unary plus: harmless, accepted
            ++i_;
            return unary();
        }
        return primary();
    }

    std::optional<Vec> call(const std::string& fn, size_t at) {
        ws();
        const bool unary_fn = fn == "log2";
        if (i_ >= s_.size() || s_[i_] != '(')
            return set(fail(fn + (unary_fn ? " takes one argument: " + fn + "(x)" : " takes two arguments: " + fn + "(a, b)"), at));
        ++i_;
        size_t a_at = i_;
        auto a = expr();
        if (!a) return a;
        ws();
        if (unary_fn) {
            if (i_ >= s_.size() || s_[i_] != ')') return set(fail("expected ')' to close " + fn + "( (it takes one argument)", i_));
            ++i_;
            return apply(*a, Vec{1}, 'l', at, a_at);
        }
        if (i_ >= s_.size() || s_[i_] != ',') return set(fail("expected ',' (" + fn + " takes two arguments)", i_));
        ++i_;
        ws();
        size_t b_at = i_;
        auto b = expr();
        if (!b) return b;
        ws();
        if (i_ >= s_.size() || s_[i_] != ')') return set(fail("expected ')' to close " + fn + "(", i_));
        ++i_;
        if (fn == "vec2") {  // (a, b) from two scalars: a size whose sides follow different rules
            if (a->size() != 1 || b->size() != 1) return set(fail("vec2(a, b) takes two scalars", at));
            return Vec{(*a)[0], (*b)[0]};
        }
        return apply(*a, *b, fn == "min" ? 'm' : fn == "max" ? 'M' : 'c', at, b_at);
    }

    std::optional<Vec> primary() {
        ws();
        if (i_ >= s_.size()) return set(fail("the expression ends where a value was expected", i_));
        size_t at = i_;
        char c = s_[i_];
        if constexpr (kFloat)
            if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number(at);
        if (std::isdigit(static_cast<unsigned char>(c))) {
            int64_t v = 0;
            while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) {
                if (__builtin_mul_overflow(v, 10, &v) || __builtin_add_overflow(v, s_[i_] - '0', &v))
                    return set(fail("the number is too large", at));
                ++i_;
            }
            if (i_ < s_.size() && (s_[i_] == '.' || std::isalpha(static_cast<unsigned char>(s_[i_]))))
                return set(fail("sizes are integers: '" + word_at(at) + "' is not one", at));
            return Vec{T(v)};
        }
        if (c == '(') {
            ++i_;
            auto v = expr();
            if (!v) return v;
            ws();
            if (i_ >= s_.size() || s_[i_] != ')') return set(fail("expected ')' to close the '(' at column " + std::to_string(col(at)), i_));
            ++i_;
            return v;
        }
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            std::string id;
            while (i_ < s_.size() && ident_char(s_[i_])) id += s_[i_++];
            if (id == "min" || id == "max" || id == "ceil_div" || id == "log2" || id == "vec2") return call(id, at);
            if (auto l = env_.locals.find(id); l != env_.locals.end()) return Vec{T(l->second)};
            if constexpr (kFloat)
                if (is_float_function(id)) return call1(id, at);
            if (id == "view") return Vec{T(env_.view_w), T(env_.view_h)};
            if (id == "view.w" || id == "view.x") return Vec{T(env_.view_w)};
            if (id == "view.h" || id == "view.y") return Vec{T(env_.view_h)};
            if constexpr (kFloat)
                if (auto v = float_param(id)) return v;
            if (id.rfind("params.", 0) == 0) {
                auto p = env_.params.find(id.substr(7));
                if (p != env_.params.end()) {
                    double v = p->second;
                    if (!(v > -9.2e18 && v < 9.2e18)) return set(fail("param '" + p->first + "' is out of range", at));
                    return Vec{T(static_cast<int64_t>(v))};  // floats truncate toward zero
                }
            }
            Error e = fail("unknown name '" + id + "'", at);
            auto names = kFloat ? float_names(env_) : size_names(env_);
            suggest(e, id, names, "names");
            return set(std::move(e));
        }
        if (c == '\'' || c == '"')
            return set(fail("a quoted option name goes right of a comparison with an enum param: \"params.mode == 'fast'\"", at));
        return set(fail("unexpected '" + std::string(1, c) + "'", at));
    }

    // A decimal number: 2, 0.5, .5, 1e-3.
    std::optional<Vec> number(size_t at) {
        const char* begin = s_.c_str() + at;
        char* end = nullptr;
        double v = std::strtod(begin, &end);
        if (end == begin) return set(fail("'" + word_at(at) + "' is not a number", at));
        i_ = at + static_cast<size_t>(end - begin);
        if (i_ < s_.size() && (std::isalpha(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_'))
            return set(fail("'" + word_at(at) + "' is not a number", at));
        if (!std::isfinite(v)) return set(fail("the number is too large", at));
        return Vec{T(v)};
    }

    // params.NAME (every component of a vector param) or params.NAME.x (one: x y z w or r g b a).
    std::optional<Vec> float_param(const std::string& id) const {
        if (id.rfind("params.", 0) != 0) return std::nullopt;
        std::string name = id.substr(7);
        if (auto p = env_.vectors.find(name); p != env_.vectors.end()) return p->second;
        if (auto p = env_.params.find(name); p != env_.params.end()) return Vec{p->second};  // untruncated
        size_t dot = name.rfind('.');
        if (dot == std::string::npos || dot + 2 != name.size()) return std::nullopt;
        auto p = env_.vectors.find(name.substr(0, dot));
        size_t k = std::string("xyzw").find(name[dot + 1]);
        if (k == std::string::npos) k = std::string("rgba").find(name[dot + 1]);
        if (p == env_.vectors.end() || k >= p->second.size()) return std::nullopt;
        return Vec{p->second[k]};
    }

    int col(size_t at) const { return loc_.col > 0 ? loc_.col + 1 + static_cast<int>(at) : static_cast<int>(at) + 1; }
};

} // namespace

std::vector<std::string> float_names(const SizeEnv& env) {
    std::vector<std::string> names = {"view", "view.w", "view.h"};
    for (const auto& [k, v] : env.params)
        if (!env.vectors.count(k)) names.push_back("params." + k);
    for (const auto& [k, v] : env.vectors) {
        names.push_back("params." + k);
        for (size_t c = 0; v.size() > 1 && c < v.size(); ++c) names.push_back("params." + k + "." + "xyzw"[c]);
    }
    names.insert(names.end(), {"min", "max", "sin", "cos", "tan", "sqrt", "abs", "radians", "normalize"});
    return names;
}

Result<std::vector<double>> eval_floats(const FloatExpr& e, const SizeEnv& env) {
    if (!e.literal.empty()) return e.literal;
    if (e.text.find_first_not_of(" \t") == std::string::npos) return make_error("empty expression", e.loc);
    return Evaluator<double>(e.text, e.loc, env).run();
}

std::vector<std::string> size_names(const SizeEnv& env) {
    std::vector<std::string> names = {"view", "view.w", "view.h"};
    for (const auto& [k, v] : env.params) names.push_back("params." + k);
    for (const auto& [k, v] : env.locals) names.push_back(k);
    names.insert(names.end(), {"min", "max", "ceil_div", "log2", "vec2"});
    return names;
}

Result<std::vector<int64_t>> eval_size(const SizeExpr& e, const SizeEnv& env) {
    if (!e.literal.empty()) return e.literal;
    if (e.text.find_first_not_of(" \t") == std::string::npos) return make_error("empty size expression", e.loc);
    return Evaluator<int64_t>(e.text, e.loc, env).run();
}

Result<int64_t> eval_scalar(const SizeExpr& e, const SizeEnv& env) {
    auto v = eval_size(e, env);
    if (!v) return v.error();
    if (v->size() != 1) {
        Error err = make_error("expected a single number; " + std::string(e.text.empty() ? "the size" : "\"" + e.text + "\"") +
                                   " is a " + std::to_string(v->size()) + "-vector",
                               e.loc);
        if (e.text.find("view") != std::string::npos) err.hint = "use view.w or view.h for one side of the view";
        return err;
    }
    return (*v)[0];
}

Result<Extent> eval_extent(const SizeExpr& e, const SizeEnv& env, int dims) {
    auto v = eval_size(e, env);
    if (!v) return v.error();
    Extent x;
    const auto& a = *v;
    if (a.size() == 1) {
        x.w = x.h = a[0];
        x.d = dims == 3 ? a[0] : 1;
    } else if (a.size() == 2) {
        x.w = a[0];
        x.h = a[1];
    } else if (a.size() == 3 && dims == 3) {
        x.w = a[0];
        x.h = a[1];
        x.d = a[2];
    } else if (a.size() == 3) {
        return make_error("a 2D size has 1 or 2 components, not 3 (only kind = \"3d\" images have a depth)", e.loc);
    } else {
        return make_error("a size has 1 to 3 components, not " + std::to_string(a.size()), e.loc);
    }
    return x;
}

} // namespace pl::graph
