#include "import/import.hpp"

#include "import/shadertoy_read.hpp"

#include <fstream>

namespace pl::import {

namespace fs = std::filesystem;

namespace {

std::string head_of(const fs::path& p, size_t n) {
    std::ifstream in(p, std::ios::binary);
    std::string s(n, '\0');
    in.read(s.data(), static_cast<std::streamsize>(n));
    s.resize(static_cast<size_t>(in.gcount()));
    if (s.rfind("\xEF\xBB\xBF", 0) == 0) s.erase(0, 3);
    return s;
}

// An ISF file starts with a comment holding its JSON header: /*{ ... }*/.
bool looks_isf(const fs::path& p) {
    std::string h = head_of(p, 4096);
    size_t b = h.find_first_not_of(" \t\r\n");
    if (b == std::string::npos || h.compare(b, 2, "/*") != 0) return false;
    size_t j = h.find_first_not_of(" \t\r\n", b + 2);
    return j != std::string::npos && h[j] == '{';
}

} // namespace

std::optional<SourceKind> detect_source(const fs::path& path, const std::string& forced) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
        if (fs::exists(path / "preset.toml", ec)) return std::nullopt;
        if (fs::exists(path / "image.glsl", ec) || forced == "shadertoy") return SourceKind::shadertoy_folder;
        return std::nullopt;
    }
    if (!fs::is_regular_file(path, ec)) return std::nullopt;
    const std::string ext = path.extension().string();
    if (ext == ".toml") return std::nullopt;
    if (forced == "isf") return SourceKind::isf;
    if (ext == ".json") return SourceKind::shadertoy_json;
    if (forced == "shadertoy") return SourceKind::shadertoy_file;
    if (ext == ".fs" || ((ext == ".frag" || ext == ".glsl") && looks_isf(path))) return SourceKind::isf;
    // A .frag/.glsl is a Shadertoy Image tab only if it defines mainImage: an ordinary shader
    // given where a preset is expected gets the "a preset is a folder" message instead.
    if ((ext == ".frag" || ext == ".glsl") && head_of(path, 1u << 20).find("mainImage") != std::string::npos)
        return SourceKind::shadertoy_file;
    return std::nullopt;
}

Result<PresetFiles> import_source(const fs::path& path, const ImportOptions& o) {
    if (!o.kind.empty() && o.kind != "shadertoy" && o.kind != "isf") {
        Error e = make_error("--kind " + o.kind + ": expected shadertoy or isf");
        e.code = ExitCode::usage;
        return e;
    }
    auto kind = detect_source(path, o.kind);
    if (!kind) {
        Error e = make_error("'" + path.string() + "' is not a Shadertoy or ISF source");
        e.hint = "Shadertoy: an API .json, a .glsl/.frag with mainImage, or a folder with image.glsl; ISF: a .fs with its JSON header";
        return e;
    }
    if (*kind == SourceKind::isf) return import_isf(path, o);
    Result<Toy> toy = *kind == SourceKind::shadertoy_json   ? read_shadertoy_json(path)
                      : *kind == SourceKind::shadertoy_file ? read_shadertoy_file(path)
                                                            : read_shadertoy_folder(path);
    if (!toy) return toy.error();
    auto files = shadertoy_preset(*toy, o);
    if (!files) return files.error();
    std::error_code ec;
    if (*kind == SourceKind::shadertoy_folder) {
        for (const auto& f : fs::directory_iterator(path, ec))
            if (f.is_regular_file()) files->inputs.push_back(fs::absolute(f.path()));
    } else {
        files->inputs.push_back(fs::absolute(path));
    }
    return files;
}

} // namespace pl::import
