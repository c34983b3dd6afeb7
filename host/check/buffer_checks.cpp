#include "check/buffer_checks.hpp"

#include "graph/readable.hpp"

#include <cmath>
#include <cstring>

namespace pl::check {

namespace {

std::string show(double v, WordType t) {
    if (t == WordType::f32 || !std::isfinite(v)) return fmt(v);
    char b[48];
    if (t == WordType::uint && v > 65535) std::snprintf(b, sizeof b, "%.0f (0x%x)", v, static_cast<uint32_t>(v));
    else std::snprintf(b, sizeof b, "%.0f", v);
    return b;
}

const char* type_name(WordType t) { return t == WordType::uint ? "uint" : t == WordType::sint ? "int" : "float"; }

// `expect` as numbers: literal(s) or an expression of the view and params.
Result<std::vector<double>> expected(const graph::CheckDesc& c, const graph::SizeEnv& env) {
    auto it = c.args.find("expect");
    if (it == c.args.end()) return std::vector<double>{};
    if (auto s = std::get_if<std::string>(&it->second)) {
        auto v = graph::eval_scalar(graph::SizeExpr{*s, {}, c.keys.at("expect", c.loc)}, env);
        if (!v) return v.error();
        return std::vector<double>{static_cast<double>(*v)};
    }
    return vec(c.args, "expect");
}

// What a float buffer holds for a written number: the nearest float, so that expect = 0.1
// matches a shader's 0.1 exactly.
double as_stored(double v, WordType t) { return t == WordType::f32 ? double(static_cast<float>(v)) : v; }

} // namespace

Result<Selection> select(const Args& a, size_t words) {
    Selection s;
    std::string type = str(a, "type", "float");
    s.type = type == "uint" ? WordType::uint : type == "int" ? WordType::sint : WordType::f32;
    s.stride = static_cast<size_t>(num(a, "stride", 4));
    s.field = static_cast<size_t>(num(a, "field", 0));
    size_t elements = graph::buffer_elements(words * 4, s.stride, s.field);
    auto range = vec(a, "range");
    if (a.count("index")) s.first = static_cast<size_t>(num(a, "index", 0)), s.count = 1;
    else if (range.size() == 2) s.first = static_cast<size_t>(range[0]), s.count = static_cast<size_t>(range[1]);
    else s.first = 0, s.count = elements;
    std::string name = str(a, "buffer");
    s.label = "buffer '" + name + "'[" + std::to_string(s.first) + (s.count == 1 ? "" : ".." + std::to_string(s.first + s.count - 1)) + "]";
    if (s.stride != 4 || s.field) s.label += " field " + std::to_string(s.field) + " (stride " + std::to_string(s.stride) + ")";
    if (s.first + s.count > elements || s.count == 0) {
        Error e = make_error(s.label + " is outside the buffer: " + std::to_string(words * 4) + " bytes hold " + std::to_string(elements) +
                             " element(s) of " + std::to_string(s.stride) + " bytes");
        e.resource = name;
        return e;
    }
    return s;
}

std::vector<double> decode(const std::vector<uint32_t>& words, const Selection& s) {
    std::vector<double> out(s.count);
    for (size_t i = 0; i < s.count; ++i) {
        uint32_t w = words[((s.first + i) * s.stride + s.field) / 4];
        if (s.type == WordType::uint) out[i] = w;
        else if (s.type == WordType::sint) out[i] = static_cast<int32_t>(w);
        else {
            float f;
            std::memcpy(&f, &w, 4);
            out[i] = f;
        }
    }
    return out;
}

CheckResult buffer_property(const std::vector<uint32_t>& words, const graph::CheckDesc& c, const graph::SizeEnv& env) {
    CheckResult r;
    r.what = c.kind + " buffer '" + str(c.args, "buffer") + "'";
    auto sel = select(c.args, words.size());
    if (!sel) {
        r.detail = sel.error().message;
        return r;
    }
    const Selection& s = *sel;
    r.what = c.kind + " " + s.label;
    const bool integer = s.type != WordType::f32;
    std::vector<double> v = decode(words, s);
    auto exp = expected(c, env);
    if (!exp) {
        r.detail = exp.error().message;
        return r;
    }
    auto at = [&](size_t i) { return "element " + std::to_string(s.first + i); };

    if (c.kind == "probe") {
        double tol = num(c.args, "tol", 0.0);
        size_t bad = 0;
        std::string first;
        double worst = 0;
        for (size_t i = 0; i < v.size(); ++i) {
            double e = as_stored((*exp)[exp->size() == 1 ? 0 : i], s.type);
            double d = std::fabs(v[i] - e);
            bool ok = integer ? v[i] == e : d <= tol;
            worst = std::isfinite(d) ? std::max(worst, d) : INFINITY;
            if (!ok && bad++ < 3) first += (first.empty() ? "" : "; ") + at(i) + " = " + show(v[i], s.type) + ", expected " + show(e, s.type);
        }
        r.passed = bad == 0;
        if (v.size() == 1) r.detail = "got " + show(v[0], s.type) + (integer ? ", expected " + show(as_stored((*exp)[0], s.type), s.type) + " exactly" : ", error " + fmt(worst) + " (tol " + fmt(tol) + ")");
        else r.detail = std::to_string(bad) + " of " + std::to_string(v.size()) + " element(s) differ" + (first.empty() ? "" : ": " + first) +
                        (integer ? " (exact)" : "; max error " + fmt(worst) + " (tol " + fmt(tol) + ")");
        return r;
    }
    if (c.kind == "no_nan") {
        size_t bad = 0, first = 0;
        for (size_t i = 0; i < v.size(); ++i)
            if (!std::isfinite(v[i]) && !bad++) first = i;
        r.passed = bad == 0;
        r.detail = std::to_string(bad) + " NaN/Inf value(s)" + (bad ? ", the first at " + at(first) : "");
        return r;
    }
    if (c.kind == "range") {
        double lo = num(c.args, "min", -INFINITY), hi = num(c.args, "max", INFINITY), mn = INFINITY, mx = -INFINITY;
        size_t bad = 0, first = 0;
        for (size_t i = 0; i < v.size(); ++i) {
            mn = std::min(mn, v[i]), mx = std::max(mx, v[i]);
            if (!(v[i] >= lo && v[i] <= hi) && !bad++) first = i;
        }
        r.passed = bad == 0;
        r.detail = "values in [" + show(mn, s.type) + ", " + show(mx, s.type) + "], allowed [" + show(lo, s.type) + ", " + show(hi, s.type) + "]";
        if (bad) r.detail += "; " + std::to_string(bad) + " outside, the first " + at(first) + " = " + show(v[first], s.type);
        return r;
    }
    if (c.kind == "mean") {
        double sum = 0;
        for (double x : v) sum += x;
        double mean = sum / double(v.size()), e = num(c.args, "expect", 0.0), tol = num(c.args, "tol", 0.01);
        r.passed = std::fabs(mean - e) <= tol;
        r.detail = "mean " + fmt(mean) + " of " + std::to_string(v.size()) + " element(s), expected " + fmt(e) + " ± " + fmt(tol);
        return r;
    }
    if (c.kind == "sum") {
        double e = (*exp)[0];
        if (integer) {
            int64_t total = 0;  // exact: 2^32 x 2^31 elements cannot overflow 63 bits
            for (double x : v) total += static_cast<int64_t>(x);
            r.passed = double(total) == e;
            r.detail = "sum " + std::to_string(total) + " of " + std::to_string(v.size()) + " element(s), expected " + show(e, WordType::sint) + " exactly";
        } else {
            double total = 0, tol = num(c.args, "tol", 0.0);
            for (double x : v) total += x;
            r.passed = std::fabs(total - e) <= tol;
            r.detail = "sum " + fmt(total) + " of " + std::to_string(v.size()) + " element(s), expected " + fmt(e) + " ± " + fmt(tol);
        }
        return r;
    }
    if (c.kind == "count") {
        bool eq = c.args.count("value") > 0;
        double lo = eq ? as_stored(num(c.args, "value", 0), s.type) : num(c.args, "min", -INFINITY);
        double hi = eq ? lo : num(c.args, "max", INFINITY);
        size_t n = 0;
        for (double x : v) n += x >= lo && x <= hi;
        std::string which = eq ? "equal to " + show(lo, s.type) : "in [" + show(lo, s.type) + ", " + show(hi, s.type) + "]";
        r.passed = double(n) == (*exp)[0];
        r.detail = std::to_string(n) + " of " + std::to_string(v.size()) + " element(s) " + which + ", expected " + show((*exp)[0], WordType::sint);
        return r;
    }
    if (c.kind == "sorted") {
        // Within each group of `group` consecutive elements (default: one group), every element
        // is <= (ascending) or >= (descending) the next; NaN is never in order.
        size_t group = static_cast<size_t>(num(c.args, "group", double(v.size())));
        bool desc = str(c.args, "order", "ascending") == "descending";
        // tol (floats): a step back by at most tol still counts as in order (a weighted sum that
        // should be constant moves in its last bits).
        double tol = num(c.args, "tol", 0.0);
        size_t bad = 0, bad_groups = 0;
        std::string first;
        for (size_t g0 = 0; g0 < v.size(); g0 += group) {
            size_t end = std::min(v.size(), g0 + group);
            bool group_bad = false;
            for (size_t i = g0; i + 1 < end; ++i) {
                bool ok = desc ? v[i] >= v[i + 1] - tol : v[i] <= v[i + 1] + tol;
                if (ok) continue;
                group_bad = true;
                if (!bad++)
                    first = "group " + std::to_string(g0 / group) + ": " + at(i) + " = " + show(v[i], s.type) + (desc ? " < " : " > ") +
                            at(i + 1) + " = " + show(v[i + 1], s.type);
            }
            bad_groups += group_bad;
        }
        r.passed = bad == 0;
        r.what += std::string(desc ? " descending" : " ascending") + " in groups of " + std::to_string(group) + (tol > 0 ? " (tol " + fmt(tol) + ")" : "");
        r.detail = std::to_string(bad_groups) + " of " + std::to_string((v.size() + group - 1) / group) + " group(s) out of order" +
                   (first.empty() ? "" : " (" + std::to_string(bad) + " pair(s); first: " + first + ")");
        return r;
    }
    r.detail = "no buffer check of kind '" + c.kind + "' (" + std::string(type_name(s.type)) + ")";
    return r;
}

CheckResult buffer_reduction(const std::vector<uint32_t>& words, const graph::CheckDesc& c, const image::Image& of, const Mask& mask) {
    CheckResult r;
    std::string op = str(c.args, "op"), image = str(c.args, "of");
    r.what = "reduction buffer '" + str(c.args, "buffer") + "'";
    auto sel = select(c.args, words.size());
    if (!sel) {
        r.detail = sel.error().message;
        return r;
    }
    const Selection& s = *sel;
    const size_t ch = static_cast<size_t>(num(c.args, "of_channel", 0));
    r.what = "reduction " + s.label + " = " + op + " of '" + image + "' channel " + std::to_string(ch);
    // In double: min and max are one of the (float) values exactly; the sum is exact far beyond
    // what a float sum on the GPU keeps.
    double acc = op == "min" ? INFINITY : op == "max" ? -INFINITY : 0.0;
    size_t counted = 0;
    for (size_t p = 0; p < of.pixels.size() / 4; ++p) {
        if (!mask.counts(p)) continue;
        double x = of.pixels[p * 4 + ch];
        acc = op == "min" ? std::min(acc, x) : op == "max" ? std::max(acc, x) : acc + x;
        ++counted;
    }
    if (!counted) {
        r.detail = "the mask counts no pixel of '" + image + "': nothing to reduce";
        return r;
    }
    const bool integer = s.type != WordType::f32;
    const double tol = num(c.args, "tol", 0.0);
    std::vector<double> v = decode(words, s);
    size_t bad = 0;
    double worst = 0;
    for (double x : v) {
        double d = std::fabs(x - acc);
        worst = std::isfinite(d) ? std::max(worst, d) : INFINITY;
        bad += integer ? x != acc : !(d <= tol);
    }
    r.passed = bad == 0;
    r.detail = "host " + op + " over " + std::to_string(counted) + " pixel(s) = " + show(acc, s.type) + "; buffer " +
               (v.size() == 1 ? "holds " + show(v[0], s.type) : std::to_string(bad) + " of " + std::to_string(v.size()) + " element(s) differ") +
               (integer ? " (exact)" : ", error " + fmt(worst) + " (tol " + fmt(tol) + ")");
    return r;
}

} // namespace pl::check
