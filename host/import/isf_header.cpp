#include "import/isf.hpp"

#include "import/source_text.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <regex>

namespace pl::import {

namespace {

using json = nlohmann::json;

struct Header {
    std::string file, text;
    size_t begin = 0;  // offset of the JSON in text
    SourceLoc at(const std::string& needle, size_t from = 0) const {
        size_t p = text.find(needle, std::max(begin, from));
        auto [l, c] = line_col(text, p == std::string::npos ? begin : p);
        return {file, l, c};
    }
    Error error(const std::string& msg, const SourceLoc& loc) const {
        Error e = make_error(msg, loc);
        e.source_line = read_source_line(file, loc.line);
        return e;
    }
};

std::vector<double> numbers(const json& j) {
    std::vector<double> out;
    if (j.is_number()) out.push_back(j.get<double>());
    else if (j.is_boolean()) out.push_back(j.get<bool>() ? 1.0 : 0.0);
    else if (j.is_array())
        for (const json& v : j)
            if (v.is_number()) out.push_back(v.get<double>());
    return out;
}
std::string text_of(const json& j, const char* k) {
    if (!j.contains(k)) return {};
    if (j[k].is_string()) return j[k].get<std::string>();
    if (j[k].is_number_integer()) return std::to_string(j[k].get<long long>());
    if (j[k].is_number()) return std::to_string(j[k].get<double>());
    return {};
}

} // namespace

Result<IsfDesc> read_isf(const std::string& raw, const std::string& file) {
    Header h{file, clean_text(raw), 0};
    size_t open = h.text.find("/*");
    size_t close = open == std::string::npos ? std::string::npos : h.text.find("*/", open + 2);
    if (open == std::string::npos || close == std::string::npos)
        return h.error("not an ISF shader: no /*{ ... }*/ JSON header comment", {file, 1, 1});
    h.begin = open + 2;
    json root;
    try {
        root = json::parse(h.text.substr(h.begin, close - h.begin));
    } catch (const json::parse_error& e) {
        auto [l, c] = line_col(h.text, h.begin + (e.byte > 0 ? e.byte - 1 : 0));
        return h.error(std::string("ISF header is not valid JSON: ") + e.what(), {file, l, c});
    }
    if (!root.is_object()) return h.error("the ISF header must be a JSON object", h.at("{"));
    IsfDesc d;
    d.description = text_of(root, "DESCRIPTION");
    d.credit = text_of(root, "CREDIT");
    if (root.contains("CATEGORIES") && root["CATEGORIES"].is_array())
        for (const json& c : root["CATEGORIES"])
            if (c.is_string()) d.categories.push_back(c.get<std::string>());
    static const std::regex ident("^[A-Za-z_][A-Za-z0-9_]*$");
    static const char* types[] = {"float", "bool", "long", "color", "point2D", "event", "image", "audio", "audioFFT"};
    if (root.contains("INPUTS")) {
        if (!root["INPUTS"].is_array()) return h.error("INPUTS must be an array", h.at("\"INPUTS\""));
        for (const json& in : root["INPUTS"]) {
            IsfInput i;
            i.name = text_of(in, "NAME");
            i.type = text_of(in, "TYPE");
            i.label = text_of(in, "LABEL");
            i.loc = h.at("\"" + i.name + "\"");
            if (!std::regex_match(i.name, ident)) return h.error("input NAME '" + i.name + "' is not an identifier", i.loc);
            bool known = false;
            for (const char* t : types) known = known || i.type == t;
            if (!known) {
                Error e = h.error("input '" + i.name + "': unknown TYPE '" + i.type + "'", i.loc);
                e.hint = "ISF input types: float, bool, long, color, point2D, event, image, audio, audioFFT";
                return e;
            }
            if (in.contains("DEFAULT")) i.def = numbers(in["DEFAULT"]);
            if (in.contains("MIN")) i.min = numbers(in["MIN"]);
            if (in.contains("MAX")) i.max = numbers(in["MAX"]);
            if (in.contains("VALUES"))
                for (double v : numbers(in["VALUES"])) i.values.push_back(static_cast<int>(v));
            if (in.contains("LABELS") && in["LABELS"].is_array())
                for (const json& l : in["LABELS"]) i.labels.push_back(l.is_string() ? l.get<std::string>() : l.dump());
            d.inputs.push_back(std::move(i));
        }
    }
    if (root.contains("PASSES")) {
        if (!root["PASSES"].is_array()) return h.error("PASSES must be an array", h.at("\"PASSES\""));
        for (const json& p : root["PASSES"]) {
            IsfPass q;
            q.target = text_of(p, "TARGET");
            q.loc = q.target.empty() ? h.at("\"PASSES\"") : h.at("\"" + q.target + "\"");
            if (!q.target.empty() && !std::regex_match(q.target, ident))
                return h.error("TARGET '" + q.target + "' is not an identifier", q.loc);
            auto flag = [&](const char* k) {
                if (!p.contains(k)) return false;
                const json& v = p[k];
                return v.is_boolean() ? v.get<bool>() : v.is_number() ? v.get<double>() != 0 : v.is_string() && v.get<std::string>() == "true";
            };
            q.persistent = flag("PERSISTENT");
            q.is_float = flag("FLOAT");
            q.width = text_of(p, "WIDTH");
            q.height = text_of(p, "HEIGHT");
            // The expressions' own columns (searched from this pass's TARGET on).
            size_t from = q.target.empty() ? 0 : h.text.find("\"" + q.target + "\"", h.begin);
            if (!q.width.empty()) q.width_loc = h.at("\"" + q.width + "\"", from == std::string::npos ? 0 : from);
            if (!q.height.empty()) q.height_loc = h.at("\"" + q.height + "\"", from == std::string::npos ? 0 : from);
            d.passes.push_back(std::move(q));
        }
    }
    if (d.passes.empty()) d.passes.push_back({});
    if (root.contains("IMPORTED") && root["IMPORTED"].is_object())
        for (const auto& [name, v] : root["IMPORTED"].items())
            d.imported.emplace_back(name, text_of(v, "PATH"));
    // Old GLSL in the body (the header is a comment and stays, so lines do not move).
    std::string code = replace_word(h.text, "gl_FragColor", "isf_FragColor");
    code = replace_word(code, "texture2D", "texture");
    code = replace_word(code, "texture2DRect", "texture");
    code = replace_word(code, "varying", "in");
    d.code = glsl_es_to_450(code);
    return d;
}

Result<std::string> isf_size_expression(const std::string& e, const SourceLoc& loc, const std::map<std::string, std::string>& terms) {
    std::string out;
    for (size_t i = 0; i < e.size();) {
        char c = e[i];
        if (c == '$') {
            size_t j = i + 1;
            while (j < e.size() && (std::isalnum(static_cast<unsigned char>(e[j])) || e[j] == '_')) ++j;
            const std::string n = e.substr(i + 1, j - i - 1);
            auto t = terms.find(n);
            out += n == "WIDTH" ? "view.w" : n == "HEIGHT" ? "view.h" : t != terms.end() ? t->second : "params." + n;
            i = j;
        } else if (std::isalpha(static_cast<unsigned char>(c))) {
            size_t j = i;
            while (j < e.size() && std::isalnum(static_cast<unsigned char>(e[j]))) ++j;
            const std::string f = e.substr(i, j - i);
            if (f == "floor" || f == "round") out += "";  // integer arithmetic floors already
            else if (f == "max" || f == "min") out += f;
            else {
                Error err = make_error("size expression '" + e + "': '" + f + "' cannot be evaluated by passlab's integer size expressions", loc);
                err.hint = "supported: $WIDTH, $HEIGHT, $input, integers, + - * /, floor, max, min";
                return err;
            }
            i = j;
        } else if (std::isdigit(static_cast<unsigned char>(c))) {
            size_t j = i;
            while (j < e.size() && std::isdigit(static_cast<unsigned char>(e[j]))) ++j;
            if (j < e.size() && e[j] == '.') {
                size_t k = j + 1;
                while (k < e.size() && std::isdigit(static_cast<unsigned char>(e[k]))) ++k;
                if (e.find_first_not_of('0', j + 1) < k) {
                    Error err = make_error("size expression '" + e + "': the decimal '" + e.substr(i, k - i) +
                                               "' cannot be expressed (passlab size expressions are integers)", loc);
                    err.hint = "write $WIDTH/2 instead of $WIDTH*0.5";
                    return err;
                }
                out += e.substr(i, j - i);  // 2.0 -> 2
                i = k;
            } else {
                out += e.substr(i, j - i);
                i = j;
            }
        } else {
            out += c;
            ++i;
        }
    }
    return out;
}

} // namespace pl::import
