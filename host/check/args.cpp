#include "check/args.hpp"

#include <cstdio>

namespace pl::check {

double num(const Args& args, const std::string& k, double def) {
    auto it = args.find(k);
    if (it == args.end()) return def;
    if (auto d = std::get_if<double>(&it->second)) return *d;
    if (auto b = std::get_if<bool>(&it->second)) return *b ? 1.0 : 0.0;
    return def;
}

std::vector<double> vec(const Args& args, const std::string& k) {
    auto it = args.find(k);
    if (it == args.end()) return {};
    if (auto v = std::get_if<std::vector<double>>(&it->second)) return *v;
    if (auto d = std::get_if<double>(&it->second)) return {*d};
    return {};
}

std::string str(const Args& args, const std::string& k, const std::string& def) {
    auto it = args.find(k);
    if (it == args.end()) return def;
    if (auto s = std::get_if<std::string>(&it->second)) return *s;
    return def;
}

std::vector<int> channels(const Args& args) {
    std::vector<int> out;
    for (double c : vec(args, "channels")) out.push_back(static_cast<int>(c));
    if (args.count("channel")) out = {static_cast<int>(num(args, "channel", 0))};
    // The parser refuses channels outside 0..3; this keeps a check from ever indexing past a
    // texel's four floats even if one got through (it once read out of bounds).
    std::erase_if(out, [](int c) { return c < 0 || c > 3; });
    if (out.empty()) out = {0, 1, 2};
    return out;
}

std::string fmt(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}

} // namespace pl::check
