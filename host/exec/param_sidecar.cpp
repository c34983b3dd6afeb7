#include "exec/param_sidecar.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace pl::exec {

fs::path sidecar_path(const fs::path& preset_toml) {
    return preset_toml.parent_path() / (preset_toml.stem().string() + ".params.toml");
}

std::string format_param_value(const graph::ParamDesc& p, const std::array<double, 4>& v) {
    using graph::ParamType;
    char buf[64];
    switch (p.type) {
    case ParamType::boolean: return v[0] != 0.0 ? "true" : "false";
    case ParamType::enumeration: {
        size_t i = static_cast<size_t>(v[0]);
        return i < p.options.size() ? p.options[i] : std::to_string(i);
    }
    case ParamType::i32: return std::to_string(static_cast<long long>(v[0]));
    default: break;
    }
    std::string out;
    for (int c = 0; c < p.components(); ++c) {
        std::snprintf(buf, sizeof buf, "%.6g", v[static_cast<size_t>(c)]);
        out += (c ? "," : "") + std::string(buf);
    }
    return out;
}

Status save_sidecar(const fs::path& file, const std::vector<graph::ParamDesc>& params,
                    const std::map<std::string, std::array<double, 4>>& values) {
    std::ostringstream o;
    o << "# Param values saved by `passlab run` (the panel's Save button). The next `passlab run`\n"
         "# of this preset applies them; delete this file to return to preset.toml's values.\n";
    for (const auto& p : params) {
        auto it = values.find(p.name);
        if (it == values.end()) continue;
        std::string v = format_param_value(p, it->second);
        if (p.type == graph::ParamType::enumeration) v = "\"" + v + "\"";
        else if (p.components() > 1) v = "[" + v + "]";
        o << p.name << " = " << v << "\n";
    }
    // Temp file + rename: a crash mid-write never leaves a half file the next run trips on.
    fs::path tmp = file;
    tmp += ".tmp";
    {
        std::ofstream f(tmp, std::ios::trunc);
        if (!(f << o.str())) return make_error("cannot write '" + tmp.string() + "'");
    }
    std::error_code ec;
    fs::rename(tmp, file, ec);
    if (ec) return make_error("cannot rename '" + tmp.string() + "' to '" + file.string() + "': " + ec.message());
    return ok_status();
}

Result<std::vector<std::string>> load_sidecar(const fs::path& file) {
    std::vector<std::string> sets;
    std::ifstream f(file);
    if (!f) return sets;  // no sidecar: nothing saved yet
    std::string line;
    int n = 0;
    while (std::getline(f, line)) {
        ++n;
        size_t hash = line.find('#');
        if (hash != std::string::npos) line.erase(hash);
        size_t eq = line.find('=');
        std::string key, value;
        for (char c : line.substr(0, eq == std::string::npos ? line.size() : eq))
            if (c != ' ' && c != '\t' && c != '\r') key += c;
        if (key.empty() && eq == std::string::npos) continue;  // blank or comment line
        if (key.empty() || eq == std::string::npos) {
            Error e = make_error("expected `name = value`");
            e.loc = {file.string(), n, 1};
            return e;
        }
        // The values this file holds map onto `--set` syntax by dropping brackets and quotes.
        for (char c : line.substr(eq + 1))
            if (c != ' ' && c != '\t' && c != '\r' && c != '[' && c != ']' && c != '"') value += c;
        sets.push_back(key + "=" + value);
    }
    return sets;
}

} // namespace pl::exec
